// Reading OpenStreetMap footprints: io::stream_osm (libosmium's passes and assembly, features in
// longitude/latitude) and io::read_osm (plus reprojection, repair, ids) on the .osm.pbf named by
// OSM_BENCH_FILE, made by bench/make_osm_grid.sh. Run one benchmark per process so that the
// peak memory counter is its own (figures and command in docs/PERFORMANCE.md):
//   bench/make_osm_grid.sh 1000000 /tmp/grid.osm.pbf
//   OSM_BENCH_FILE=/tmp/grid.osm.pbf build/bench/osm_read_bench --benchmark_filter=Stream
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <cstdlib>
#include <string>

#include "io/osm_reader.h"

namespace insula::io {
namespace {

std::string bench_file() {
  const char* path = std::getenv("OSM_BENCH_FILE");
  return path != nullptr ? path : "";
}

double peak_rss_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
}

void BM_StreamOsm(benchmark::State& state) {
  const std::string path = bench_file();
  if (path.empty()) {
    state.SkipWithError("set OSM_BENCH_FILE to a .osm.pbf (bench/make_osm_grid.sh)");
    return;
  }
  std::size_t features = 0;
  for (auto _ : state) {
    features = 0;
    const auto stats = stream_osm(path, {}, [&](std::vector<OsmFeature>& batch) {
      features += batch.size();
      benchmark::DoNotOptimize(batch.data());
    });
    if (!stats.ok()) state.SkipWithError("stream_osm failed");
  }
  state.counters["buildings"] = static_cast<double>(features);
  state.counters["buildings_per_min"] = benchmark::Counter(
      static_cast<double>(features) * 60, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["peak_rss_MB"] = peak_rss_mb();
}
BENCHMARK(BM_StreamOsm)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

void BM_ReadOsm(benchmark::State& state) {
  const std::string path = bench_file();
  if (path.empty()) {
    state.SkipWithError("set OSM_BENCH_FILE to a .osm.pbf (bench/make_osm_grid.sh)");
    return;
  }
  std::size_t footprints = 0;
  for (auto _ : state) {
    const auto set = read_osm(path);
    if (!set.ok()) state.SkipWithError("read_osm failed");
    footprints = set.ok() ? set->footprints.size() : 0;
  }
  state.counters["buildings"] = static_cast<double>(footprints);
  state.counters["buildings_per_min"] = benchmark::Counter(
      static_cast<double>(footprints) * 60, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["peak_rss_MB"] = peak_rss_mb();
}
BENCHMARK(BM_ReadOsm)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

}  // namespace
}  // namespace insula::io
