// A `.graph.json` document as read (docs/graph-executor.md): graphs, nodes, edges, gates,
// declarations and parameter values, each with the byte offset it came from in its file. The
// reader fills it (reader.h); the checker (checker.h) resolves it against the catalogue.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "base/diagnostic.h"
#include "lang/graph/json.h"
#include "lang/graph/types.h"

namespace insula::lang::graph {

struct Graph;

// "node.port" in an edge or a gate.
struct PortRef {
  std::string node;
  std::string port;
  std::size_t offset = 0;  // the reference's first byte (inside an edge string: its first letter)
  std::string text() const { return node + "." + port; }
};

struct Edge {
  PortRef from;
  PortRef to;
  std::size_t offset = 0;  // the edge string or object
  bool enabled = true;
  std::string text() const { return from.text() + " -> " + to.text(); }
};

// A parameter value: a literal or an expression (a string starting with `=`; `{"value": "=..."}`
// is the literal string). Expressions are kept as text with the offset of their `=`; the
// expression stage parses them.
struct ParamValue {
  std::string name;
  std::size_t name_offset = 0;
  const JsonValue* value = nullptr;  // the literal (or the expression's string)
  bool expression = false;
};

struct Augmentation {
  std::string kind;  // as written, or the node type's only kind
  std::size_t kind_offset = 0;
  std::string out;  // the output port it feeds (given, or <kind><i>)
  std::size_t out_offset = 0;
  std::size_t offset = 0;
  std::vector<ParamValue> fields;
};

enum class Direction : std::uint8_t { kIn, kOut, kInOut };

// Node attribute -> graph attribute (paper §3.6).
struct AttributeMapping {
  std::string node_attribute;
  std::size_t offset = 0;  // the key
  std::string to;
  std::size_t to_offset = 0;
  Direction direction = Direction::kInOut;
};

struct PortOptions {
  std::string port;
  std::size_t offset = 0;
  bool blocked = false;
  std::optional<bool> collective;  // `mode`, when given
  std::size_t mode_offset = 0;
};

struct Node {
  std::string id;
  std::size_t offset = 0;  // the node object
  std::size_t id_offset = 0;
  std::string type;
  std::size_t type_offset = 0;
  std::string graph_ref;  // subgraph: "#name" or a path relative to the file
  std::size_t graph_offset = 0;
  std::vector<ParamValue> params;
  std::size_t params_offset = 0;
  std::vector<Augmentation> augment;
  std::vector<AttributeMapping> attributes;
  std::vector<PortOptions> ports;
  bool enabled = true;
  bool standalone_only = false;
  const Graph* subgraph = nullptr;  // resolved by the reader for `subgraph` nodes
};

struct Declaration {
  std::string name;
  std::size_t offset = 0;
  ValueType type = ValueType::kNumber;
  std::size_t type_offset = 0;
  const JsonValue* default_value = nullptr;  // null for an attribute without a default
  std::optional<double> min;
  std::optional<double> max;
  std::vector<std::string> choices;
  bool is_public = true;
};

struct Gate {
  std::string name;
  std::size_t offset = 0;
  std::vector<PortRef> ports;
};

struct Limits {
  std::int64_t max_rounds = 10'000'000;
  std::int64_t max_entities = 10'000'000;
  std::int64_t max_subgraph_depth = 32;
};

struct Graph {
  const base::Source* source = nullptr;  // the file it is in
  std::string folder;  // its file's folder, relative to the top-level graph's ("" for that one)
  std::string ref;     // how it is named: the file's path, or "#name" for an inline graph
  std::size_t offset = 0;
  const Graph* enclosing = nullptr;  // the graph whose `subgraphs` defines it (inline only)
  std::string name;
  std::int64_t seed = 0;
  std::vector<Declaration> parameters;
  std::vector<Declaration> attributes;
  std::vector<Node> nodes;
  std::vector<Edge> edges;
  std::vector<Gate> inputs;
  std::vector<Gate> outputs;
  std::vector<std::pair<std::string, const Graph*>> subgraphs;  // inline, in file order
  Limits limits;

  const Node* node(std::string_view id) const;
  const Declaration* parameter(std::string_view name) const;
  const Declaration* attribute(std::string_view name) const;
};

// Everything one top-level file brings: its graph, the inline graphs and the subgraph files it
// reaches (each file read once), and their texts.
struct Document {
  const Graph* root = nullptr;
  std::vector<std::unique_ptr<Graph>> graphs;          // root first, then in reading order
  std::vector<std::unique_ptr<base::Source>> sources;  // the root's first
  std::vector<std::unique_ptr<JsonValue>> json;        // one per source
  // The first `subgraph` node that uses each graph (for notes), by graph.
  std::map<const Graph*, std::pair<const Graph*, const Node*>> used_by;
};

}  // namespace insula::lang::graph
