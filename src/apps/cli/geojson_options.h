// The footprint reading flags shared by `mass`, `build --lot` and `check`: --crs, --out-crs, and
// what --keep-going means to the readers (docs/geojson.md, "Coordinates, units and CRS" and
// "Repair policy"; docs/osm.md).
#pragma once

#include <CLI/CLI.hpp>

#include <string>

#include "apps/cli/crs_flags.h"
#include "io/crs.h"
#include "io/geojson_reader.h"

namespace insula::cli {

inline void add_crs_option(CLI::App& command, CrsFlags& flags) {
  command
      .add_option("--crs", flags.crs,
                  "CRS of input that names none, EPSG:N (lon/lat, Web Mercator and feet are "
                  "reprojected to the local UTM zone); for lon/lat input or a file naming its "
                  "CRS, a projected CRS in meters is the CRS to build in")
      ->check(CLI::Validator(
          [](const std::string& text) {
            std::string error;
            return io::describe_crs(text, error) ? std::string() : error;
          },
          "EPSG:N"));
  command
      .add_option("--out-crs", flags.out_crs,
                  "CRS to build in and write, EPSG:N (projected, in ground meters; default: the "
                  "input's when it is one, else the UTM zone of the data)")
      ->check(CLI::Validator([](const std::string& text) { return io::buildable_crs(text); },
                             "EPSG:N"));
  command.add_option("--id-attr", flags.id_attr,
                     "property that names each building (a register's id column; default: the "
                     "feature's id, else its 'id' or 'name' property, else its OSM element)");
}

// `keep_going`: invalid features are skipped with a warning; otherwise the first feature error
// suggests --keep-going when the command has it (`has_keep_going`).
inline io::GeoJsonOptions geojson_options(const CrsFlags& flags, bool keep_going,
                                          bool has_keep_going = true) {
  io::GeoJsonOptions options;
  options.crs = flags.crs;
  options.out_crs = flags.out_crs;
  options.id_property = flags.id_attr;
  options.skip_invalid = keep_going;
  if (has_keep_going) options.skip_invalid_flag = "--keep-going";
  return options;
}

}  // namespace insula::cli
