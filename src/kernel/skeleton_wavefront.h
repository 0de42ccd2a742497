// The straight skeleton of a simple polygon of any shape (holes allowed), by a kinetic wavefront
// simulated in double precision (Aichholzer, Aurenhammer, Alberts, Gärtner 1995; events as in
// Felkel and Obdržálek 1998): an edge event where a wavefront edge shrinks to a point, a split
// event where a reflex vertex reaches another wavefront edge (splitting its cycle, or joining a
// hole's cycle to the one around it). Used by interior_straight_skeleton (skeleton.h) for the
// outlines that are neither strictly convex nor rectilinear, which are most real footprints:
// CGAL's general builder falls back to exact arithmetic on their nearly parallel and nearly
// simultaneous events and took 0.1 to 0.3 ms for a concave footprint of 5 to 12 vertices, half of
// `insula mass` on Utrecht's buildings (docs/PERFORMANCE.md, "Straight skeletons of real
// footprints").
#pragma once

#include <optional>

#include "kernel/polygon.h"
#include "kernel/skeleton.h"

namespace insula::kernel {

// The interior straight skeleton of a simple polygon (normalized orientation, already accepted by
// is_simple_polygon), with the invariants documented in skeleton.h. Returns nullopt when the
// polygon has more vertices than the direct simulation is for, or when the result fails its own
// checks (every face simple and counter-clockwise, the faces tiling the polygon, every face
// vertex at its time above the face's edge line); the caller then uses the general builder.
std::optional<Skeleton> wavefront_straight_skeleton(const Polygon& polygon);

}  // namespace insula::kernel
