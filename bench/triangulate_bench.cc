// Triangulation speed on concave stars of 16..1024 vertices, alone and with holes.
// Run: build/bench/triangulate_bench --benchmark_repetitions=5
// --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>

#include "kernel/polygon.h"
#include "kernel/triangulate.h"

namespace insula::kernel {
namespace {

Ring star(int vertices, double r_in, double r_out, Vec2 centre, bool clockwise) {
  Ring ring;
  for (int i = 0; i < vertices; ++i) {
    const double t = 2 * std::numbers::pi * i / vertices * (clockwise ? -1 : 1);
    const double r = i % 2 ? r_in : r_out;
    ring.push_back(centre + Vec2{r * std::cos(t), r * std::sin(t)});
  }
  return ring;
}

// A concave star; with holes, 8 small stars on a circle take a quarter of the vertex budget.
Polygon make_polygon(int vertices, bool holes) {
  if (!holes) return Polygon{star(vertices, 60, 100, {}, false), {}};
  const int per_hole = std::max(4, vertices / 32);
  Polygon p{star(vertices - 8 * per_hole, 60, 100, {}, false), {}};
  for (int h = 0; h < 8; ++h) {
    const double a = 2 * std::numbers::pi * h / 8;
    p.holes.push_back(star(per_hole, 4, 8, {35 * std::cos(a), 35 * std::sin(a)}, true));
  }
  return p;
}

void run(benchmark::State& state, bool holes) {
  const Polygon polygon = make_polygon(int(state.range(0)), holes);
  Triangulation t;
  for (auto _ : state) {
    const bool ok = triangulate(polygon, t);
    benchmark::DoNotOptimize(ok);
    if (!ok) state.SkipWithError("triangulation failed");
  }
  state.counters["triangles"] = double(t.triangles.size());
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

void BM_TriangulateStar(benchmark::State& state) {
  run(state, false);
}
void BM_TriangulateStarWithHoles(benchmark::State& state) {
  run(state, true);
}
BENCHMARK(BM_TriangulateStar)->RangeMultiplier(4)->Range(16, 1024)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_TriangulateStarWithHoles)
    ->RangeMultiplier(4)
    ->Range(64, 1024)
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace insula::kernel
