// Simple 3D Buildings (S3DB, docs/osm-buildings.md): building:part features inside a building
// outline are built instead of it. Mass models plan with it (mass_plan.cc), and so do the
// front-ends that take --lot, which would otherwise build the outline over its parts (a church's
// outline as one tall block around its nave, apse and tower).
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "io/geojson_reader.h"
#include "kernel/polygon_overlaps.h"

namespace insula::cli {

// Per footprint, the outline this building:part stands in: the outline (tagged building, not
// building:part) that holds most of the part's area, when that is at least half of it.
// `is_part[i]`, `is_outline[i]` say which footprints are which.
std::vector<std::optional<std::size_t>> part_outlines(const io::FootprintSet& set,
                                                      const std::vector<kernel::Overlap>& overlaps,
                                                      const std::vector<bool>& is_part,
                                                      const std::vector<bool>& is_outline);

// What leave_out_for_lots() left out.
struct LotsLeftOut {
  std::size_t outlines = 0;  // outlines whose building:parts stand in them
  std::size_t elevated = 0;  // buildings and parts that start above the ground
};

// Leaves out of `set`, by their S3DB tags, what a grammar building each lot from the ground
// cannot build: outlines whose parts stand in them (the parts are built instead), and buildings
// or parts above the ground (`min_height` or `building:min_level` > 0: a tower's upper stage,
// a bridge, a roof on posts), which would stand on the ground through what is below them.
// Footprints without those tags are never touched.
LotsLeftOut leave_out_for_lots(io::FootprintSet& set);

}  // namespace insula::cli
