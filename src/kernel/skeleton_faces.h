// Faces of a straight skeleton from the arcs a wavefront traced (skeleton.h has the invariants):
// shared by the builders that simulate the wavefront themselves (skeleton_rectilinear.cc,
// skeleton_wavefront.cc).
#pragma once

#include <cstdint>
#include <vector>

#include "kernel/skeleton.h"

namespace insula::kernel {

// A skeleton arc from node `from` to node `to` (ids into Skeleton::vertices), traced by a
// wavefront vertex between the wavefront edges of contour edges `left` (before it) and `right`
// (after it): the faces of those two edges lie on its two sides.
struct SkeletonArc {
  std::uint32_t from, to, left, right;
};

// Fills out.face_indices and out.face_offsets: each face is its contour edge, then the arcs
// bordering it, chained from the edge's end back to its start. False when a face's arcs do not
// form one simple chain. Arcs from a node to itself are skipped.
bool assemble_skeleton_faces(const std::vector<SkeletonArc>& arcs, Skeleton& out);

}  // namespace insula::kernel
