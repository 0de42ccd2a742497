// The GeoJSON reading flags shared by `mass`, `build --lot` and `check`: --crs, and what
// --keep-going means to the reader (docs/geojson.md, "Coordinates, units and CRS" and "Repair
// policy").
#pragma once

#include <CLI/CLI.hpp>

#include <string>

#include "io/crs.h"
#include "io/geojson_reader.h"

namespace insula::cli {

inline void add_crs_option(CLI::App& command, std::string& crs) {
  command
      .add_option("--crs", crs,
                  "CRS to build in, EPSG:N (projected, meters): lon/lat and other input is "
                  "reprojected to it (default: lon/lat goes to its UTM zone); input in meters "
                  "whose file names no CRS is taken to be in it")
      ->check(CLI::Validator([](const std::string& text) { return io::buildable_crs(text); },
                             "EPSG:N"));
}

// `keep_going`: invalid features are skipped with a warning; otherwise the first feature error
// suggests --keep-going when the command has it (`has_keep_going`).
inline io::GeoJsonOptions geojson_options(const std::string& crs, bool keep_going,
                                          bool has_keep_going = true) {
  io::GeoJsonOptions options;
  options.crs = crs;
  options.skip_invalid = keep_going;
  if (has_keep_going) options.skip_invalid_flag = "--keep-going";
  return options;
}

}  // namespace insula::cli
