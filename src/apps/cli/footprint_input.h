// Footprints from a file, for every verb that takes them (`mass`, `build --lot`): OpenStreetMap
// data (.osm, .osm.pbf, ...: io::is_osm_path) through io::read_osm, anything else as GeoJSON
// through io::read_geojson, with the same options (docs/osm.md, docs/geojson.md).
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "io/geojson_reader.h"

namespace insula::cli {

// Prints the reader's diagnostics (warnings unless `quiet`); nullopt when the file could not be
// read or has errors (the caller exits with code 1).
std::optional<io::FootprintSet> read_footprints(const std::string& path,
                                                const io::GeoJsonOptions& options, bool quiet);

// The lots of --lot: read_footprints(), then without the building outlines whose building:parts
// are built instead and the buildings and parts above the ground (S3DB, s3db_parts.h), with a
// note saying how many unless `quiet`, and their heights in meters (lot_heights_in_meters) when
// `height_unit` (--height-unit) is not "m".
std::optional<io::FootprintSet> read_lot_footprints(const std::string& path,
                                                    const io::GeoJsonOptions& options, bool quiet,
                                                    const std::string& height_unit);
// --height-unit of `build --lot`: the `height` property of each lot that does not follow S3DB
// (io::follows_s3db), when it is a number or a text that is only a number, becomes that many
// `height_unit`s in meters, as `mass` reads a register's height; a text with a unit ("40 ft")
// keeps it. Returns how many lots changed.
std::size_t lot_heights_in_meters(io::FootprintSet& set, const std::string& height_unit);
// Leaves those footprints out of `set`, and the map areas that are not buildings
// (leave_out_non_buildings); prints the notes unless `quiet`.
void leave_out_for_lots(io::FootprintSet& set, bool quiet);
// Leaves out of `set` the OpenStreetMap areas that are not buildings (landuse=forest,
// natural=water, ...: s3db_parts.h, non_building_area), with a note naming their tags unless
// `quiet`; returns how many. `mass` and every --lot front-end call it; `check` does not (it
// checks the whole file).
std::size_t leave_out_non_buildings(io::FootprintSet& set, bool quiet);

// The footprints of an OpenStreetMap file read with `options`; its diagnostics are left to the
// caller.
base::Result<io::FootprintSet> read_osm_footprints(const std::string& path,
                                                   const io::GeoJsonOptions& options);

}  // namespace insula::cli
