#include "kernel/context_query_grid.h"

#include <algorithm>
#include <cmath>

namespace insula::kernel::detail {

namespace {

double component(Vec3 v, int axis) {
  return axis == 0 ? v.x : axis == 1 ? v.y : v.z;
}

// The cube side giving about one cell per box over the extents that are not flat, but no less
// than the mean box extent.
double cell_side(const std::vector<Bounds3>& boxes, const Bounds3& all, std::size_t count) {
  const Vec3 extent = all.size();
  double volume = 1;
  int dims = 0;
  for (int a = 0; a < 3; ++a) {
    if (component(extent, a) > 0) {
      volume *= component(extent, a);
      ++dims;
    }
  }
  double mean = 0;
  for (const Bounds3& b : boxes) {
    if (b.empty()) continue;
    const Vec3 s = b.size();
    mean += std::max({s.x, s.y, s.z});
  }
  mean /= static_cast<double>(count);
  const double even = dims == 0 ? 0 : std::pow(volume / static_cast<double>(count), 1.0 / dims);
  const double side = std::max(even, mean);
  return side > 0 ? side : 1;
}

}  // namespace

Bounds3 flat_bounds(std::span<const Vec2> points) {
  Bounds3 b;
  for (const Vec2 p : points) b.add({p.x, p.y, 0});
  return b;
}

Bounds3 grown(const Bounds3& box, double margin) {
  if (box.empty()) return box;
  const Vec3 m{margin, margin, margin};
  return {box.min - m, box.max + m};
}

BoxGrid::BoxGrid(std::vector<Bounds3> boxes) : boxes_(std::move(boxes)), stamp_(boxes_.size(), 0) {
  std::size_t count = 0;
  for (const Bounds3& b : boxes_) {
    if (b.empty()) continue;
    all_.add(b.min);
    all_.add(b.max);
    ++count;
  }
  if (count == 0) return;  // query() finds nothing: all_ stays empty
  const double side = cell_side(boxes_, all_, count);
  const Vec3 extent = all_.size();
  for (int a = 0; a < 3; ++a) {
    // floor keeps the cell count at most about the box count; the cap guards absurd spreads.
    const double cells = std::floor(component(extent, a) / side);
    dims_[a] = static_cast<int>(std::clamp(cells, 1.0, 1024.0));
  }
  cell_ = {std::max(extent.x / dims_[0], 1e-300), std::max(extent.y / dims_[1], 1e-300),
           std::max(extent.z / dims_[2], 1e-300)};
  const std::size_t cells = static_cast<std::size_t>(dims_[0]) * dims_[1] * dims_[2];
  start_.assign(cells + 1, 0);
  auto for_cells = [&](const Bounds3& b, auto&& f) {
    for (int z = cell_of(b.min.z, 2); z <= cell_of(b.max.z, 2); ++z)
      for (int y = cell_of(b.min.y, 1); y <= cell_of(b.max.y, 1); ++y)
        for (int x = cell_of(b.min.x, 0); x <= cell_of(b.max.x, 0); ++x)
          f((static_cast<std::size_t>(z) * dims_[1] + y) * dims_[0] + x);
  };
  for (const Bounds3& b : boxes_) {
    if (!b.empty()) for_cells(b, [&](std::size_t c) { ++start_[c + 1]; });
  }
  for (std::size_t c = 0; c < cells; ++c) start_[c + 1] += start_[c];
  items_.resize(start_[cells]);
  std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
  for (std::size_t i = 0; i < boxes_.size(); ++i) {
    if (boxes_[i].empty()) continue;
    for_cells(boxes_[i], [&](std::size_t c) { items_[fill[c]++] = static_cast<std::uint32_t>(i); });
  }
}

int BoxGrid::cell_of(double value, int axis) const {
  const double t = (value - component(all_.min, axis)) / component(cell_, axis);
  if (!(t > 0)) return 0;  // also NaN
  if (t >= dims_[axis] - 1) return dims_[axis] - 1;
  return static_cast<int>(t);
}

}  // namespace insula::kernel::detail
