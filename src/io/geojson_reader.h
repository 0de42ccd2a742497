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
#include "kernel/polygon.h"
#include "kernel/vec.h"
#include "shape/value.h"

namespace insula::io {

struct Footprint {
  // The feature's "id" member, else properties.id, else properties.name, else "feature-<index>".
  // Unique within a FootprintSet: a repeated id is renamed "<id>-2", "<id>-3"... with a warning.
  std::string id;
  // Local coordinates (world - origin) in meters, normalized (outer ring counter-clockwise, holes
  // clockwise, no closing vertex) and repaired by kernel::repair(). One entry per Polygon of a
  // MultiPolygon, in file order.
  std::vector<kernel::Polygon> polygons;
  // What the file said before normalization, per polygon (same order and frame as `polygons`):
  // the outer ring's first edge as written (its first position and the next distinct one), and
  // whether that ring ran clockwise. Lets a front-end orient a lot by the file's first edge
  // without reading the GeoJSON again.
  std::vector<std::array<kernel::Vec2, 2>> first_edges;
  std::vector<bool> outer_clockwise;
  // JSON properties: numbers -> double, bool, string, null -> monostate; nested objects and arrays
  // as compact JSON strings.
  shape::AttributeMap properties;
  // 0-based position in the FeatureCollection (0 for a single Feature or a bare geometry).
  std::size_t feature_index = 0;
};

struct FootprintSet {
  // world = local + origin. x and y are whole meters; z is always 0.
  kernel::Vec3 origin;
  // The CRS of the world coordinates ("EPSG:32633"): the file's "crs" member, GeoJsonOptions::crs,
  // or the UTM zone geographic input was reprojected to; empty when nothing names one.
  std::string crs;
  // The CRS the file's coordinates were in when they were reprojected ("OGC:CRS84" for RFC 7946
  // longitude/latitude); empty when nothing was reprojected.
  std::string source_crs;
  std::vector<Footprint> footprints;
  // Features left out because they were invalid (GeoJsonOptions::skip_invalid).
  std::size_t skipped_invalid = 0;
};

struct GeoJsonOptions {
  // Deepest allowed nesting of arrays and objects; checked by a byte scan before JSON parsing,
  // so hostile input (100000 '[') cannot exhaust the stack. A MultiPolygon needs 8.
  std::size_t max_depth = 64;
  // Largest accepted |coordinate| in meters; 1e8 m is well beyond any projected CRS.
  double max_abs_coordinate = 1e8;
  // When set, local = world - origin for this origin (z ignored): lets several files share one
  // local frame. When unset, see shift_threshold.
  std::optional<kernel::Vec2> origin;
  // Data whose bounding box lies within +-shift_threshold meters of (0, 0) keeps origin (0, 0, 0);
  // otherwise the origin is the bounding-box centre rounded down to whole meters.
  double shift_threshold = 1e4;
  // Tolerance in meters handed to kernel::repair() (duplicate / collinear vertices).
  double repair_tolerance = 1e-7;
  // false: any invalid feature makes the whole read fail (exit code 1 for the CLI).
  // true: invalid features are dropped, each with one warning giving its first error.
  bool skip_invalid = false;
  // How a user asks for skip_invalid ("--keep-going"): named in the note of skipped features
  // and, when skip_invalid is off, suggested under the first feature error.
  std::string skip_invalid_flag;
  // The CRS to build in, "EPSG:N" (projected, in meters; see io::buildable_crs): coordinates in
  // another known CRS are reprojected to it; coordinates in no named CRS that are not
  // longitude/latitude are taken to be in it already. Empty: geographic input goes to its UTM
  // zone, projected input stays as it is. docs/geojson.md gives the whole rule.
  std::string crs;
  // Stop after this many errors; further warnings past max_warnings are counted, not listed.
  std::size_t max_errors = 50;
  std::size_t max_warnings = 100;
};

// Reads GeoJSON `text` (a FeatureCollection, a single Feature, or a bare Polygon / MultiPolygon
// geometry) in projected meters or in longitude/latitude, which is reprojected. `source_name` names
// the file in diagnostics. Never throws and never prints: on failure the result holds the errors
// (`file:line:col: error[GEOnnn]: feature 3 (id "b12"): ...`); on success it may hold warnings.
base::Result<FootprintSet> read_geojson(std::string_view text, const std::string& source_name,
                                        const GeoJsonOptions& options = {});

}  // namespace insula::io
