// GeoJSON footprint reader: Polygon and MultiPolygon features become footprints in local
// coordinates, with their properties as attributes. Accepted input, origin shift, CRS handling,
// repair policy and every diagnostic code (GEO001...) are documented in docs/geojson.md.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "base/diagnostic.h"
#include "io/footprint_finish.h"

namespace insula::io {

// FootprintOptions (io/footprint_finish.h) gives the shared options: origin, repair, CRS,
// skip_invalid, caps.
struct GeoJsonOptions : FootprintOptions {
  // Deepest allowed nesting of arrays and objects; checked by a byte scan before JSON parsing,
  // so hostile input (100000 '[') cannot exhaust the stack. A MultiPolygon needs 8.
  std::size_t max_depth = 64;
  // Largest accepted |coordinate| in meters; 1e8 m is well beyond any projected CRS.
  double max_abs_coordinate = 1e8;
  // A GeoJSON text sequence instead of one document: one Feature per line, a line optionally
  // starting with the record separator 0x1E (RFC 8142 GeoJSONSeq; newline-delimited GeoJSON as
  // Microsoft's building footprints ship it). Blank lines are skipped. read_geojson also reads a
  // text whose `source_name` is_geojson_sequence_path() so.
  bool sequence = false;
};

// Whether a file of this name holds a GeoJSON text sequence: it ends in .geojsonl, .geojsons,
// .geojsonseq or .ndjson (any letter case).
bool is_geojson_sequence_path(std::string_view path);

// Reads GeoJSON `text` (a FeatureCollection, a single Feature, a bare Polygon / MultiPolygon
// geometry, or a sequence of Features one per line: GeoJsonOptions::sequence) in projected meters
// or in longitude/latitude, which is reprojected. `source_name` names the file in diagnostics.
// Never throws and never prints: on failure the result holds the errors
// (`file:line:col: error[GEOnnn]: feature 3 (id "b12"): ...`); on success it may hold warnings.
base::Result<FootprintSet> read_geojson(std::string_view text, const std::string& source_name,
                                        const GeoJsonOptions& options = {});

}  // namespace insula::io
