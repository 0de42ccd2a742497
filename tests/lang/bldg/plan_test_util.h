// Reachability of a floor plan recomputed in the tests, independently of the engine
// (plan_reach.cc): a breadth-first search from the entrances through doors and stairs.
#pragma once

#include <queue>
#include <utility>
#include <vector>

#include "lang/bldg/floorplan.h"

namespace insula::lang::bldg::testing {

// SplitMix64: the same buildings and lots on every platform.
struct Rng {
  std::uint64_t state;
  std::uint64_t next() {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  int uniform(int lo, int hi) { return lo + static_cast<int>(next() % (hi - lo + 1)); }
  double real(double lo, double hi) { return lo + (hi - lo) * (next() >> 11) * 0x1.0p-53; }
  bool chance(double p) { return real(0, 1) < p; }
};

// Reachability: a breadth-first search from the entrances through doors and stairs.

// seen[level][room]: room reached from an entrance.
inline std::vector<std::vector<bool>> reached_rooms(const FloorPlan& plan) {
  std::vector<std::vector<bool>> seen(plan.storeys.size());
  for (std::size_t i = 0; i < plan.storeys.size(); ++i)
    seen[i].assign(plan.storeys[i].rooms.size(), false);
  if (plan.storeys.empty()) return seen;
  std::queue<std::pair<int, int>> q;
  auto visit = [&](int level, int x) {
    if (!seen[level][x]) {
      seen[level][x] = true;
      q.push({level, x});
    }
  };
  for (const PlanDoor& e : plan.storeys[0].entrances) visit(0, e.room_a);
  while (!q.empty()) {
    const auto [l, room] = q.front();
    q.pop();
    for (const PlanDoor& d : plan.storeys[l].doors) {
      if (d.room_a == room) visit(l, d.room_b);
      if (d.room_b == room) visit(l, d.room_a);
    }
    for (const PlanStair& st : plan.storeys[l].stairs)
      if (st.lower_room == room) visit(l + 1, st.upper_room);
    if (l > 0)
      for (const PlanStair& st : plan.storeys[l - 1].stairs)
        if (st.upper_room == room) visit(l - 1, st.lower_room);
  }
  return seen;
}

}  // namespace insula::lang::bldg::testing
