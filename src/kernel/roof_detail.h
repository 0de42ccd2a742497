// Private to roof*.cc and mass.cc: the roof plan shared by planning (roof.cc), emission
// (roof_emit.cc) and the mansard split (roof_mansard.cc). Not part of the kernel's API.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "kernel/mesh.h"
#include "kernel/polygon.h"
#include "kernel/roof.h"
#include "kernel/skeleton.h"

namespace insula::kernel::roof_detail {

// An eave corner may reach at most this many overhangs from its footprint corner (a corner of
// about 14 degrees; 2 / sin(angle / 2) grows without bound as the corner sharpens): a sliver's
// near-zero corner put the eave of a real OpenStreetMap lot 400 m away (docs/kernel-roofs.md,
// "Overhang"). Used by every eave polygon (roof.cc, roof_shapes.cc).
inline constexpr double kEaveMiterLimit = 8;

// A polygon's rings flattened in ring order (outer, then holes), so vertex k of the footprint, of
// its eave polygon and of its skeleton's contour are the same k.
struct Contour {
  std::vector<Vec2> points;
  std::vector<std::uint32_t> ring_starts;  // first vertex of each ring, then the total

  static Contour from(const Polygon& polygon);
  Polygon polygon() const;
  std::uint32_t size() const { return static_cast<std::uint32_t>(points.size()); }
  std::uint32_t next(std::uint32_t k) const;
  std::uint32_t prev(std::uint32_t k) const;
};

// A skeleton face turned into a vertical gable: its apex node moves to `apex` on the edge's line.
struct GableEnd {
  std::uint32_t edge = 0;
  std::uint32_t node = 0;  // skeleton vertex id of the triangle's apex
  Vec2 apex;
  double time = 0;  // distance of `apex` from the neighbouring edges' lines
};

// A roof given directly as faces (the S3DB shapes of roof_shapes.cc). Point ids below the
// footprint's vertex count are the eave vertices; id k above is points[k - count], with z in
// meters above the eave.
struct CustomRoof {
  std::vector<Vec3> points;
  std::vector<std::uint32_t> face_indices;
  std::vector<std::uint32_t> face_offsets{0};
  // Per footprint edge, the point ids closing the wall above it, from the edge's end back to its
  // start (RoofBuild::cap_indices).
  std::vector<std::vector<std::uint32_t>> caps;
  // Per footprint edge, 1 on an end of an overhanging quadrilateral shape: its wall rises into the
  // roof, so its cap takes in the eave corners as a gable's does, even with no roof point inside
  // the edge (a 4 cm edge at a corner). Empty: no overhang.
  std::vector<std::uint8_t> ends;
  // Per footprint vertex, the roof's height (m) above the eave there; empty: all 0. Not 0 at a
  // vertex dropped by outline_core: the roof planned over the core passes above or below it.
  std::vector<double> eave_rise;
};

struct RoofPlan {
  RoofType type = RoofType::kFlat;
  RoofStatus status = RoofStatus::kOk;
  std::string message;
  std::string reason;  // why the type being planned could not be built: "stage: finding"
  Contour footprint;
  Contour eave;                 // footprint offset by `offsets` (== footprint without overhang)
  std::vector<double> offsets;  // per edge, meters
  std::vector<std::uint32_t> party_edges;  // footprint edges on party walls: never overhang
  double overhang = 0;                     // the overhang actually used
  double slope = 0;                        // tan(pitch): hip, gable, shed, pyramid
  double eave_slope = 0;   // slope of the faces at the eave (mansard: the lower slope)
  double upper_slope = 0;  // mansard top
  double break_time = 0;   // mansard break, as skeleton time of the eave polygon
  double fascia = 0;       // flat and shed with overhang
  Vec2 shed_origin;        // the shed rises at `slope` along shed_normal from this point
  Vec2 shed_normal;
  Vec2 apex;  // pyramid
  double apex_time = 0;
  std::optional<Skeleton> skeleton;  // of the eave polygon
  std::vector<GableEnd> gables;
  CustomRoof custom;  // gambrel, half-hipped, saltbox, round, dome, onion
};

// The footprint with the outer ring's nearly straight vertices (turning by less than
// kCornerMinTurnDeg, roof.cc) dropped, holes unchanged: what decides whether a footprint is a
// quadrilateral (plan_custom) or convex (the pyramid). The roof is still built over every vertex.
Contour outline_core(const Contour& c);

// Which pair of opposite edges of a quadrilateral carries the slopes: edges r and r + 2 for the
// returned r in {0, 1}, so the ridge runs along them (roof_shapes.cc): from direction_deg, else
// orientation, else (kAuto) the square rule or the longer pair.
std::uint32_t quad_slope_pair(const Contour& c, const RoofSpec& spec);
// The S3DB shapes; false when the footprint does not define them (the caller falls back).
// Gambrel, half-hipped and saltbox overhang their slope sides by `overhang` (docs/kernel-roofs.md,
// "Overhang"); the other shapes ignore it.
bool plan_custom(RoofPlan& plan, const RoofSpec& spec, double overhang);
// Signed distance of `p` from the supporting line of contour edge e, positive inside.
double edge_distance(const Contour& c, std::uint32_t e, Vec2 p);
// The ridge point of a gable on edge e, see roof.cc.
std::optional<GableEnd> gable_apex(const Contour& c, std::uint32_t e);

bool plan_roof(const Polygon& footprint, const RoofSpec& spec, RoofPlan& plan);
// Signed distance from the shed's low edge line, positive inside.
double shed_distance(const RoofPlan& plan, Vec2 p);
// Writes the planned roof into `mesh` (never fails once planned).
void emit_roof(const RoofPlan& plan, double eave_z, Mesh& mesh, RoofBuild& build);

// An edge without overhang between overhanging ones (a party wall, kernel-roofs.md) has its wall
// top (the footprint edge) inside its eave edge, which reaches over the neighbouring soffits' ends:
// the face over the eave edge takes the wall-top vertices into its bottom edge, so the wall, the
// soffits and the roof meet edge to edge.
struct WallTopJog {
  std::uint32_t eave_from = 0, eave_to = 0;  // the eave edge, as the face over it runs
  std::uint32_t wall_from = 0, wall_to = 0;  // the wall top's ends in that order
};

// Inserts each jog's wall-top vertices into `loop` where it runs along the jog's eave edge.
void insert_wall_tops(std::span<const WallTopJog> jogs, std::vector<std::uint32_t>& loop);

// Mansard split of the skeleton faces at plan.break_time (roof_mansard.cc). `eave_ids` are the
// mesh ids of the eave polygon's vertices at height z_eave.
void emit_mansard(const RoofPlan& plan, double z_eave, double floor_z,
                  std::span<const std::uint32_t> eave_ids, std::span<const WallTopJog> jogs,
                  Mesh& mesh, std::uint32_t& face_id);

// Adds the region bounded by `contour` over existing vertex ids `ids` (contour order) as faces:
// one face without holes, triangles (k2d's triangulate) with holes; `downward` reverses them.
// Returns false if the triangulation fails.
bool add_region(const Contour& contour, std::span<const std::uint32_t> ids, FaceTag tag,
                bool downward, Mesh& mesh);

}  // namespace insula::kernel::roof_detail
