// The interior straight skeleton of a polygon with holes (Aichholzer, Aurenhammer, Alberts,
// Gärtner, "A novel type of skeleton for polygons", J.UCS 1995), computed by CGAL 5.5's
// create_interior_straight_skeleton_2 and returned in plain types so no CGAL header leaks out.
//
// Invariants of a Skeleton built from polygon P (normalized: outer counter-clockwise, holes
// clockwise):
//  - vertices [0, contour_count) are P's vertices in ring order (outer ring, then each hole), with
//    time 0; the others are skeleton nodes with time > 0 = their distance to the supporting lines
//    of the edges whose faces meet there (the offset distance at which the wavefront reaches them).
//  - contour edge e runs from contour vertex e to the next vertex of the same ring; face(e) is the
//    loop of vertex ids bounding the region swept by edge e, counter-clockwise seen from above
//    (interior on the left), starting with edge e's two end points.
//  - every point of face(e) is at distance `time` from e's supporting line, so lifting each vertex
//    by time * tan(pitch) gives a planar roof face (the hip roof).
// Strictly convex polygons and rectilinear ones (skeleton_rectilinear.h) take direct wavefront
// simulations; the rest, and anything those decline, go to CGAL.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "kernel/polygon.h"
#include "kernel/vec.h"

namespace insula::kernel {

struct SkeletonVertex {
  Vec2 position;
  double time = 0;  // meters of inward offset; 0 for contour vertices
};

struct Skeleton {
  std::vector<SkeletonVertex> vertices;
  std::vector<std::uint32_t> face_indices;  // all face loops, concatenated
  std::vector<std::uint32_t> face_offsets;  // face e is [face_offsets[e], face_offsets[e + 1])
  std::vector<std::uint32_t> ring_starts;   // first contour vertex of each ring, then the total
  std::uint32_t contour_count = 0;

  std::size_t face_count() const { return face_offsets.empty() ? 0 : face_offsets.size() - 1; }
  std::span<const std::uint32_t> face(std::size_t edge) const {
    return {face_indices.data() + face_offsets[edge], face_offsets[edge + 1] - face_offsets[edge]};
  }
  // The contour vertex after `vertex` in its ring (the end point of edge `vertex`).
  std::uint32_t next_contour(std::uint32_t vertex) const;
  // The contour vertex before `vertex` in its ring (the start of the previous edge).
  std::uint32_t previous_contour(std::uint32_t vertex) const;
  // The largest vertex time (the height of the highest ridge point per unit slope).
  double max_time() const;
};

// Contour checks made before handing a polygon to CGAL, whose preconditions are not checked in
// release builds: every ring has >= 3 vertices, finite coordinates, no repeated consecutive vertex,
// the outer ring counter-clockwise, holes clockwise, and no two edges of any rings cross or touch
// except consecutive edges at their shared vertex. O(n^2) in the vertex count.
bool is_simple_polygon(const Polygon& polygon);

// The interior straight skeleton of `polygon` (normalized orientation, see polygon.h). Returns
// nullopt when the polygon is not simple (is_simple_polygon), has a coordinate beyond 1e100 in
// magnitude (CGAL's predicates would overflow and trap), or CGAL fails; never throws.
std::optional<Skeleton> interior_straight_skeleton(const Polygon& polygon);

// The same skeleton from CGAL's general builder alone, bypassing the convex and rectilinear
// wavefronts interior_straight_skeleton prefers: the reference the tests compare them with.
std::optional<Skeleton> general_straight_skeleton(const Polygon& polygon);

}  // namespace insula::kernel
