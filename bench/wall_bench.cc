// Openings per second for walls with 1, 10 and 100 openings, rectangular and arched (8 segments).
// Each iteration builds the complete closed wall mesh (validation, partition, mesh emission).
// Run: build/bench/wall_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include "kernel/wall.h"

namespace insula::kernel {
namespace {

// A façade of `count` openings in rows of at most 10 bays (1.5 m wide, 2 m pitch), 3 m storeys.
WallSpec facade(int count, bool arched) {
  const int columns = count < 10 ? count : 10;
  const int rows = (count + columns - 1) / columns;
  WallSpec spec;
  spec.thickness = 0.3;
  const double length = 0.5 + 2.0 * columns;
  const double height = 3.0 * rows + 0.5;
  spec.outline = {{0, 0}, {length, 0}, {length, height}, {0, height}};
  for (int i = 0; i < count; ++i) {
    Opening o;
    o.u = 0.5 + 2.0 * (i % columns);
    o.sill = 0.9 + 3.0 * (i / columns);
    o.width = 1.5;
    o.height = 1.8;
    if (arched) {
      o.arch_rise = 0.75;
      o.arch_segments = 8;
    }
    spec.openings.push_back(o);
  }
  return spec;
}

void BM_Wall(benchmark::State& state) {
  const int count = static_cast<int>(state.range(0));
  const WallSpec spec = facade(count, state.range(1) != 0);
  std::size_t faces = 0;
  for (auto _ : state) {
    WallResult r = build_wall(spec);
    if (!r.ok()) state.SkipWithError(r.message.c_str());
    faces = r.mesh.face_count();
    benchmark::DoNotOptimize(r.mesh);
  }
  state.counters["openings/s"] =
      benchmark::Counter(static_cast<double>(count), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["faces"] = static_cast<double>(faces);
}

BENCHMARK(BM_Wall)
    ->ArgNames({"openings", "arched"})
    ->ArgsProduct({{1, 10, 100}, {0, 1}})
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace insula::kernel
