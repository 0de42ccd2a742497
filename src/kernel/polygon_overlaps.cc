#include "kernel/polygon_overlaps.h"

#include <algorithm>
#include <numeric>

#include "kernel/boolean2d.h"

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
  std::vector<std::size_t> order(regions.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return boxes[a].min.x < boxes[b].min.x; });
  std::vector<Overlap> overlaps;
  for (std::size_t i = 0; i < order.size(); ++i) {
    const Bounds2& a = boxes[order[i]];
    for (std::size_t j = i + 1; j < order.size() && boxes[order[j]].min.x < a.max.x; ++j) {
      const Bounds2& b = boxes[order[j]];
      if (b.min.y >= a.max.y || a.min.y >= b.max.y) continue;
      const double shared = intersection_area(regions[order[i]], regions[order[j]]);
      if (shared <= min_area) continue;
      overlaps.push_back({std::min(order[i], order[j]), std::max(order[i], order[j]), shared});
    }
  }
  std::sort(overlaps.begin(), overlaps.end(), [](const Overlap& x, const Overlap& y) {
    return x.first != y.first ? x.first < y.first : x.second < y.second;
  });
  return overlaps;
}

}  // namespace insula::kernel
