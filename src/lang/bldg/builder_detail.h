// Internals of the 3D builder (builder.h), shared by builder_*.cc: the build context and the stage
// entry points. Every solid comes from the kernel (kernel/solids.h, opening_frame.h, roof_solid.h),
// the functions the shape operations slab, stair, frame and roof use too.
#pragma once

#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "kernel/mesh.h"
#include "kernel/polygon.h"
#include "kernel/solids.h"
#include "kernel/vec.h"
#include "lang/bldg/builder.h"
#include "lang/bldg/floorplan.h"

namespace insula::lang::bldg::detail {

using kernel::FaceTag;
using kernel::SemanticClass;
using kernel::Vec2;
using kernel::Vec3;

// Material ids of the builder's own materials (BuildResult::materials); 0 = default by class.
enum Material : kernel::MaterialId {
  kDefaultMaterial = 0,
  kPlinthMaterial,
  kFrameMaterial,
  kGlassMaterial,
  kFloorMaterial,
  kFooterMaterial,
  kStairMaterial,
  kBuiltinMaterials,  // restriction-rule colours follow
};

struct Context {
  const Building& building;
  const FloorPlan& plan;
  const Restrictions& rules;
  const BuilderOptions& options;
  BuildResult& result;
  // Roof openings (HoledMansard compluvia) per part symbol, from build_roofs: the ceilings of the
  // part's top storey stay open under them.
  std::map<std::string, std::vector<kernel::Polygon>>* compluvia = nullptr;

  // Floor level of a storey: the plinth's top plus the storey's elevation.
  double floor_z(int storey) const;
  double storey_height(int storey) const;
  void warn(std::string message) const { result.warnings.push_back(std::move(message)); }
};

// `polygon` as simple polygons a roof or plinth can be built on (kernel/skeleton.h
// is_simple_polygon): repaired, else cut where a ring touches itself, else rebuilt by the kernel's
// polygon union (strictly simple output), which may split it into pieces. Empty when none of that
// gives simple polygons (builder_roofs.cc).
std::vector<kernel::Polygon> simple_pieces(const kernel::Polygon& polygon);

// A wall piece of a storey placed in the plan: the segment it stands on (extended to close
// corners), its side of the segment, and its footprint.
struct WallGeometry {
  Vec2 start;          // extended start on the wall's reference line
  Vec2 dir;            // unit, along the wall
  Vec2 left;           // unit, perp(dir): towards the wall's `left` room
  double length = 0;   // extended length
  double offset0 = 0;  // footprint across the reference line, along `left`: [offset0, offset1]
  double offset1 = 0;
  double thickness = 0;
  bool exterior = false;      // exterior or dead-zone side: the wall stands inside the room's cell
  bool reaches_past = false;  // lengthened at a reflex corner, into a neighbouring cell
  kernel::Polygon footprint;
  kernel::Bounds2 box;  // bounds(footprint), cached: the room stage tests it against every cell

  double u_of(Vec2 p) const { return kernel::dot(p - start, dir); }
  // Plan point at distance u along the wall and `across` along `left`.
  Vec2 at(double u, double across) const { return start + dir * u + left * across; }
  kernel::Polygon rect(double u0, double u1, double across0, double across1) const;
};

// What the wall stage hands to the room stage of the same storey.
struct StoreyWalls {
  std::vector<WallGeometry> walls;           // per FloorPlan wall piece (same index)
  std::vector<kernel::Polygon> door_gaps;    // per door and entrance cut: the gap across the wall
  std::vector<std::vector<int>> room_walls;  // per room: the wall pieces bordering it
};

// Stage entry points (builder_walls.cc, builder_rooms.cc, builder_roofs.cc).
StoreyWalls build_walls(const Context& context, int storey, kernel::Mesh& mesh,
                        shape::StoreyPlan& plan);
void build_rooms(const Context& context, int storey, const StoreyWalls& walls,
                 std::vector<shape::Part>& parts, shape::StoreyPlan& plan);
void build_stairs(const Context& context, int storey, kernel::Mesh& mesh, shape::StoreyPlan& plan);
void build_base(const Context& context, const std::vector<StoreyWalls>& walls, kernel::Mesh& mesh);
void build_roofs(const Context& context, std::vector<shape::Part>& parts);

}  // namespace insula::lang::bldg::detail
