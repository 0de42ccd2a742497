// CGA derivation throughput and memory (issue 4, "Performance"; docs/PERFORMANCE.md).
// Run: build/bench/cga_derive_bench --benchmark_repetitions=5
//      --benchmark_report_aggregates_only=true
// One thread. A facade grammar (comp, floors, tiles, window columns) over 200 x 200 m lots of 300
// storeys derives 396,001 terminals per lot, 1.19 million per iteration. Counters:
//   terminals/s       terminal shapes derived per second
//   bytes/live_shape  peak heap growth during a lot's derivation (counted by the global
//                     operator new below) / (terminals kept + the largest number of pending shapes)
//   peak_heap_MB      that peak heap growth of one lot
// Rates are per CPU second of the (single) deriving thread, so a busy machine does not skew them.
#include <benchmark/benchmark.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "lang/cga/compile.h"
#include "lang/cga/derive.h"
#include "lang/cga/parser.h"

// A counting allocator: live and peak heap bytes of the whole process.
namespace {
std::atomic<std::size_t> g_live{0};
std::atomic<std::size_t> g_peak{0};

void* counted_alloc(std::size_t n) {
  void* p = std::malloc(n + 16);
  if (p == nullptr) throw std::bad_alloc();
  *static_cast<std::size_t*>(p) = n;
  const std::size_t live = g_live.fetch_add(n) + n;
  std::size_t peak = g_peak.load();
  while (live > peak && !g_peak.compare_exchange_weak(peak, live)) {
  }
  return static_cast<char*>(p) + 16;
}
void counted_free(void* p) noexcept {
  if (p == nullptr) return;
  char* base = static_cast<char*>(p) - 16;
  g_live.fetch_sub(*reinterpret_cast<std::size_t*>(base));
  std::free(base);
}
}  // namespace

void* operator new(std::size_t n) {
  return counted_alloc(n);
}
void* operator new[](std::size_t n) {
  return counted_alloc(n);
}
void operator delete(void* p) noexcept {
  counted_free(p);
}
void operator delete[](void* p) noexcept {
  counted_free(p);
}
void operator delete(void* p, std::size_t) noexcept {
  counted_free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
  counted_free(p);
}

namespace insula::lang::cga {
namespace {

constexpr const char* kGrammar = R"(
attr floors = 300
Lot --> extrude(floors * 3) Mass
Mass --> comp("f"){ side: Facade | top: Roof | bottom: ε }
Facade --> split("y"){ { ~3: Floor }* }
Floor --> split("x"){ { ~3: Tile }* }
Tile --> split("x"){ ~1: Wall | 1.4: WindowColumn | ~1: Wall }
WindowColumn --> split("y"){ 0.9: Wall | 1.6: Window | ~1: Wall }
)";

// The same building in CityEngine's dialect (issue 20: "derivation speed of CityEngine-dialect
// grammars within 20% of seed 004 grammars of the same size"), written as CityEngine users
// write it: a const, annotations, terminals `Name.`, and the storey index passed down through
// parametric rules (a rule-argument frame per floor and per tile).
constexpr const char* kCityEngineGrammar = R"(version "2019.0"
@Range(min = 1, max = 400)
attr floors = 300
const floorH = 3
@StartRule
Lot --> extrude(floors * floorH) Mass
Mass --> comp(f) { side : Facade | top : Roof. | bottom : NIL }
Facade --> split(y) { ~floorH : Floor(split.index) }*
Floor(level) --> split(x) { ~3 : Tile(level) }*
Tile(level) --> split(x) { ~1 : Wall. | 1.4 : WindowColumn | ~1 : Wall. }
WindowColumn --> split(y) { 0.9 : Wall. | 1.6 : Window. | ~1 : Wall. }
)";

std::shared_ptr<const Program> compiled(const char* text) {
  const base::Source source("bench.cga", text);
  auto grammar = parse(source);
  CompileOptions options;
  options.start = "Lot";
  auto result = compile(grammar.value(), source, options);
  return result.value();
}

std::shared_ptr<const Program> program(bool cityengine = false) {
  static const std::shared_ptr<const Program> seed004 = compiled(kGrammar);
  static const std::shared_ptr<const Program> dialect = compiled(kCityEngineGrammar);
  return cityengine ? dialect : seed004;
}

Lot big_lot() {
  Lot lot;
  lot.id = "bench";
  lot.polygons.push_back({{{0, 0}, {200, 0}, {200, 200}, {0, 200}}, {}});
  return lot;
}

void derive(benchmark::State& state, bool keep, bool cityengine = false) {
  const auto p = program(cityengine);
  const Lot lot = big_lot();
  DeriveOptions options;
  options.keep_terminals = keep;
  constexpr int kLots = 3;
  std::uint64_t terminals = 0;
  double bytes_per_shape = 0;
  double peak_bytes = 0;
  for (auto _ : state) {
    for (int i = 0; i < kLots; ++i) {
      const std::size_t before = g_live.load();
      g_peak.store(before);
      LotResult r = derive_lot(*p, lot, static_cast<std::size_t>(i), options);
      const std::size_t peak = g_peak.load() - before;
      if (!r.ok) state.SkipWithError("derivation failed");
      terminals += r.terminals;
      const double live = static_cast<double>((keep ? r.terminals : 0) + r.peak_pending);
      bytes_per_shape = static_cast<double>(peak) / live;
      peak_bytes = static_cast<double>(peak);
      benchmark::DoNotOptimize(r.shapes);
    }
  }
  state.counters["terminals/s"] =
      benchmark::Counter(static_cast<double>(terminals), benchmark::Counter::kIsRate);
  state.counters["terminals/iter"] =
      static_cast<double>(terminals) / static_cast<double>(state.iterations());
  state.counters["bytes/live_shape"] = bytes_per_shape;
  state.counters["peak_heap_MB"] = peak_bytes / 1e6;
}

// Terminals kept for output (what a run with -o does).
void BM_DeriveFacadesKeep(benchmark::State& state) {
  derive(state, true);
}
BENCHMARK(BM_DeriveFacadesKeep)->Unit(benchmark::kMillisecond);

// Counting only (a --report-only run).
void BM_DeriveFacadesCount(benchmark::State& state) {
  derive(state, false);
}
BENCHMARK(BM_DeriveFacadesCount)->Unit(benchmark::kMillisecond);

// The same building from CityEngine's dialect, terminals kept.
void BM_DeriveFacadesCityEngineKeep(benchmark::State& state) {
  derive(state, true, true);
}
BENCHMARK(BM_DeriveFacadesCityEngineKeep)->Unit(benchmark::kMillisecond);

// The same building from CityEngine's dialect, counting only.
void BM_DeriveFacadesCityEngineCount(benchmark::State& state) {
  derive(state, false, true);
}
BENCHMARK(BM_DeriveFacadesCityEngineCount)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace insula::lang::cga
