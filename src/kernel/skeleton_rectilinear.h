// The straight skeleton of a rectilinear polygon (every edge horizontal or vertical, holes
// allowed), computed without CGAL. Used by interior_straight_skeleton (skeleton.h) for the
// axis-parallel outlines the building generators make (L, U, T, H parts, unions of rectangles):
// CGAL's general builder falls back to exact arithmetic on their many simultaneous events and takes
// ~0.5 ms on a 12-vertex H (bench/roof_bench.cc), a third of a whole generated building (paper 000,
// §4.7).
#pragma once

#include <optional>

#include "kernel/polygon.h"
#include "kernel/skeleton.h"

namespace insula::kernel {

// True when every edge of every ring is exactly horizontal or vertical.
bool is_rectilinear(const Polygon& polygon);

// The interior straight skeleton of a simple rectilinear polygon (normalized orientation, already
// accepted by is_simple_polygon), with the invariants documented in skeleton.h. Returns nullopt
// when the polygon is not rectilinear or when the result fails its own checks (faces tile the
// polygon, every face vertex lies at its time above the face's edge line); the caller then uses
// the general builder.
std::optional<Skeleton> rectilinear_straight_skeleton(const Polygon& polygon);

}  // namespace insula::kernel
