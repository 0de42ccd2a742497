// The reachability guarantee (past seed 000: the paper never checks that a room can be entered):
// every room must be reachable from an entrance through doors and stairs. Unreachable rooms get a
// door to a reachable neighbour on the same storey with a free slot on a shared wall; a storey the
// stairs do not reach gets a stair from a reachable room below; what stays unreachable is listed
// with the reason.
#include <algorithm>
#include <cstdio>
#include <tuple>

#include "base/union_find.h"
#include "kernel/boolean2d.h"
#include "lang/bldg/plan_geometry.h"
#include "lang/bldg/plan_openings.h"
#include "lang/bldg/plan_stages.h"

namespace insula::lang::bldg::plan {
namespace {

using Reach = std::vector<std::vector<bool>>;  // [level][room]

// Rooms reachable from the entrances through doors and stairs: doors and stairs join rooms both
// ways, so the rooms reached are those of the groups (union-find over rooms numbered across
// storeys) that hold an entrance room.
Reach reachable(const FloorPlan& plan) {
  Reach reach(plan.storeys.size());
  if (plan.storeys.empty()) return reach;
  const std::size_t levels = plan.storeys.size();
  std::vector<int> first(levels + 1, 0);  // global number of room r of storey s: first[s] + r
  for (std::size_t s = 0; s < levels; ++s)
    first[s + 1] = first[s] + static_cast<int>(plan.storeys[s].rooms.size());
  base::UnionFind groups(static_cast<std::size_t>(first[levels]));
  auto join = [&](int a, int b) { groups.unite(std::uint32_t(a), std::uint32_t(b)); };
  auto find = [&](int g) { return groups.find(std::uint32_t(g)); };
  for (std::size_t s = 0; s < levels; ++s) {
    const PlanStorey& storey = plan.storeys[s];
    for (const PlanDoor& d : storey.doors) join(first[s] + d.room_a, first[s] + d.room_b);
    if (s + 1 >= levels) continue;
    for (const PlanStair& st : storey.stairs)
      join(first[s] + st.lower_room, first[s + 1] + st.upper_room);
  }
  std::vector<bool> entered(groups.size(), false);  // by group root
  for (const PlanDoor& e : plan.storeys[0].entrances) entered[find(e.room_a)] = true;
  for (std::size_t s = 0; s < levels; ++s) {
    reach[s].assign(plan.storeys[s].rooms.size(), false);
    for (int g = first[s]; g < first[s + 1]; ++g) reach[s][g - first[s]] = entered[find(g)];
  }
  return reach;
}

// Adds one door from an unreachable room to a reachable neighbour; true when it did.
bool add_doors(Work& work, FloorPlan& plan, Reach& reach) {
  bool progress = false;
  for (std::size_t s = 0; s < plan.storeys.size(); ++s) {
    PlanStorey& storey = plan.storeys[s];
    const std::vector<kernel::Polygon> keep_out = stair_keep_out(plan, static_cast<int>(s));
    for (std::size_t u = 0; u < storey.rooms.size(); ++u) {
      if (reach[s][u]) continue;
      std::vector<std::pair<double, int>> neighbours;
      for (std::size_t v = 0; v < storey.rooms.size(); ++v) {
        if (!reach[s][v]) continue;
        const double len = shared_length(storey.rooms[u].cell, storey.rooms[v].cell);
        if (len > 0) neighbours.push_back({-len, static_cast<int>(v)});
      }
      std::sort(neighbours.begin(), neighbours.end());
      for (const auto& [len, v] : neighbours) {
        std::optional<PlanDoor> door = door_between(
            storey, static_cast<int>(u), v,
            door_width_between(work, storey.rooms[u].part_index, storey.rooms[v].part_index),
            work.clearance, keep_out);
        if (!door) continue;
        door->height = work.restrictions->door_height;
        door->added = true;
        ++work.adaptations.doors_added;
        storey.doors.push_back(*door);
        reach[s][u] = true;
        progress = true;
        warn(work,
             "door added between '" + storey.rooms[u].symbol + "' and '" + storey.rooms[v].symbol +
                 "' so that '" + storey.rooms[u].symbol + "' can be reached",
             storey.rooms[u].where);
        break;
      }
    }
  }
  return progress;
}

// Adds one stair from a reachable room to an unreachable room of the storey above.
bool add_stairs(Work& work, FloorPlan& plan, const Reach& reach) {
  for (std::size_t s = 1; s < plan.storeys.size(); ++s) {
    const PlanStorey& above = plan.storeys[s];
    const PlanStorey& below = plan.storeys[s - 1];
    if (std::find(reach[s].begin(), reach[s].end(), false) == reach[s].end()) continue;
    std::vector<std::tuple<double, int, int>> pairs;
    for (std::size_t u = 0; u < above.rooms.size(); ++u) {
      if (reach[s][u]) continue;
      for (std::size_t l = 0; l < below.rooms.size(); ++l) {
        if (!reach[s - 1][l]) continue;
        const kernel::BooleanResult o =
            kernel::intersect({below.rooms[l].cell}, {above.rooms[u].cell});
        const double a = o.ok() ? area_of(o.polygons) : 0;
        if (a > 1) pairs.push_back({-a, static_cast<int>(l), static_cast<int>(u)});
      }
    }
    std::sort(pairs.begin(), pairs.end());
    for (const auto& [a, l, u] : pairs) {
      if (!add_stair(work, plan, static_cast<int>(s - 1), l, u, "", {}, true)) continue;
      ++work.adaptations.stairs_added;
      warn(work,
           "stair added from '" + below.rooms[l].symbol + "' up to '" +
               plan.storeys[s].rooms[u].symbol + "' so that storey " + std::to_string(s) +
               " can be reached",
           plan.storeys[s].rooms[u].where);
      return true;
    }
  }
  return false;
}

// Past doors and stairs ("Rooms that fit"): one room no door reaches joins a reachable neighbour
// it shares a wall with; true when one did (room indices changed).
bool merge_unreachable(Work& work, FloorPlan& plan, const Reach& reach) {
  for (std::size_t s = 0; s < plan.storeys.size(); ++s)
    for (std::size_t u = 0; u < plan.storeys[s].rooms.size(); ++u)
      if (!reach[s][u] && merge_room(work, plan, static_cast<int>(s), static_cast<int>(u), reach[s],
                                     "cannot be reached by a door on this lot"))
        return true;
  return false;
}

// A ground-storey room that no door can reach (a piece of the footprint on its own) gets its own
// entrance: the unreachable room with the longest open-air wall that holds one. True when added.
bool add_island_entrance(Work& work, FloorPlan& plan, const Reach& reach) {
  if (plan.storeys.empty()) return false;
  const PlanStorey& ground = plan.storeys[0];
  std::vector<std::pair<double, int>> candidates;
  for (std::size_t u = 0; u < ground.rooms.size(); ++u) {
    if (reach[0][u]) continue;
    double longest = 0;
    for (const EdgePiece& p : open_air_pieces(ground, static_cast<int>(u), plan.footprint))
      longest = std::max(longest, p.length());
    if (longest > 0) candidates.push_back({-longest, static_cast<int>(u)});
  }
  std::sort(candidates.begin(), candidates.end());
  for (const auto& [len, u] : candidates)
    if (add_entrance(work, plan, u)) return true;
  return false;
}

std::string why_unreachable(const Work& work, const FloorPlan& plan, const Reach& reach, int s,
                            int u) {
  if (plan.storeys[0].entrances.empty()) return "the building has no entrance";
  const PlanStorey& storey = plan.storeys[s];
  const bool storey_reached = std::find(reach[s].begin(), reach[s].end(), true) != reach[s].end();
  if (!storey_reached)
    return "no stair fits between storey " + std::to_string(s - 1) + " and storey " +
           std::to_string(s) + " from a reachable room";
  double best = 0;
  for (std::size_t v = 0; v < storey.rooms.size(); ++v)
    if (reach[s][v])
      for (const EdgePiece& p : shared_segments(storey.rooms[u].cell, storey.rooms[v].cell))
        best = std::max(best, p.length());
  if (best <= 0) return "it shares no wall with a reachable room";
  const double need = work.door_widths[storey.rooms[u].part_index] + 2 * work.clearance;
  if (best < need)
    return "its longest wall shared with a reachable room is " + meters(best) +
           " m; a door needs " + meters(need) + " m";
  return "its walls shared with reachable rooms are taken by other openings or stairs";
}

}  // namespace

void guarantee_reachability(Work& work, FloorPlan& plan, bool repair) {
  Reach reach = reachable(plan);
  for (int round = 0; repair && round < 1000; ++round) {
    bool progress = add_doors(work, plan, reach);
    reach = reachable(plan);
    if (!progress) {
      progress = add_stairs(work, plan, reach);
      reach = reachable(plan);
    }
    if (!progress) {
      progress = merge_unreachable(work, plan, reach);
      reach = reachable(plan);
    }
    if (!progress) {
      progress = add_island_entrance(work, plan, reach);
      reach = reachable(plan);
    }
    if (!progress) break;
  }
  for (std::size_t s = 0; s < plan.storeys.size(); ++s) {
    for (std::size_t u = 0; u < plan.storeys[s].rooms.size(); ++u) {
      if (reach[s][u]) continue;
      PlanUnreachable entry;
      entry.storey = static_cast<int>(s);
      entry.room = static_cast<int>(u);
      entry.symbol = plan.storeys[s].rooms[u].symbol;
      entry.reason = why_unreachable(work, plan, reach, static_cast<int>(s), static_cast<int>(u));
      warn(work, "room '" + entry.symbol + "' cannot be reached: " + entry.reason,
           plan.storeys[s].rooms[u].where);
      plan.unreachable_rooms.push_back(std::move(entry));
    }
  }
}

}  // namespace insula::lang::bldg::plan
