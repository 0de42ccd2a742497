// GeoJSON footprint reader: Polygon and MultiPolygon features become footprints in local
// coordinates, with their properties as attributes. Accepted input, origin shift, CRS handling,
// repair policy and every diagnostic code (GEO001...) are documented in docs/geojson.md.
#pragma once

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
  // JSON properties: numbers -> double, bool, string, null -> monostate; nested objects and arrays
  // as compact JSON strings.
  shape::AttributeMap properties;
  // 0-based position in the FeatureCollection (0 for a single Feature or a bare geometry).
  std::size_t feature_index = 0;
};

struct FootprintSet {
  // world = local + origin. x and y are whole meters; z is always 0.
  kernel::Vec3 origin;
  // "EPSG:<code>" when the file names one in a GeoJSON-2008 "crs" member, else empty.
  std::string crs;
  std::vector<Footprint> footprints;
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
  // true: invalid features are dropped and their errors reported as warnings.
  bool skip_invalid = false;
  // Stop after this many errors; further warnings past max_warnings are counted, not listed.
  std::size_t max_errors = 50;
  std::size_t max_warnings = 100;
};

// Reads GeoJSON `text` (a FeatureCollection, a single Feature, or a bare Polygon / MultiPolygon
// geometry) whose coordinates are projected meters; no reprojection is done. `source_name` names
// the file in diagnostics. Never throws and never prints: on failure the result holds the errors
// (`file:line:col: error[GEOnnn]: feature 3 (id "b12"): ...`); on success it may hold warnings.
base::Result<FootprintSet> read_geojson(std::string_view text, const std::string& source_name,
                                        const GeoJsonOptions& options = {});

}  // namespace insula::io
