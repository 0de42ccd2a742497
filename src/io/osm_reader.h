// OpenStreetMap footprint reader (.osm XML, .osm.pbf, and the compressed forms libosmium reads):
// closed ways and multipolygon relations tagged `building` or `building:part`, assembled into
// polygons with holes by libosmium (Debian libosmium2-dev; its headers stay inside
// osm_reader.cc). docs/osm.md documents passes, memory, ids, tags and diagnostics (OSM001...).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "base/diagnostic.h"
#include "io/footprint_finish.h"
#include "kernel/polygon.h"

namespace insula::io {

// One building or building part as libosmium assembled it, before CRS, origin and repair.
struct OsmFeature {
  bool relation = false;  // a multipolygon relation, else a closed way
  std::int64_t id = 0;    // the way's or relation's OSM id
  // Longitude/latitude in degrees (x = longitude), no closing vertex: one polygon per outer
  // ring, each with the inner rings libosmium placed in it. Empty when `problem` is set.
  std::vector<kernel::Polygon> polygons;
  // Every tag verbatim, in the element's order (a multipolygon's without its `type` tag).
  std::vector<std::pair<std::string, std::string>> tags;
  // Non-empty when no footprint could be made: why ("node 17 is not in the file", "ring not
  // closed: it ends at node 5 of way 789").
  std::string code;     // "OSM002"...
  std::string problem;  // the message
  // "way 123" / "relation 456": names the element in messages.
  std::string element() const;
};

struct OsmStreamOptions {
  // Features per call of the consumer.
  std::size_t batch_size = 4096;
};

struct OsmStreamStats {
  std::size_t features = 0;   // OsmFeatures delivered, problems included
  std::size_t ways = 0;       // features from closed ways
  std::size_t relations = 0;  // features from multipolygon relations
};

// Reads the file at `path` in two streaming passes (docs/osm.md): relations first (remembering
// building multipolygons and the ids of their member ways), then nodes and ways, keeping node
// locations in a libosmium flex_mem index and the member ways of unfinished multipolygons. Calls
// `consume` with batches of features in the order they are completed (ways as they are read, a
// multipolygon when its last member way is read, multipolygons missing members at the end). Never
// throws: a file that cannot be opened, is truncated or malformed gives errors (OSM001), and
// then some batches may already have been delivered.
base::Result<OsmStreamStats> stream_osm(
    const std::string& path, const OsmStreamOptions& options,
    const std::function<void(std::vector<OsmFeature>&)>& consume);

struct OsmOptions : FootprintOptions {
  OsmStreamOptions stream;
};

// True for the file names libosmium reads as OpenStreetMap data: .osm, .osm.pbf, .pbf, .osm.bz2,
// .osm.gz, .osc, .opl (case-insensitive).
bool is_osm_path(const std::string& path);

// The whole file as a FootprintSet, in the frame read_geojson() gives (longitude/latitude
// reprojected to the local UTM zone unless options.out_crs says otherwise, origin shift, repair,
// ids "way/123" and "relation/456", skip_invalid). Properties: every tag as a string, plus
// "osm_type" ("way" / "relation") and "osm_id". Messages: `FILE: error[OSM003]: way 123: ...`.
base::Result<FootprintSet> read_osm(const std::string& path, const OsmOptions& options = {});

}  // namespace insula::io
