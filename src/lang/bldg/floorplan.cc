// make_floor_plan: the floor-plan engine's entry point (floorplan.h). It runs the stages in the
// paper's order (§3.3 probing with weight borrowing, then §3.4's last subdivision, fake-concave
// suppression and room shape adaptation) followed by the stages past the paper (stairs,
// reachability) and the walls the 3D builder needs.
#include "lang/bldg/floorplan.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "kernel/boolean2d.h"
#include "lang/bldg/plan_geometry.h"
#include "lang/bldg/plan_stages.h"
#include "lang/bldg/plan_state.h"
#include "lang/bldg/plan_transitions.h"

namespace insula::lang::bldg {
namespace {

using plan::Work;

base::Span span_at(const std::string& file, Location where) {
  return where.line > 0 ? base::Span::at(file, where.line, where.column) : base::Span::whole(file);
}

// Surveyed outlines bend their walls by centimetres between many short edges; a wall holds a door
// only where it is straight, so a vertex within kStraighten of the segment joining its neighbours
// is removed, the closest first ("Rooms that fit"). Kept only when the ring stays valid.
constexpr double kStraighten = 0.05;

void straighten_ring(kernel::Ring& ring) {
  while (ring.size() > 3) {
    const std::size_t n = ring.size();
    std::size_t best = n;
    double best_d = kStraighten;
    for (std::size_t i = 0; i < n; ++i) {
      const double d =
          kernel::distance_to_segment(ring[i], ring[(i + n - 1) % n], ring[(i + 1) % n]);
      if (d < best_d) {
        best_d = d;
        best = i;
      }
    }
    if (best == n) return;
    ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(best));
  }
}

void straighten(kernel::Polygon& outline) {
  kernel::Polygon p = outline;
  straighten_ring(p.outer);
  for (kernel::Ring& h : p.holes) straighten_ring(h);
  const kernel::RepairResult checked = kernel::repair(p);
  if (!checked.ok || checked.polygon.outer.size() != p.outer.size() ||
      checked.polygon.holes.size() != p.holes.size())
    return;
  outline = std::move(p);
}

bool check_outline(const Building& building, Work& work, std::vector<base::Diagnostic>& errors,
                   const std::string& file) {
  const Location where = building.outline_where.line > 0 ? building.outline_where : building.where;
  if (building.outline.outer.size() < 3) {
    errors.push_back(base::Diagnostic::error(
        "PLAN003",
        building.outline_file.empty()
            ? "the building has no outline"
            : "the outline from '" + building.outline_file + "' was not loaded",
        span_at(file, where)));
    return false;
  }
  const kernel::RepairResult repaired = kernel::repair(building.outline);
  if (!repaired.ok) {
    std::string why = "invalid";
    for (const kernel::PolygonIssue& issue : repaired.issues)
      if (!issue.repaired) {
        why = issue.message;
        break;
      }
    errors.push_back(base::Diagnostic::error(
        "PLAN004", "the building outline is not a valid polygon: " + why, span_at(file, where)));
    return false;
  }
  work.outline = repaired.polygon;
  plan::simplify(work.outline);
  straighten(work.outline);
  return true;
}

// PLAN007: the lot cannot hold the grammar (`insula build --keep-going` skips it with this reason).
base::Diagnostic cannot_hold(const std::string& file, const Building& building,
                             const std::string& why) {
  return base::Diagnostic::error("PLAN007", "the lot cannot hold this grammar: " + why,
                                 span_at(file, building.where));
}

// Storeys, parts and rooms of the plan from the work state (fake-concave: disposable parts and
// their rooms stay out, §3.2).
void assemble(Work& work, FloorPlan& out) {
  out.outline = work.outline;
  out.storeys.resize(static_cast<std::size_t>(work.levels));
  for (int level = 0; level < work.levels; ++level) out.storeys[level].level = level;
  std::vector<kernel::Polygon> kept;
  out.parts.reserve(work.parts.size());
  for (const plan::WorkPart& p : work.parts) {
    PlanPart part;
    part.symbol = p.node->symbol;
    part.where = p.node->where;
    part.roof = p.node->part->roof;
    part.roof_height = p.node->part->height;
    part.disposable = p.disposable();
    part.outline = p.cell;
    part.storeys = p.disposable() ? 0 : static_cast<int>(p.floors.size());
    part.door_width = work.door_widths[out.parts.size()];
    out.parts.push_back(std::move(part));
    if (p.disposable() || !p.has_cell) continue;
    kept.push_back(p.cell);
    for (int f : p.floors) {
      const plan::WorkFloor& floor = work.floors[f];
      PlanStorey& storey = out.storeys[floor.level];
      storey.height = std::max(storey.height, floor.height);
      for (const PlanDeadZone& z : floor.dead_zones) storey.dead_zones.push_back(z);
    }
  }
  double elevation = 0;
  for (PlanStorey& storey : out.storeys) {
    storey.elevation = elevation;
    elevation += storey.height;
  }
  for (PlanPart& part : out.parts)
    if (part.storeys > 0)
      part.eaves = out.storeys[part.storeys - 1].elevation + out.storeys[part.storeys - 1].height;
  out.footprint = kept.size() == 1 ? kept : kernel::union_all(kept);
  // Rooms, part by part in grammar order; each storey's list sized once (a room moved with every
  // growth).
  std::vector<std::size_t> rooms_of(out.storeys.size(), 0);
  for (const plan::WorkRoom& r : work.rooms)
    if (r.has_cell && r.division != nullptr && !work.parts[r.part].disposable() &&
        r.level < work.levels)
      ++rooms_of[static_cast<std::size_t>(r.level)];
  for (std::size_t level = 0; level < out.storeys.size(); ++level)
    out.storeys[level].rooms.reserve(rooms_of[level]);
  for (std::size_t p = 0; p < work.parts.size(); ++p) {
    const plan::WorkPart& wp = work.parts[p];
    if (wp.disposable()) continue;
    const double part_area = wp.has_cell ? kernel::area(wp.cell) : 0;
    for (int f : wp.floors) {
      const plan::WorkFloor& floor = work.floors[f];
      double floor_weight = 0;
      for (int r : floor.rooms) floor_weight += work.rooms[r].weight;
      for (int r : floor.rooms) {
        plan::WorkRoom& wr = work.rooms[r];
        if (!wr.has_cell) continue;
        const Room& room = *wr.division->room;
        PlanRoom pr;
        pr.symbol = wr.division->symbol;
        pr.type = room.type;
        pr.part = wp.node->symbol;
        pr.part_index = static_cast<int>(p);
        pr.storey = floor.level;
        pr.where = wr.division->where;
        pr.size = room.size;
        pr.cell = std::move(wr.cell);  // the work cells are not read past this stage
        pr.weight = floor_weight > 0 ? wr.weight / floor_weight : 0;
        pr.target_area = pr.weight * part_area;
        pr.walls_asked = room.walls;
        pr.windows_asked = room.windows;
        pr.entrance_asked = room.entrance;
        std::vector<PlanRoom>& rooms = out.storeys[floor.level].rooms;
        wr.plan_index = static_cast<int>(rooms.size());
        rooms.push_back(std::move(pr));
      }
    }
  }
}

// Cells of one storey agree exactly on shared boundaries (plan_geometry.h, weld).
void weld_storeys(FloorPlan& out) {
  for (PlanStorey& storey : out.storeys) {
    std::vector<kernel::Polygon*> cells;
    for (PlanRoom& r : storey.rooms) cells.push_back(&r.cell);
    for (PlanDeadZone& z : storey.dead_zones) cells.push_back(&z.cell);
    plan::weld(cells);
  }
}

}  // namespace

