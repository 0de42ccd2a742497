#include "lang/cga/derivation_graph.h"

#include <initializer_list>
#include <map>
#include <string_view>
#include <unordered_set>
#include <utility>

#include "lang/cga/json_out.h"
#include "lang/cga/printer.h"

namespace insula::lang::cga {
namespace {

// Concatenation through append: GCC 12 reports a false -Wrestrict on `"n" + std::to_string(i)`.
std::string cat(std::initializer_list<std::string_view> parts) {
  std::string out;
  for (const std::string_view part : parts) out.append(part);
  return out;
}

std::string node_id(std::size_t i) {
  return cat({"n", std::to_string(i)});
}

// The value of a probability written as arithmetic on numbers (`0.5`, `(1 - 0.25)`); nullopt
// when it depends on anything else (attributes, random functions).
std::optional<double> constant_value(const Expr& e) {
  if (e.kind == ExprKind::kNumber) return e.number;
  if (e.kind == ExprKind::kUnary && e.unary_op == UnaryOp::kNegate) {
    const std::optional<double> inner = constant_value(*e.operands[0]);
    if (inner) return -*inner;
    return std::nullopt;
  }
  if (e.kind != ExprKind::kBinary) return std::nullopt;
  const std::optional<double> a = constant_value(*e.operands[0]);
  const std::optional<double> b = constant_value(*e.operands[1]);
  if (!a || !b) return std::nullopt;
  switch (e.binary_op) {
    case BinaryOp::kAdd:
      return *a + *b;
    case BinaryOp::kSub:
      return *a - *b;
    case BinaryOp::kMul:
      return *a * *b;
    case BinaryOp::kDiv:
      if (*b == 0) return std::nullopt;
      return *a / *b;
    default:
      return std::nullopt;
  }
}

// CityEngine's lower-case `split`/`comp` are the paper's basic and component splits; a `split`
// made only of repeat patterns `{ ... }*` is a repeat.
std::optional<EdgeType> derivation_type(const Item& it) {
  if (it.kind != ItemKind::kOp) return std::nullopt;
  switch (it.op) {
    case OpKind::kSplit:
      return EdgeType::kBasicSplit;
    case OpKind::kRepeat:
      return EdgeType::kRepeat;
    case OpKind::kComp:
      return EdgeType::kComponentSplit;
    case OpKind::kGeneric:
      break;
    default:
      return std::nullopt;
  }
  if (it.name == "comp") return EdgeType::kComponentSplit;
  if (it.name != "split" || it.branches.empty()) return std::nullopt;
  for (const Branch& b : it.branches) {
    if (!b.repeat) return EdgeType::kBasicSplit;
  }
  return EdgeType::kRepeat;
}

class Builder {
 public:
  explicit Builder(const base::Source& source) : source_(source) {}

  DerivationGraph run(const Grammar& g) {
    graph_.file = g.file;
    // Non-terminals first, in order of their first rule, so the kind is known before targets.
    for (const PrioritySet& set : g.sets) {
      for (const Rule& r : set.rules)
        node(symbol_key(r.predecessor), r.predecessor, NodeKind::kNonTerminal);
    }
    for (const PrioritySet& set : g.sets) {
      for (const Rule& r : set.rules) rule(set, r);
    }
    std::vector<bool> reached(graph_.nodes.size(), false);
    for (const RuleEdge& e : graph_.edges) {
      for (const std::size_t t : e.targets) {
        if (t != e.source) reached[t] = true;
      }
    }
    for (std::size_t i = 0; i < graph_.nodes.size(); ++i) graph_.nodes[i].root = !reached[i];
    return std::move(graph_);
  }

 private:
  static std::string symbol_key(const std::string& name) { return cat({"s:", name}); }

  std::size_t node(const std::string& key, const std::string& name, NodeKind kind,
                   bool predefined = false) {
    const auto [it, inserted] = index_.emplace(key, graph_.nodes.size());
    if (inserted) graph_.nodes.push_back(GraphNode{name, kind, predefined, false});
    return it->second;
  }

