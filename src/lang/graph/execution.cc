#include "lang/graph/execution.h"

#include <algorithm>
#include <chrono>

#include "lang/graph/context.h"
#include "lang/graph/nodes.h"

namespace insula::lang::graph {

GraphExecution::GraphExecution(RunState& run, const CheckedGraph& graph, bool encapsulated,
                               std::vector<Value> parameters, std::string prefix,
                               std::vector<std::string> notes, int depth)
    : run_(run),
      graph_(graph),
      order_(encapsulated ? graph.encapsulated : graph.standalone),
      encapsulated_(encapsulated),
      execution_(run.next_execution++),
      parameters_(std::move(parameters)),
      prefix_(std::move(prefix)),
      notes_(std::move(notes)),
      depth_(depth) {
  const std::size_t n = graph.nodes.size();
  active_.assign(n, false);
  for (std::size_t node : order_.order) active_[node] = true;
  queues_.resize(n);
  connected_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const CheckedNode& node = graph.nodes[i];
    queues_[i].resize(node.inputs.size());
    connected_[i].resize(node.inputs.size());
    for (std::size_t p = 0; p < node.inputs.size(); ++p) {
      // A gate port counts as connected even when nothing feeds the gate (a graph run on its
      // own): the node waits for entities instead of running as a source.
      const ResolvedPort& port = node.inputs[p];
      bool any = port.gate;
      for (std::size_t e : port.edges) any = any || active_[graph.edges[e].from_node];
      connected_[i][p] = any;
    }
  }
  gate_outputs_.resize(graph.graph->outputs.size());
}

AttributeKey GraphExecution::attribute_key(const std::string& name) const {
  const Declaration* d = graph_.graph->attribute(name);
  const std::size_t index = static_cast<std::size_t>(d - graph_.graph->attributes.data());
  return graph::attribute_key(execution_, index);
}

std::string GraphExecution::label(std::size_t node, std::string_view port) const {
  return prefix_ + graph_.nodes[node].node->id + "." + std::string(port);
}

std::string GraphExecution::cycle_of(std::size_t node) const {
  if (!order_.in_cycle[node]) return "";
  std::string text;
  std::string first;
  for (std::size_t n : order_.order) {
    if (order_.component[n] != order_.component[node]) continue;
    if (first.empty()) first = graph_.nodes[n].node->id;
    text += graph_.nodes[n].node->id + " -> ";
  }
  return text + first;
}

void GraphExecution::fail_at(const std::string& code, std::string message,
                             std::size_t offset) const {
  throw RunError{code, std::move(message), graph_.graph, offset, notes_};
}

void GraphExecution::feed_gate(std::size_t gate, std::span<const EntityId> entities) {
  const Gate& g = graph_.graph->inputs[gate];
  bool first = true;
  for (const PortRef& ref : g.ports) {
    const std::optional<std::size_t> node = graph_.node(ref.node);
    if (!node || !active_[*node]) continue;
    const CheckedNode& n = graph_.nodes[*node];
    for (std::size_t p = 0; p < n.inputs.size(); ++p) {
      if (n.inputs[p].name != ref.port) continue;
      for (EntityId e : entities) arrive(*node, p, first ? e : run_.out.entities.copy(e));
    }
    first = false;
  }
}

void GraphExecution::run() {
  for (std::size_t node : order_.order) {
    if (is_source(node) || inputs_ready(node)) ready_.insert(order_.index[node]);
  }
  while (!ready_.empty()) {
    if (run_.options.interrupted && run_.options.interrupted()) {
      throw RunError{"", "interrupted", graph_.graph, 0, {}};
    }
    const std::size_t node = order_.order[*ready_.begin()];
    ready_.erase(ready_.begin());
    execute(node);
  }
  for (std::size_t i = 0; i < graph_.nodes.size(); ++i) {
    for (std::size_t p = 0; p < queues_[i].size(); ++p) {
      if (queues_[i][p].empty()) continue;
      const std::string where = label(i, graph_.nodes[i].inputs[p].name);
      run_.out.unprocessed[where] += queues_[i][p].size();
      run_.unprocessed_at.try_emplace(
          where, RunError{"W010", "", graph_.graph, graph_.nodes[i].node->id_offset, notes_});
      run_.live -= static_cast<std::int64_t>(queues_[i][p].size());
    }
  }
}

bool GraphExecution::is_source(std::size_t node) const {
  return std::none_of(connected_[node].begin(), connected_[node].end(), [](bool c) { return c; });
}

bool GraphExecution::inputs_ready(std::size_t node) const {
  bool any = false;
  for (std::size_t p = 0; p < queues_[node].size(); ++p) {
    if (!connected_[node][p]) continue;
    if (queues_[node][p].empty()) return false;
    any = true;
  }
  return any;
}

void GraphExecution::maybe_ready(std::size_t node) {
  if (active_[node] && inputs_ready(node)) ready_.insert(order_.index[node]);
}

