// libFuzzer target for io::read_geojson (docs/geojson.md). Beyond "no crash, no hang, no
// sanitizer report" it checks the reader's contract on every input: a failure carries an error,
// a success carries none, and every footprint is usable (unique id, finite local coordinates,
// rings of at least 3 vertices, positive area).
//
// Builds: with clang and INSULA_FUZZ=ON, fuzz/CMakeLists.txt links it with -fsanitize=fuzzer.
// With -DINSULA_FUZZ_REPLAY it gets a main() that feeds the files and folders named on the
// command line (a replay tool for GCC builds). tests/io/geojson_replay_test.cc includes this file
// with INSULA_FUZZ_NO_ENTRY to run check_geojson() over the corpus and the bad-input catalog.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>
#include <string_view>

#include "base/diagnostic.h"
#include "io/geojson_reader.h"
#include "kernel/polygon.h"

namespace insula::fuzz {

inline std::string check_footprints(const io::FootprintSet& set,
                                    const io::GeoJsonOptions& options) {
  std::set<std::string> ids;
  for (const io::Footprint& footprint : set.footprints) {
    if (!ids.insert(footprint.id).second) return "duplicate id " + footprint.id;
    if (footprint.polygons.empty()) return "footprint " + footprint.id + " has no polygon";
    for (const kernel::Polygon& polygon : footprint.polygons) {
      if (polygon.outer.size() < 3) return "outer ring with fewer than 3 vertices";
      if (!(kernel::area(polygon) > 0)) return "polygon without positive area";
      for (std::size_t r = 0; r <= polygon.holes.size(); ++r) {
        const kernel::Ring& ring = r == 0 ? polygon.outer : polygon.holes[r - 1];
        for (const kernel::Vec2& v : ring) {
          // local = world - origin with |world| <= max_abs_coordinate.
          const double limit = 2 * options.max_abs_coordinate + 1;
          if (!std::isfinite(v.x) || !std::isfinite(v.y) || std::abs(v.x) > limit ||
              std::abs(v.y) > limit) {
            return "vertex out of range";
          }
        }
      }
    }
  }
  return {};
}

// Empty when read_geojson kept its contract on `text` (with and without skip_invalid), else what
// broke.
inline std::string check_geojson(std::string_view text) {
  for (const bool skip_invalid : {false, true}) {
    io::GeoJsonOptions options;
    options.skip_invalid = skip_invalid;
    const base::Result<io::FootprintSet> result = io::read_geojson(text, "fuzz.geojson", options);
    for (const base::Diagnostic& d : result.diagnostics()) {
      if (d.message.empty() || base::render(d).empty()) return "empty diagnostic";
      if (d.code.empty() && d.severity != base::Severity::kWarning) return "error without code";
    }
    const bool errors = base::has_errors(result.diagnostics());
    if (!result.ok()) {
      if (!errors) return "failure without an error diagnostic";
      continue;
    }
    if (errors) return "success with an error diagnostic";
    if (std::string problem = check_footprints(result.value(), options); !problem.empty()) {
      return problem;
    }
  }
  return {};
}

}  // namespace insula::fuzz

#ifndef INSULA_FUZZ_NO_ENTRY
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string problem =
      insula::fuzz::check_geojson(std::string_view(reinterpret_cast<const char*>(data), size));
  if (!problem.empty()) {
    std::fprintf(stderr, "geojson_fuzz: %s\n", problem.c_str());
    std::abort();
  }
  return 0;
}
#endif

#ifdef INSULA_FUZZ_REPLAY
#define INSULA_FUZZ_REPLAY_NAME "geojson_fuzz_replay"
#include "replay_main.h"
#endif
