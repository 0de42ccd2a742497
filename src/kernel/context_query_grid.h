// The uniform grid of boxes behind the context queries' prefilters (context_query.h): each box is
// listed in every cell its bounds overlap, and a query visits the boxes listed in the cells the
// query box overlaps whose own bounds meet it, each once. Internal to the kernel.
#pragma once

#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include "kernel/mesh.h"

namespace insula::kernel::detail {

class BoxGrid {
 public:
  // Cells are cubes (squares when all boxes share one z) sized so that there are about as many
  // cells as boxes, and no smaller than the mean box, so a box lies in a few cells. Empty boxes
  // are never visited.
  explicit BoxGrid(std::vector<Bounds3> boxes);

  // Calls visit(index) for every box that meets `query` (closed bounds), once each, in no
  // particular order. Not const: it stamps visited boxes.
  template <class Visit>
  void query(const Bounds3& query, Visit&& visit);

  const Bounds3& box(std::size_t index) const { return boxes_[index]; }
  std::size_t size() const { return boxes_.size(); }
  // The bounds of all boxes (empty for none).
  const Bounds3& bounds() const { return all_; }

 private:
  int cell_of(double value, int axis) const;

  std::vector<Bounds3> boxes_;
  Bounds3 all_;
  Vec3 cell_{1, 1, 1};
  int dims_[3] = {1, 1, 1};
  std::vector<std::uint32_t> start_;  // cell c holds items_[start_[c] .. start_[c + 1])
  std::vector<std::uint32_t> items_;
  std::vector<std::uint32_t> stamp_;
  std::uint32_t epoch_ = 0;
};

inline bool meets(const Bounds3& a, const Bounds3& b) {
  return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y && b.min.y <= a.max.y &&
         a.min.z <= b.max.z && b.min.z <= a.max.z;
}

template <class Visit>
void BoxGrid::query(const Bounds3& query, Visit&& visit) {
  if (boxes_.empty() || query.empty() || !meets(query, all_)) return;
  if (++epoch_ == 0) {  // wrapped: old stamps could collide with the new epoch
    std::fill(stamp_.begin(), stamp_.end(), 0);
    epoch_ = 1;
  }
  const int x0 = cell_of(query.min.x, 0), x1 = cell_of(query.max.x, 0);
  const int y0 = cell_of(query.min.y, 1), y1 = cell_of(query.max.y, 1);
  const int z0 = cell_of(query.min.z, 2), z1 = cell_of(query.max.z, 2);
  for (int z = z0; z <= z1; ++z) {
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        const std::size_t c = (static_cast<std::size_t>(z) * dims_[1] + y) * dims_[0] + x;
        for (std::uint32_t i = start_[c]; i < start_[c + 1]; ++i) {
          const std::uint32_t item = items_[i];
          if (stamp_[item] == epoch_) continue;
          stamp_[item] = epoch_;
          if (meets(boxes_[item], query)) visit(static_cast<std::size_t>(item));
        }
      }
    }
  }
}

// Bounds of a planar point set at height 0, for the ground-plane queries.
Bounds3 flat_bounds(std::span<const Vec2> points);
// `box` grown by `margin` on every side.
Bounds3 grown(const Bounds3& box, double margin);

}  // namespace insula::kernel::detail
