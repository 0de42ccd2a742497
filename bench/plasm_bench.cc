// PLaSM programs end to end (issue 13, "Performance"): parse, check, evaluate and convert every
// polyhedron to meshes of the shared scene (lang::plasm::program_scene), one thread, for the four
// programs of bench/plasm: 100 columns of Listing 2, a wall with 100 window holes, the dome of
// Listing 6 with 24 x 12 patches and a leaning tower of stacked arcades. Target: at least 5x
// faster than pyplasm on the same programs. Run:
//   build/bench/plasm_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
// `plasm_bench --memory` prints, per program, the bytes per cell of the hierarchical value (its
// distinct nodes, counted) and of the flattened complex (heap growth while flattening).
// Figures in docs/PERFORMANCE.md.
#include <benchmark/benchmark.h>
#include <malloc.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <new>
#include <set>
#include <sstream>
#include <string>

#include "lang/plasm/checker.h"
#include "lang/plasm/output.h"
#include "lang/plasm/parser.h"
#include "lang/plasm/polyhedron.h"

namespace {

// Live heap bytes, counted for --memory only (usable sizes: what the allocator really holds);
// the timed runs pay one branch per allocation.
bool g_counting = false;
long long g_live = 0;

}  // namespace

void* operator new(std::size_t size) {
  void* p = std::malloc(size == 0 ? 1 : size);
  if (p == nullptr) throw std::bad_alloc();
  if (g_counting) g_live += static_cast<long long>(malloc_usable_size(p));
  return p;
}
void operator delete(void* p) noexcept {
  if (p == nullptr) return;
  if (g_counting) g_live -= static_cast<long long>(malloc_usable_size(p));
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
  operator delete(p);
}

namespace insula::lang::plasm {
namespace {

const std::filesystem::path kPrograms = std::filesystem::path(INSULA_BENCH_DIR) / "plasm";

std::string read(const std::string& name) {
  std::ifstream in(kPrograms / name, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

struct Run {
  std::size_t triangles = 0;
  std::size_t cells = 0;
};

[[noreturn]] void fail(const base::Source& source, const char* stage) {
  std::fprintf(stderr, "%s: %s failed (%zu bytes read from %s)\n", source.name().c_str(), stage,
               source.text().size(), kPrograms.c_str());
  std::abort();
}

Run run(const base::Source& source) {
  base::Result<Program> program = parse(source);
  if (!program.ok()) fail(source, "parse");
  if (!check(program.value(), source).ok) fail(source, "check");
  base::Result<ProgramOutput> out = program_scene(program.value(), source);
  if (!out.ok()) fail(source, "evaluation");
  Run r;
  r.cells = out.value().stats.solid_cells + out.value().stats.surface_cells;
  for (const shape::Building& b : out.value().scene.buildings)
    for (const shape::Part& p : b.parts) r.triangles += p.mesh.triangle_count();
  return r;
}

void program(benchmark::State& state, const char* file) {
  const base::Source source(file, read(file));
  Run r;
  for (auto _ : state) r = run(source);
  state.counters["triangles"] = static_cast<double>(r.triangles);
  state.counters["cells"] = static_cast<double>(r.cells);
}

void BM_Columns100(benchmark::State& state) {
  program(state, "columns100.psm");
}
BENCHMARK(BM_Columns100)->Unit(benchmark::kMillisecond);

void BM_WallWindows100(benchmark::State& state) {
  program(state, "wall_windows.psm");
}
BENCHMARK(BM_WallWindows100)->Unit(benchmark::kMillisecond);

void BM_Dome24x12(benchmark::State& state) {
  program(state, "dome24x12.psm");
}
BENCHMARK(BM_Dome24x12)->Unit(benchmark::kMillisecond);

void BM_LeaningTower(benchmark::State& state) {
  program(state, "leaning_tower.psm");
}
BENCHMARK(BM_LeaningTower)->Unit(benchmark::kMillisecond);

// The bytes the distinct nodes of a hierarchical value hold (a part placed many times counts
// once), with their cells.
void node_bytes(const Polyhedron& p, std::set<const Polyhedron*>& seen, std::size_t& bytes,
                std::size_t& cells) {
  if (!seen.insert(&p).second) return;
  bytes += sizeof(Polyhedron) + p.points.capacity() * sizeof(double) +
           p.cells.capacity() * sizeof(Cell) + p.children.capacity() * sizeof(Polyhedron::Child) +
           p.label.capacity();
  for (const Cell& c : p.cells) bytes += c.capacity() * sizeof(std::uint32_t);
  cells += p.cells.size();
  if (p.solid) bytes += p.solid->vertex_count() * sizeof(kernel::Vec3) + p.solid->face_count() * 16;
  for (const Polyhedron::Child& child : p.children) {
    bytes += child.transform.m.capacity() * sizeof(double);
    node_bytes(*child.part, seen, bytes, cells);
  }
}

int memory() {
  for (const char* file :
       {"columns100.psm", "wall_windows.psm", "dome24x12.psm", "leaning_tower.psm"}) {
    const base::Source source(file, read(file));
    base::Result<Program> program = parse(source);
    if (!program.ok()) return 1;
    Evaluator evaluator(program.value(), source);
    for (std::size_t i = 0; i < program.value().statements.size(); ++i) {
      if (program.value().statements[i].is_def) continue;
      base::Result<ValuePtr> value = evaluator.statement(i);
      if (!value.ok() || !value.value()->is_polyhedron()) return 1;
      const Polyhedron& p = *value.value()->polyhedron();
      std::set<const Polyhedron*> seen;
      std::size_t node = 0;
      std::size_t stored = 0;
      node_bytes(p, seen, node, stored);
      // Blocks allocated before counting starts are never freed inside it (flat outlives it).
      g_live = 0;
      g_counting = true;
      const FlatComplex flat = flatten(p);
      g_counting = false;
      const long long flat_bytes = g_live;
      const std::size_t cells = flat.cells.size() + flat.solids.size();
      std::printf(
          "%-18s hierarchical: %zu nodes, %zu cells stored, %zu bytes (%.0f per stored cell, %.1f "
          "per flattened cell); flattened: %zu cells, %lld bytes (%.0f per cell)\n",
          file, seen.size(), stored, node, stored ? double(node) / double(stored) : 0.0,
          cells ? double(node) / double(cells) : 0.0, cells, flat_bytes,
          cells ? double(flat_bytes) / double(cells) : 0.0);
    }
  }
  return 0;
}

}  // namespace
}  // namespace insula::lang::plasm

int main(int argc, char** argv) {
  if (argc > 1 && std::strcmp(argv[1], "--memory") == 0) return insula::lang::plasm::memory();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
