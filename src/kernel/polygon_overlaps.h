// Pairs of regions that overlap: footprints drawn over each other in map data (two mappers, a
// building and its own duplicate), which become buildings standing in each other.
#pragma once

#include <cstddef>
#include <vector>

#include "kernel/polygon.h"

namespace insula::kernel {

struct Overlap {
  std::size_t first = 0;  // indices into the regions, first < second
  std::size_t second = 0;
  double area = 0;  // of the intersection, square meters
};

// Every pair of regions (each a union of polygons) whose intersection has an area above
// `min_area`, by a sweep over bounding boxes in x and an exact intersection of the candidates
// (boolean2d). Sorted by pair.
std::vector<Overlap> find_overlaps(const std::vector<std::vector<Polygon>>& regions,
                                   double min_area = 0.01);

}  // namespace insula::kernel
