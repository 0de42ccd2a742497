// Rooms that fit the lot (past seed 000, whose buildings stand on the outlines they were written
// for): a grammar applied to any lot may leave rooms too small or too narrow to use, or rooms no
// door can reach. Such a room joins a neighbouring room (its doors, entrance and stairs go with
// it); a room touching no other room becomes a dead zone.
// docs/bldg-floorplan.md, "Rooms that fit".
#include <algorithm>

#include "kernel/boolean2d.h"
#include "lang/bldg/plan_geometry.h"
#include "lang/bldg/plan_stages.h"

namespace insula::lang::bldg::plan {
namespace {

using kernel::Polygon;

// Renumbers the rooms of storey `level` after room `gone` left it (its openings already moved to
// `into`, an index before the removal): indices above `gone` shift down by one.
void renumber(Work& work, FloorPlan& plan, int level, int gone, int into) {
  auto fix = [&](int& room) {
    if (room == gone) room = into;
    if (room > gone) --room;
  };
  PlanStorey& storey = plan.storeys[level];
  for (PlanDoor& d : storey.doors) {
    fix(d.room_a);
    fix(d.room_b);
  }
  for (PlanDoor& d : storey.entrances) fix(d.room_a);
  for (PlanStair& s : storey.stairs) fix(s.lower_room);
  if (level > 0)
    for (PlanStair& s : plan.storeys[level - 1].stairs) fix(s.upper_room);
  for (WorkRoom& r : work.rooms)
    if (r.level == level && r.plan_index >= 0) {
      if (r.plan_index == gone) r.plan_index = into;
      if (r.plan_index > gone) --r.plan_index;
    }
  storey.rooms.erase(storey.rooms.begin() + gone);
}

// Cells of a storey agree exactly on shared boundaries after a boolean moved some (weld).
void weld_storey(PlanStorey& storey) {
  std::vector<Polygon*> cells;
  for (PlanRoom& r : storey.rooms) cells.push_back(&r.cell);
  for (PlanDeadZone& z : storey.dead_zones) cells.push_back(&z.cell);
  weld(cells);
}

}  // namespace

bool narrower_than(const Polygon& cell, double width) {
  if (width <= 0) return false;
  const kernel::BooleanResult r = kernel::offset({cell}, -width / 2);
  return !r.ok() || r.polygons.empty();
}

bool merge_room(Work& work, FloorPlan& plan, int level, int x, const std::vector<bool>& allowed,
                const std::string& why) {
  PlanStorey& storey = plan.storeys[level];
  const PlanRoom& from = storey.rooms[x];
  // Neighbours by shared wall: one whose union with the room fits (a strip of a thin lot joins the
  // strip beside it and stays a strip; across, it makes a room), then rooms of the same part (a
  // room across two parts would stand under two roofs), then the longest wall.
  const Restrictions& rules = *work.restrictions;
  struct Candidate {
    bool fits;
    bool same_part;
    double length;
    int room;
    Polygon united;
  };
  std::vector<Candidate> candidates;
  for (std::size_t y = 0; y < storey.rooms.size(); ++y) {
    if (static_cast<int>(y) == x || (!allowed.empty() && !allowed[y])) continue;
    const double len = shared_length(from.cell, storey.rooms[y].cell);
    if (len <= kLineTolerance) continue;
    kernel::BooleanResult u = kernel::unite({storey.rooms[y].cell}, {from.cell});
    if (!u.ok() || u.polygons.size() != 1) continue;
    simplify(u.polygons[0]);
    const bool fits = kernel::area(u.polygons[0]) >= rules.min_room_area &&
                      !narrower_than(u.polygons[0], rules.min_room_width);
    candidates.push_back({fits, storey.rooms[y].part_index == from.part_index, len, int(y),
                          std::move(u.polygons[0])});
  }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Candidate& a, const Candidate& b) {
                     if (a.fits != b.fits) return a.fits;
                     return a.same_part != b.same_part ? a.same_part : a.length > b.length;
                   });
  if (candidates.empty()) return false;
  {
    Candidate& c = candidates.front();
    PlanRoom& into = storey.rooms[c.room];
    into.cell = std::move(c.united);
    into.area = kernel::area(into.cell);
    into.weight += from.weight;
    into.target_area += from.target_area;
    into.windows_asked = std::max(into.windows_asked, from.windows_asked);
    into.entrance_asked = into.entrance_asked || from.entrance_asked;
    into.merged.push_back(from.symbol);
    into.merged.insert(into.merged.end(), from.merged.begin(), from.merged.end());
    warn(work, "room '" + from.symbol + "' " + why + "; merged into '" + into.symbol + "'",
         from.where, "BLD602");
    // A door between the two rooms now stands inside one room.
    std::erase_if(storey.doors, [&](const PlanDoor& d) {
      return (d.room_a == x && d.room_b == c.room) || (d.room_a == c.room && d.room_b == x);
    });
    renumber(work, plan, level, x, c.room);
    weld_storey(storey);
    ++work.adaptations.rooms_merged;
  }
  return true;
}

void drop_room(Work& work, FloorPlan& plan, int level, int x, const std::string& why) {
  PlanStorey& storey = plan.storeys[level];
  PlanRoom& room = storey.rooms[x];
  warn(work, "room '" + room.symbol + "' " + why + " and touches no other room; dropped",
       room.where, "BLD602");
  storey.dead_zones.push_back({std::move(room.cell), "room '" + room.symbol + "' dropped: " + why});
  std::erase_if(storey.doors, [&](const PlanDoor& d) { return d.room_a == x || d.room_b == x; });
  std::erase_if(storey.entrances, [&](const PlanDoor& d) { return d.room_a == x; });
  std::erase_if(storey.stairs, [&](const PlanStair& s) { return s.lower_room == x; });
  if (level > 0)
    std::erase_if(plan.storeys[level - 1].stairs,
                  [&](const PlanStair& s) { return s.upper_room == x; });
  renumber(work, plan, level, x, -1);
  ++work.adaptations.rooms_dropped;
}

void fit_rooms(Work& work, FloorPlan& plan) {
  const Restrictions& r = *work.restrictions;
  for (std::size_t level = 0; level < plan.storeys.size(); ++level) {
    PlanStorey& storey = plan.storeys[level];
    // The smallest offending room first: it is the one a neighbour absorbs most easily, and its
    // neighbour may then be large enough. Each round merges or drops a room: at most as many
    // rounds as rooms.
    const std::size_t rounds = storey.rooms.size();
    for (std::size_t round = 0; round < rounds; ++round) {
      int worst = -1;
      double worst_area = 0;
      bool worst_narrow = false;
      for (std::size_t i = 0; i < storey.rooms.size(); ++i) {
        const double a = kernel::area(storey.rooms[i].cell);
        const bool small = a < r.min_room_area;
        const bool narrow = !small && narrower_than(storey.rooms[i].cell, r.min_room_width);
        if ((small || narrow) && (worst < 0 || a < worst_area)) {
          worst = static_cast<int>(i);
          worst_area = a;
          worst_narrow = narrow;
        }
      }
      if (worst < 0) break;
      const std::string why =
          worst_narrow ? "is narrower than " + meters(r.min_room_width) + " m on this lot"
                       : "has " + meters(worst_area) + " m² on this lot, below the minimum " +
                             meters(r.min_room_area) + " m²";
      if (!merge_room(work, plan, static_cast<int>(level), worst, {}, why))
        drop_room(work, plan, static_cast<int>(level), worst, why);
    }
  }
}

}  // namespace insula::lang::bldg::plan
