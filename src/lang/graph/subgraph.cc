// Rounds of a subgraph node (graph-format.md §8): each round runs the whole subgraph with the
// round's entities at its input gates, mapped attributes copied in and out, and what reaches
// the output gates leaves on the node's ports of the same names. The subgraph's own attributes
// are keyed by its execution (entity.h), so they are gone once its entities leave.
#include "lang/graph/context.h"
#include "lang/graph/execution.h"

namespace insula::lang::graph {

void GraphExecution::run_subgraph(std::size_t node, const Rounds& rounds,
                                  std::vector<std::vector<EntityId>>& outputs) {
  const CheckedNode& n = graph_.nodes[node];
  const Graph& sub = *n.node->subgraph;
  const CheckedGraph& checked = *run_.checked_of.at(&sub);
  const std::int64_t max_depth = run_.root_limits.max_subgraph_depth;
  if (depth_ + 1 > max_depth) {
    fail_at("G053",
            "subgraph nesting deeper than max_subgraph_depth = " + std::to_string(max_depth),
            n.node->id_offset);
  }
  ExecutionContext outer(*this, node, rounds, outputs);
  std::vector<std::string> notes{"in subgraph '" + n.node->id + "' (" + n.node->graph_ref + ")"};
  notes.insert(notes.end(), notes_.begin(), notes_.end());
  for (std::size_t round = 0; round < rounds.count; ++round) {
    std::vector<Value> parameters;
    for (const Declaration& d : sub.parameters) {
      const ParamValue* given = nullptr;
      for (const ParamValue& v : n.node->params) {
        if (v.name == d.name && d.is_public) given = &v;
      }
      if (given == nullptr) {
        parameters.push_back(declared_default(d, run_));
        continue;
      }
      ParamSpec spec{};
      spec.name = d.name;
      spec.type = d.type;
      spec.min = d.min;
      spec.max = d.max;
      spec.choices = d.choices;
      parameters.push_back(outer.evaluate(*given, spec, round, outer.current(round),
                                          "parameter '" + d.name + "' of '" + n.node->id + "'"));
    }
    GraphExecution inner(run_, checked, true, std::move(parameters), prefix_ + n.node->id + "/",
                         notes, depth_ + 1);
    for (std::size_t gate = 0; gate < sub.inputs.size(); ++gate) {
      const std::span<const EntityId> entering = rounds.at(round, gate);
      for (EntityId e : entering) {
        for (const AttributeMapping& m : n.node->attributes) {
          if (m.direction == Direction::kOut) continue;
          run_.out.entities.set_attribute(e, inner.attribute_key(m.node_attribute),
                                          outer.attribute(e, m.to));
        }
      }
      inner.feed_gate(gate, entering);
    }
    inner.run();
    for (std::size_t gate = 0; gate < sub.outputs.size(); ++gate) {
      for (EntityId e : inner.gate_outputs()[gate]) {
        for (const AttributeMapping& m : n.node->attributes) {
          if (m.direction == Direction::kIn) continue;
          const Value* v = run_.out.entities.attribute(e, inner.attribute_key(m.node_attribute));
          outer.set_attribute(
              e, m.to,
              v != nullptr ? *v : declared_default(*sub.attribute(m.node_attribute), run_));
        }
        outputs[gate].push_back(e);
      }
    }
  }
}

}  // namespace insula::lang::graph
