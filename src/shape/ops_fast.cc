#include "shape/ops_fast.h"

#include <algorithm>
#include <cmath>

namespace insula::shape {

using kernel::FaceTag;
using kernel::SemanticClass;
using kernel::Vec3;

namespace {

constexpr double kMinPiece = 1e-9;  // meters: as resolve_sizes

}  // namespace

FaceTag cut_face_tag(Axis axis, bool faces_up) {
  if (axis != Axis::kY) return {SemanticClass::kInteriorWallSurface, 0, 0};
  return {faces_up ? SemanticClass::kCeilingSurface : SemanticClass::kFloorSurface, 0, 0};
}

Scope split_piece_scope(const Scope& parent, Axis axis, const Piece& piece) {
  Vec3 offset;
  set_component(offset, axis, piece.start);
  Vec3 size = parent.size;
  set_component(size, axis, piece.size);
  return parent.sub(offset, size);
}

std::array<FaceTag, 6> split_box_tags(const std::array<FaceTag, 6>& tags, Axis axis,
                                      const Piece& piece, double total) {
  const auto a = static_cast<std::size_t>(axis);
  std::array<FaceTag, 6> t = tags;
  if (piece.start > kMinPiece) t[2 * a] = cut_face_tag(axis, false);
  if (piece.start + piece.size < total - kMinPiece) t[2 * a + 1] = cut_face_tag(axis, true);
  return t;
}

kernel::Polygon rectangle_outline(double w, double h) {
  return {{{0, 0}, {w, 0}, {w, h}, {0, h}}, {}};
}

std::optional<kernel::Bounds2> as_rectangle(const kernel::Polygon& outline) {
  if (!outline.holes.empty() || outline.outer.size() != 4) return std::nullopt;
  const kernel::Ring& r = outline.outer;
  const bool x_first = r[0].y == r[1].y && r[1].x == r[2].x && r[2].y == r[3].y && r[3].x == r[0].x;
  const bool y_first = r[0].x == r[1].x && r[1].y == r[2].y && r[2].x == r[3].x && r[3].y == r[0].y;
  if (!x_first && !y_first) return std::nullopt;
  const kernel::Bounds2 box = kernel::bounds(outline);
  if (!(box.max.x > box.min.x && box.max.y > box.min.y)) return std::nullopt;
  return box;
}

bool is_rectangle_inset(const kernel::Bounds2& box, double distance) {
  return distance < 0 && -2 * distance < std::min(box.max.x - box.min.x, box.max.y - box.min.y);
}

namespace {

kernel::Ring rectangle_ring(kernel::Vec2 min, kernel::Vec2 max) {
  return {min, {max.x, min.y}, max, {min.x, max.y}};
}

}  // namespace

kernel::Polygon rectangle_inset_piece(const kernel::Bounds2& box, double depth,
                                      std::uint32_t piece) {
  const kernel::Vec2 inner_min = box.min + kernel::Vec2{depth, depth};
  const kernel::Vec2 inner_max = box.max - kernel::Vec2{depth, depth};
  if (piece == 0) return {rectangle_ring(inner_min, inner_max), {}};
  kernel::Ring hole = rectangle_ring(inner_min, inner_max);
  std::reverse(hole.begin(), hole.end());  // holes run clockwise
  return {rectangle_ring(box.min, box.max), {std::move(hole)}};
}

FlatRegion flat_region(kernel::Polygon region) {
  const kernel::Bounds2 b = kernel::bounds(region);
  for (kernel::Vec2& p : region.outer) p -= b.min;
  for (auto& hole : region.holes) {
    for (kernel::Vec2& p : hole) p -= b.min;
  }
  return {{b.min.x, b.min.y, 0}, {b.max.x - b.min.x, b.max.y - b.min.y, 0}, std::move(region)};
}

std::size_t repeat_count(double total, double size, std::string& error) {
  if (!(size > 0) || !std::isfinite(size)) {
    error = "size must be > 0";
    return 0;
  }
  const double count = std::max(1.0, std::floor(total / size + 1e-9));
  if (!(count <= 1e6)) {
    error = "more than 1000000 pieces";
    return 0;
  }
  return static_cast<std::size_t>(count);
}

}  // namespace insula::shape
