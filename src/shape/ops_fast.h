// Tree-free cores of split and repeat (seed 004, "Basic Split Rule" and "Repeat Rule"), shared by
// shape::split / shape::repeat (ops_split.cc) and by interpreters that derive without a ShapeTree
// (the CGA derivation engine keeps compact records instead of Shapes, docs/cga-derivation.md).
// Given the same inputs, both paths produce bit-identical scopes, pieces and box face tags, because
// both call these functions.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "kernel/mesh.h"
#include "kernel/polygon.h"
#include "shape/ops.h"
#include "shape/scope.h"

namespace insula::shape {

// resolve_sizes (ops.h) into a caller's buffer (cleared first), so a hot loop reuses one
// allocation; resolve_sizes itself calls this.
void resolve_sizes_into(double total, std::span<const SizeSpec> sizes, std::vector<Piece>& out);

// The scope of split piece `piece` of `parent` along `axis`: the parent's frame moved to the
// piece's start, with the piece's extent on `axis` and the parent's on the other two.
Scope split_piece_scope(const Scope& parent, Axis axis, const Piece& piece);

// The tag of a face made by a cut, seen from the piece it bounds: floors and ceilings for
// horizontal cuts (scope y is up), interior walls otherwise.
kernel::FaceTag cut_face_tag(Axis axis, bool faces_up);

// The face tags of split piece `piece` of a box of extent `total` along `axis` whose sides carry
// `tags` (order of box_mesh: -x, +x, -y, +y, -z, +z): outer sides keep theirs, sides made by a cut
// become floors/ceilings (y cuts) or interior walls.
std::array<kernel::FaceTag, 6> split_box_tags(const std::array<kernel::FaceTag, 6>& tags, Axis axis,
                                              const Piece& piece, double total);

// The rectangle [0, w] x [0, h] as an outline (counter-clockwise from the origin): the outline of a
// split piece of a rectangular flat shape.
kernel::Polygon rectangle_outline(double w, double h);

// ---- offset of an axis-aligned rectangle (shape::offset's inset without Clipper; the CGA engine
// calls these too, so windows inset either way are the same to the bit)

// An axis-aligned rectangle without holes (as split() leaves façade tiles and windows): its box.
std::optional<kernel::Bounds2> as_rectangle(const kernel::Polygon& outline);

// Whether offset(distance) of the rectangle `box` is an inset these cores cut: distance < 0 and
// less than half the shorter side.
bool is_rectangle_inset(const kernel::Bounds2& box, double distance);

// Piece `piece` of insetting the rectangle `box` by `depth` (> 0), in the shape's outline
// coordinates: 0 the smaller rectangle, 1 the frame around it (the rectangle with a hole), as the
// Clipper offset and subtraction would give them.
kernel::Polygon rectangle_inset_piece(const kernel::Bounds2& box, double depth,
                                      std::uint32_t piece);

// A flat region of a shape as a shape of its own: its scope is the parent's moved by `offset`
// (parent scope coordinates) with extent `size`, fitted to the region's bounds, and `outline` is
// the region in that scope.
struct FlatRegion {
  kernel::Vec3 offset;
  kernel::Vec3 size;
  kernel::Polygon outline;
};
FlatRegion flat_region(kernel::Polygon region);

// Number of pieces of a repeat of about `size` meters over `total`: max(1, floor(total / size)).
// Returns 0 with `error` set when size is not > 0 and finite, or the count exceeds 1,000,000.
std::size_t repeat_count(double total, double size, std::string& error);

}  // namespace insula::shape
