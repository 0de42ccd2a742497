// Splitting a polygon mesh by a plane into the part on the negative side and the part on the
// positive side (used by the CGA split of non-box shapes and by cutaways).
//
// Method: every face is cut along its line of intersection with the plane (the classic
// polygon-by-line split: the boundary runs on each side are joined by chords along that line, so
// non-convex faces give several pieces); cut points are shared by the faces around an edge. Each
// part's open boundary then lies in the plane; with capping, its edges are chained into loops,
// loops are classified as outer (counter-clockwise seen from outside the part) or hole, holes are
// assigned to the smallest enclosing outer loop, and each region becomes one cap face, or
// triangles sharing one face id when it has holes (mesh.h). Faces lying in the plane go to the
// part they bound (the negative part when they face along the normal).
//
// Invariants: pieces keep their face's tag (semantic class, material, face id); both parts share
// no vertices with each other and each part's faces share vertex indices, so a closed input
// gives closed parts (kernel::check) whose volumes add up to the input's.
#pragma once

#include <span>
#include <string_view>
#include <vector>

#include "kernel/mesh.h"
#include "kernel/vec.h"

namespace insula::kernel {

// The plane dot(normal, p) = offset. `normal` need not be unit length (it is normalised; the
// offset is scaled with it) but must be finite and non-zero.
struct Plane {
  Vec3 normal{0, 0, 1};
  double offset = 0;
};

struct SplitOptions {
  // Close the cut cross-section with cap faces (for closed input). Without capping an open mesh is
  // cut into two open meshes.
  bool cap = true;
  FaceTag cap_tag{};  // tag of every cap face, e.g. {kClosureSurface, 0, next free face id}
  // Vertices closer than this to the plane (meters) count as lying on it.
  double tolerance = 1e-7;
};

enum class SplitStatus {
  kOk,
  kInvalidPlane,            // zero or non-finite normal or offset
  kNonFiniteInput,          // a vertex coordinate is NaN or infinite
  kOpenCut,                 // capping: the cut edges did not close into loops (input not closed)
  kCapTriangulationFailed,  // a cap region with holes could not be triangulated
  kInvalidPositions,        // split_into_slabs: positions not finite or not ascending
};

std::string_view split_status_message(SplitStatus status);

struct SplitResult {
  SplitStatus status = SplitStatus::kOk;
  Mesh negative;  // the part with dot(normal, p) <= offset; empty when nothing lies there
  Mesh positive;  // the part with dot(normal, p) >= offset
  std::size_t cap_loops = 0;  // loops found in the cross-section (outer and holes, both parts)
  bool ok() const { return status == SplitStatus::kOk; }
};

// Splits `mesh` by `plane`. Capping needs faces that share vertex indices along their edges
// (kernel::weld() a polygon soup first); otherwise the cut edges do not chain and kOpenCut is
// reported. On kOpenCut or kCapTriangulationFailed the parts are still returned,
// cut but with the failing caps left out (so they are open); on the other errors both are empty.
SplitResult split(const Mesh& mesh, const Plane& plane, const SplitOptions& options = {});

struct SlabResult {
  SplitStatus status = SplitStatus::kOk;
  // positions.size() + 1 pieces: below positions[0], between consecutive positions, above the
  // last. A piece is an empty mesh when the solid has nothing in that range.
  std::vector<Mesh> pieces;
  bool ok() const { return status == SplitStatus::kOk; }
};

// Cuts `mesh` by the planes dot(normalize(direction), p) = positions[i]; `positions` must be
// finite and non-decreasing (equal positions give empty slabs). Used for splits along a scope
// axis: with direction = scope axis and positions = origin . axis + cumulative sizes.
SlabResult split_into_slabs(const Mesh& mesh, Vec3 direction, std::span<const double> positions,
                            const SplitOptions& options = {});

}  // namespace insula::kernel
