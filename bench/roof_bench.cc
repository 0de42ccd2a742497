// Skeleton roofs and mass shells. Run: build/bench/roof_bench --benchmark_repetitions=5
// --benchmark_report_aggregates_only=true (figures in docs/kernel-roofs.md).
#include <benchmark/benchmark.h>

#include <cmath>
#include <iterator>
#include <random>
#include <string>
#include <vector>

#include "kernel/mass.h"
#include "kernel/roof.h"
#include "kernel/skeleton.h"
#include "kernel/skeleton_rectilinear.h"

namespace insula::kernel {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A star-shaped, non-convex footprint with n vertices (alternating radii), handled by CGAL.
Polygon star(int n) {
  Polygon p;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * kPi * i / n;
    const double r = i % 2 == 0 ? 20.0 : 16.0 + 0.37 * std::sin(i * 1.7);
    p.outer.push_back({r * std::cos(a), r * std::sin(a)});
  }
  return p;
}

// A convex footprint with n vertices (an ellipse), handled by the convex wavefront.
Polygon ellipse(int n) {
  Polygon p;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * kPi * i / n;
    p.outer.push_back({20 * std::cos(a), 12 * std::sin(a)});
  }
  return p;
}

Polygon l_shape8() {
  return {{{0, 0}, {14, 0}, {14, 6}, {10, 6}, {6, 6}, {6, 12}, {3, 12}, {0, 12}}, {}};
}

void BM_HipRoofStar(benchmark::State& state) {
  const Polygon p = star(static_cast<int>(state.range(0)));
  RoofSpec spec;
  for (auto _ : state) {
    RoofResult r = build_roof(p, spec, 10);
    benchmark::DoNotOptimize(r.mesh.face_count());
  }
}
BENCHMARK(BM_HipRoofStar)->Arg(16)->Arg(64)->Arg(256)->Unit(benchmark::kMicrosecond);

void BM_HipRoofConvex(benchmark::State& state) {
  const Polygon p = ellipse(static_cast<int>(state.range(0)));
  RoofSpec spec;
  for (auto _ : state) {
    RoofResult r = build_roof(p, spec, 10);
    benchmark::DoNotOptimize(r.mesh.face_count());
  }
}
BENCHMARK(BM_HipRoofConvex)->Arg(16)->Arg(64)->Arg(256)->Unit(benchmark::kMicrosecond);

void BM_SkeletonStar(benchmark::State& state) {
  const Polygon p = star(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    auto s = interior_straight_skeleton(p);
    benchmark::DoNotOptimize(s.has_value());
  }
}
BENCHMARK(BM_SkeletonStar)->Arg(16)->Arg(64)->Arg(256)->Unit(benchmark::kMicrosecond);

void BM_MassHip(benchmark::State& state, Polygon footprint) {
  MassSpec spec;
  spec.wall_height = 9;
  for (auto _ : state) {
    MassResult r = build_mass(footprint, spec);
    benchmark::DoNotOptimize(r.mesh.face_count());
  }
}
BENCHMARK_CAPTURE(BM_MassHip, l_shape_8, l_shape8())->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_MassHip, rectangle, Polygon{{{0, 0}, {14, 0}, {14, 8}, {0, 8}}, {}})
    ->Unit(benchmark::kMicrosecond);

// Every roof type over a rotated 14 x 8 m rectangle (the S3DB shapes included), argument =
// RoofType.
void BM_MassEveryRoof(benchmark::State& state) {
  MassSpec spec;
  spec.wall_height = 9;
  spec.roof = static_cast<RoofType>(state.range(0));
  const Polygon footprint{{{0, 0}, {13.74, 2.67}, {12.21, 10.52}, {-1.53, 7.85}}, {}};
  for (auto _ : state) {
    MassResult r = build_mass(footprint, spec);
    benchmark::DoNotOptimize(r.mesh.face_count());
  }
  state.SetLabel(std::string(roof_type_name(spec.roof)));
}
BENCHMARK(BM_MassEveryRoof)
    ->DenseRange(0, static_cast<int>(std::size(kRoofTypes)) - 1)
    ->Unit(benchmark::kMicrosecond);

// The eave outline of Table 2's heaviest generated building (group 5, building 4): an H of 12
// axis-parallel edges, the typical input of the generator's HipGlued roofs.
Polygon h_shape12() {
  return {{{63.5, 44.3},
           {57.371146, 44.3},
           {57.371146, 29.684259},
           {5.187385, 29.684259},
           {5.187385, 44.3},
           {-0.3, 44.3},
           {-0.3, -0.3},
           {5.187385, -0.3},
           {5.187385, 14.315741},
           {57.371146, 14.315741},
           {57.371146, -0.3},
           {63.5, -0.3}},
          {}};
}

void BM_SkeletonRectilinear(benchmark::State& state, Polygon footprint) {
  for (auto _ : state) {
    auto s = interior_straight_skeleton(footprint);
    benchmark::DoNotOptimize(s.has_value());
  }
}
BENCHMARK_CAPTURE(BM_SkeletonRectilinear, l_shape_8, l_shape8())->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_SkeletonRectilinear, h_shape_12, h_shape12())->Unit(benchmark::kMicrosecond);

