#include "apps/cli/footprint_input.h"

#include "apps/cli/front_ends.h"
#include "apps/cli/input_file.h"
#include "io/osm_reader.h"

namespace insula::cli {

std::optional<io::FootprintSet> read_footprints(const std::string& path,
                                                const io::GeoJsonOptions& options, bool quiet) {
  if (io::is_osm_path(path)) {
    io::OsmOptions osm;
    static_cast<io::FootprintOptions&>(osm) = options;
    base::Result<io::FootprintSet> set = io::read_osm(path, osm);
    // No text to quote: OSM messages name the element, XML syntax errors their line.
    print_diagnostics(set.diagnostics(), base::Source(path, ""), quiet);
    if (!set.ok()) return std::nullopt;
    return std::move(set.value());
  }
  const std::optional<std::string> text = read_input_or_report(path);
  if (!text) return std::nullopt;
  const base::Source source(path, *text);
  base::Result<io::FootprintSet> set = io::read_geojson(source.text(), path, options);
  print_diagnostics(set.diagnostics(), source, quiet);
  if (!set.ok()) return std::nullopt;
  return std::move(set.value());
}

}  // namespace insula::cli