double default_door_width(double layout_perimeter, const Restrictions& restrictions) {
  if (restrictions.door_width_fraction <= 0) return restrictions.door_width;
  const double from_perimeter = restrictions.door_width_fraction * layout_perimeter;
  return std::max(restrictions.door_min_width, std::isfinite(from_perimeter) ? from_perimeter : 0);
}

int find_room(const PlanStorey& storey, const std::string& symbol) {
  for (std::size_t i = 0; i < storey.rooms.size(); ++i)
    if (storey.rooms[i].symbol == symbol) return static_cast<int>(i);
  return -1;
}

base::Result<FloorPlan> make_floor_plan(const Building& building, const Restrictions& restrictions,
                                        const FloorPlanOptions& options) {
  std::vector<base::Diagnostic> errors;
  Work work;
  work.file = options.file;
  work.sliver = options.on_lot ? 2 * restrictions.min_room_width : 0;
  if (!check_outline(building, work, errors, options.file))
    return base::Result<FloorPlan>::failure(std::move(errors));
  // Seed 000's treemap cuts along the axes of the building's frame: a turned lot is planned in the
  // frame of its walls and the plan turned back.
  const plan::PlanFrame frame = plan::lot_frame(work.outline);
  plan::into_frame(work.outline, frame);
  plan::build_work(building, restrictions, work, errors);
  if (work.levels == 0 && errors.empty()) {
    errors.push_back(base::Diagnostic::error(
        "PLAN005", "the building has no building part that is kept (all are disposable)",
        span_at(options.file, building.where)));
  }
  if (!errors.empty()) return base::Result<FloorPlan>::failure(std::move(errors));
  // A door keeps half the thickest wall meeting its wall plus 10 cm of jamb from each end.
  work.clearance =
      0.5 * std::max(restrictions.outer_wall_thickness, restrictions.inner_wall_thickness) + 0.1;

  plan::subdivide_all(work);  // §3.2, first arrangement
  for (const plan::WorkPart& p : work.parts)
    work.door_widths.push_back(
        default_door_width(p.has_cell ? kernel::perimeter(p.cell) : 0, restrictions));
  std::vector<plan::DoorRequest> doors = plan::collect_doors(work);
  plan::fit_doors(work, doors);  // §3.3 probing: weight borrowing
  // Past the paper: doors that connect every room, probed and borrowed for like the grammar's.
  for (int round = 0; options.guarantee_reachability && round < 64; ++round) {
    const std::size_t start = doors.size();
    if (plan::request_connections(work, doors) == 0) break;
    plan::fit_doors(work, doors, start);
  }

  // A part with no area: the lot cannot hold the grammar. A room with none is dropped (its
  // neighbours hold its floor).
  for (const plan::WorkPart& part : work.parts) {
    if (part.disposable() || part.has_cell) continue;
    errors.push_back(cannot_hold(options.file, building,
                                 "building part '" + part.node->symbol + "' gets no area"));
    return base::Result<FloorPlan>::failure(std::move(errors));
  }
  for (const plan::WorkRoom& room : work.rooms) {
    if (room.division == nullptr || room.has_cell || work.parts[room.part].disposable()) continue;
    ++work.adaptations.rooms_dropped;
    plan::warn(work, "room '" + room.division->symbol + "' gets no area on this lot; dropped",
               room.division->where, "BLD602");
  }

  FloorPlan out;
  assemble(work, out);  // §3.4: the last subdivision, fake-concave suppression
  weld_storeys(out);
  plan::place_doors(work, out, doors);
  plan::place_entrances(work, out);
  if (options.adapt_room_shapes) {
    plan::adapt_room_shapes(work, out);
    weld_storeys(out);
  }
  if (options.fit_rooms) plan::fit_rooms(work, out);
  plan::place_stairs(work, out);
  plan::guarantee_reachability(work, out, options.guarantee_reachability);
  // Never a broken building: a storey left without rooms, or a room still unreachable after
  // doors, stairs and merges, means the lot cannot hold the grammar.
  if (options.guarantee_reachability) {
    for (const PlanStorey& storey : out.storeys)
      if (storey.rooms.empty()) {
        errors.push_back(cannot_hold(options.file, building,
                                     "no room of " + plan::meters(restrictions.min_room_area) +
                                         " m² and " + plan::meters(restrictions.min_room_width) +
                                         " m wide fits on storey " + std::to_string(storey.level)));
        return base::Result<FloorPlan>::failure(std::move(errors));
      }
    if (!out.unreachable_rooms.empty()) {
      const PlanUnreachable& u = out.unreachable_rooms.front();
      errors.push_back(cannot_hold(options.file, building,
                                   "room '" + u.symbol + "' on storey " + std::to_string(u.storey) +
                                       " cannot be reached: " + u.reason));
      return base::Result<FloorPlan>::failure(std::move(errors));
    }
  }
  plan::place_windows(work, out);
  plan::build_walls(work, out);
  out.warnings = std::move(work.warnings);
  out.adaptations = work.adaptations;
  plan::out_of_frame(out, frame);
  return out;
}

}  // namespace insula::lang::bldg
