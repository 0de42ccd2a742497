// Planar helpers of the floor-plan engine (floorplan.h): areas cut by an axis-parallel line (the
// treemap's Eqs. 3-5 need them thousands of times, so they avoid a full polygon boolean), shared
// boundaries between cells, ring simplification and wall counting. Booleans themselves come from
// kernel/boolean2d.h.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "kernel/polygon.h"
#include "kernel/vec.h"

namespace insula::lang::bldg::plan {

// Cells are snapped to the boolean grid (1e-6 m); boundaries closer than this are the same line.
inline constexpr double kLineTolerance = 1e-5;

// Area of the part of `region` with coordinate (x when along_x, else y) <= t. Rings are clipped
// to the half-plane (Sutherland-Hodgman); the signed areas of the clipped rings are exact even for
// concave rings and holes, because the degenerate edges the clipper leaves on the line cancel.
double area_below(const std::vector<kernel::Polygon>& region, bool along_x, double t);
double area_of(const std::vector<kernel::Polygon>& region);

namespace detail {
// Twice the signed area of `ring` clipped to coord <= t (Sutherland-Hodgman against one line),
// the axis fixed at compile time: the treemap's cut search evaluates it thousands of times, so it
// is inline here, for the search's loop.
template <bool kAlongX>
inline double clipped_twice_area(const kernel::Ring& ring, double t) {
  const std::size_t n = ring.size();
  if (n < 3) return 0;
  auto coord = [](kernel::Vec2 p) { return kAlongX ? p.x : p.y; };
  const kernel::Vec2 origin = ring[0];
  double twice = 0;
  bool have_first = false;
  kernel::Vec2 first;
  kernel::Vec2 last;
  auto emit = [&](kernel::Vec2 p) {
    p = p - origin;
    if (!have_first) {
      first = p;
      have_first = true;
    } else {
      twice += kernel::cross(last, p);
    }
    last = p;
  };
  kernel::Vec2 p = ring[0];
  double cp = coord(p) - t;
  for (std::size_t i = 0; i < n; ++i) {
    const kernel::Vec2 q = ring[i + 1 < n ? i + 1 : 0];
    const double cq = coord(q) - t;
    if (cp <= 0) emit(p);
    if ((cp < 0 && cq > 0) || (cp > 0 && cq < 0)) emit(p + (q - p) * (cp / (cp - cq)));
    p = q;
    cp = cq;
  }
  if (have_first) twice += kernel::cross(last, first);
  return twice;
}

}  // namespace detail

// area_below with the axis fixed at compile time (x when kAlongX); the same value.
template <bool kAlongX>
inline double area_below_axis(const std::vector<kernel::Polygon>& region, double t) {
  double twice = 0;
  for (const kernel::Polygon& p : region) {
    twice += detail::clipped_twice_area<kAlongX>(p.outer, t);
    for (const kernel::Ring& h : p.holes) twice += detail::clipped_twice_area<kAlongX>(h, t);
  }
  return twice / 2;
}

// The box of the outer rings of `region`.
kernel::Bounds2 bounds_of(const std::vector<kernel::Polygon>& region);

// Axis-parallel rectangle [x0, x1] x [y0, y1], counter-clockwise.
kernel::Polygon rectangle(double x0, double y0, double x1, double y1);
// Rectangle spanning `from` + `along` x [0, length], offset by `inward` x [0, depth].
kernel::Polygon oriented_rectangle(kernel::Vec2 from, kernel::Vec2 along, kernel::Vec2 inward,
                                   double length, double depth);

// Removes repeated and collinear vertices (within kLineTolerance) from every ring.
void simplify(kernel::Polygon& polygon);
// Edges of the outer ring once collinear vertices are merged (the room's "walls", §3.4).
int wall_count(const kernel::Polygon& polygon);

// kernel::length(d) bit for bit, without std::hypot's call when d is axis-parallel (most walls):
// hypot(x, +-0) is |x| exactly (C11 F.10.4.3), and likewise hypot(+-0, y).
inline double edge_length(kernel::Vec2 d) {
  if (d.y == 0) return std::abs(d.x);
  if (d.x == 0) return std::abs(d.y);
  return kernel::length(d);
}

// A piece of an edge of `cell`, oriented as the edge (the cell lies on its left), and the index
// (into the `others` list) of the polygon on its right, or -1 when none is.
struct EdgePiece {
  kernel::Vec2 a;
  kernel::Vec2 b;
  int other = -1;
  double length() const { return edge_length(b - a); }
};

// Splits every edge of `cell` (outer ring and holes) into pieces by which of `others` lies on the
// other side (an edge of another polygon on the same line, running the other way). Pieces come
// in ring order. Null entries in `others` are skipped.
std::vector<EdgePiece> boundary_pieces(const kernel::Polygon& cell,
                                       const std::vector<const kernel::Polygon*>& others);
// The same with the bounds of `cell` and of every entry of `others` given (boxes[k] =
// kernel::bounds(*others[k]); unused for null entries), for callers that ask about every cell of a
// storey in turn and would otherwise recompute every box for every cell.
std::vector<EdgePiece> boundary_pieces(const kernel::Polygon& cell, const kernel::Bounds2& cell_box,
                                       const std::vector<const kernel::Polygon*>& others,
                                       const std::vector<kernel::Bounds2>& boxes);

// For every polygon of a list, the others whose boxes touch its own within `margin`
// (kernel::touches), in increasing index order: near[start[i] .. start[i + 1]) for polygon i.
// Found by a sweep over the boxes sorted by their left side, not by testing every pair.
struct NearLists {
  std::vector<std::uint32_t> start;
  std::vector<std::uint32_t> near;
  std::span<const std::uint32_t> of(std::size_t i) const {
    return {near.data() + start[i], near.data() + start[i + 1]};
  }
};
NearLists touching_boxes(const std::vector<kernel::Bounds2>& boxes, double margin);

// boundary_pieces with the candidates given: `near` lists, in increasing order, the indices into
// `others` whose boxes touch the cell's within kLineTolerance (touching_boxes(boxes,
// kLineTolerance).of(cell's own index) when `cell` is one of a list).
std::vector<EdgePiece> boundary_pieces(const kernel::Polygon& cell,
                                       const std::vector<const kernel::Polygon*>& others,
                                       const std::vector<kernel::Bounds2>& boxes,
                                       std::span<const std::uint32_t> near);

// The maximal straight segments of `cell`'s boundary shared with `other` (oriented as in `cell`).
std::vector<EdgePiece> shared_segments(const kernel::Polygon& cell, const kernel::Polygon& other);
double shared_length(const kernel::Polygon& cell, const kernel::Polygon& other);
// Length of the longest of shared_segments(cell, other), with both boxes given (kernel::bounds); 0
// when they share nothing. Allocates only for a pair whose boxes touch: probing asks it for every
// pair of neighbouring rooms.
double longest_shared_segment(const kernel::Polygon& cell, const kernel::Bounds2& cell_box,
                              const kernel::Polygon& other, const kernel::Bounds2& other_box);

// True when `inner` lies inside `outer` (area of inner minus outer below 1e-9 m²).
bool covers(const std::vector<kernel::Polygon>& outer, const kernel::Polygon& inner);
// True when the interiors of a and b overlap by more than 1e-9 m².
bool overlaps(const kernel::Polygon& a, const kernel::Polygon& b);

// Makes neighbouring cells agree exactly on their common boundaries. Each boolean operation
// rounds to a grid centred on its own inputs (kernel/boolean2d.h), so two cells cut in different
// calls may place the same line up to a micrometre apart. Vertices closer than `tolerance` are
// merged (the first one seen wins) and a vertex within `tolerance` of another cell's edge is moved
// onto it, then rings are simplified.
void weld(const std::vector<kernel::Polygon*>& cells, double tolerance = kLineTolerance);

// Interiors of two convex polygons (outer rings) overlap by more than a sliver (separating axes,
// 1e-9 m slack): the cheap test for stair and door rectangles.
bool convex_overlap(const kernel::Polygon& a, const kernel::Polygon& b);
// The convex ring `inner` lies inside `region` (its boundary may touch region's): every vertex of
// inner inside or on region, no vertex of region strictly inside inner, no proper crossing.
bool convex_inside(const kernel::Polygon& region, const kernel::Ring& inner);

// Index of the polygon of largest area; -1 when empty.
int largest(const std::vector<kernel::Polygon>& polygons);

}  // namespace insula::lang::bldg::plan
