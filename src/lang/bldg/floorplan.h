// The floor-plan engine of the ontology-based building grammar (seed 000, §3.2-3.4, Figs. 2-4, 7):
// it turns the checked building model (model.h) into per-storey floor plans that the 3D builder
// (builder.h) raises into walls, openings, slabs, stairs and roofs.
//
// Pipeline (docs/bldg-floorplan.md):
//  1. Weights (Fig. 3): every room starts at Restrictions::initial_weight and grows by its size
//     label's growth factor until the weights sum to 1; containers get the sum of their children
//     (back-propagation). Building parts weigh what their ground-floor rooms weigh.
//  2. Treemap (Fig. 2, Eqs. 1-5): each container's region is cut into its children's cells by
//     auxiliary rectangles placed one after the other along the container's axis (alternating per
//     depth unless the container states one), intersected with the region (kernel/boolean2d.h),
//     scaled until the cell's area crosses its target, then refined; the last child takes the
//     remainder. Works on concave outlines and outlines with holes.
//  3. Transitions (§3.3, Fig. 4): a door needs a shared wall portion at least its width plus a
//     clearance at each end; when it does not fit, weight is borrowed between rooms up to
//     Restrictions::borrow_limit and the subdivision redone; otherwise rolled back and the door
//     dropped with a warning. Transitions touching a disposable part are ignored.
//  4. Fake-concave (§3.2, §4.2): disposable parts (height 0) take part in the subdivision and are
//     removed afterwards, leaving notches or holes.
//  5. Room shape adaptation (§3.4) toward the requested number of walls, windows on exterior walls,
//     stairs between storeys, and the reachability guarantee (every room reachable from an
//     entrance through doors and stairs, doors added where needed; the rest reported).
//
// Coordinates: the building's local frame, meters, the same frame as Building::outline.
//
// Tiling contract: on every storey the room cells and the dead zones tile the union of the storey's
// (non-disposable) part outlines exactly: no overlap, no gap. Walls are NOT subtracted: the 3D
// builder centres inner walls on the shared cell boundaries and puts outer walls inside the
// outline, so a room's clear floor is its cell shrunk by half the inner wall thickness (and the
// whole outer thickness along the exterior).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "base/diagnostic.h"
#include "kernel/polygon.h"
#include "kernel/vec.h"
#include "lang/bldg/model.h"