void GraphExecution::arrive(std::size_t node, std::size_t port, EntityId entity,
                            std::string_view from) {
  const ResolvedPort& p = graph_.nodes[node].inputs[port];
  // §4: an edge from a wider type is accepted and each entity checked as it arrives.
  const EntityType type = run_.out.entities[entity].type;
  if (!is_subtype(type, p.type)) {
    std::string message(1, '\'');
    message += graph_.nodes[node].node->id;
    message += '.';
    message += p.name;
    message += "' accepts ";
    message += entity_type_name(p.type);
    if (type == EntityType::kEntity) {
      message += " entities; an entity arrived";
    } else {
      message += " entities; a ";
      message += entity_type_name(type);
      message += " entity arrived";
    }
    if (!from.empty()) {
      message += " from '";
      message += from;
      message += '\'';
    }
    fail_at("G052", std::move(message), graph_.nodes[node].node->id_offset);
  }
  if (p.blocked) {
    ++run_.out.blocked[label(node, p.name)];
    return;
  }
  queues_[node][port].push_back(entity);
  ++run_.live;
  const std::int64_t limit = run_.root_limits.max_entities;
  if (run_.live > limit) {
    const std::string cycle = cycle_of(node);
    fail_at("G051",
            "more than max_entities = " + std::to_string(limit) + " live entities (node '" +
                graph_.nodes[node].node->id + "'" +
                (cycle.empty() ? "" : ", in the cycle " + cycle) + ")",
            graph_.nodes[node].node->id_offset);
  }
}

void GraphExecution::count_round(std::size_t node) {
  ++run_.rounds;
  const std::int64_t limit = run_.root_limits.max_rounds;
  if (run_.rounds > static_cast<std::uint64_t>(limit)) {
    const std::string cycle = cycle_of(node);
    fail_at("G050",
            "graph did not finish within max_rounds = " + std::to_string(limit) + " node rounds; " +
                (cycle.empty() ? "the last was node '" + graph_.nodes[node].node->id + "'"
                               : "entities still circulate in the cycle " + cycle),
            graph_.nodes[node].node->id_offset);
  }
}

void GraphExecution::take_inputs(std::size_t node, Rounds& rounds) {
  const CheckedNode& n = graph_.nodes[node];
  const std::size_t ports = n.inputs.size();
  rounds.ports = ports;
  rounds.offsets.assign(1, 0);
  const auto take_round = [&](bool collective_node) {
    for (std::size_t p = 0; p < ports; ++p) {
      std::deque<EntityId>& q = queues_[node][p];
      const std::size_t take =
          q.empty() ? 0 : (collective_node && n.inputs[p].collective ? q.size() : 1);
      for (std::size_t k = 0; k < take; ++k) {
        rounds.flat.push_back(q.front());
        q.pop_front();
      }
      run_.live -= static_cast<std::int64_t>(take);
      rounds.offsets.push_back(static_cast<std::uint32_t>(rounds.flat.size()));
    }
    ++rounds.count;
    count_round(node);
  };
  if (is_source(node)) {
    take_round(false);  // a source: one round, once per run
  } else if (n.collective) {
    take_round(true);  // a collective node: one execution
  } else {
    while (inputs_ready(node)) take_round(false);
  }
}

void GraphExecution::execute(std::size_t node) {
  const CheckedNode& n = graph_.nodes[node];
  Rounds rounds;
  take_inputs(node, rounds);
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::vector<EntityId>> outputs(n.outputs.size());
  if (n.type == nullptr) {
    run_subgraph(node, rounds, outputs);
  } else {
    const NodeImpl* impl = find_node_impl(n.node->type);
    if (impl == nullptr) {
      fail_at("G010", "node type '" + n.node->type + "' cannot run yet in this version",
              n.node->type_offset);
    }
    ExecutionContext context(*this, node, rounds, outputs);
    impl->run(context);
  }
  NodeRuns& runs = run_.node_runs(prefix_ + n.node->id);
  ++runs.executions;
  runs.rounds += rounds.count;
  runs.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  transfer(node, outputs);
}

void GraphExecution::transfer(std::size_t node, std::vector<std::vector<EntityId>>& outputs) {
  const CheckedNode& n = graph_.nodes[node];
  std::vector<std::size_t> targets;
  for (std::size_t p = 0; p < n.outputs.size(); ++p) {
    const ResolvedPort& port = n.outputs[p];
    const std::vector<EntityId>& produced = outputs[p];
    if (produced.empty()) continue;
    run_.out.ports[label(node, port.name)] += produced.size();
    if (!run_.options.probe.empty() && prefix_ + n.node->id == run_.options.probe) {
      // Copies: the next nodes change the entities they take.
      for (EntityId entity : produced) {
        run_.probed.push_back({run_.out.entities.copy(entity), label(node, port.name)});
      }
    }
    if (port.blocked) {
      run_.out.blocked[label(node, port.name)] += produced.size();
      continue;
    }
    bool used = false;
    for (std::size_t e : port.edges) {
      const CheckedEdge& edge = graph_.edges[e];
      if (!active_[edge.to_node]) continue;
      const std::string from = n.node->id + "." + port.name;
      for (EntityId entity : produced) {
        arrive(edge.to_node, edge.to_port, used ? run_.out.entities.copy(entity) : entity, from);
      }
      used = true;
      targets.push_back(edge.to_node);
    }
    if (port.gate && encapsulated_) {
      for (std::size_t g = 0; g < graph_.graph->outputs.size(); ++g) {
        for (const PortRef& ref : graph_.graph->outputs[g].ports) {
          if (ref.node != n.node->id || ref.port != port.name) continue;
          for (EntityId entity : produced) {
            gate_outputs_[g].push_back(used ? run_.out.entities.copy(entity) : entity);
          }
          used = true;
        }
      }
    }
    // A leaf port: the result of a top-level run; inside a subgraph its entities are dropped
    // (W020 said so at check time).
    if (!used && !encapsulated_) {
      const std::string where = label(node, port.name);
      PortCount& leaf = run_.leaf(where);
      for (EntityId entity : produced) {
        run_.out.results.push_back({entity, where});
        ++leaf.count;
        ++leaf.types[std::string(entity_type_name(run_.out.entities[entity].type))];
      }
    }
  }
  for (std::size_t t : targets) maybe_ready(t);
}

}  // namespace insula::lang::graph
