// Small closed solids the building front-ends share: boxes (frames, footers), prisms with one tag
// per side (slabs, plinths), floor and ceiling slabs with openings, and massive staircases (seed
// 000 §4.1: "producing entrance's stairs, rooms' footers"). Every solid is appended to a mesh that
// gathers many of them (a storey), faces outward, vertices shared within each solid.
#pragma once

#include <span>

#include "kernel/mesh.h"
#include "kernel/polygon.h"
#include "kernel/vec.h"

namespace insula::kernel {

// A parallelepiped: corner `origin` and edges u, v, w (any handedness).
struct BoxEdges {
  Vec3 origin;
  Vec3 u;
  Vec3 v;
  Vec3 w;
};

// Appends the closed box (8 vertices, 6 quads, all tagged `tag`), faces outward whatever the
// handedness of (u, v, w).
void add_box(Mesh& mesh, Vec3 origin, Vec3 u, Vec3 v, Vec3 w, FaceTag tag);
// add_box for each box in order (the same vertices and faces), the mesh's arrays grown once.
void add_boxes(Mesh& mesh, std::span<const BoxEdges> boxes, FaceTag tag);

// Tags of a prism or slab: the cap at the lower height, the cap at the upper one, every side face.
struct PrismTags {
  FaceTag bottom{SemanticClass::kClosureSurface};
  FaceTag top{SemanticClass::kClosureSurface};
  FaceTag side{SemanticClass::kWallSurface};
};

// Appends the closed prism of `polygon` between z0 and z1 (z0 < z1, meters); every side face keeps
// `tags.side` as it is (kernel::extrude numbers them). False, nothing added, when the polygon is
// degenerate (consecutive vertices within 1e-6 m are merged first).
bool add_prism(Mesh& mesh, const Polygon& polygon, double z0, double z1, const PrismTags& tags);

// A floor or ceiling slab: the prisms of `region` minus `openings` (stairwells, a compluvium)
// between z0 and z1. When the difference fails, the region is used whole. Returns the number of
// prisms added.
std::size_t add_slab(Mesh& mesh, std::span<const Polygon> region, std::span<const Polygon> openings,
                     double z0, double z1, const PrismTags& tags);

// A straight flight: `steps` steps of depth `run` and rise `rise` (meters, > 0) climbing along the
// horizontal unit vector `dir` from the foot line centred on `foot` at height z0, `width` wide.
struct StairSpec {
  Vec2 foot;
  Vec2 dir{0, 1};
  double width = 1;
  double z0 = 0;
  int steps = 1;
  double run = 0.3;
  double rise = 0.18;
};

// The highest step of a flight between storeys (meters) when the plan gives no step count.
inline constexpr double kMaxStepRise = 0.18;
// As few steps as keep each at most `max_rise` (> 0) high over `rise` meters; at least 1.
int stair_steps(double rise, double max_rise);

// Appends the closed staircase solid of `spec` (2 steps + 4 faces: the two side profiles, the
// bottom, the back and each step's riser and tread): every step reaches down to z0 (a massive
// flight, as entrance steps and the stairs between storeys are built). False, nothing added, for
// steps < 1 or a size that is not positive.
bool add_staircase(Mesh& mesh, const StairSpec& spec, FaceTag tag);

}  // namespace insula::kernel
