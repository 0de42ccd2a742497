// run_graph: parameters with --set (§6), the top-level execution, and run-time diagnostics
// (graph-format.md §9, §12; docs/graph-executor.md, "Execution").
#include "lang/graph/executor.h"

#include <algorithm>

#include "lang/graph/context.h"
#include "lang/graph/execution.h"

namespace insula::lang::graph {
namespace {

base::Diagnostic diagnostic(const RunError& e, bool warning) {
  base::Span span = base::Span::whole(
      e.graph != nullptr && e.graph->source != nullptr ? e.graph->source->name() : std::string());
  if (e.graph != nullptr && e.graph->source != nullptr) {
    const auto [line, column] = e.graph->source->locate(e.offset);
    span = base::Span::at(e.graph->source->name(), line, column);
  }
  base::Diagnostic d = warning ? base::Diagnostic::warning(e.code, e.message, span)
                               : base::Diagnostic::error(e.code, e.message, span);
  d.notes = e.notes;
  return d;
}

// A --set value as the parameter's type: numbers, integers, true/false, text, vec3 and lists
// as JSON ("[1,2,3]").
std::optional<Value> parse_set(const Declaration& d, const std::string& text) {
  if (d.type == ValueType::kString || d.type == ValueType::kEnum) return Value(text);
  base::Source source("--set", text);
  base::Result<JsonValue> json = parse_json(source);
  if (!json.ok()) return std::nullopt;
  std::optional<Value> v = value_from_json(json.value(), d.type);
  if (!v) return std::nullopt;
  return convert(*v, d.type);
}

std::vector<Value> root_parameters(const Graph& root, const RunOptions& options, RunState& state,
                                   std::vector<base::Diagnostic>& diagnostics) {
  std::vector<Value> values;
  for (const Declaration& d : root.parameters) values.push_back(declared_default(d, state));
  std::vector<std::string> names;
  for (const Declaration& d : root.parameters) names.push_back(d.name);
  for (const auto& [name, text] : options.sets) {
    const base::Span where = base::Span::whole("--set " + name + "=" + text);
    const Declaration* d = root.parameter(name);
    if (d == nullptr) {
      const std::string near = nearest(name, names);
      diagnostics.push_back(base::Diagnostic::error(
          "G021",
          "unknown graph parameter '" + name + "'" +
              (near.empty() ? std::string() : " (did you mean '" + near + "'?)"),
          where));
      continue;
    }
    std::optional<Value> v = parse_set(*d, text);
    std::string problem;
    if (!v) {
      problem = "must be " + std::string(value_type_name(d->type)) + "; got '" + text + "'";
    } else if (v->is_number() && d->min && v->number() < *d->min) {
      problem = "must be >= " + to_string(Value(*d->min)) + "; got " + text;
    } else if (v->is_number() && d->max && v->number() > *d->max) {
      problem = "must be <= " + to_string(Value(*d->max)) + "; got " + text;
    } else if (d->type == ValueType::kEnum &&
               std::find(d->choices.begin(), d->choices.end(), text) == d->choices.end()) {
      std::string list;
      for (const std::string& c : d->choices) list += (list.empty() ? "" : ", ") + c;
      problem = "must be one of " + list + "; got '" + text + "'";
    }
    if (!problem.empty()) {
      diagnostics.push_back(
          base::Diagnostic::error("G025", "parameter '" + name + "' " + problem, where));
      continue;
    }
    values[static_cast<std::size_t>(d - root.parameters.data())] = *v;
  }
  return values;
}

}  // namespace

RunResult run_graph(const Document& document, const CheckResult& checked,
                    const RunOptions& options) {
  RunResult out;
  const Graph& root = *document.root;
  out.seed = options.seed.value_or(static_cast<std::uint64_t>(root.seed));
  out.tree = shape::ShapeTree(out.seed);
  out.materials.push_back({"default", {0.8F, 0.8F, 0.8F, 1.0F}});
  RunState state(document, checked, options, out);
  state.root_limits = root.limits;
  if (options.limits_cap) {
    state.root_limits.max_rounds =
        std::min(state.root_limits.max_rounds, options.limits_cap->max_rounds);
    state.root_limits.max_entities =
        std::min(state.root_limits.max_entities, options.limits_cap->max_entities);
    state.root_limits.max_subgraph_depth =
        std::min(state.root_limits.max_subgraph_depth, options.limits_cap->max_subgraph_depth);
  }
  for (std::size_t i = 0; i < document.graphs.size() && i < checked.graphs.size(); ++i) {
    state.checked_of[document.graphs[i].get()] = &checked.graphs[i];
  }
  const CheckedGraph& top = *state.checked_of.at(&root);
  for (std::size_t e = 0; e < top.edges.size(); ++e) {
    if (top.standalone.cyclic[e]) out.cyclic_edges.push_back(top.edges[e].edge->text());
  }
  std::vector<Value> parameters = root_parameters(root, options, state, out.diagnostics);
  if (base::has_errors(out.diagnostics)) return out;
  for (std::size_t a = 0; a < root.attributes.size(); ++a) {
    out.attribute_names[attribute_key(0, a)] = root.attributes[a].name;
  }
  try {
    GraphExecution execution(state, top, false, std::move(parameters), "", {}, 0);
    execution.run();
  } catch (const RunError& e) {
    out.diagnostics.push_back(diagnostic(e, false));
    return out;
  }
  // §13: results by leaf port in order of first arrival, each port's in arrival order.
  std::stable_sort(out.results.begin(), out.results.end(),
                   [&state](const ResultEntity& a, const ResultEntity& b) {
                     return state.leaf_index.at(a.port) < state.leaf_index.at(b.port);
                   });
  if (!options.probe.empty()) out.results = std::move(state.probed);
  for (const RunError& w : state.warnings) out.diagnostics.push_back(diagnostic(w, true));
  for (const auto& [port, count] : out.unprocessed) {
    // At the node whose input port they wait at.
    RunError w = state.unprocessed_at.at(port);
    w.message = std::to_string(count) + " entit" + (count == 1 ? "y" : "ies") +
                " left unprocessed at '" + port + "'";
    out.diagnostics.push_back(diagnostic(w, true));
  }
  for (const std::string& who : state.failure_order) {
    const auto& [count, first] = state.failures.at(who);
    RunError e = first;
    e.message = "node '" + who + "': " + std::to_string(count) + " entit" +
                (count == 1 ? "y" : "ies") + " dropped; " + first.message;
    out.diagnostics.push_back(diagnostic(e, true));
  }
  out.ok = true;
  return out;
}

}  // namespace insula::lang::graph
