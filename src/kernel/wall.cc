// Walls with openings (wall.h, docs/kernel-walls.md): validate the outline and the openings
// (wall_validate.cc), cut the front face into u-monotone pieces (wall_partition.cc, or
// wall_plain.cc for a plain wall), then emit front and back pieces and one side quad per boundary
// edge (wall_emit.cc). Because every piece boundary and every quad use only ring vertices, the mesh
// has no T-junctions and is closed on shared indices.
#include "kernel/wall.h"

#include <cmath>
#include <optional>
#include <utility>

#include "kernel/wall_detail.h"

namespace insula::kernel {

using wall_detail::Accepted;
using wall_detail::kEps;

// Everything one wall needs between validation and emission; reused from wall to wall.
struct WallWorkspace::Buffers {
  Ring outline;  // the spec's outline reversed, when it is clockwise
  std::vector<Accepted> cut;
  std::vector<Ring> spare_rings;  // the rings of `cut` between walls
  std::vector<const Accepted*> notches;
  wall_detail::Boundary boundary;
  wall_detail::PartitionScratchPtr partition = wall_detail::make_partition_scratch();
  std::vector<std::uint32_t> loops;              // the pieces' vertex loops, one after the other
  std::vector<std::uint32_t> offsets;            // piece f is loops[offsets[f], offsets[f + 1])
  std::vector<wall_detail::PlainOpening> plain;  // a plain wall's openings by u
  WallResult result;                             // of the last appending build_wall
};

WallWorkspace::WallWorkspace() : buffers_(std::make_unique<Buffers>()) {}
WallWorkspace::~WallWorkspace() = default;
WallWorkspace::WallWorkspace(WallWorkspace&&) noexcept = default;
WallWorkspace& WallWorkspace::operator=(WallWorkspace&&) noexcept = default;

namespace {

// Validation, boundary rings and the partition into pieces, left in `w` (boundary, loops,
// offsets). On failure `result` says why and nothing is left to emit. `result` is reset first, so
// a workspace's result can be reused.
bool partition_wall(const WallSpec& spec, WallWorkspace::Buffers& w, WallResult& result) {
  result.status = WallStatus::kOk;
  result.message.clear();
  result.issues.clear();
  result.cut.clear();
  result.face_opening.clear();
  result.front_pieces = 0;
  const double area = signed_area(spec.outline);
  if (std::string why = wall_detail::wall_problem(spec, area); !why.empty()) {
    result.status = WallStatus::kInvalidWall;
    result.message = std::move(why);
    return false;
  }
  const Ring& ccw = wall_detail::counter_clockwise(spec.outline, area, w.outline);
  for (Accepted& c : w.cut) w.spare_rings.push_back(std::move(c.ring));
  w.cut.clear();
  if (wall_detail::plain_wall(ccw, spec, w.plain)) {
    wall_detail::plain_boundary(ccw, spec, w.boundary);
    wall_detail::plain_loops(w.plain, w.loops, w.offsets);
    for (std::size_t i = 0; i < spec.openings.size(); ++i) result.cut.push_back(i);
    result.front_pieces = w.offsets.size() - 1;
    return true;
  }
  result.issues = wall_detail::validate(ccw, spec, w.cut, &w.spare_rings);
  if (!result.issues.empty() && spec.policy == OpeningPolicy::kFail) {
    result.status = WallStatus::kRejectedOpening;
    result.message = result.issues.front().message;
    return false;
  }
  w.boundary.clear();
  wall_detail::build_boundary(ccw, w.cut, w.boundary, w.notches);
  w.loops.clear();
  w.offsets.assign(1, 0);
  if (!wall_detail::partition(w.boundary, *w.partition, w.loops, w.offsets)) {
    result.status = WallStatus::kDecompositionFailed;
    result.message = "the planar partition of the wall failed";
    result.issues.clear();
    return false;
  }
  for (const Accepted& c : w.cut) result.cut.push_back(c.index);
  result.front_pieces = w.offsets.size() - 1;
  return true;
}

}  // namespace

WallResult build_wall(const WallSpec& spec, const WallFrame& frame) {
  WallWorkspace workspace;
  WallWorkspace::Buffers& w = workspace.buffers();
  WallResult result;
  if (!partition_wall(spec, w, result)) return result;
  wall_detail::emit(w.boundary, w.loops, w.offsets, spec, frame, result.mesh);
  // Faces in emission order: the front and back pieces, then one side quad per boundary edge.
  result.face_opening.assign(2 * result.front_pieces, -1);
  result.face_opening.insert(result.face_opening.end(), w.boundary.opening.begin(),
                             w.boundary.opening.end());
  return result;
}

WallResult build_wall(const WallSpec& spec, const WallFrame& frame, Mesh& out) {
  WallWorkspace workspace;
  build_wall(spec, frame, out, workspace);
  return std::move(workspace.buffers().result);
}

const WallResult& build_wall(const WallSpec& spec, const WallFrame& frame, Mesh& out,
                             WallWorkspace& workspace) {
  WallWorkspace::Buffers& w = workspace.buffers();
  if (partition_wall(spec, w, w.result)) {
    wall_detail::emit(w.boundary, w.loops, w.offsets, spec, frame, out);
  }
  return w.result;
}

namespace {

// place_wall's frame, and the wall's length; nullopt as documented there.
std::optional<std::pair<WallFrame, double>> frame_and_length(Vec3 base_start, Vec3 base_end,
                                                             double height, double thickness,
                                                             WallAlignment alignment) {
  const bool inputs_finite = std::isfinite(base_start.x) && std::isfinite(base_start.y) &&
                             std::isfinite(base_start.z) && std::isfinite(base_end.x) &&
                             std::isfinite(base_end.y) && std::isfinite(base_end.z) &&
                             std::isfinite(height) && std::isfinite(thickness);
  if (!inputs_finite || height <= 0 || thickness <= 0) return std::nullopt;
  const Vec3 run{base_end.x - base_start.x, base_end.y - base_start.y, 0};
  const double len = length(run);
  if (len <= kEps) return std::nullopt;
  WallFrame frame;
  frame.u_axis = run / len;
  frame.v_axis = {0, 0, 1};
  frame.normal = cross(frame.u_axis, frame.v_axis);
  const double shift = alignment == WallAlignment::kInside   ? thickness
                       : alignment == WallAlignment::kCenter ? thickness / 2
                                                             : 0;
  frame.origin = base_start - frame.normal * shift;
  return std::pair{frame, len};
}

}  // namespace

std::optional<WallPlacement> place_wall(Vec3 base_start, Vec3 base_end, double height,
                                        double thickness, WallAlignment alignment) {
  const auto placed = frame_and_length(base_start, base_end, height, thickness, alignment);
  if (!placed) return std::nullopt;
  WallPlacement w;
  w.frame = placed->first;
  const double len = placed->second;
  w.outline = {{0, 0}, {len, 0}, {len, height}, {0, height}};
  w.length = len;
  w.height = height;
  w.thickness = thickness;
  return w;
}

std::optional<WallFrame> place_wall_frame(Vec3 base_start, Vec3 base_end, double height,
                                          double thickness, WallAlignment alignment) {
  const auto placed = frame_and_length(base_start, base_end, height, thickness, alignment);
  if (!placed) return std::nullopt;
  return placed->first;
}

}  // namespace insula::kernel
