// Face lattices and pulling triangulations of the cells PLaSM builds: boxes of dimension 2..4 and
// hulls of random points in the unit cube of R^3 (docs/kernel-polytopes.md gives the figures).
// Run: build/bench/hull_nd_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

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

}  // namespace
}  // namespace insula::kernel
#include "kernel/convex_hull.h"
namespace insula::kernel {
void BM_Surface(benchmark::State& state) {
  std::vector<Vec3> v;
  if (state.range(0) == 0) {
    for (int i = 0; i < 8; ++i) v.push_back({double(i & 1) * 2, double((i >> 1) & 1) * 3, double(i >> 2) * 4});
  } else {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(0, 1);
    for (int i = 0; i < 100; ++i) v.push_back({u(rng), u(rng), u(rng)});
  }
  for (auto _ : state) benchmark::DoNotOptimize(convex_hull_3d(v));
}
BENCHMARK(BM_Surface)->Arg(0)->Arg(100);
}