  void rule(const PrioritySet& set, const Rule& r) {
    const std::size_t source = index_.at(symbol_key(r.predecessor));
    for (std::size_t k = 0; k < r.alternatives.size(); ++k) {
      const Alternative& alt = r.alternatives[k];
      RuleEdge edge;
      edge.source = source;
      edge.rule_id = r.id;
      edge.priority = set.priority;
      edge.rule_part = k;
      edge.line = source_.locate(alt.range.begin).first;
      if (r.condition) edge.condition = print(*r.condition);
      if (alt.probability) {
        edge.probability_text = print(*alt.probability);
        edge.probability = constant_value(*alt.probability);
      } else if (r.alternatives.size() == 1) {
        edge.probability = 1.0;
      }
      // The first split of the successor types the edge; without one it is a substitution.
      for (const Item& it : alt.items) {
        if (const std::optional<EdgeType> type = derivation_type(it)) {
          edge.type = *type;
          break;
        }
      }
      seen_.clear();
      collect(alt.items, edge);
      graph_.edges.push_back(std::move(edge));
    }
  }

  // Each target once per edge; `seen_` holds the targets of the edge being built, so a successor
  // with thousands of shapes stays linear.
  void add_target(RuleEdge& edge, std::size_t target) {
    if (seen_.insert(target).second) edge.targets.push_back(target);
  }

  // Every shape the successor generates, through nested blocks and repeat patterns
  // (the ATL helper getTargetNodes of §VII.B).
  void collect(const std::vector<Item>& items, RuleEdge& edge) {
    for (const Item& it : items) {
      switch (it.kind) {
        case ItemKind::kSymbol:
          add_target(edge, node(symbol_key(it.name), it.name, NodeKind::kTerminal));
          break;
        case ItemKind::kEmpty:
          add_target(edge, node("e:", "\xCE\xB5", NodeKind::kEmpty));
          break;
        case ItemKind::kPush:
        case ItemKind::kPop:
          break;
        case ItemKind::kCase:
        case ItemKind::kChance:
          for (const Branch& b : it.branches) branch(b, edge);
          break;
        case ItemKind::kOp:
          edge.operations.push_back(it.name);
          if ((it.op == OpKind::kPredefined || it.op == OpKind::kInsert) && it.args.size() == 1) {
            const Expr& arg = *it.args[0];
            const std::string name = arg.kind == ExprKind::kString ? arg.text : print(arg);
            add_target(edge, node(cat({"p:", name}), name, NodeKind::kTerminal, true));
          }
          for (const Branch& b : it.branches) branch(b, edge);
          break;
      }
    }
  }

  void branch(const Branch& b, RuleEdge& edge) {
    for (const Branch& inner : b.pattern) branch(inner, edge);
    collect(b.items, edge);
  }

  const base::Source& source_;
  DerivationGraph graph_;
  std::map<std::string, std::size_t> index_;
  std::unordered_set<std::size_t> seen_;
};

std::string dot_string(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    out += c;
  }
  out += '"';
  return out;
}

std::string_view edge_type_label(EdgeType type) {
  constexpr std::string_view kLabels[] = {"component split", "basic split", "repeat",
                                          "substitution"};
  return kLabels[static_cast<int>(type)];
}

std::string probability_label(const RuleEdge& e) {
  if (e.probability) return number_text(*e.probability);
  return e.probability_text.empty() ? "?" : e.probability_text;
}

}  // namespace

std::string_view node_kind_name(NodeKind kind) {
  constexpr std::string_view kNames[] = {"nonTerminal", "terminal", "empty"};
  return kNames[static_cast<int>(kind)];
}

std::string_view edge_type_name(EdgeType type) {
  constexpr std::string_view kNames[] = {"componentSplit", "basicSplit", "repeat", "substitution"};
  return kNames[static_cast<int>(type)];
}

DerivationGraph derivation_graph(const Grammar& grammar, const base::Source& source) {
  return Builder(source).run(grammar);
}

