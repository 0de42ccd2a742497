#include "apps/cli/footprint_input.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string_view>

#include "apps/cli/front_ends.h"
#include "apps/cli/height_unit.h"
#include "apps/cli/input_file.h"
#include "apps/cli/s3db_parts.h"
#include "apps/cli/warnings.h"
#include "base/tag_numbers.h"
#include "io/building_tags.h"
#include "io/osm_reader.h"

namespace insula::cli {

base::Result<io::FootprintSet> read_osm_footprints(const std::string& path,
                                                   const io::GeoJsonOptions& options) {
  io::OsmOptions osm;
  static_cast<io::FootprintOptions&>(osm) = options;
  return io::read_osm(path, osm);
}

base::Source osm_source(const std::string& path, const base::Result<io::FootprintSet>& set) {
  // OSM messages name the element; only an XML syntax error has a line to quote, and only then
  // is the text read.
  const bool positioned = std::any_of(set.diagnostics().begin(), set.diagnostics().end(),
                                      [](const base::Diagnostic& d) { return d.span.line > 0; });
  const std::optional<std::string> text =
      positioned ? read_input_file(path) : std::optional<std::string>();
  return base::Source(path, text.value_or(""));
}

void print_footprint_read(const base::Result<io::FootprintSet>& set, const base::Source& source,
                          bool quiet) {
  std::vector<base::Diagnostic> diagnostics = set.diagnostics();
  if (set.ok()) {
    // The reader's closing notes, one per code, are given to the run's tally instead.
    std::erase_if(diagnostics,
                  [](const base::Diagnostic& d) { return d.severity == base::Severity::kNote; });
    for (const auto& [code, count] : set->unlisted_warnings) count_unlisted_warnings(code, count);
  }
  print_diagnostics(diagnostics, source, quiet);
}

std::optional<io::FootprintSet> read_footprints(const std::string& path,
                                                const io::GeoJsonOptions& options, bool quiet) {
  if (io::is_osm_path(path)) {
    base::Result<io::FootprintSet> set = read_osm_footprints(path, options);
    print_footprint_read(set, osm_source(path, set), quiet);
    if (!set.ok()) return std::nullopt;
    return std::move(set.value());
  }
  std::optional<std::string> text = read_input_or_report(path);
  if (!text) return std::nullopt;
  // Moved, not copied: a city's GeoJSON is hundreds of megabytes.
  const base::Source source(path, std::move(*text));
  base::Result<io::FootprintSet> set = io::read_geojson(source.text(), path, options);
  print_footprint_read(set, source, quiet);
  if (!set.ok()) return std::nullopt;
  return std::move(set.value());
}

LeftOutLots& LeftOutLots::operator+=(const LeftOutLots& other) {
  not_buildings += other.not_buildings;
  replaced_outlines += other.replaced_outlines;
  elevated += other.elevated;
  return *this;
}

void add_left_out_lots(nlohmann::json& report, const LeftOutLots& left) {
  report["not_buildings"] = left.not_buildings;
  report["replaced_outlines"] = left.replaced_outlines;
  report["elevated_lots"] = left.elevated;
}

io::GeoJsonOptions building_options(io::GeoJsonOptions options) {
  options.leave_out_non_buildings = true;
  return options;
}

std::size_t note_non_buildings(const io::FootprintSet& set, bool quiet) {
  const std::size_t count = set.non_buildings;
  if (quiet || count == 0) return count;
  std::string tags;
  constexpr std::size_t kNamed = 4;
  for (std::size_t i = 0; i < std::min(set.non_building_tags.size(), kNamed); ++i) {
    tags += (i > 0 ? ", " : "") + set.non_building_tags[i];
  }
  if (set.non_building_tags.size() > kNamed) tags += ", ...";
  std::fprintf(stderr,
               "note: %zu map area%s that %s not a building left out (%s; no building or "
               "building:part tag)\n",
               count, count == 1 ? "" : "s", count == 1 ? "is" : "are", tags.c_str());
  return count;
}

LeftOutLots leave_out_for_lots(io::FootprintSet& set, bool quiet) {
  const std::size_t not_buildings = note_non_buildings(set, quiet);
  const LotsLeftOut s3db = cli::leave_out_for_lots(set);
  const LeftOutLots left{not_buildings, s3db.outlines, s3db.elevated};
  if (quiet) return left;
  if (left.replaced_outlines > 0) {
    std::fprintf(stderr,
                 "note: %zu building outline%s left out: the building:parts inside %s are built "
                 "instead (Simple 3D Buildings)\n",
                 left.replaced_outlines, left.replaced_outlines == 1 ? "" : "s",
                 left.replaced_outlines == 1 ? "it" : "them");
  }
  if (left.elevated > 0) {
    std::fprintf(stderr,
                 "note: %zu building%s or part%s above the ground (min_height, "
                 "building:min_level) left out: lots are built from the ground\n",
                 left.elevated, left.elevated == 1 ? "" : "s", left.elevated == 1 ? "" : "s");
  }
  return left;
}

std::optional<io::FootprintSet> read_lot_footprints(const std::string& path,
                                                    const io::GeoJsonOptions& options, bool quiet,
                                                    const std::string& height_unit,
                                                    LeftOutLots& left) {
  std::optional<io::FootprintSet> set = read_footprints(path, building_options(options), quiet);
  if (!set) return set;
  left = leave_out_for_lots(*set, quiet);
  lot_heights_in_meters(*set, height_unit);
  return set;
}

std::size_t lot_heights_in_meters(io::FootprintSet& set, const std::string& height_unit) {
  const double unit = meters_per_height_unit(height_unit);
  if (unit == 1) return 0;
  std::size_t changed = 0;
  for (io::Footprint& lot : set.footprints) {
    const std::optional<shape::Value> height = lot.properties.find("height");
    if (!height || io::follows_s3db(lot.properties)) continue;
    std::optional<double> number;
    if (const double* d = std::get_if<double>(&*height)) number = *d;
    if (const std::string* text = std::get_if<std::string>(&*height)) {
      std::string_view rest = *text;
      number = base::take_number(rest);
      if (!rest.empty()) number.reset();
    }
    if (!number || !std::isfinite(*number)) continue;
    // The lot's own row: the others keep sharing the set's table.
    shape::AttributeMap properties = lot.properties.map();
    properties["height"] = *number * unit;
    lot.properties = io::PropertyRow::of(properties);
    ++changed;
  }
  return changed;
}

}  // namespace insula::cli
