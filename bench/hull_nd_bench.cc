// Face lattices and pulling triangulations of the cells PLaSM builds: boxes of dimension 2..4 and
// hulls of random points in the unit cube of R^3, and for comparison the surface hull alone
// (argument 0: the box). docs/kernel-polytopes.md gives the figures.
// Run: build/bench/hull_nd_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "kernel/convex_hull.h"
#include "kernel/hull_nd.h"

namespace insula::kernel {
namespace {

std::vector<double> box(int n) {
  std::vector<double> p;
  for (int i = 0; i < (1 << n); ++i) {
    for (int c = 0; c < n; ++c) p.push_back(((i >> c) & 1) ? 2.0 + c : 0.0);
  }
  return p;
}

std::vector<double> random_points(int count) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> uniform(0, 1);
  std::vector<double> p(3 * static_cast<std::size_t>(count));
  for (double& x : p) x = uniform(rng);
  return p;
}

void run(benchmark::State& state, const std::vector<double>& points, int n, bool triangulate) {
  std::size_t faces = 0;
  for (auto _ : state) {
    const PolytopeNd p = polytope_nd(points, n);
    if (!p.ok()) state.SkipWithError("polytope_nd failed");
    faces = p.faces[n - 1].size();
    if (triangulate) benchmark::DoNotOptimize(simplices_nd(p));
    benchmark::DoNotOptimize(p);
  }
  state.counters["facets"] = static_cast<double>(faces);
}

void BM_Box(benchmark::State& state) {
  run(state, box(static_cast<int>(state.range(0))), static_cast<int>(state.range(0)), false);
}
BENCHMARK(BM_Box)->DenseRange(2, 4);

void BM_BoxWithSimplices(benchmark::State& state) {
  run(state, box(static_cast<int>(state.range(0))), static_cast<int>(state.range(0)), true);
}
BENCHMARK(BM_BoxWithSimplices)->DenseRange(2, 4);

void BM_RandomHull3d(benchmark::State& state) {
  run(state, random_points(static_cast<int>(state.range(0))), 3, false);
}
BENCHMARK(BM_RandomHull3d)->Arg(20)->Arg(100);

// The surface hull alone (the part of a solid's lattice that convex_hull_3d computes).
void BM_SurfaceHull3d(benchmark::State& state) {
  const std::vector<double> coords =
      state.range(0) == 0 ? box(3) : random_points(static_cast<int>(state.range(0)));
  std::vector<Vec3> points;
  for (std::size_t i = 0; i < coords.size(); i += 3)
    points.push_back({coords[i], coords[i + 1], coords[i + 2]});
  for (auto _ : state) benchmark::DoNotOptimize(convex_hull_3d(points));
}
BENCHMARK(BM_SurfaceHull3d)->Arg(0)->Arg(100);

}  // namespace
}  // namespace insula::kernel
