// CityJSON 2.0 writer (docs/formats.md, "CityJSON"), valid against the CityJSON 2.0.2 schema.
// One "Building" per building with its attributes and one child per part: "BuildingPart",
// "BuildingStorey" (PartKind::kStorey), "BuildingRoom" (kRoom) or "BuildingInstallation"
// (kInstallation). Vertices are integers under a "transform" with scale 0.001 (1 mm) and translate
// = origin + the scene's local minimum corner, deduplicated after quantisation; rings that repeat
// a vertex consecutively after quantisation lose the repeat, and rings left with fewer than 3
// vertices are dropped. A part becomes an LoD 2 "Solid" when its quantised mesh is closed,
// oriented, manifold, one piece and of positive volume, else a "MultiSurface". Faces carry semantic
// surfaces from kernel::citygml_surface() (null for unclassified faces). Output is deterministic.
#pragma once

#include <filesystem>
#include <string>

#include "shape/scene.h"

namespace insula::io {

struct CityJsonOptions {
  // A building's parts alike in name, kind, attributes and texture mapping become one
  // "BuildingPart" (shape::merge_alike_parts): a CGA scene made with a part per terminal for the
  // GLB's picking is written as the tiles write it (docs/formats.md, "CityJSON").
  bool merge_alike_parts = false;
};

// The CityJSON text of `scene` (compact JSON, one trailing newline).
std::string cityjson_text(const shape::Scene& scene, const CityJsonOptions& options = {});

// Writes `path` atomically. Returns an empty string on success, else a message naming the file.
std::string write_cityjson(const shape::Scene& scene, const std::filesystem::path& path,
                           const CityJsonOptions& options = {});

// "EPSG:32633" (any case, also "EPSG::32633") -> "https://www.opengis.net/def/crs/EPSG/0/32633"; an
// opengis.net CRS URL is kept; empty for anything else.
std::string cityjson_reference_system(const std::string& crs);

}  // namespace insula::io
