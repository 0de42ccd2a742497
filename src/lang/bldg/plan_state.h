// Working state of the floor-plan engine (floorplan.h), shared by its stage files: the flattened
// arrangement trees of parts and divisions, every room with its weight and cell, and the
// subdivision (plan_subdivide.cc) that turns weights into cells.
#pragma once

#include <string>
#include <vector>

#include "base/diagnostic.h"
#include "kernel/polygon.h"
#include "lang/bldg/floorplan.h"
#include "lang/bldg/model.h"
#include "lang/bldg/plan_openings.h"

namespace insula::lang::bldg::plan {

// A node of a flattened arrangement tree (building parts or a floor's divisions).
struct TreeNode {
  int parent = -1;
  std::vector<int> children;
  Orientation orientation = Orientation::kAlternate;
  int leaf = -1;  // part index (part tree) or room index (division tree) for final nodes
  int depth = 0;  // arrangement depth in its tree (0 at the root)
};

struct WorkRoom {
  const Division* division = nullptr;  // null for the stand-in of a part without rooms
  int part = 0;
  int level = 0;
  int floor = 0;  // index into Work::floors
  double weight = 0;
  kernel::Polygon cell;
  bool has_cell = false;
  int plan_index = -1;  // index in FloorPlan::storeys[level].rooms; -1 when not in the plan
};

struct WorkFloor {
  int part = 0;
  int level = 0;
  double height = 0;
  std::vector<TreeNode> tree;  // node 0 is the floor's layout root
  std::vector<int> rooms;      // room indices, in grammar order
  std::vector<PlanDeadZone> dead_zones;
};

struct WorkPart {
  const PartNode* node = nullptr;
  int tree_node = 0;
  std::vector<int> floors;        // floor indices by level
  std::vector<int> weight_rooms;  // the rooms whose weights make the part's weight (level 0)
  kernel::Polygon cell;
  bool has_cell = false;
  bool disposable() const { return node->part->disposable; }
};

struct Work {
  const Building* building = nullptr;
  const Restrictions* restrictions = nullptr;
  kernel::Polygon outline;
  std::vector<TreeNode> part_tree;  // node 0 is Building::layout
  std::vector<WorkPart> parts;
  std::vector<WorkFloor> floors;
  std::vector<WorkRoom> rooms;
  std::vector<PlanWarning> warnings;
  PlanAdaptations adaptations;  // what was merged, dropped and added to fit the lot
  // On a lot (FloorPlanOptions::on_lot): a room slab thinner than this turns the cut (m; 0 off).
  double sliver = 0;
  std::vector<double> door_widths;  // default door width per part (floorplan.h)
  double clearance = 0;  // kept free at each end of a door or window (wall junctions, jambs)
  int levels = 0;        // storeys of the tallest non-disposable part
  // The settled cells of each storey of the FloorPlan with their boundary pieces, taken by
  // place_windows and reused by build_walls (no stage between them moves a cell).
  std::vector<StoreyCells> storey_cells;
  std::string file;
};

// Flattens the model into `work`, with initial weights (Fig. 3). Errors for parts without floors
// and trees that hold no room.
void build_work(const Building& building, const Restrictions& restrictions, Work& work,
                std::vector<base::Diagnostic>& errors);

// Cells for the parts from the part weights (back-propagated from their ground-floor rooms).
// Returns true when some part cell changed.
bool subdivide_parts(Work& work);
// Cells for a floor's rooms inside its part's cell; pieces a concave region split off a room are
// merged into the neighbouring room sharing the longest boundary, or kept as dead zones.
void subdivide_floor(Work& work, int floor);
void subdivide_all(Work& work);

void warn(Work& work, std::string message, Location where = {}, std::string code = {});
// Default width of a door between rooms of parts a and b (the narrower part's).
double door_width_between(const Work& work, int part_a, int part_b);
std::string room_name(const Work& work, int room);
// A length for messages: two decimals ("1.40").
std::string meters(double v);

}  // namespace insula::lang::bldg::plan
