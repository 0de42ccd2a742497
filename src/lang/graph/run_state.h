// State shared by every graph execution of one run (internal to the executor): the options, the
// result being filled, counters toward the limits, and caches of parsed expressions and literal
// values, filled before anything runs so node rounds only read them.
#pragma once

#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "lang/graph/checker.h"
#include "lang/graph/executor.h"
#include "lang/graph/expr.h"
#include "lang/graph/value.h"

namespace insula::lang::graph {

// A run-time error that stops the run (G052 and the limits): thrown by the context, caught by
// the executor, which turns it into a diagnostic at `offset` of `graph`'s file.
struct RunError {
  std::string code;
  std::string message;
  const Graph* graph = nullptr;
  std::size_t offset = 0;
  std::vector<std::string> notes;  // "in subgraph 'houseA' (house.graph.json)", innermost first
};

// The inputs of a node's rounds, flat: port p of round r is flat[offsets[r*ports+p] ..
// offsets[r*ports+p+1]).
struct Rounds {
  std::size_t count = 0;
  std::size_t ports = 0;
  std::vector<EntityId> flat;
  std::vector<std::uint32_t> offsets;
  std::span<const EntityId> at(std::size_t round, std::size_t port) const {
    const std::size_t k = round * ports + port;
    return {flat.data() + offsets[k], flat.data() + offsets[k + 1]};
  }
};

// A parsed expression with where it came from (diagnostics point into its string).
struct ParsedExpression {
  Expr expr;
  const JsonValue* string = nullptr;  // the JSON string holding "= ..."
  std::size_t skip = 0;               // bytes of the string before the expression text
};

struct RunState {
  const Document& document;
  const CheckResult& checked;
  const RunOptions& options;
  RunResult& out;
  Limits root_limits;
  std::uint64_t next_execution = 0;
  std::uint64_t rounds = 0;
  std::int64_t live = 0;
  std::map<const Graph*, const CheckedGraph*> checked_of;
  std::map<const JsonValue*, ParsedExpression> expressions;     // by the JSON string
  std::map<const JsonValue*, Value> literals;                   // by the JSON literal
  std::map<std::string, Value> catalogue_defaults;              // "type.param" -> value
  std::map<std::string, ParsedExpression> default_expressions;  // "type.param" -> expression
  std::vector<std::unique_ptr<JsonValue>> default_json;
  std::vector<std::unique_ptr<base::Source>> default_sources;
  std::map<std::string, std::size_t> node_run_index;
  std::map<std::string, std::size_t> leaf_index;
  std::map<std::string, std::pair<std::uint64_t, RunError>> failures;  // W040 per node label
  std::vector<std::string> failure_order;
  std::vector<RunError> warnings;                  // W030, in order
  std::map<std::string, RunError> unprocessed_at;  // W010: where each port's node is
  std::set<std::string> warned;
  std::vector<ResultEntity> probed;  // what left RunOptions::probe's node, in order

  RunState(const Document& d, const CheckResult& c, const RunOptions& o, RunResult& r)
      : document(d), checked(c), options(o), out(r) {}

  NodeRuns& node_runs(const std::string& id) {
    auto [it, added] = node_run_index.emplace(id, out.node_runs.size());
    if (added) out.node_runs.emplace_back(id, NodeRuns{});
    return out.node_runs[it->second].second;
  }
  PortCount& leaf(const std::string& port) {
    auto [it, added] = leaf_index.emplace(port, out.leaves.size());
    if (added) out.leaves.emplace_back(port, PortCount{});
    return out.leaves[it->second].second;
  }
};

}  // namespace insula::lang::graph
