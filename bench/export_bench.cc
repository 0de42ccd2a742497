// Writers' throughput on a district of hip-roofed L-shaped buildings: GLB, OBJ and CityJSON text
// generation in memory (no disk). Reports triangles per second.
// Run: build/bench/export_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cstring>
#include <memory>
#include <span>

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

// The same buildings as a 3D Tiles tile holds them (io/tileset_writer.cc): one mesh for all, each
// building a feature that points at its id.
shape::Scene district_tile(int count) {
  shape::Scene scene = district(count);
  shape::Building tile;
  tile.id = "tile";
  for (shape::Building& building : scene.buildings) {
    const auto attributes = std::make_shared<const shape::AttributeMap>(
        shape::AttributeMap{{"building_id", building.id}});
    for (shape::Part& part : building.parts) {
      part.inherited = attributes;
      tile.parts.push_back(std::move(part));
    }
  }
  scene.buildings = {std::move(tile)};
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
void run(benchmark::State& state, Writer writer, bool as_tile = false) {
  const int count = static_cast<int>(state.range(0));
  const shape::Scene scene = as_tile ? district_tile(count) : district(count);
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
// A 3D Tiles tile's GLB: the same triangles in one mesh, a feature per building.
void BM_GlbTile(benchmark::State& state) {
  run(
      state, [](const shape::Scene& s) { return glb_bytes(s); }, true);
}
void BM_Obj(benchmark::State& state) {
  run(state, [](const shape::Scene& s) { return obj_text(s, "district.mtl").obj; });
}
void BM_CityJson(benchmark::State& state) {
  run(state, [](const shape::Scene& s) { return cityjson_text(s); });
}
// The store-loop limit (issue 17, item 4): the least any mesh writer does, every triangle's three
// corners stored as float positions (36 bytes) into one buffer, fan-triangulating each face, with
// no attributes, no welding, no text. The writers' rates are compared to this one.
std::string store_loop(const shape::Scene& scene) {
  std::string out;
  out.resize(36 * triangles(scene));
  char* at = out.data();
  const auto store = [&at](kernel::Vec3 p) {
    const float xyz[3] = {static_cast<float>(p.x), static_cast<float>(p.y),
                          static_cast<float>(p.z)};
    std::memcpy(at, xyz, sizeof xyz);
    at += sizeof xyz;
  };
  for (const shape::Building& building : scene.buildings) {
    for (const shape::Part& part : building.parts) {
      const kernel::Mesh& mesh = part.mesh;
      for (std::size_t f = 0; f < mesh.face_count(); ++f) {
        const std::span<const std::uint32_t> face = mesh.face(f);
        for (std::size_t k = 1; k + 1 < face.size(); ++k) {
          store(mesh.position(face[0]));
          store(mesh.position(face[k]));
          store(mesh.position(face[k + 1]));
        }
      }
    }
  }
  return out;
}

void BM_StoreLoop(benchmark::State& state) {
  run(state, store_loop);
}

BENCHMARK(BM_StoreLoop)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Glb)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GlbTile)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Obj)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CityJson)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace insula::io
