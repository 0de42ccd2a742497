// One execution of a graph (internal to the executor, graph-format.md §9.4-9.6): the top-level
// run, or one round of a subgraph node (§8). It owns the input queues and the set of ready nodes
// by execution index; node rounds run through an ExecutionContext (context.h).
#pragma once

#include <deque>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "lang/graph/run_state.h"

namespace insula::lang::graph {

class GraphExecution {
 public:
  GraphExecution(RunState& run, const CheckedGraph& graph, bool encapsulated,
                 std::vector<Value> parameters, std::string prefix, std::vector<std::string> notes,
                 int depth);

  // Places entities at input gate `gate` (each of its ports gets them; later ports copies).
  void feed_gate(std::size_t gate, std::span<const EntityId> entities);
  // Runs until no node is ready (§9.4-9.6).
  void run();

  RunState& state() const { return run_; }
  const CheckedGraph& graph() const { return graph_; }
  std::uint64_t execution() const { return execution_; }
  const std::vector<Value>& parameters() const { return parameters_; }
  const std::string& prefix() const { return prefix_; }
  const std::vector<std::string>& notes() const { return notes_; }
  int depth() const { return depth_; }
  // What reached each output gate, in arrival order.
  const std::vector<std::vector<EntityId>>& gate_outputs() const { return gate_outputs_; }
  bool connected(std::size_t node, std::size_t port) const { return connected_[node][port]; }

  // The attribute key of `name` in this execution (a declared attribute of the graph).
  AttributeKey attribute_key(const std::string& name) const;
  // "prefix/node.port".
  std::string label(std::size_t node, std::string_view port) const;
  // "a -> b -> a" for the node's cycle in execution order, "" when it is in none.
  std::string cycle_of(std::size_t node) const;
  [[noreturn]] void fail_at(const std::string& code, std::string message, std::size_t offset) const;

 private:
  bool is_source(std::size_t node) const;
  bool inputs_ready(std::size_t node) const;
  void maybe_ready(std::size_t node);
  // `from` names the output port it left ("pick.true"; empty for a gate) for G052.
  void arrive(std::size_t node, std::size_t port, EntityId entity, std::string_view from = {});
  void count_round(std::size_t node);
  void take_inputs(std::size_t node, Rounds& rounds);
  void execute(std::size_t node);
  void run_subgraph(std::size_t node, const Rounds& rounds,
                    std::vector<std::vector<EntityId>>& outputs);
  void transfer(std::size_t node, std::vector<std::vector<EntityId>>& outputs);

  RunState& run_;
  const CheckedGraph& graph_;
  const ExecutionOrder& order_;
  bool encapsulated_;
  std::uint64_t execution_;
  std::vector<Value> parameters_;
  std::string prefix_;
  std::vector<std::string> notes_;
  int depth_;
  std::vector<bool> active_;
  std::vector<std::vector<std::deque<EntityId>>> queues_;
  std::vector<std::vector<bool>> connected_;
  std::set<std::size_t> ready_;  // execution indices
  std::vector<std::vector<EntityId>> gate_outputs_;
};

}  // namespace insula::lang::graph
