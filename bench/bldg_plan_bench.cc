// Floor-plan engine (lang/bldg/floorplan.h) on the groups of seed 000's Table 2: group g has g
// building parts with [1 + 2g, 5 + 2g] rooms per part (3-7 ... 11-15), five stochastic buildings
// per group (25 generations), L/U/T/H/convex in turn. Run:
//   build/bench/bldg_plan_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
// Figures in docs/PERFORMANCE.md. Each iteration plans all five buildings of the group.
#include <benchmark/benchmark.h>

#include <vector>

#include "lang/bldg/floorplan.h"
#include "lang/bldg/stochastic.h"

namespace insula::lang::bldg {
namespace {

std::vector<Building> group(int g) {
  const RandomShape shapes[] = {RandomShape::kConvex, RandomShape::kL, RandomShape::kU,
                                RandomShape::kT, RandomShape::kH};
  std::vector<Building> out;
  for (int i = 0; i < 5; ++i) {
    RandomSpec spec;
    spec.shape = shapes[i];
    spec.parts = g;
    spec.rooms_min = 1 + 2 * g;
    spec.rooms_max = 5 + 2 * g;
    out.push_back(random_building(spec, batch_seed(2020, static_cast<std::uint64_t>(g * 5 + i))));
  }
  return out;
}

void BM_FloorPlanTable2(benchmark::State& state) {
  const std::vector<Building> buildings = group(static_cast<int>(state.range(0)));
  const Restrictions restrictions;
  std::size_t rooms = 0;
  for (auto _ : state) {
    rooms = 0;
    for (const Building& b : buildings) {
      base::Result<FloorPlan> plan = make_floor_plan(b, restrictions);
      for (const PlanStorey& s : plan->storeys) rooms += s.rooms.size();
      benchmark::DoNotOptimize(plan);
    }
  }
  state.counters["rooms"] = static_cast<double>(rooms);
  state.counters["buildings/s"] = benchmark::Counter(static_cast<double>(buildings.size()),
                                                     benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_FloorPlanTable2)->DenseRange(1, 5)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace insula::lang::bldg