// A comb of `teeth` rectangular teeth: 4 * teeth + 2 axis-parallel edges.
Polygon comb(int teeth) {
  Polygon p;
  for (int i = 0; i < teeth; ++i) {
    p.outer.push_back({4.0 * i, 0});
    p.outer.push_back({4.0 * i + 2, 0});
    p.outer.push_back({4.0 * i + 2, -3});
    p.outer.push_back({4.0 * i + 4, -3});
  }
  p.outer.push_back({4.0 * teeth, 5});
  p.outer.push_back({0, 5});
  return p;
}

// A comb whose teeth all differ in depth, so each one is its own event: the wavefront's worst case.
Polygon uneven_comb(int teeth) {
  Polygon p;
  for (int i = 0; i < teeth; ++i) {
    const double depth = 3 + 0.01 * i;
    p.outer.push_back({4.0 * i, 0});
    p.outer.push_back({4.0 * i + 2, 0});
    p.outer.push_back({4.0 * i + 2, -depth});
    p.outer.push_back({4.0 * i + 4, -depth});
  }
  p.outer.push_back({4.0 * teeth, 5});
  p.outer.push_back({0, 5});
  return p;
}

// The rectilinear wavefront alone, and CGAL's general builder on the same outlines.
void BM_RectilinearWavefront(benchmark::State& state, Polygon footprint) {
  for (auto _ : state) {
    auto s = rectilinear_straight_skeleton(footprint);
    benchmark::DoNotOptimize(s.has_value());
  }
}
BENCHMARK_CAPTURE(BM_RectilinearWavefront, l_shape_8, l_shape8())->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_RectilinearWavefront, h_shape_12, h_shape12())->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_RectilinearWavefront, comb_66, comb(16))->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_RectilinearWavefront, comb_254, comb(63))->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_RectilinearWavefront, comb_1002, comb(250))->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_RectilinearWavefront, uneven_comb_254, uneven_comb(63))
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_RectilinearWavefront, uneven_comb_1002, uneven_comb(250))
    ->Unit(benchmark::kMicrosecond);

void BM_SkeletonCgal(benchmark::State& state, Polygon footprint) {
  for (auto _ : state) {
    auto s = general_straight_skeleton(footprint);
    benchmark::DoNotOptimize(s.has_value());
  }
}
BENCHMARK_CAPTURE(BM_SkeletonCgal, l_shape_8, l_shape8())->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_SkeletonCgal, h_shape_12, h_shape12())->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_SkeletonCgal, comb_66, comb(16))->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_SkeletonCgal, comb_254, comb(63))->Unit(benchmark::kMicrosecond);

// Footprints as surveys give them (L, T, U and Z outlines turned to any angle, each corner moved by
// up to 1 cm): neither convex nor rectilinear, they take the general wavefront
// (skeleton_wavefront.h) or CGAL. Per footprint: time / 200.
std::vector<Polygon> surveyed_footprints() {
  const std::vector<Ring> shapes = {
      {{0, 0}, {16, 0}, {16, 6}, {6, 6}, {6, 14}, {0, 14}},
      {{0, 0}, {6, 0}, {6, 8}, {12, 8}, {12, 12}, {-6, 12}, {-6, 8}, {0, 8}},
      {{0, 0}, {14, 0}, {14, 10}, {10, 10}, {10, 4}, {4, 4}, {4, 10}, {0, 10}},
      {{0, 0}, {10, 0}, {10, 5}, {15, 5}, {15, 10}, {5, 10}, {5, 5}, {0, 5}}};
  std::mt19937 random(42);
  std::uniform_real_distribution<double> angle(0, kPi);
  std::uniform_real_distribution<double> noise(-0.01, 0.01);
  std::vector<Polygon> out;
  for (int k = 0; k < 200; ++k) {
    const double a = angle(random);
    Polygon p;
    for (Vec2 v : shapes[static_cast<std::size_t>(k) % shapes.size()]) {
      p.outer.push_back({v.x * std::cos(a) - v.y * std::sin(a) + noise(random),
                         v.x * std::sin(a) + v.y * std::cos(a) + noise(random)});
    }
    out.push_back(std::move(p));
  }
  return out;
}

template <typename Skeletonize>
void skeletons_of_surveyed_footprints(benchmark::State& state, Skeletonize skeletonize) {
  const std::vector<Polygon> footprints = surveyed_footprints();
  for (auto _ : state) {
    for (const Polygon& p : footprints) {
      auto s = skeletonize(p);
      benchmark::DoNotOptimize(s.has_value());
    }
  }
}
void BM_SkeletonSurveyed(benchmark::State& state) {
  skeletons_of_surveyed_footprints(state, interior_straight_skeleton);
}
void BM_SkeletonSurveyedCgal(benchmark::State& state) {
  skeletons_of_surveyed_footprints(state, general_straight_skeleton);
}
BENCHMARK(BM_SkeletonSurveyed)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SkeletonSurveyedCgal)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace insula::kernel
