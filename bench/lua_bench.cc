// Lua component programs (seed 001) end to end: run the program in the sandboxed runtime (the
// component tree, every boolean, joint extrusion and door/window cut: §5 "creating its geometry
// ... executing boolean operations for doors, windows") and collect the export scene. The paper
// took < 5 s for the tree and up to 2 min for the geometry of 20K-500K triangles (Core 2 Duo,
// 2.2 GHz); the target here is the apartment building, >= 500K triangles with every door and
// window cut, in <= 1 s on one core. Run:
//   build/bench/lua_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
// Figures in docs/PERFORMANCE.md.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "io/gltf_writer.h"
#include "io/obj_reader.h"
#include "lang/lua/runtime.h"

namespace insula::lua {
namespace {

std::string read(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The repository from this file's path (bench targets get no source-directory define).
const std::filesystem::path kExamples =
    std::filesystem::path(__FILE__).parent_path().parent_path() / "examples/lua";

// The example assets, read once (as build_lua.cc's provider caches them).
class Assets : public shape::AssetProvider {
 public:
  std::shared_ptr<const kernel::Mesh> find(std::string_view name,
                                           std::string& error) const override {
    if (auto it = cache_.find(name); it != cache_.end()) return it->second;
    const auto path = kExamples / "assets" / (std::string(name) + ".obj");
    auto mesh = io::read_obj(read(path), path.filename().string());
    if (!mesh) {
      error = "cannot read " + path.string();
      return nullptr;
    }
    auto shared = std::make_shared<const kernel::Mesh>(std::move(mesh.value()));
    cache_.emplace(std::string(name), shared);
    return shared;
  }

 private:
  mutable std::map<std::string, std::shared_ptr<const kernel::Mesh>, std::less<>> cache_;
};

struct Built {
  std::size_t components = 0;
  std::size_t triangles = 0;
  shape::Scene scene;
};

Built build(const base::Source& source, const Assets& assets,
            std::vector<std::pair<std::string, shape::Value>> params = {}) {
  RunOptions options;
  options.assets = &assets;
  options.params = std::move(params);
  Runtime runtime(options);
  if (!runtime.run(source).empty()) return {};
  Built out;
  out.components = runtime.tree().size();
  out.scene = collect_program(runtime.program());
  for (const auto& b : out.scene.buildings) {
    for (const auto& p : b.parts) {
      out.triangles += p.instance_of ? p.instance_of->triangle_count() : p.mesh.triangle_count();
    }
  }
  return out;
}

// Program run + collect (the "tree" and "geometry" stages of §5 together).
void BM_LuaExample(benchmark::State& state, const char* name) {
  const auto path = kExamples / name;
  const base::Source source(path.string(), read(path));
  const Assets assets;
  build(source, assets);  // warm the asset cache
  Built built;
  for (auto _ : state) {
    built = build(source, assets);
    benchmark::DoNotOptimize(built.triangles);
  }
  if (built.triangles == 0) state.SkipWithError("the program failed");
  state.counters["components"] = static_cast<double>(built.components);
  state.counters["triangles"] = static_cast<double>(built.triangles);
  state.counters["triangles/s"] =
      benchmark::Counter(static_cast<double>(built.triangles), benchmark::Counter::kIsRate);
}
BENCHMARK_CAPTURE(BM_LuaExample, hotel, "hotel.lua")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_LuaExample, loft_office, "loft_office.lua")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_LuaExample, apartment_building, "apartment_building.lua")
    ->Unit(benchmark::kMillisecond);

// Writing the largest example as GLB (shared furniture meshes instanced when collected so).
void BM_LuaApartmentGlb(benchmark::State& state) {
  const auto path = kExamples / "apartment_building.lua";
  const Assets assets;
  const Built built = build(base::Source(path.string(), read(path)), assets);
  std::size_t bytes = 0;
  for (auto _ : state) {
    bytes = io::glb_bytes(built.scene).size();
    benchmark::DoNotOptimize(bytes);
  }
  state.counters["MB"] = static_cast<double>(bytes) / 1e6;
}
BENCHMARK(BM_LuaApartmentGlb)->Unit(benchmark::kMillisecond);

// The row house scaled to 40 houses (--set houses=40): 4,884 components, one 249 m facade per side
// with ~160 openings each. Measures that the opening stage stays linear in the number of walls
// and openings (docs/PERFORMANCE.md: 18.8 s before, one corefinement per opening on the
// whole, growing facade).
void BM_LuaRowHouses(benchmark::State& state) {
  const auto path = kExamples / "row_house.lua";
  const base::Source source(path.string(), read(path));
  const Assets assets;
  const double houses = static_cast<double>(state.range(0));
  Built built;
  for (auto _ : state) {
    built = build(source, assets, {{"houses", shape::Value{houses}}});
    benchmark::DoNotOptimize(built.triangles);
  }
  if (built.triangles == 0) state.SkipWithError("the program failed");
  state.counters["components"] = static_cast<double>(built.components);
  state.counters["triangles"] = static_cast<double>(built.triangles);
}
BENCHMARK(BM_LuaRowHouses)->Arg(4)->Arg(40)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace insula::lua
