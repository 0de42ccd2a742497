// Roofs over arbitrary polygons with holes: flat, shed, gable, hip, pyramid, mansard and the Roman
// holed mansard (a compluvium: seed 000, Table 3, "Hip type with a central descending hole").
// Gambrel, half-hipped, saltbox, round, dome and onion are the remaining shapes of OpenStreetMap's
// Simple 3D Buildings. Hip, gable and mansard come from the interior straight skeleton
// (skeleton.h): each skeleton face lifted by height = time * tan(pitch) is one planar roof face
// (seed 000, §4.6). The rules chosen for gables, pyramids on concave input, shed direction, the
// mansard break, the opening and the fallbacks are in docs/kernel-roofs.md.
//
// Heights: `eave_z` is the height (meters) at which the roof surface passes over the footprint's
// edges (the low edge for a shed). With overhang > 0 the roof continues beyond the footprint down
// to a lower eave, and the walls stop under a soffit; a building's walls go from the ground up to
// the wall-top vertices this module creates, so walls and roof share vertices and the building is
// one closed shell (mass.h).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "kernel/mesh.h"
#include "kernel/party_walls.h"
#include "kernel/polygon.h"

namespace insula::kernel {

enum class RoofType : std::uint8_t {
  kFlat,
  kShed,
  kGable,
  kHip,
  kPyramid,
  kMansard,
  kHoledMansard,  // mansard whose top is left open at the break line (a compluvium)
  // OpenStreetMap's Simple 3D Buildings shapes (docs/kernel-roofs.md, "S3DB shapes"): on
  // quadrilaterals, two-sided profiles across a ridge; elsewhere their documented fallbacks.
  kGambrel,     // two slopes per side with gable ends (a barn)
  kHalfHipped,  // gable whose ridge ends are clipped by small hips
  kSaltbox,     // gable with an off-centre ridge: one side longer and lower
  kRound,       // barrel vault along the ridge
  kDome,        // over a footprint star-shaped about its centroid
  kOnion,       // bulging dome with a pointed top
};

// Every roof type, in enum order.
inline constexpr RoofType kRoofTypes[] = {
    RoofType::kFlat,       RoofType::kShed,    RoofType::kGable,        RoofType::kHip,
    RoofType::kPyramid,    RoofType::kMansard, RoofType::kHoledMansard, RoofType::kGambrel,
    RoofType::kHalfHipped, RoofType::kSaltbox, RoofType::kRound,        RoofType::kDome,
    RoofType::kOnion};

// "flat", "shed", "gable", "hip", "pyramid", "mansard", "holed_mansard", "gambrel",
// "half_hipped", "saltbox", "round", "dome", "onion".
std::string_view roof_type_name(RoofType type);
// Accepts the names above, case-insensitive; "holedmansard" and "compluvium" too, and the
// OpenStreetMap roof:shape spellings: "gabled", "hipped", "pyramidal", "skillion" (shed),
// "half-hipped", "half_hip", "halfhipped".
std::optional<RoofType> roof_type_from_name(std::string_view name);

// S3DB roof:orientation: the ridge along the longest side of a quadrilateral footprint (the
// default), or across it.
enum class RidgeOrientation : std::uint8_t { kAuto, kAlong, kAcross };

struct RoofSpec {
  RoofType type = RoofType::kHip;
  // Slope in degrees, (0, 89]: of every face for hip, gable, shed; of the steepest face of a
  // pyramid; of the upper part of a mansard (0 gives a flat top). Ignored for flat roofs.
  double pitch_deg = 30;
  // Horizontal distance (meters, >= 0) by which the roof reaches beyond the footprint's edges.
  double overhang = 0;
  // Mansard: slope of the steep lower part (degrees) and height of its break line above eave_z.
  double mansard_pitch_deg = 70;
  double mansard_break_height = 2.5;
  // Shed: index of the outer-ring edge the roof rises from; -1 picks the longest outer edge.
  int shed_edge = -1;
  // Vertical thickness (meters, > 0) of the roof edge of flat and shed roofs with overhang: their
  // soffit runs that far below the roof surface, closed by a vertical fascia.
  double fascia = 0.25;
  // Roof height (meters) above the eave; when set it overrides pitch_deg: every pitched type is
  // built as asked and scaled in z (scale_roof_height) so its top is this high (for hip and gable
  // without overhang that is the pitch giving this ridge height); with overhang the soffit stays at
  // eave_z, the walls' top. A shed's high edge; a dome's or onion's top. Ignored by flat roofs.
  std::optional<double> height = std::nullopt;
  // When `height` is unset: the most the roof may rise above the eave at `pitch_deg`. A roof that
  // would rise higher is built lower, as with `height` (a register's wall height under a default
  // pitch: a 12,000 m2 plant got 62 m of hip roof over 10 m of walls).
  std::optional<double> height_limit = std::nullopt;
  // S3DB roof:direction: compass azimuth (degrees clockwise from north, +y) the main roof face
  // looks toward (downhill). Shed: the roof falls toward it on any footprint. Gable, gambrel,
  // half-hipped, saltbox, round on a quadrilateral: the ridge runs perpendicular to it.
  std::optional<double> direction_deg = std::nullopt;
  // S3DB roof:orientation on quadrilaterals (ignored when direction_deg is set).
  RidgeOrientation orientation = RidgeOrientation::kAuto;
  // Stretches of the footprint's edges that a neighbour's wall runs along (party_walls.h): an edge
  // on one has no overhang, so the eave does not reach into the neighbour.
  std::vector<PartyWall> party_walls;
};

enum class RoofStatus : std::uint8_t {
  kOk,
  kFallback,  // built, but not as asked (another type, or without overhang); see message
  kFailed,    // nothing built (invalid footprint)
};

// What add_roof appended to a mesh, for the caller that puts walls under it.
struct RoofBuild {
  RoofStatus status = RoofStatus::kFailed;
  RoofType built = RoofType::kFlat;
  std::string message;  // empty when kOk
  // Mesh vertex ids of the footprint's vertices at wall-top height, in ring order (outer ring, then
  // holes). The wall under edge e (from vertex e to the next of its ring) ends at these vertices.
  std::vector<std::uint32_t> wall_top;
  // Per footprint edge e, the path of vertex ids that closes the wall above its top edge, from the
  // top of the edge's end vertex back to its start, excluding the wall_top vertices themselves:
  // cap_indices[cap_offsets[e] .. cap_offsets[e + 1]). Empty for ordinary edges; a gable's
  // triangle (and its overhanging eave corners) for gable ends. The wall under edge e is then
  // {ground(e), ground(next), wall_top(next), cap..., wall_top(e)}.
  std::vector<std::uint32_t> cap_offsets;
  std::vector<std::uint32_t> cap_indices;
  std::uint32_t next_face_id = 0;  // the first face id add_roof did not use
};

// Appends to `mesh` the roof over `footprint` (valid, normalized: is_simple_polygon in skeleton.h)
// with its eave at `eave_z`: roof faces (RoofSurface), soffits (OuterCeilingSurface), fascias and
// the opening walls of a holed mansard (WallSurface), the opening's floor (OuterFloorSurface), and
// the wall-top vertices. Gable triangles are not added as faces but returned as caps. Face ids
// start at `first_face_id`. Falls back to hip, then flat, when the asked type cannot be built, and
// drops the overhang when the offset polygon would not be simple; both reported in the result.
RoofBuild add_roof(const Polygon& footprint, const RoofSpec& spec, double eave_z, Mesh& mesh,
                   std::uint32_t first_face_id = 0);

// Scales the z of `mesh`'s vertices from `first_vertex` on so the lowest of them (the soffit of an
// overhang, else the eave) lies at `eave_z` and the highest `height` (> 0, meters) above it: the
// rise scales, the eave stays on the wall top (docs/kernel-roofs.md, "Roof height"). An affine map
// of z keeps every face planar. Nothing changes for height <= 0 or a mesh without rise.
void scale_roof_height(Mesh& mesh, double eave_z, double height, std::size_t first_vertex = 0);

struct RoofResult {
  Mesh mesh;  // roof faces, soffits and gable walls; open at the bottom (no walls below eave_z)
  RoofStatus status = RoofStatus::kFailed;
  RoofType built = RoofType::kFlat;
  std::string message;
};

// The roof alone: add_roof plus each gable cap as a WallSurface face standing on the footprint
// edge. Without overhang its eave edges are exactly the footprint's edges at eave_z.
RoofResult build_roof(const Polygon& footprint, const RoofSpec& spec, double eave_z);

}  // namespace insula::kernel
