// The 3D builder of the ontology-based building grammar (seed 000, §3.4 "the extrusion of the
// elements takes place to provide a 3D model", §4.1 "wall extrusion, roof placement, and building's
// detailing", §4.6 merged straight-skeleton roofs). It turns the floor plan made by the floor-plan
// engine (floorplan.h) into a traversable building:
//  - outer walls (inside the outline) and inner walls (centred on the cells' shared boundaries),
//    raised to storey height with door and window openings through kernel/wall.h;
//  - per room a floor slab (FloorSurface on top) and a ceiling slab (CeilingSurface below), room
//    footers (skirting) that leave the door gaps free;
//  - the building base (plinth) under the ground storey, entrance steps in front of every entrance
//    door, stairs between storeys (Stair) with a stairwell cut through the slab above;
//  - each part's roof (Flat, Pyramid, Hip, Mansard, HoledMansard, Gable via kernel/roof.h; None
//    leaves the part open) scaled so its ridge is the part's roof height above the eaves, and one
//    merged roof over every group of HipGlued parts in contact (union with kernel/boolean2d.h).
// Every face carries its semantic class; every solid (wall, slab, footer, step, roof) is closed.
// docs/bldg-building.md describes the conventions.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "lang/bldg/model.h"
#include "shape/scene.h"

namespace insula::lang::bldg {

struct FloorPlan;  // lang/bldg/floorplan.h (the floor-plan engine's output)

// Tunables of the 3D model that the restriction rules (model.h) do not carry. Meters.
struct BuilderOptions {
  double slab_thickness = 0.1;  // floor slab (and ceiling slab) of every room
  double footer_depth = 0.02;   // how far a room footer stands out of the wall
  double roof_overhang = 0.3;   // eaves beyond the outline (0 for None / Flat parapets)
  double step_rise = 0.15;      // entrance steps: at most this high each
  double step_run = 0.3;        // entrance steps and stairs: tread depth
  double frame_width = 0.06;    // door and window frames: width of the frame profile
  double frame_depth = 0.04;    // how far a frame stands out of the wall face
  bool frames = true;           // door and window frames (§4.1 "frame portals")
  bool footers = true;          // room footers (§3.4)
};

// What was built, for the `--report` JSON and the tests.
struct BuildStats {
  std::size_t storeys = 0;
  std::size_t rooms = 0;
  std::size_t walls = 0;      // wall solids
  std::size_t doors = 0;      // openings cut for doors between rooms
  std::size_t entrances = 0;  // openings cut for entrance doors
  std::size_t windows = 0;    // openings cut for windows
  std::size_t stairs = 0;
  std::size_t roofs = 0;      // roof solids (a merged HipGlued group counts once)
  std::size_t vertices = 0;   // over every part's mesh
  std::size_t triangles = 0;  // Mesh::triangle_count over every part
  // Seconds per stage: walls, slabs (floors, ceilings, footers, base, steps), stairs, roofs.
  double seconds_walls = 0;
  double seconds_slabs = 0;
  double seconds_stairs = 0;
  double seconds_roofs = 0;
};

struct BuildResult {
  shape::Building building;  // parts, attributes and plans (shape::StoreyPlan per storey)
  // Material table the faces' MaterialIds index into (index 0 = default by class); set from the
  // restriction rules' colours per semantic class. to_scene() installs it.
  std::vector<shape::Material> materials;
  BuildStats stats;
  // Things built differently from what was asked (a roof fallback, an opening that did not fit
  // and was left out), one sentence each naming the part or room.
  std::vector<std::string> warnings;
};

// Builds the 3D model of `building` from its floor plan. Parts of the result (all in the
// building's local frame, meters, Z up, ground at z = 0):
//  - one kRoom part per room, named after the room symbol (with "@s<level>" when a room symbol
//    repeats across storeys), attributes name/type/storey/area (m², clear floor), holding its slabs
//    and footers;
//  - one kStorey part per storey ("storey <level>") holding its walls (with openings and frames)
//    and stairs, attributes storey/elevation/height;
//  - one kBuildingPart part per roof ("roof <part symbol>" or "roof <a>+<b>+..." for a merged
//    HipGlued group) and one "base" part (plinth and entrance steps).
// Never throws; an invalid plan gives an empty building and a warning.
BuildResult build_building(const Building& building, const FloorPlan& plan,
                           const Restrictions& restrictions, const BuilderOptions& options = {});

// A scene with the result's building and materials (origin 0, no CRS).
shape::Scene to_scene(BuildResult result);

}  // namespace insula::lang::bldg
