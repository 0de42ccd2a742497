// Convex hulls of point sets.
//  - 2D: Andrew's monotone chain (A. M. Andrew, "Another efficient algorithm for convex hulls in
//    two dimensions", Inf. Proc. Letters 9, 1979), O(n log n).
//  - 3D: incremental hull with conflict lists in the manner of Quickhull (Barber, Dobkin,
//    Huhdanpaa, "The Quickhull algorithm for convex hulls", ACM TOMS 22, 1996): each pending
//    point belongs to one face it lies in front of; the farthest point of a face is added by
//    removing the faces it sees and coning the horizon to it. A point counts as in front of a face
//    only when farther than the tolerance, so near-coplanar points never create slivers of
//    inverted orientation; the result is closed and convex within the tolerance.
// Degenerate input (too few points, all collinear, all coplanar, non-finite) gives a status and
// an empty result, never a crash.
#pragma once

#include <optional>
#include <span>
#include <string_view>

#include "kernel/mesh.h"
#include "kernel/polygon.h"
#include "kernel/vec.h"

namespace insula::kernel {

enum class HullStatus {
  kOk,
  kTooFewPoints,      // fewer than 3 (2D) or 4 (3D) distinct points
  kCollinear,         // all points on one line
  kCoplanar,          // 3D: all points in one plane (use the 2D hull in that plane)
  kNonFinite,         // a coordinate is NaN or infinite
  kNumericalFailure,  // 3D: the horizon of a point was not a simple loop (should not happen)
};

std::string_view hull_status_message(HullStatus status);

struct Hull2Result {
  HullStatus status = HullStatus::kOk;
  Ring ring;  // counter-clockwise, no collinear or repeated vertices; empty unless ok()
  bool ok() const { return status == HullStatus::kOk; }
};

// The convex hull of `points` (any order, duplicates allowed), starting at the lowest-x
// (then lowest-y) point.
Hull2Result convex_hull_2d(std::span<const Vec2> points);

// The direction of the longer side of the minimum-area rectangle around `points`: one side of
// that rectangle lies on a hull edge (H. Freeman and R. Shapira, "Determining the minimum-area
// encasing rectangle for an arbitrary closed curve", CACM 18(7), 1975), so each hull edge is
// tried. Null for points with no area or length.
std::optional<Vec2> min_area_rectangle_direction(std::span<const Vec2> points);

struct HullOptions {
  // Merge coplanar neighbouring triangles into one convex polygon face (6 faces for a cube, not
  // 12).
  bool merge_coplanar = true;
  // Tag of every face; face k gets face id tag.face_id + k.
  FaceTag tag{};
  // Distance (meters) within which a point counts as on a face's plane; 0 picks 1e-10 times the
  // extent plus the largest absolute coordinate of the input.
  double tolerance = 0;
};

struct Hull3Result {
  HullStatus status = HullStatus::kOk;
  Mesh mesh;  // closed, outward, vertices shared; only hull vertices are kept
  bool ok() const { return status == HullStatus::kOk; }
};

Hull3Result convex_hull_3d(std::span<const Vec3> points, const HullOptions& options = {});

}  // namespace insula::kernel
