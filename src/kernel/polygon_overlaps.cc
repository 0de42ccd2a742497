#include "kernel/polygon_overlaps.h"

#include <algorithm>

#include "kernel/boolean2d.h"
#include "kernel/box_pairs.h"

namespace insula::kernel {
namespace {

Bounds2 region_bounds(const std::vector<Polygon>& region) {
  Bounds2 box;
  for (const Polygon& polygon : region) {
    const Bounds2 b = bounds(polygon);
    box.add(b.min);
    box.add(b.max);
  }
  return box;
}

double intersection_area(const std::vector<Polygon>& a, const std::vector<Polygon>& b) {
  double total = 0;
  for (const Polygon& polygon : intersect(a, b).polygons) total += area(polygon);
  return total;
}

}  // namespace

std::vector<Overlap> find_overlaps(const std::vector<std::vector<Polygon>>& regions,
                                   double min_area) {
  std::vector<Bounds2> boxes;
  boxes.reserve(regions.size());
  for (const std::vector<Polygon>& region : regions) boxes.push_back(region_bounds(region));
  std::vector<Overlap> overlaps;
  for_each_box_pair(boxes, 0, [&](std::size_t i, std::size_t j) {
    const double shared = intersection_area(regions[i], regions[j]);
    if (shared > min_area) overlaps.push_back({std::min(i, j), std::max(i, j), shared});
  });
  std::sort(overlaps.begin(), overlaps.end(), [](const Overlap& x, const Overlap& y) {
    return x.first != y.first ? x.first < y.first : x.second < y.second;
  });
  return overlaps;
}

}  // namespace insula::kernel
