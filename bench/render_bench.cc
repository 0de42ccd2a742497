// Speed of the built-in PNG renderer on generated districts: N buildings on a grid, each a box
// with a hipped (pyramid) roof or an L-shaped flat-roofed block, at the default 1024 x 768 output
// with 2 x 2 supersampling. Run: build/bench/render_bench --benchmark_repetitions=5
#include <benchmark/benchmark.h>

#include <cstdint>
#include <string>
#include <vector>

#include "io/png_renderer.h"

namespace {

using insula::kernel::Mesh;
using insula::kernel::SemanticClass;
using insula::kernel::Vec2;
using insula::kernel::Vec3;

// Walls and a ground face of a prism over a counter-clockwise ring.
void add_walls(Mesh& mesh, const std::vector<Vec2>& ring, double height) {
  const auto n = static_cast<std::uint32_t>(ring.size());
  const auto base = static_cast<std::uint32_t>(mesh.vertex_count());
  for (Vec2 p : ring) mesh.add_vertex({p.x, p.y, 0});
  for (Vec2 p : ring) mesh.add_vertex({p.x, p.y, height});
  std::vector<std::uint32_t> bottom;
  for (std::uint32_t i = 0; i < n; ++i) bottom.push_back(base + n - 1 - i);
  mesh.add_face(bottom, {SemanticClass::kGroundSurface, 0, 0});
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t j = (i + 1) % n;
    mesh.add_face({base + i, base + j, base + n + j, base + n + i},
                  {SemanticClass::kWallSurface, 0, 1 + i});
  }
}

Mesh hipped_box(double x, double y, double w, double d, double h) {
  Mesh mesh;
  add_walls(mesh, {{x, y}, {x + w, y}, {x + w, y + d}, {x, y + d}}, h);
  const std::uint32_t apex = mesh.add_vertex({x + w / 2, y + d / 2, h + 0.4 * std::min(w, d)});
  for (std::uint32_t i = 0; i < 4; ++i) {
    mesh.add_face({4 + i, 4 + (i + 1) % 4, apex}, {SemanticClass::kRoofSurface, 0, 10 + i});
  }
  return mesh;
}

Mesh l_block(double x, double y, double s, double h) {
  Mesh mesh;
  const std::vector<Vec2> ring{{x + s, y + 0.4 * s},
                               {x + 0.4 * s, y + 0.4 * s},
                               {x + 0.4 * s, y + s},
                               {x, y + s},
                               {x, y},
                               {x + s, y}};
  add_walls(mesh, ring, h);
  std::vector<std::uint32_t> top;
  for (std::uint32_t i = 0; i < 6; ++i) top.push_back(6 + i);
  mesh.add_face(top, {SemanticClass::kRoofSurface, 0, 20});
  return mesh;
}

insula::shape::Scene district(int count) {
  insula::shape::Scene scene;
  int side = 1;
  while (side * side < count) ++side;
  std::uint32_t state = 12345;
  auto next = [&state] {
    state = state * 1664525U + 1013904223U;
    return static_cast<double>(state >> 8) / static_cast<double>(1U << 24);
  };
  for (int i = 0; i < count; ++i) {
    const double x = (i % side) * 20.0, y = (i / side) * 20.0;
    insula::shape::Building building;
    building.id = std::to_string(i);  // not "b" + ...: GCC 12 -Wrestrict false positive at -O3
    Mesh mesh = i % 3 == 0 ? l_block(x, y, 10 + 6 * next(), 4 + 12 * next())
                           : hipped_box(x, y, 8 + 6 * next(), 8 + 6 * next(), 4 + 10 * next());
    building.parts.push_back({"mass", insula::shape::PartKind::kBuildingPart, {}, std::move(mesh)});
    scene.buildings.push_back(std::move(building));
  }
  return scene;
}

void render_district(benchmark::State& state, bool cutaway) {
  const insula::shape::Scene scene = district(static_cast<int>(state.range(0)));
  insula::io::RenderOptions options;
  options.cutaway = cutaway;
  for (auto _ : state) {
    insula::io::Image image = insula::io::render(scene, options);
    benchmark::DoNotOptimize(image.pixels.data());
  }
  state.counters["buildings"] = static_cast<double>(state.range(0));
}

void BM_RenderDistrict(benchmark::State& state) {
  render_district(state, false);
}
void BM_RenderDistrictCutaway(benchmark::State& state) {
  render_district(state, true);
}

void BM_EncodePng(benchmark::State& state) {
  const insula::io::Image image = insula::io::render(district(1000));
  for (auto _ : state) benchmark::DoNotOptimize(insula::io::encode_png(image));
}

BENCHMARK(BM_RenderDistrict)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RenderDistrictCutaway)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_EncodePng)->Unit(benchmark::kMillisecond);

}  // namespace
