// Executor overhead per entity per node (issue 14 target: under 1 us for attribute and list
// nodes): N carriers through a chain of attribute and list nodes, timed whole, divided by N and
// by the number of nodes an entity passes.
//   ninja -C build graph_executor_bench && build/bench/graph_executor_bench
#include <benchmark/benchmark.h>

#include <string>

#include "lang/graph/checker.h"
#include "lang/graph/executor.h"
#include "lang/graph/reader.h"

namespace {

using namespace insula;

// create.entity -> set -> count -> order_by -> set -> condition (10 nodes per entity after the
// source, half attribute nodes, half list and flow nodes).
const char* kChain = R"({
  "format": "insula-graph", "version": 1,
  "parameters": { "n": { "type": "integer", "default": 1000 } },
  "attributes": { "a": { "type": "number", "default": 0 }, "i": { "type": "integer", "default": 0 } },
  "nodes": [
    { "id": "make", "type": "create.entity", "params": { "count": "= n" } },
    { "id": "s1", "type": "attr.set", "params": { "values": { "a": 1.5 } } },
    { "id": "count", "type": "list.count", "attributes": { "index": "i" } },
    { "id": "s2", "type": "attr.set", "params": { "values": { "a": "= @a * 2 + @i" } } },
    { "id": "sort", "type": "list.order_by", "augment": [ { "value": "= @a", "descending": true } ] },
    { "id": "s3", "type": "attr.set", "params": { "values": { "a": "= @a - 1" } } },
    { "id": "rev", "type": "list.reverse" },
    { "id": "odd", "type": "flow.condition", "params": { "if": "= @i % 2 == 1" } },
    { "id": "s4", "type": "attr.set", "params": { "values": { "i": "= @i + 1" } } },
    { "id": "s5", "type": "attr.set", "params": { "values": { "i": "= @i * 3" } } },
    { "id": "all", "type": "list.count" } ],
  "edges": [ "make.out -> s1.in", "s1.out -> count.in", "count.out -> s2.in", "s2.out -> sort.in",
             "sort.out -> s3.in", "s3.out -> rev.in", "rev.out -> odd.in", "odd.true -> s4.in",
             "odd.false -> s5.in", "s4.out -> all.in", "s5.out -> all.in" ] })";
constexpr int kNodesPerEntity = 10;

void BM_AttributeAndListNodes(benchmark::State& state) {
  const base::Source source("chain.graph.json", kChain);
  base::Result<lang::graph::Document> document = lang::graph::read_graph(
      source, [](const std::string&, std::string&, std::string&) { return false; });
  const lang::graph::CheckResult checked = lang::graph::check(document.value());
  lang::graph::RunOptions options;
  options.sets = {{"n", std::to_string(state.range(0))}};
  for (auto _ : state) {
    lang::graph::RunResult run = lang::graph::run_graph(document.value(), checked, options);
    if (!run.ok || run.results.size() != static_cast<std::size_t>(state.range(0))) {
      state.SkipWithError("the chain did not run");
      return;
    }
    benchmark::DoNotOptimize(run.results.data());
  }
  state.counters["ns_per_entity_node"] = benchmark::Counter(
      static_cast<double>(state.range(0) * kNodesPerEntity),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_AttributeAndListNodes)
    ->Arg(1000)
    ->Arg(10000)
    ->Arg(100000)
    ->Unit(benchmark::kMillisecond);

}  // namespace
