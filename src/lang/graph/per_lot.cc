#include "lang/graph/per_lot.h"

#include <algorithm>
#include <array>
#include <string_view>
#include <vector>

#include "lang/graph/catalogue.h"

namespace insula::lang::graph {
namespace {

// Families whose nodes make entities or look at several at once.
constexpr std::array<std::string_view, 5> kRelating = {"creation", "list", "query", "path",
                                                       "terrain"};

std::string named(const CheckedNode& node) {
  return "node '" + node.node->id + "' (" + (node.type ? node.type->name : "subgraph") + ")";
}

std::size_t connected_inputs(const CheckedNode& node) {
  return static_cast<std::size_t>(
      std::count_if(node.inputs.begin(), node.inputs.end(),
                    [](const ResolvedPort& p) { return !p.edges.empty(); }));
}

// Why create.lots `node` does not read the --lot file once per run, or empty.
std::string lots_obstacle(const CheckedNode& node) {
  for (const ParamValue& p : node.node->params) {
    if (p.name != "file") continue;
    if (p.expression || p.value == nullptr || p.value->kind != JsonValue::Kind::kString ||
        !p.value->text.empty()) {
      return named(node) + " reads its own file, not --lot";
    }
  }
  if (connected_inputs(node) > 0) return named(node) + " runs once per impulse";
  return {};
}

}  // namespace

bool reads_lot_file(const CheckResult& checked) {
  for (const CheckedGraph& graph : checked.graphs) {
    for (const CheckedNode& node : graph.nodes) {
      if (node.type == nullptr || node.type->name != "create.lots") continue;
      const auto file = std::find_if(node.node->params.begin(), node.node->params.end(),
                                     [](const ParamValue& p) { return p.name == "file"; });
      if (file == node.node->params.end() || file->expression || file->value == nullptr ||
          file->value->kind != JsonValue::Kind::kString || file->value->text.empty()) {
        return true;
      }
    }
  }
  return false;
}

std::string per_lot_obstacle(const CheckResult& checked) {
  if (!checked.ok || checked.graphs.empty()) return "the graph has errors";
  const CheckedGraph& graph = checked.graphs.front();
  std::vector<std::size_t> lots;
  for (std::size_t n = 0; n < graph.nodes.size(); ++n) {
    const CheckedNode& node = graph.nodes[n];
    if (node.type != nullptr && node.type->name == "create.lots") lots.push_back(n);
  }
  if (lots.size() != 1) {
    return lots.empty() ? "no create.lots node" : "more than one create.lots node";
  }
  if (std::string why = lots_obstacle(graph.nodes[lots[0]]); !why.empty()) return why;
  // Every node must be fed from the lots: a node that is not makes entities of its own.
  std::vector<bool> fed(graph.nodes.size(), false);
  std::vector<std::size_t> stack = lots;
  fed[lots[0]] = true;
  while (!stack.empty()) {
    const std::size_t n = stack.back();
    stack.pop_back();
    for (const ResolvedPort& port : graph.nodes[n].outputs) {
      for (const std::size_t e : port.edges) {
        const std::size_t to = graph.edges[e].to_node;
        if (!fed[to]) {
          fed[to] = true;
          stack.push_back(to);
        }
      }
    }
  }
  for (std::size_t n = 0; n < graph.nodes.size(); ++n) {
    if (n == lots[0]) continue;
    const CheckedNode& node = graph.nodes[n];
    if (node.type == nullptr) return named(node) + " is a subgraph";
    const std::string_view family = node.type->category;
    if (std::find(kRelating.begin(), kRelating.end(), family) != kRelating.end()) {
      return named(node) + " is a " + std::string(family) + " node";
    }
    if (!fed[n]) return named(node) + " is not fed from the lots";
    if (family == "light") return named(node) + " makes lights, which 3D Tiles do not carry";
    if (node.collective) return named(node) + " takes its entities together";
    if (connected_inputs(node) > 1) return named(node) + " pairs entities of several inputs";
  }
  return {};
}

}  // namespace insula::lang::graph
