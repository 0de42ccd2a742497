// Private to wall*.cc: the types the stages of build_wall hand one another (wall.h,
// docs/kernel-walls.md). Stages: validation (wall_validate.cc), boundary rings and the monotone
// partition (wall_partition.cc), the plain-wall shortcut (wall_plain.cc), mesh emission
// (wall_emit.cc); wall.cc runs them. Not part of the kernel's API.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "kernel/mesh.h"
#include "kernel/polygon.h"
#include "kernel/vec.h"
#include "kernel/wall.h"

namespace insula::kernel::wall_detail {

// Absolute tolerance in meters: distances at or below it count as touching.
inline constexpr double kEps = 1e-9;

// ---------------------------------------------------------------------------------------------
// Validation (wall_validate.cc).

// An opening that passed validation, with its ring.
struct Accepted {
  std::size_t index = 0;
  Opening opening;  // with the sill snapped onto the host edge for notches
  Ring ring;        // clockwise; for a notch the last edge (the sill) lies on the host edge
  Bounds2 box;
  int host = -1;  // outline edge a notch opens through, or -1 for a hole
};

// Why the wall itself (thickness, margin, outline) is unusable, or empty. `outline_area` is
// signed_area(spec.outline).
std::string wall_problem(const WallSpec& spec, double outline_area);
// Why an opening's parameters are unusable, or empty.
std::string parameter_problem(const Opening& opening);
// The outline counter-clockwise: `ring` itself when it is (no copy), else its reverse, written
// into `scratch`.
const Ring& counter_clockwise(const Ring& ring, double area, Ring& scratch);
// Greedy validation in input order against the outline (counter-clockwise) and the earlier
// accepted openings, which are appended to `accepted`. `spare` (optional) holds rings of an
// earlier wall whose storage the accepted openings take over.
std::vector<OpeningIssue> validate(const Ring& outline, const WallSpec& spec,
                                   std::vector<Accepted>& accepted,
                                   std::vector<Ring>* spare = nullptr);

// ---------------------------------------------------------------------------------------------
// Boundary rings: every vertex starts one directed edge with the wall's material on its left.

// emit_into indexes its tag table by this order (top, bottom, end, jamb, sill, lintel).
enum class EdgeKind : std::uint8_t { kTop, kBottom, kEnd, kJamb, kSill, kLintel };

struct Boundary {
  std::vector<Vec2> points;
  std::vector<std::uint32_t> next;
  std::vector<std::uint32_t> prev;
  std::vector<EdgeKind> kind;         // of the edge leaving each vertex
  std::vector<std::int32_t> opening;  // opening of that edge, or -1 for the rim
  std::uint32_t ring_start = 0;

  // Empties every array, keeping its storage for the next wall (WallWorkspace).
  void clear() {
    points.clear();
    next.clear();
    prev.clear();
    kind.clear();
    opening.clear();
    ring_start = 0;
  }

  void add(Vec2 p, EdgeKind k, std::int32_t o) {
    points.push_back(p);
    kind.push_back(k);
    opening.push_back(o);
  }
  // Links the vertices added since the last close() into a ring.
  void close() {
    const auto n = static_cast<std::uint32_t>(points.size());
    for (std::uint32_t i = ring_start; i < n; ++i) {
      next.push_back(i + 1 < n ? i + 1 : ring_start);
      prev.push_back(i > ring_start ? i - 1 : n - 1);
    }
    ring_start = n;
  }
};

// ---------------------------------------------------------------------------------------------
// Partition (wall_partition.cc).

// The boundary of the wall's front face: the outline with door notches spliced in, then one
// clockwise ring per hole. `notches` is scratch storage (its contents are replaced).
void build_boundary(const Ring& outline, const std::vector<Accepted>& cut, Boundary& out,
                    std::vector<const Accepted*>& notches);

// The sweep's and the walk's arrays, kept from wall to wall (WallWorkspace).
struct PartitionScratch;
struct PartitionScratchDeleter {
  void operator()(PartitionScratch* scratch) const;
};
using PartitionScratchPtr = std::unique_ptr<PartitionScratch, PartitionScratchDeleter>;
PartitionScratchPtr make_partition_scratch();

// Cuts the region of `b` into u-monotone hole-free pieces with diagonals between its vertices and
// appends each piece as a vertex loop to `loops` (piece f is loops[offsets[f], offsets[f + 1]);
// `offsets` holds its leading 0). False when a guard fails (the pieces do not close).
bool partition(const Boundary& b, PartitionScratch& scratch, std::vector<std::uint32_t>& loops,
               std::vector<std::uint32_t>& offsets);

// ---------------------------------------------------------------------------------------------
// The plain-wall shortcut (wall_plain.cc).

struct PlainOpening {
  double u0;
  double u1;
  std::uint32_t index;  // into WallSpec::openings
};

// The openings of a plain wall in `sorted`, ordered by u; false when the wall is not plain.
// `ccw` is the validated outline, counter-clockwise.
bool plain_wall(const Ring& ccw, const WallSpec& spec, std::vector<PlainOpening>& sorted);
// build_boundary's rings for a plain wall.
void plain_boundary(const Ring& ccw, const WallSpec& spec, Boundary& b);
// partition's loops for a plain wall.
void plain_loops(const std::vector<PlainOpening>& sorted, std::vector<std::uint32_t>& loops,
                 std::vector<std::uint32_t>& offsets);

// ---------------------------------------------------------------------------------------------
// Emission (wall_emit.cc).

// Writes the wall's faces into `mesh` after whatever it already holds (vertex indices shifted by
// its vertex count): front pieces, back pieces, then one quad per boundary edge.
void emit(const Boundary& b, const std::vector<std::uint32_t>& loops,
          const std::vector<std::uint32_t>& offsets, const WallSpec& spec, const WallFrame& frame,
          Mesh& mesh);

}  // namespace insula::kernel::wall_detail