std::string graph_dot(const DerivationGraph& graph) {
  std::string out = "digraph derivation {\n";
  out += "  graph [label=" + dot_string(graph.file) + ", labelloc=t, fontname=\"Helvetica\"];\n";
  out += "  node [fontname=\"Helvetica\", fontsize=11];\n";
  out += "  edge [fontname=\"Helvetica\", fontsize=9];\n";
  for (std::size_t i = 0; i < graph.nodes.size(); ++i) {
    const GraphNode& n = graph.nodes[i];
    std::string style;
    switch (n.kind) {
      case NodeKind::kNonTerminal:
        style = n.root ? "shape=ellipse, peripheries=2" : "shape=ellipse";
        break;
      case NodeKind::kTerminal:
        style = n.predefined ? "shape=box3d" : "shape=box";
        break;
      case NodeKind::kEmpty:
        style = "shape=circle, width=0.3, fixedsize=true";
        break;
    }
    out += cat({"  ", node_id(i), " [label=", dot_string(n.name), ", ", style, "];\n"});
  }
  for (std::size_t i = 0; i < graph.edges.size(); ++i) {
    const RuleEdge& e = graph.edges[i];
    std::string label = (e.rule_id.empty() ? std::string("_") : e.rule_id) + ": " +
                        std::string(edge_type_label(e.type)) + "\np=" + probability_label(e);
    if (!e.condition.empty()) label += cat({"\n[", e.condition, "]"});
    const std::string id = cat({"e", std::to_string(i)});
    out += cat({"  ", id, " [label=", dot_string(label),
                ", shape=box, style=\"rounded,dashed\", fontsize=9];\n"});
    out += cat({"  ", node_id(e.source), " -> ", id, " [arrowhead=none];\n"});
    for (const std::size_t t : e.targets) out += cat({"  ", id, " -> ", node_id(t), ";\n"});
  }
  out += "}\n";
  return out;
}

std::string graph_json(const DerivationGraph& graph) {
  JsonOut out;
  const auto field = [&](std::string_view name, std::string_view value) {
    out.key(name);
    out.string(value);
  };
  out.begin_object();
  field("format", "insula-cga-derivation-graph");
  out.key("version");
  out.integer(1);
  field("file", graph.file);
  out.key("nodes");
  out.begin_array();
  for (std::size_t i = 0; i < graph.nodes.size(); ++i) {
    const GraphNode& n = graph.nodes[i];
    out.begin_object();
    field("id", node_id(i));
    field("name", n.name);
    field("kind", node_kind_name(n.kind));
    out.key("predefined");
    out.boolean(n.predefined);
    out.key("root");
    out.boolean(n.root);
    out.end_object();
  }
  out.end_array();
  out.key("edges");
  out.begin_array();
  for (std::size_t i = 0; i < graph.edges.size(); ++i) {
    const RuleEdge& e = graph.edges[i];
    out.begin_object();
    field("id", cat({"e", std::to_string(i)}));
    field("rule", e.rule_id);
    out.key("priority");
    out.integer(e.priority);
    out.key("rulePart");
    out.integer(static_cast<long long>(e.rule_part));
    field("type", edge_type_name(e.type));
    field("source", node_id(e.source));
    out.key("targets");
    out.begin_array();
    for (const std::size_t t : e.targets) out.string(node_id(t));
    out.end_array();
    out.key("probability");
    if (e.probability) {
      out.number(*e.probability);
    } else {
      out.null();
    }
    field("probabilityText", e.probability_text);
    out.key("condition");
    if (e.condition.empty()) {
      out.null();
    } else {
      out.string(e.condition);
    }
    out.key("operations");
    out.begin_array();
    for (const std::string& op : e.operations) out.string(op);
    out.end_array();
    out.key("line");
    out.integer(e.line);
    out.end_object();
  }
  out.end_array();
  out.end_object();
  return out.take();
}

}  // namespace insula::lang::cga
