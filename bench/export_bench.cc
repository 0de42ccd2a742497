// Writers' throughput on a district of hip-roofed L-shaped buildings: GLB, OBJ and CityJSON text
// generation in memory (no disk). Reports triangles per second.
// Run: build/bench/export_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include "io/cityjson_writer.h"
#include "io/gltf_writer.h"
#include "io/obj_writer.h"
#include "kernel/mass.h"
#include "shape/scene.h"

namespace insula::io {
namespace {

shape::Scene district(int count) {
  const kernel::Polygon l_shape{{{0, 0}, {16, 0}, {16, 6}, {6, 6}, {6, 14}, {0, 14}}, {}};
  kernel::MassSpec spec;
  spec.wall_height = 9;
  const kernel::Mesh mesh = kernel::build_mass(l_shape, spec).mesh;
  shape::Scene scene;
  scene.origin = {455000, 5428000, 0};
  for (int i = 0; i < count; ++i) {
    shape::Building building;
    building.id = "b" + std::to_string(i);
    shape::Part part;
    part.name = building.id;
    part.mesh = mesh;
    for (kernel::Vec3& p : part.mesh.positions())
      p += kernel::Vec3{(i % 100) * 25.0, (i / 100) * 25.0, 0};
    building.parts.push_back(std::move(part));
    scene.buildings.push_back(std::move(building));
  }
  return scene;
}

std::size_t triangles(const shape::Scene& scene) {
  std::size_t n = 0;
  for (const auto& b : scene.buildings) {
    for (const auto& p : b.parts) n += p.mesh.triangle_count();
  }
  return n;
}

template <typename Writer>
void run(benchmark::State& state, Writer writer) {
  const shape::Scene scene = district(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    std::string bytes = writer(scene);
    benchmark::DoNotOptimize(bytes.data());
  }
  state.counters["triangles_per_second"] = benchmark::Counter(
      static_cast<double>(triangles(scene)) * static_cast<double>(state.iterations()),
      benchmark::Counter::kIsRate);
}

void BM_Glb(benchmark::State& state) {
  run(state, [](const shape::Scene& s) { return glb_bytes(s); });
}
void BM_Obj(benchmark::State& state) {
  run(state, [](const shape::Scene& s) { return obj_text(s, "district.mtl").obj; });
}
void BM_CityJson(benchmark::State& state) {
  run(state, [](const shape::Scene& s) { return cityjson_text(s); });
}
BENCHMARK(BM_Glb)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Obj)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CityJson)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace insula::io
