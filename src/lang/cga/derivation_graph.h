// The derivation graph of a CGA grammar: the model-to-model transformation of seed 004 §VII.B
// (Fig. 12 metamodel, Fig. 13 example). Nodes are the shapes of the grammar: non-terminal (the
// predecessor of some rule), terminal (a symbol no rule rewrites, or a predefined shape
// `Pshape("f.obj")` / inserted object `I("cube")`) and empty (ε). Each rule part (alternative)
// becomes one directed rule edge from its predecessor to every shape its successor generates,
// typed component split, basic split, repeat or substitution and labelled with the rule id and
// probability. Scope rules are not derivation rules (§VII.B) and make no edges of their own.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "base/diagnostic.h"
#include "lang/cga/ast.h"

namespace insula::lang::cga {

enum class NodeKind { kNonTerminal, kTerminal, kEmpty };

// §VII.B: "of a type (component split, basic split, repeat, substitution)".
enum class EdgeType { kComponentSplit, kBasicSplit, kRepeat, kSubstitution };

struct GraphNode {
  std::string name;  // symbol; the file/object for predefined shapes; "ε" for the empty node
  NodeKind kind = NodeKind::kNonTerminal;
  bool predefined = false;  // a Pshape/I object rather than a symbol
  bool root = false;        // no rule edge reaches it (a start symbol)
};

struct RuleEdge {
  std::size_t source = 0;            // node index of the predecessor
  std::vector<std::size_t> targets;  // node indices, each once, in order of first appearance
  EdgeType type = EdgeType::kSubstitution;
  std::string rule_id;  // empty for an unnamed rule
  std::uint32_t priority = 1;
  std::size_t rule_part = 0;            // index of the alternative in its rule
  std::optional<double> probability;    // constant value; 1 for a rule's only part
  std::string probability_text;         // as written (empty when omitted)
  std::string condition;                // the rule's guard, empty when none
  std::vector<std::string> operations;  // operation names of the successor, in order
  std::uint32_t line = 0;               // of the rule part
};

struct DerivationGraph {
  std::string file;
  std::vector<GraphNode> nodes;
  std::vector<RuleEdge> edges;
};

std::string_view node_kind_name(NodeKind kind);  // "nonTerminal", "terminal", "empty"
std::string_view edge_type_name(EdgeType type);  // "componentSplit", "basicSplit", ...

// Builds the graph of `grammar` (parsed from `source`, used for line numbers).
DerivationGraph derivation_graph(const Grammar& grammar, const base::Source& source);

// Graphviz text: shapes as nodes (ellipse: non-terminal, box: terminal, small circle: ε), each
// rule edge as a small labelled node joining its predecessor to its targets (a rule edge of
// Fig. 12 has several target nodes). Ends with a newline.
std::string graph_dot(const DerivationGraph& graph);

// The same content as JSON ("format": "insula-cga-derivation-graph"; schema in
// docs/cga-model.schema.json). Ends with a newline.
std::string graph_json(const DerivationGraph& graph);

}  // namespace insula::lang::cga
