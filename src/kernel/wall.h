// Walls with openings: a planar outline in the wall plane times a thickness, with rectangular and
// arched openings (windows, doors) cut through it, as one closed, outward-oriented mesh without
// T-junctions. A planar algorithm, not a 3D boolean: the front face (outline minus openings) is
// partitioned into u-monotone hole-free pieces with diagonals between existing vertices (de Berg et
// al., "Computational Geometry", 3rd ed., section 3.2, MakeMonotone), mirrored for the back face,
// and closed with one quad per boundary edge (rim, jamb, sill, lintel). docs/kernel-walls.md.
//
// Wall coordinates: u along the wall, v up, w through the wall; the slab occupies w in [0, t].
// The front face lies at w = t (outward normal +w, seen with u to the right and v up), the back
// face at w = 0. A WallFrame maps (u, v, w) to world space.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "kernel/mesh.h"
#include "kernel/polygon.h"
#include "kernel/vec.h"

namespace insula::kernel {

// One opening, in wall coordinates (meters). The opening is the rectangle
// [u, u + width] x [sill, sill + height - arch_rise] topped, when arch_rise > 0, by a circular arch
// through both springing points and the apex (u + width / 2, sill + height): segmental for
// 0 < arch_rise < width / 2, semicircular for arch_rise = width / 2. The arch is approximated by
// arch_segments straight segments (1..1024). An opening whose sill lies on a horizontal bottom edge
// of the outline (a door at v = 0) becomes a notch in that edge instead of a hole.
struct Opening {
  double u = 0;
  double sill = 0;
  double width = 0;
  double height = 0;  // sill to the highest point (the apex for arches); > arch_rise
  double arch_rise = 0;
  int arch_segments = 8;
};

// Tags for each kind of face; the caller chooses semantic class, material and face id per side.
// Every front piece carries `front` (so the pieces of the front face share one face id), and so on.
struct WallFaceTags {
  FaceTag front{SemanticClass::kWallSurface};
  FaceTag back{SemanticClass::kInteriorWallSurface};
  FaceTag jamb{SemanticClass::kJamb};              // vertical reveals of an opening
  FaceTag sill{SemanticClass::kSill};              // bottom reveal (absent for a door notch)
  FaceTag lintel{SemanticClass::kLintel};          // top reveal; the soffit pieces of an arch
  FaceTag top{SemanticClass::kClosureSurface};     // rim faces whose outward normal points up
  FaceTag bottom{SemanticClass::kClosureSurface};  // rim faces whose outward normal points down
  FaceTag end{SemanticClass::kClosureSurface};     // vertical rim faces (the wall's ends)
};

// What to do with an opening that fails validation.
enum class OpeningPolicy {
  kFail,  // no mesh; every problem is reported
  kSkip,  // build the wall without the rejected openings and report them
};

struct WallSpec {
  Ring outline;  // simple polygon in (u, v), either orientation, no repeated vertices
  double thickness = 0.3;
  std::vector<Opening> openings;
  // Least distance (m) between an opening and the outline or another opening. Openings that touch
  // are rejected even with a zero margin: they would leave a zero-width pier.
  double min_margin = 0.05;
  OpeningPolicy policy = OpeningPolicy::kFail;
  WallFaceTags tags;
};

// Maps wall coordinates to world: p = origin + u_axis * u + v_axis * v + normal * w. The axes
// should be orthonormal; a left-handed frame is allowed (faces are flipped to stay outward).
struct WallFrame {
  Vec3 origin;
  Vec3 u_axis{1, 0, 0};
  Vec3 v_axis{0, 1, 0};
  Vec3 normal{0, 0, 1};

  Vec3 map(double u, double v, double w) const {
    return origin + u_axis * u + v_axis * v + normal * w;
  }
};

enum class OpeningProblem {
  kBadParameters,    // non-finite, non-positive size, arch rise or segment count out of range
  kOutsideOutline,   // extends beyond the wall outline
  kTouchesOutline,   // boundary meets the outline (and the opening is not a door notch)
  kNearOutline,      // closer to the outline than min_margin
  kOverlapsOpening,  // interiors overlap an earlier accepted opening
  kTouchesOpening,   // boundaries meet an earlier accepted opening
  kNearOpening,      // closer to an earlier accepted opening than min_margin
};

struct OpeningIssue {
  std::size_t opening = 0;  // index into WallSpec::openings
  OpeningProblem problem = OpeningProblem::kBadParameters;
  std::optional<std::size_t> other;  // the earlier opening involved, if any
  std::string message;               // e.g. "opening 3 overlaps opening 1"
};

enum class WallStatus {
  kOk,
  kInvalidWall,          // outline, thickness or margin unusable; see message
  kRejectedOpening,      // policy kFail and at least one issue
  kDecompositionFailed,  // internal guard: the planar partition did not close (report a bug)
};

struct WallResult {
  WallStatus status = WallStatus::kOk;
  std::string message;  // empty when ok; otherwise why (the first issue for kRejectedOpening)
  Mesh mesh;
  std::vector<OpeningIssue> issues;        // every rejected opening (also when skipped)
  std::vector<std::size_t> cut;            // indices of the openings cut, in input order
  std::vector<std::int32_t> face_opening;  // per mesh face: index of its opening, or -1
  std::size_t front_pieces = 0;            // hole-free pieces of the front face (same on the back)

