// Checking a read document before anything runs (§12 codes G010-G030, W001, W020) and the
// execution order of §9 steps 2-3: cyclic edges and execution indices, deterministic, so the
// executor starts from a resolved graph (docs/graph-executor.md, "What the executor gets").
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "base/diagnostic.h"
#include "lang/graph/catalogue.h"
#include "lang/graph/model.h"

namespace insula::lang::graph {

// A port of a node as used: catalogue ports, augmentation ports, or a subgraph's gates.
struct ResolvedPort {
  std::string name;
  EntityType type = EntityType::kEntity;  // a generic port: the inferred type, else its bound
  bool generic = false;
  bool collective = false;  // inputs: after `ports.X.mode`
  bool optional = false;
  bool blocked = false;
  bool gate = false;               // named by one of the graph's gates
  std::vector<std::size_t> edges;  // indices into CheckedGraph::edges (outgoing or incoming)
};

struct CheckedNode {
  const Node* node = nullptr;
  const NodeType* type = nullptr;  // null for `subgraph`
  std::vector<ResolvedPort> inputs;
  std::vector<ResolvedPort> outputs;  // catalogue order, then augmentation ports in item order
  std::optional<EntityType> generic;  // the inferred `T`, when some entity type reaches it
  bool collective = false;            // some input port is collective
  std::size_t file_index = 0;         // position in the graph's `nodes`
};

struct CheckedEdge {
  const Edge* edge = nullptr;
  std::size_t from_node = 0;  // indices into CheckedGraph::nodes and their ports
  std::size_t from_port = 0;
  std::size_t to_node = 0;
  std::size_t to_port = 0;
};

// §9 steps 2-3 for one set of active nodes.
struct ExecutionOrder {
  std::vector<bool> cyclic;            // per edge
  std::vector<std::size_t> order;      // node indices by execution index
  std::vector<std::size_t> index;      // per node: its execution index
  std::vector<std::size_t> component;  // per node: its strongly connected component
  std::vector<bool> in_cycle;          // per node: its component is a cycle
  bool empty() const { return order.empty(); }
};

struct CheckedGraph {
  const Graph* graph = nullptr;
  std::vector<CheckedNode> nodes;  // enabled, non-note nodes in file order
  std::vector<CheckedEdge> edges;  // enabled edges between them, in file order
  bool used_as_subgraph = false;
  ExecutionOrder standalone;    // run on its own (standalone_only nodes kept)
  ExecutionOrder encapsulated;  // run inside a subgraph node (standalone_only nodes dropped)
  std::optional<std::size_t> node(std::string_view id) const;
};

struct CheckResult {
  bool ok = false;
  std::vector<base::Diagnostic> diagnostics;  // errors and warnings, graph by graph in file order
  std::vector<CheckedGraph> graphs;           // parallel to Document::graphs (when ok)
};

CheckResult check(const Document& document);

// §9 steps 2-3 over `graph`'s nodes, leaving out the standalone_only ones when `encapsulated`.
ExecutionOrder execution_order(const CheckedGraph& graph, bool encapsulated);

// The golden text of every graph's execution order: per graph its reference, then one line per
// node `index id (type)`, cycles as `cycle a b`, and cyclic edges.
std::string dump_order(const Document& document, const CheckResult& result);

}  // namespace insula::lang::graph