namespace insula::lang::bldg {

// Pseudo room indices for the far side of a wall.
inline constexpr int kExteriorSide = -1;  // outside the building (or above a lower part's roof)
inline constexpr int kDeadZoneSide = -2;  // a dead zone (space cut off by room shape adaptation)

struct PlanRoom {
  std::string symbol;  // the division symbol
  std::string type;    // room type from the grammar
  std::string part;    // symbol of the final building part holding it
  int part_index = 0;  // index into FloorPlan::parts
  int storey = 0;      // level
  Location where;      // of the division in the .bldg source
  SizeLabel size = SizeLabel::kMedium;
  kernel::Polygon cell;  // the room's cell (walls centred on its boundary); no holes in practice
  double area = 0;       // m², of `cell` (after fake-concave and shape adaptation)
  // Weight asked (Fig. 3, after borrowing): fraction of its floor (the part's cell on that storey)
  // the room asks for; target_area = weight x floor area. `area` differs from target_area by the
  // treemap's tolerance (docs) plus what room shape adaptation moved.
  double weight = 0;
  double target_area = 0;
  int walls_asked = 0;  // 0 = as the subdivision gives
  int walls = 0;        // edges of the cell's outer ring after adaptation (collinear points merged)
  int windows_asked = 0;
  bool entrance_asked = false;
  std::vector<int> neighbors;  // storey-local indices of rooms connected by a door (sorted)
  // Symbols of the rooms merged into this one to fit the lot ("Rooms that fit"), in merge order.
  std::vector<std::string> merged;
};

// A straight piece of a cell boundary with one room on its left (the cell is counter-clockwise)
// and a room, the exterior or a dead zone on its right. Every boundary piece of every room appears
// exactly once: a piece shared by two rooms is listed once, with left < right.
struct PlanWall {
  kernel::Vec2 a;
  kernel::Vec2 b;
  // Storey-local room index, or kDeadZoneSide for the outer wall of a dead zone (its right side is
  // then the exterior).
  int left = 0;
  int right = kExteriorSide;  // room index, kExteriorSide or kDeadZoneSide
  double thickness = 0;       // outer or inner wall thickness from the restriction rules
  bool exterior() const { return right == kExteriorSide; }
};

// A door between two rooms or an entrance door (room_b == kExteriorSide). The opening spans a..b
// on the wall's centre line (the cell boundary), centred on `center`.
struct PlanDoor {
  std::string symbol;  // the transition symbol; empty when the engine added the door
  Location where;
  int room_a = 0;
  int room_b = kExteriorSide;
  int wall = 0;  // index into PlanStorey::walls
  kernel::Vec2 a;
  kernel::Vec2 b;
  kernel::Vec2 center;
  double width = 0;
  double height = 0;   // Restrictions::door_height
  bool added = false;  // added by the reachability guarantee (or the missing-entrance rule)
};

struct PlanWindow {
  std::string symbol;  // the window transition symbol; empty for windows counted on the room
  int room = 0;
  int wall = 0;  // an exterior wall
  kernel::Vec2 a;
  kernel::Vec2 b;
  kernel::Vec2 center;
  double width = 0;
  double sill = 0;    // above the storey's floor
  double height = 0;  // of the opening
};

// A straight flight from a room of this storey to a room of the storey above. The footprint lies
// inside both rooms' cells (shrunk by half the inner wall thickness) and keeps clear of doors; the
// upper room's floor slab needs a stairwell over it.
struct PlanStair {
  std::string symbol;  // the stair transition symbol; empty when added by the engine
  Location where;
  int lower_room = 0;         // storey-local index on this storey
  int upper_room = 0;         // storey-local index on the storey above
  kernel::Polygon footprint;  // a rectangle, counter-clockwise
  kernel::Vec2 foot;          // middle of the first step's front edge
  kernel::Vec2 head;          // middle of the last step's back edge (foot -> head = ascent)
  double width = 0;
  double run = 0;  // horizontal length of the flight
  int risers = 0;  // number of risers from this floor to the floor above
  bool added = false;
};

struct PlanDeadZone {
  kernel::Polygon cell;
  std::string reason;  // e.g. "cut off from kitchen_1 to give it 5 walls"
};

struct PlanUnreachable {
  int storey = 0;
  int room = 0;  // storey-local index
  std::string symbol;
  std::string reason;  // why no door or stair could be added
};

struct PlanStorey {
  int level = 0;
  double elevation = 0;  // floor level (m) above the ground floor's level
  double height = 0;     // floor to floor (the largest floor height of the parts at this level)
  std::vector<PlanRoom> rooms;
  std::vector<PlanWall> walls;
  std::vector<PlanDoor> doors;      // between rooms
  std::vector<PlanDoor> entrances;  // from the exterior (storey 0 only)
  std::vector<PlanWindow> windows;
  std::vector<PlanStair> stairs;  // going up from this storey
  std::vector<PlanDeadZone> dead_zones;
};

struct PlanPart {
  std::string symbol;
  Location where;
  RoofKind roof = RoofKind::kFlat;
  double roof_height = 0;
  bool disposable = false;
  // The part's cell from the treemap over the building outline (disposable parts keep theirs so a
  // caller can draw them; they hold no rooms, walls or roof).
  kernel::Polygon outline;
  int storeys = 0;  // floors of the part: it occupies storeys 0 .. storeys-1
  // Top of the part's highest storey (m), where its roof starts.
  double eaves = 0;
  double door_width = 0;  // default door width in this part (default_door_width of its cell)
};

struct PlanWarning {
  std::string message;
  Location where;    // of the transition or division concerned; line 0 when none
  std::string code;  // empty for most; BLD602 for rooms merged or dropped to fit the lot
};

// What the engine changed to fit the grammar to its lot (docs/bldg-floorplan.md, "Rooms that
// fit"), counted per building for the report.
struct PlanAdaptations {
  int rooms_merged = 0;         // a room too small, too narrow or unreachable joined a neighbour
  int rooms_dropped = 0;        // a room that got no area, or too small with no neighbour
  int doors_added = 0;          // by the reachability guarantee
  int entrances_added = 0;      // the building had none
  int stairs_added = 0;         // by the reachability guarantee
  int transitions_dropped = 0;  // grammar doors, entrances or stairs that found no place
};

struct FloorPlan {
  kernel::Polygon outline;  // Building::outline, normalised
  // The building's footprint after fake-concave suppression: the union of the non-disposable
  // parts' outlines (several polygons when suppression splits the building).
  std::vector<kernel::Polygon> footprint;
  std::vector<PlanPart> parts;  // final parts in grammar order (depth first)
  std::vector<PlanStorey> storeys;
  std::vector<PlanUnreachable> unreachable_rooms;
  std::vector<PlanWarning> warnings;  // transitions dropped, rooms shrunk, walls not reached, ...
  PlanAdaptations adaptations;
};

struct FloorPlanOptions {
  std::string file;  // for diagnostics (Span::file)
  // §3.4 room shape adaptation; the reachability guarantee (adding doors and stairs; unreachable
  // rooms are listed either way). On by default.
  bool adapt_room_shapes = true;
  bool guarantee_reachability = true;
  // Rooms below Restrictions::min_room_area or min_room_width merged into a neighbour or dropped
  // ("Rooms that fit"). On by default.
  bool fit_rooms = true;
  // The outline is a lot the grammar was not written for (`insula build --lot`, a geojson()
  // outline): a cut of a floor's divisions that would leave a room slab thinner than twice
  // Restrictions::min_room_width while the other axis would not is made along the other axis
  // ("Rooms that fit"). Off: the grammar's axes are kept as written.
  bool on_lot = false;
};

// Makes the floor plan. Fails (with `file:line:col` diagnostics) when the outline is not a valid
// polygon, the building has no non-disposable part, or a part or room gets no area at all.
// Warnings (dropped transitions, walls not reached, windows that do not fit, unreachable rooms)
// are in FloorPlan::warnings. Deterministic: same input, same plan.
base::Result<FloorPlan> make_floor_plan(const Building& building, const Restrictions& restrictions,
                                        const FloorPlanOptions& options = {});

// The default width of a door between rooms: Restrictions::door_width, or with
// door_width_fraction > 0 the paper's rule (§3.3) in a layout of perimeter `layout_perimeter` (m):
// door_width_fraction x the perimeter, at least door_min_width. The layout of a door is its
// building part's cell, so a large building does not get barn doors everywhere; a door between
// two parts takes the narrower of the two.
double default_door_width(double layout_perimeter, const Restrictions& restrictions);

// Moves every position of the plan (outlines, cells, wall ends, doors, windows, stairs) by
// `offset`, meters: a plan made at a lot's own origin, taken back to the lot file's frame.
void translate(FloorPlan& plan, kernel::Vec2 offset);

// Room index (storey-local) by symbol on a storey; -1 when absent.
int find_room(const PlanStorey& storey, const std::string& symbol);

}  // namespace insula::lang::bldg