  bool ok() const { return status == WallStatus::kOk; }
};

// Builds the wall. Cost is O(n log n) in the number of boundary vertices n plus the validation,
// which compares only openings whose margin-expanded bounding boxes overlap. Never throws.
WallResult build_wall(const WallSpec& spec, const WallFrame& frame = {});

// The same wall appended straight into `out` (after the vertices and faces it already holds; the
// same faces in the same order as build_wall's mesh appended with Mesh::append), so that a caller
// building many walls into one mesh allocates and copies no mesh per wall. The result's mesh and
// face_opening stay empty; status, message, issues, cut and front_pieces are as build_wall's.
// Nothing is appended unless the result is ok.
WallResult build_wall(const WallSpec& spec, const WallFrame& frame, Mesh& out);

// Scratch memory for building many walls: the boundary rings, the sweep's arrays and the pieces of
// one wall are kept here and reused by the next, so a caller building a storey's walls allocates
// them once instead of per wall. Also holds the last result (see the overload below). One
// workspace per thread; it may be moved but not copied.
class WallWorkspace {
 public:
  WallWorkspace();
  ~WallWorkspace();
  WallWorkspace(WallWorkspace&&) noexcept;
  WallWorkspace& operator=(WallWorkspace&&) noexcept;

  struct Buffers;  // defined in wall.cc
  Buffers& buffers() { return *buffers_; }

 private:
  std::unique_ptr<Buffers> buffers_;
};

// build_wall appending into `out` (the overload above, same faces, same result fields) with its
// intermediate arrays taken from `workspace`. The result is stored in the workspace and stays valid
// until the next call with the same workspace; its mesh and face_opening stay empty.
const WallResult& build_wall(const WallSpec& spec, const WallFrame& frame, Mesh& out,
                             WallWorkspace& workspace);

// Validation alone (what build_wall reports), for front-ends testing whether an opening fits.
// Openings are checked in input order against the outline and the earlier accepted ones.
// Returns the issues and, in `accepted`, the indices of the openings that pass. Outline problems
// are not reported here (build_wall reports them as kInvalidWall).
std::vector<OpeningIssue> check_openings(const WallSpec& spec,
                                         std::vector<std::size_t>* accepted = nullptr);

// The opening's boundary in wall coordinates, clockwise (as a hole): bottom-left, left jamb up, the
// top (arch points left to right), right jamb down. Empty for bad parameters.
Ring opening_ring(const Opening& opening);
// Area of opening_ring (the polygonal arch, i.e. what build_wall actually removes), m^2.
double opening_area(const Opening& opening);

// Where a wall goes along a footprint edge.
enum class WallAlignment {
  kInside,   // the wall lies left of base_start -> base_end (inside a counter-clockwise footprint);
             // its front face (w = t) is on the segment
  kCenter,   // the segment is the wall's center line
  kOutside,  // the back face (w = 0) is on the segment; the wall lies right of it
};

struct WallPlacement {
  WallFrame frame;  // u along the segment (horizontal), v = +Z, normal = u x v (right of the edge)
  Ring outline;     // the rectangle [0, length] x [0, height]
  double length = 0;
  double height = 0;
  double thickness = 0;
};

// Frame and rectangular outline for a wall standing on the ground segment base_start -> base_end
// (world, Z up). The base is the horizontal projection of the segment at base_start's height.
// nullopt when the segment's horizontal length is below 1e-9 m or any input is non-finite or
// height/thickness is not positive.
std::optional<WallPlacement> place_wall(Vec3 base_start, Vec3 base_end, double height,
                                        double thickness,
                                        WallAlignment alignment = WallAlignment::kInside);

// place_wall's frame alone, without the outline ring (nothing allocated), for callers that build
// their own outline, e.g. wall after wall of a storey. nullopt in the same cases as place_wall.
std::optional<WallFrame> place_wall_frame(Vec3 base_start, Vec3 base_end, double height,
                                          double thickness,
                                          WallAlignment alignment = WallAlignment::kInside);

}  // namespace insula::kernel
