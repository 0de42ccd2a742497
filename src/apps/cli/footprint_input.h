// Footprints from a file, for every verb that takes them (`mass`, `build --lot`): OpenStreetMap
// data (.osm, .osm.pbf, ...: io::is_osm_path) through io::read_osm, anything else as GeoJSON
// through io::read_geojson, with the same options (docs/osm.md, docs/geojson.md).
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "io/geojson_reader.h"

namespace insula::cli {

// Prints the reader's diagnostics (warnings unless `quiet`); nullopt when the file could not be
// read or has errors (the caller exits with code 1).
std::optional<io::FootprintSet> read_footprints(const std::string& path,
                                                const io::GeoJsonOptions& options, bool quiet);

// What was left out of a --lot file, for the build reports (add_left_out_lots).
struct LeftOutLots {
  std::size_t not_buildings = 0;      // map areas (io/map_areas.h: landuse=forest, ...)
  std::size_t replaced_outlines = 0;  // outlines whose building:parts are built instead
  std::size_t elevated = 0;           // buildings and parts that start above the ground
  LeftOutLots& operator+=(const LeftOutLots& other);
};
// The report keys of `left`: not_buildings, replaced_outlines, elevated_lots (docs/cli.md).
void add_left_out_lots(nlohmann::json& report, const LeftOutLots& left);

// Reading options for building footprints (`mass`, `--lot`): `options` that leave out the map
// areas that are not buildings (io::FootprintOptions::leave_out_non_buildings).
io::GeoJsonOptions building_options(io::GeoJsonOptions options);

// The lots of --lot: read_footprints() with building_options(), then without the building
// outlines whose building:parts are built instead and the buildings and parts above the ground
// (S3DB, s3db_parts.h), with a note saying how many unless `quiet`, and their heights in meters
// (lot_heights_in_meters) when `height_unit` (--height-unit) is not "m". `left` gets the counts.
std::optional<io::FootprintSet> read_lot_footprints(const std::string& path,
                                                    const io::GeoJsonOptions& options, bool quiet,
                                                    const std::string& height_unit,
                                                    LeftOutLots& left);
// --height-unit of `build --lot`: the `height` property of each lot that does not follow S3DB
// (io::follows_s3db), when it is a number or a text that is only a number, becomes that many
// `height_unit`s in meters, as `mass` reads a register's height; a text with a unit ("40 ft")
// keeps it. Returns how many lots changed.
std::size_t lot_heights_in_meters(io::FootprintSet& set, const std::string& height_unit);
// Leaves those footprints out of `set` (of a file read with building_options()); prints the
// notes, and the one of the map areas the reader left out, unless `quiet`.
LeftOutLots leave_out_for_lots(io::FootprintSet& set, bool quiet);
// The note naming the tags of the map areas the reader left out of `set` (building_options()),
// unless `quiet`; returns how many. `mass` and every --lot front-end print it; `check` reads
// every feature.
std::size_t note_non_buildings(const io::FootprintSet& set, bool quiet);

// The footprints of an OpenStreetMap file read with `options`; its diagnostics are left to the
// caller.
base::Result<io::FootprintSet> read_osm_footprints(const std::string& path,
                                                   const io::GeoJsonOptions& options);

// The source an OpenStreetMap file's diagnostics are quoted from: its text only when one of
// them has a line (an XML syntax error), since a .osm.pbf or a city's XML is large.
base::Source osm_source(const std::string& path, const base::Result<io::FootprintSet>& set);

// Prints a footprint reader's diagnostics (warnings unless `quiet`). Warnings it did not list
// (past its max_warnings) are counted by code for the run's "and N more like it" lines and the
// report, in place of its closing notes that count them; a failed read, which has no counts to
// give, prints those notes.
void print_footprint_read(const base::Result<io::FootprintSet>& set, const base::Source& source,
                          bool quiet);

}  // namespace insula::cli
