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

// Leaves out of `set` the outlines whose parts stand in them (by their S3DB tags: `building`,
// `building:part`); returns how many. Footprints without those tags are never touched.
std::size_t drop_outlines_with_parts(io::FootprintSet& set);

}  // namespace insula::cli
