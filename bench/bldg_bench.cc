// The whole generation of seed 000 (§4.7, Table 2, Fig. 11): groups of g = 1..5 building parts
// with [1 + 2g, 5 + 2g] rooms per part (3-7 ... 11-15), five stochastic buildings per group
// (convex, L, U, T, H; 25 generations, the same buildings as bench/bldg_plan_bench.cc). Per group:
//   BM_Generate/g  stochastic grammar -> floor plan -> 3D model (what the paper timed)
//   BM_Build/g     the 3D builder alone on ready plans
// with the vertices made and vertices per second. The paper's heaviest building: 25,728 vertices in
// 125 ms with 40-45 MB of RAM (i7 M620); the target is 50 times its speed (10.3 M vertices/s per
// core) and under 20 MB peak.
// Peak memory needs a fresh process: `bldg_bench --peak-memory` generates the heaviest of the 25
// buildings once and prints the process's VmHWM (/proc/self/status). `bldg_bench --digest` prints
// one hash of all 25 generated models (an optimisation must leave it unchanged).
// docs/PERFORMANCE.md.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "lang/bldg/builder.h"
#include "lang/bldg/floorplan.h"
#include "lang/bldg/stochastic.h"

namespace insula::lang::bldg {
namespace {

RandomSpec spec_of(int g, int i) {
  const RandomShape shapes[] = {RandomShape::kConvex, RandomShape::kL, RandomShape::kU,
                                RandomShape::kT, RandomShape::kH};
  RandomSpec spec;
  spec.shape = shapes[i];
  spec.parts = g;
  spec.rooms_min = 1 + 2 * g;
  spec.rooms_max = 5 + 2 * g;
  return spec;
}

std::uint64_t seed_of(int g, int i) {
  return batch_seed(2020, static_cast<std::uint64_t>(g * 5 + i));
}

// One generation: grammar model, floor plan, 3D model. Returns the vertices made.
std::size_t generate(int g, int i) {
  const Building building = random_building(spec_of(g, i), seed_of(g, i));
  const Restrictions rules;
  const base::Result<FloorPlan> plan = make_floor_plan(building, rules);
  if (!plan.ok()) return 0;
  const BuildResult built = build_building(building, plan.value(), rules);
  return built.stats.vertices;
}

void BM_Generate(benchmark::State& state) {
  const int g = static_cast<int>(state.range(0));
  std::size_t vertices = 0;
  for (auto _ : state) {
    vertices = 0;
    for (int i = 0; i < 5; ++i) vertices += generate(g, i);
  }
  state.counters["vertices"] = static_cast<double>(vertices);
  state.counters["vertices/s"] = benchmark::Counter(static_cast<double>(vertices),
                                                    benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_Generate)->DenseRange(1, 5)->Unit(benchmark::kMillisecond);

// The heaviest of the 25 generations alone (group 5, building 4), to set beside the paper's
// 25,728 vertices in 125 ms.
void BM_GenerateHeaviest(benchmark::State& state) {
  std::size_t vertices = 0;
  for (auto _ : state) vertices = generate(5, 4);
  state.counters["vertices"] = static_cast<double>(vertices);
  state.counters["vertices/s"] = benchmark::Counter(static_cast<double>(vertices),
                                                    benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_GenerateHeaviest)->Unit(benchmark::kMillisecond);

void BM_Build(benchmark::State& state) {
  const int g = static_cast<int>(state.range(0));
  const Restrictions rules;
  std::vector<Building> buildings;
  std::vector<FloorPlan> plans;
  for (int i = 0; i < 5; ++i) {
    buildings.push_back(random_building(spec_of(g, i), seed_of(g, i)));
    plans.push_back(make_floor_plan(buildings.back(), rules).value());
  }
  std::size_t vertices = 0;
  for (auto _ : state) {
    vertices = 0;
    for (int i = 0; i < 5; ++i) {
      const BuildResult built = build_building(buildings[i], plans[i], rules);
      vertices += built.stats.vertices;
      benchmark::DoNotOptimize(built);
    }
  }
  state.counters["vertices"] = static_cast<double>(vertices);
  state.counters["vertices/s"] = benchmark::Counter(static_cast<double>(vertices),
                                                    benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_Build)->DenseRange(1, 5)->Unit(benchmark::kMillisecond);

// FNV-1a over the bytes of a value: the digest below must not move when the generation is
// optimised (same vertices, faces, tags and part names, bit for bit).
template <typename T>
void mix(std::uint64_t& hash, const T& value) {
  const auto* bytes = reinterpret_cast<const unsigned char*>(&value);
  for (std::size_t i = 0; i < sizeof(T); ++i) hash = (hash ^ bytes[i]) * 1099511628211ULL;
}

// `--digest`: one hash of everything the 25 generations build (parts' names, positions, face
// loops and tags, warnings), to check that an optimisation changed no output.
int digest() {
  std::uint64_t hash = 14695981039346656037ULL;
  std::size_t vertices = 0;
  for (int g = 1; g <= 5; ++g) {
    for (int i = 0; i < 5; ++i) {
      const Building building = random_building(spec_of(g, i), seed_of(g, i));
      const Restrictions rules;
      const base::Result<FloorPlan> plan = make_floor_plan(building, rules);
      if (!plan.ok()) continue;
      const BuildResult built = build_building(building, plan.value(), rules);
      vertices += built.stats.vertices;
      for (const shape::Part& part : built.building.parts) {
        for (char c : part.name) mix(hash, c);
        for (const kernel::Vec3& p : part.mesh.positions()) mix(hash, p);
        for (std::size_t f = 0; f < part.mesh.face_count(); ++f) {
          for (std::uint32_t v : part.mesh.face(f)) mix(hash, v);
          const kernel::FaceTag& tag = part.mesh.tag(f);
          mix(hash, tag.semantic);
          mix(hash, tag.material);
          mix(hash, tag.face_id);
        }
      }
      for (const std::string& warning : built.warnings) {
        for (char c : warning) mix(hash, c);
      }
    }
  }
  std::printf("digest %016llx, %zu vertices\n", static_cast<unsigned long long>(hash), vertices);
  return 0;
}

// Peak resident memory (kB) of this process so far.
long peak_kb() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmHWM:", 0) == 0) return std::stol(line.substr(6));
  }
  return -1;
}

// Generates group 5 (the heaviest buildings) one after the other: the process's peak is the
// heaviest generation's, plus the binary's baseline, which is printed first.
int peak_memory() {
  const long baseline = peak_kb();
  int heaviest = 0;
  std::size_t most = 0;
  for (int i = 0; i < 5; ++i) {
    const std::size_t v = generate(5, i);
    if (v > most) {
      most = v;
      heaviest = i;
    }
  }
  std::printf("heaviest building: group 5, building %d, %zu vertices\n", heaviest, most);
  std::printf("VmHWM: %ld kB at start, %ld kB after generating group 5\n", baseline, peak_kb());
  return 0;
}

}  // namespace
}  // namespace insula::lang::bldg

int main(int argc, char** argv) {
  if (argc > 1 && std::strcmp(argv[1], "--peak-memory") == 0) {
    return insula::lang::bldg::peak_memory();
  }
  if (argc > 1 && std::strcmp(argv[1], "--digest") == 0) return insula::lang::bldg::digest();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
