// Placement of doors, entrance doors and windows on the final cells (seed 000, §3.3-3.4): doors on
// the longest wall two rooms share, entrances and windows on walls that face the open air.
#include <algorithm>
#include <cmath>
#include <optional>
#include <string_view>
#include <unordered_map>

#include "lang/bldg/plan_openings.h"
#include "lang/bldg/plan_stages.h"

namespace insula::lang::bldg::plan {
namespace {

using kernel::Polygon;

// Default width of an entrance door into part `part` (model.h, Restrictions::entrance_width).
double entrance_width(const Work& work, int part) {
  const Restrictions& r = *work.restrictions;
  return r.door_width_fraction > 0 ? std::max(r.entrance_width, work.door_widths[part])
                                   : r.entrance_width;
}

struct EntranceRequest {
  int room = -1;  // work room index
  std::string symbol;
  Location where;
  double width = 0;
};

// Places an entrance on the longest open-air wall of storey 0's room `index` that fits it.
std::optional<PlanDoor> entrance_for(const FloorPlan& plan, int index, double width,
                                     double clearance) {
  const PlanStorey& storey = plan.storeys[0];
  std::vector<EdgePiece> pieces = open_air_pieces(storey, index, plan.footprint);
  // Street side first: a wall on a courtyard (a hole of the footprint) leads nowhere unless the
  // room has no other; then the longest.
  auto street = [&](const EdgePiece& p) {
    const kernel::Vec2 m = (p.a + p.b) * 0.5;
    for (const Polygon& f : plan.footprint) {
      const std::size_t n = f.outer.size();
      for (std::size_t i = 0; i < n; ++i)
        if (kernel::distance_to_segment(m, f.outer[i], f.outer[(i + 1) % n]) < 1e-4) return true;
    }
    return false;
  };
  // Each piece's side and length found once (the sort compared them anew at every comparison),
  // then a stable insertion sort of the room's few pieces.
  struct Ranked {
    EdgePiece piece;
    bool street;
    double length;
  };
  std::vector<Ranked> ranked;
  ranked.reserve(pieces.size());
  for (const EdgePiece& p : pieces) ranked.push_back({p, street(p), p.length()});
  const auto before = [](const Ranked& x, const Ranked& y) {
    return x.street != y.street ? x.street : x.length > y.length;
  };
  for (std::size_t i = 1; i < ranked.size(); ++i)
    for (std::size_t j = i; j > 0 && before(ranked[j], ranked[j - 1]); --j)
      std::swap(ranked[j - 1], ranked[j]);
  const std::vector<Polygon> keep_out = stair_keep_out(plan, 0);
  for (const Ranked& r : ranked) {
    const EdgePiece& piece = r.piece;
    const std::optional<Slot> slot =
        find_slot(storey, piece.a, piece.b, width, clearance, keep_out);
    if (!slot) continue;
    PlanDoor door;
    door.room_a = index;
    door.room_b = kExteriorSide;
    door.a = slot->a;
    door.b = slot->b;
    door.center = slot->center;
    door.width = width;
    return door;
  }
  return std::nullopt;
}

std::vector<EntranceRequest> entrance_requests(Work& work) {
  std::vector<EntranceRequest> out;
  for (std::size_t r = 0; r < work.rooms.size(); ++r) {
    const WorkRoom& room = work.rooms[r];
    if (room.division == nullptr || !room.division->room->entrance) continue;
    out.push_back({static_cast<int>(r), "", room.division->where, entrance_width(work, room.part)});
  }
  for (const Transition& t : work.building->transitions) {
    if (t.kind != TransitionKind::kEntrance) continue;
    const std::vector<int> rooms = rooms_named(work, t.from);
    if (rooms.empty()) {
      warn(work, "entrance '" + t.symbol + "' names a room that does not exist; ignored", t.where);
      continue;
    }
    const double width = t.width > 0 ? t.width : entrance_width(work, work.rooms[rooms[0]].part);
    auto same = std::find_if(out.begin(), out.end(), [&](const EntranceRequest& e) {
      return e.room == rooms[0] && e.symbol.empty();
    });
    if (same != out.end()) {
      same->symbol = t.symbol;
      same->where = t.where;
      same->width = width;
    } else {
      out.push_back({rooms[0], t.symbol, t.where, width});
    }
  }
  return out;
}

}  // namespace

void place_doors(Work& work, FloorPlan& plan, const std::vector<DoorRequest>& doors) {
  // Each storey's openings indexed once (this stage only appends doors), when a door asks.
  std::vector<std::optional<OpeningIndex>> openings(plan.storeys.size());
  for (const DoorRequest& d : doors) {
    if (!d.accepted) continue;
    const WorkRoom& a = work.rooms[d.a];
    const WorkRoom& b = work.rooms[d.b];
    if (a.plan_index < 0 || b.plan_index < 0) continue;
    PlanStorey& storey = plan.storeys[a.level];
    std::optional<OpeningIndex>& index = openings[a.level];
    if (!index) index.emplace(storey);
    std::optional<PlanDoor> door =
        door_between(*index, a.plan_index, b.plan_index, d.width, work.clearance);
    if (!door) {
      if (d.transition != nullptr) ++work.adaptations.transitions_dropped;
      if (d.transition != nullptr)
        warn(work,
             "door '" + d.transition->symbol + "' finds no free place on the wall between '" +
                 room_name(work, d.a) + "' and '" + room_name(work, d.b) + "'; dropped",
             d.transition->where);
      continue;
    }
    if (d.transition != nullptr) {
      door->symbol = d.transition->symbol;
      door->where = d.transition->where;
    } else {
      door->added = true;
      ++work.adaptations.doors_added;
      warn(work,
           "door added between '" + room_name(work, d.a) + "' and '" + room_name(work, d.b) +
               "' so that every room can be reached",
           work.rooms[d.a].division->where);
    }
    door->height = work.restrictions->door_height;
    storey.doors.push_back(*door);
  }
}

void place_entrances(Work& work, FloorPlan& plan) {
  if (plan.storeys.empty()) return;
  for (const EntranceRequest& e : entrance_requests(work)) {
    const WorkRoom& room = work.rooms[e.room];
    if (room.plan_index < 0) continue;
    if (room.level > 0) {
      warn(work,
           "room '" + room_name(work, e.room) + "' is on storey " + std::to_string(room.level) +
               ": entrances are on the ground storey; ignored",
           e.where);
      continue;
    }
    std::optional<PlanDoor> door = entrance_for(plan, room.plan_index, e.width, work.clearance);
    if (!door) {
      ++work.adaptations.transitions_dropped;
      warn(work,
           "room '" + room_name(work, e.room) + "' has no open-air wall of " +
               meters(e.width + 2 * work.clearance) + " m for its entrance; dropped",
           e.where);
      continue;
    }
    door->symbol = e.symbol;
    door->where = e.where;
    door->height = work.restrictions->door_height;
    plan.storeys[0].entrances.push_back(*door);
  }
  if (!plan.storeys[0].entrances.empty()) return;
  // Past the paper: a building needs a way in. The room with the longest open-air wall gets one.
  int best = -1;
  double best_len = 0;
  const PlanStorey& ground = plan.storeys[0];
  for (std::size_t i = 0; i < ground.rooms.size(); ++i) {
    for (const EdgePiece& piece : open_air_pieces(ground, static_cast<int>(i), plan.footprint)) {
      if (piece.length() > best_len + 1e-9 &&
          entrance_for(plan, static_cast<int>(i), entrance_width(work, ground.rooms[i].part_index),
                       work.clearance)) {
        best_len = piece.length();
        best = static_cast<int>(i);
      }
    }
  }
  if (best < 0) {
    warn(work, "the building has no entrance and no room has an open-air wall long enough for one");
    return;
  }
  PlanDoor door = *entrance_for(plan, best, entrance_width(work, ground.rooms[best].part_index),
                                work.clearance);
  door.height = work.restrictions->door_height;
  door.added = true;
  ++work.adaptations.entrances_added;
  plan.storeys[0].entrances.push_back(door);
  warn(work,
       "the building has no entrance; one was added to room '" + ground.rooms[best].symbol + "'",
       ground.rooms[best].where);
}

bool add_entrance(Work& work, FloorPlan& plan, int room) {
  const PlanStorey& ground = plan.storeys[0];
  std::optional<PlanDoor> door =
      entrance_for(plan, room, entrance_width(work, ground.rooms[room].part_index), work.clearance);
  if (!door) return false;
  door->height = work.restrictions->door_height;
  door->added = true;
  ++work.adaptations.entrances_added;
  plan.storeys[0].entrances.push_back(*door);
  warn(work,
       "entrance added to room '" + ground.rooms[room].symbol +
           "': no door reaches it from the building's other entrances",
       ground.rooms[room].where);
  return true;
}

void place_windows(Work& work, FloorPlan& plan) {
  const Restrictions& r = *work.restrictions;
  // Window transitions by room symbol, in grammar order (listed once, not scanned per room).
  std::unordered_map<std::string_view, std::vector<const Transition*>> windows_of;
  for (const Transition& t : work.building->transitions)
    if (t.kind == TransitionKind::kWindow) windows_of[t.from].push_back(&t);
  const std::vector<const Transition*> no_windows;
  work.storey_cells.clear();
  work.storey_cells.reserve(plan.storeys.size());
  for (PlanStorey& storey : plan.storeys) {
    // Windows do not move cells: their pieces are kept for build_walls.
    const StoreyCells& cells = work.storey_cells.emplace_back(storey);
    OpeningIndex openings(storey);  // this stage only appends windows
    for (std::size_t i = 0; i < storey.rooms.size(); ++i) {
      PlanRoom& room = storey.rooms[i];
      const auto listed = windows_of.find(room.symbol);
      const std::vector<const Transition*>& named =
          listed == windows_of.end() ? no_windows : listed->second;
      const int asked = room.windows_asked + static_cast<int>(named.size());
      if (asked <= 0) continue;
      std::vector<EdgePiece> pieces =
          open_air_pieces(storey, cells, static_cast<int>(i), plan.footprint);
      // Share the windows among the open-air walls, the longest wall per window first.
      std::vector<int> count(pieces.size(), 0);
      for (int k = 0; k < asked; ++k) {
        int best = -1;
        double best_room = 0;
        for (std::size_t p = 0; p < pieces.size(); ++p) {
          const double share = pieces[p].length() / (count[p] + 1);
          if (share >= r.window_width + 2 * work.clearance && share > best_room) {
            best_room = share;
            best = static_cast<int>(p);
          }
        }
        if (best < 0) break;
        ++count[best];
      }
      int placed = 0;
      for (std::size_t p = 0; p < pieces.size(); ++p) {
        const double len = pieces[p].length();
        for (int j = 0; j < count[p]; ++j) {
          const std::size_t idx = static_cast<std::size_t>(placed);
          const double width =
              idx < named.size() && named[idx]->width > 0 ? named[idx]->width : r.window_width;
          const std::optional<Slot> slot =
              find_slot(openings, pieces[p].a, pieces[p].b, width, work.clearance, {},
                        len * (2 * j + 1) / (2 * count[p]));
          if (!slot) continue;
          PlanWindow w;
          w.symbol = idx < named.size() ? named[idx]->symbol : "";
          w.room = static_cast<int>(i);
          w.a = slot->a;
          w.b = slot->b;
          w.center = slot->center;
          w.width = width;
          w.sill = r.window_sill;
          w.height = r.window_height;
          storey.windows.push_back(w);
          ++placed;
        }
      }
      if (placed < asked) {
        warn(work,
             "room '" + room.symbol + "' asks for " + std::to_string(asked) +
                 " window(s); its open-air walls hold " + std::to_string(placed),
             room.where);
      }
    }
  }
}

}  // namespace insula::lang::bldg::plan
