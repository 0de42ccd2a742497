// Pairs of axis-aligned boxes that overlap or come within a margin of each other, by a sweep in x:
// the candidates of the city-wide footprint tests (overlaps, party walls), which would otherwise
// compare every footprint with every other.
#pragma once

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <span>
#include <vector>

#include "kernel/polygon.h"

namespace insula::kernel {

// Calls visit(i, j) once for each pair of boxes (indices into `boxes`, in sweep order, so i and j
// come in either order) whose extents, grown by `margin` on every side, overlap.
template <typename Visit>
void for_each_box_pair(std::span<const Bounds2> boxes, double margin, Visit&& visit) {
  std::vector<std::size_t> order(boxes.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return boxes[a].min.x < boxes[b].min.x; });
  const double reach = 2 * margin;
  for (std::size_t i = 0; i < order.size(); ++i) {
    const Bounds2& a = boxes[order[i]];
    for (std::size_t j = i + 1; j < order.size() && boxes[order[j]].min.x < a.max.x + reach; ++j) {
      const Bounds2& b = boxes[order[j]];
      if (b.min.y >= a.max.y + reach || a.min.y >= b.max.y + reach) continue;
      visit(order[i], order[j]);
    }
  }
}

}  // namespace insula::kernel
