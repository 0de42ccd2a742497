// Booleans of closed meshes (union, intersection, difference) by CGAL's Polygon Mesh Processing
// corefinement (CGAL translation unit #2, boolean3d.cc). For the cases that really need a 3D
// boolean; walls with openings, splits and roofs have planar algorithms of their own.
#pragma once

#include <cstdint>
#include <string>

#include "kernel/mesh.h"

namespace insula::kernel {

enum class BooleanOp : std::uint8_t { kUnion, kIntersection, kDifference };

enum class Boolean3dStatus : std::uint8_t {
  kOk,
  kNotClosed,         // an operand is not a closed, oriented 2-manifold after welding
  kSelfIntersecting,  // an operand intersects itself
  kNotAVolume,        // an operand does not bound a volume (e.g. inward oriented)
  kFailed,            // CGAL could not compute a manifold result
};

struct Boolean3dResult {
  Mesh mesh;  // triangles; empty unless kOk (an empty result of a valid operation is kOk too)
  Boolean3dStatus status = Boolean3dStatus::kFailed;
  std::string message;  // empty when kOk; names the operand ("first operand is not closed")
};

// `a` op `b` for closed, outward-oriented meshes (vertices within `weld_tolerance` meters are
// merged first, so faces need not share indices). Faces of the result are triangles; each carries
// the tag of the input face it lies on (found by plane and containment, see docs/kernel-roofs.md;
// faces of `b` inside `a` in a difference keep b's tag). Never throws.
Boolean3dResult boolean3d(const Mesh& a, const Mesh& b, BooleanOp op, double weld_tolerance = 1e-7);

}  // namespace insula::kernel
