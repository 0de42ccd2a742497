#include "shape/ops_fast.h"

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
