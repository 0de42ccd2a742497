#include "lang/bldg/plan_transitions.h"

#include <algorithm>
#include <functional>
#include <string_view>

#include "base/union_find.h"
#include "kernel/planar.h"
#include "lang/bldg/plan_geometry.h"

namespace insula::lang::bldg::plan {
namespace {

// A room listed under its symbol's hash (std::hash of the symbol), for finding the rooms of a
// symbol without a hash map of lists.
struct NamedRoom {
  std::size_t hash;
  int room;
  std::string_view symbol;
  friend bool operator<(const NamedRoom& a, const NamedRoom& b) {
    return a.hash < b.hash || (a.hash == b.hash && a.room < b.room);
  }
};

// What a borrowing attempt may change, to roll it back (§3.3: "borrowed space flows back").
struct Snapshot {
  std::vector<double> weights;
  std::vector<kernel::Polygon> room_cells;
  std::vector<bool> room_has;
  std::vector<kernel::Polygon> part_cells;
  std::vector<bool> part_has;
  std::vector<std::vector<PlanDeadZone>> dead_zones;
};

Snapshot take(const Work& work) {
  Snapshot s;
  for (const WorkRoom& r : work.rooms) {
    s.weights.push_back(r.weight);
    s.room_cells.push_back(r.cell);
    s.room_has.push_back(r.has_cell);
  }
  for (const WorkPart& p : work.parts) {
    s.part_cells.push_back(p.cell);
    s.part_has.push_back(p.has_cell);
  }
  for (const WorkFloor& f : work.floors) s.dead_zones.push_back(f.dead_zones);
  return s;
}

void restore(Work& work, const Snapshot& s) {
  for (std::size_t i = 0; i < work.rooms.size(); ++i) {
    work.rooms[i].weight = s.weights[i];
    work.rooms[i].cell = s.room_cells[i];
    work.rooms[i].has_cell = s.room_has[i];
  }
  for (std::size_t i = 0; i < work.parts.size(); ++i) {
    work.parts[i].cell = s.part_cells[i];
    work.parts[i].has_cell = s.part_has[i];
  }
  for (std::size_t i = 0; i < work.floors.size(); ++i) work.floors[i].dead_zones = s.dead_zones[i];
}

// Rooms of the same floor under the parent container of `room`, other than `room` itself.
std::vector<int> siblings(const Work& work, int room) {
  const WorkRoom& r = work.rooms[room];
  if (r.floor < 0) return {};
  const WorkFloor& floor = work.floors[r.floor];
  int node = -1;
  for (std::size_t n = 0; n < floor.tree.size(); ++n)
    if (floor.tree[n].leaf == room) node = static_cast<int>(n);
  if (node < 0 || floor.tree[node].parent < 0) return {};
  std::vector<int> out;
  std::vector<int> stack = {floor.tree[node].parent};
  while (!stack.empty()) {
    const int n = stack.back();
    stack.pop_back();
    if (floor.tree[n].leaf >= 0 && floor.tree[n].leaf != room) out.push_back(floor.tree[n].leaf);
    for (int c : floor.tree[n].children) stack.push_back(c);
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Redoes the cells after the weights of `changed` rooms moved: the parts when a ground-floor
// weight moved (they weigh what their ground floor weighs), then the floors concerned (all of them
// when a part's cell changed).
void recompute(Work& work, const std::vector<int>& changed) {
  bool ground = false;
  for (int r : changed) ground = ground || work.rooms[r].level == 0;
  if (ground && subdivide_parts(work)) {
    for (std::size_t f = 0; f < work.floors.size(); ++f) subdivide_floor(work, static_cast<int>(f));
    return;
  }
  std::vector<int> floors;
  for (int r : changed)
    if (work.rooms[r].floor >= 0) floors.push_back(work.rooms[r].floor);
  std::sort(floors.begin(), floors.end());
  floors.erase(std::unique(floors.begin(), floors.end()), floors.end());
  for (int f : floors) subdivide_floor(work, f);
}

bool all_fit(const Work& work, const std::vector<DoorRequest>& doors, std::size_t upto) {
  for (std::size_t i = 0; i < upto; ++i)
    if (doors[i].accepted && !door_fits(work, doors[i].a, doors[i].b, doors[i].width)) return false;
  return door_fits(work, doors[upto].a, doors[upto].b, doors[upto].width);
}

// Tries lending weight to `borrower` from `lenders`, in four growing amounts up to the limit.
bool try_borrow(Work& work, std::vector<DoorRequest>& doors, std::size_t index, int borrower,
                const std::vector<int>& lenders) {
  if (lenders.empty()) return false;
  const double limit = std::clamp(work.restrictions->borrow_limit, 0.0, 0.95);
  if (limit <= 0) return false;
  const Snapshot before = take(work);
  std::vector<int> changed = lenders;
  changed.push_back(borrower);
  constexpr int kAmounts = 4;
  for (int k = 1; k <= kAmounts; ++k) {
    double lent = 0;
    for (int l : lenders) {
      const double give = before.weights[l] * limit * k / kAmounts;
      work.rooms[l].weight = before.weights[l] - give;
      lent += give;
    }
    work.rooms[borrower].weight = before.weights[borrower] + lent;
    recompute(work, changed);
    if (all_fit(work, doors, index)) return true;
  }
  restore(work, before);
  return false;
}

}  // namespace

int request_connections(Work& work, std::vector<DoorRequest>& doors) {
  const int n = static_cast<int>(work.rooms.size());
  base::UnionFind groups(static_cast<std::size_t>(n));
  auto unite = [&](int a, int b) { groups.unite(std::uint32_t(a), std::uint32_t(b)); };
  auto find_set = [&](int x) { return groups.find(std::uint32_t(x)); };
  std::vector<std::pair<int, int>> failed;
  for (const DoorRequest& d : doors) {
    if (d.accepted) unite(d.a, d.b);
    if (!d.accepted) failed.push_back({std::min(d.a, d.b), std::max(d.a, d.b)});
  }
  auto has_failed = [&](int a, int b) {
    return std::find(failed.begin(), failed.end(), std::pair{std::min(a, b), std::max(a, b)}) !=
           failed.end();
  };
  int added = 0;
  std::vector<bool> source(n, false);
  for (int r = 0; r < n; ++r) {
    const Division* d = work.rooms[r].division;
    source[r] = d != nullptr && d->room->entrance && work.rooms[r].level == 0;
  }
  for (const Transition& t : work.building->transitions)
    if (t.kind == TransitionKind::kEntrance)
      for (int r : rooms_named(work, t.from)) source[r] = work.rooms[r].level == 0;
  auto kept = [&](int r) {
    const WorkRoom& room = work.rooms[r];
    return room.division != nullptr && room.has_cell && !work.parts[room.part].disposable();
  };
  for (int level = 0; level < work.levels; ++level) {
    std::vector<int> rooms;
    for (int r = 0; r < n; ++r)
      if (kept(r) && work.rooms[r].level == level) rooms.push_back(r);
    // The main group: an entrance room's on the ground storey, else the first room's.
    int main_room = rooms.empty() ? -1 : rooms[0];
    for (int r : rooms)
      if (source[r]) {
        main_room = r;
        break;
      }
    // Longest shared wall piece of a pair of the storey, computed once and only for the pairs the
    // search below looks at (one room in the main group, the other not): when the grammar's doors
    // already join every room, none is. Boxes are taken once per room; pairs whose boxes do not
    // touch (most pairs of a large storey) share nothing.
    const std::size_t m = rooms.size();
    std::vector<double> shared;  // -1: not computed yet
    std::vector<kernel::Bounds2> boxes;
    auto shared_of = [&](std::size_t i, std::size_t j) {
      if (shared.empty()) {
        shared.assign(m * m, -1);
        for (int r : rooms) boxes.push_back(kernel::bounds(work.rooms[r].cell));
      }
      double& cached = shared[i * m + j];
      if (cached < 0) {
        cached = kernel::touches(boxes[i], boxes[j], kLineTolerance)
                     ? longest_shared_segment(work.rooms[rooms[i]].cell, boxes[i],
                                              work.rooms[rooms[j]].cell, boxes[j])
                     : 0;
        shared[j * m + i] = cached;
      }
      return cached;
    };
    std::vector<bool> in_main;
    for (std::size_t guard = 0; guard < rooms.size(); ++guard) {
      // The adjacent pair, one room in the main group, with the longest shared boundary.
      int best_a = -1;
      int best_b = -1;
      double best = 0;
      const std::uint32_t main_set = find_set(main_room);
      in_main.assign(m, false);
      std::size_t outside = 0;
      for (std::size_t i = 0; i < m; ++i) {
        in_main[i] = find_set(rooms[i]) == main_set;
        if (!in_main[i]) ++outside;
      }
      if (outside == 0) break;  // the storey is one group
      for (std::size_t i = 0; i < m; ++i) {
        const int a = rooms[i];
        if (!in_main[i]) continue;
        for (std::size_t j = 0; j < m; ++j) {
          const int b = rooms[j];
          if (in_main[j] || has_failed(a, b)) continue;
          const double len = i < j ? shared_of(i, j) : shared_of(j, i);
          if (len <= 0) continue;
          if (len > best) {
            best = len;
            best_a = a;
            best_b = b;
          }
        }
      }
      if (best_a < 0) break;
      DoorRequest request;
      request.a = best_a;
      request.b = best_b;
      request.width = door_width_between(work, work.rooms[best_a].part, work.rooms[best_b].part);
      request.added = true;
      doors.push_back(request);
      unite(best_a, best_b);
      ++added;
    }
  }
  return added;
}

std::vector<int> rooms_named(const Work& work, const std::string& symbol) {
  std::vector<int> out;
  for (std::size_t i = 0; i < work.rooms.size(); ++i) {
    const Division* d = work.rooms[i].division;
    if (d != nullptr && d->symbol == symbol) out.push_back(static_cast<int>(i));
  }
  return out;
}

std::vector<DoorRequest> collect_doors(Work& work) {
  std::vector<DoorRequest> out;
  // The rooms of every symbol, listed once (rooms_named per door scanned every room per door):
  // sorted by the symbol's hash then room, the rooms of a symbol are those of its hash's run that
  // bear it, in increasing room order. One list, where a hash map of lists allocated a node and a
  // list per symbol; hashes, where sorting the symbols themselves compared long common prefixes.
  const std::hash<std::string_view> hash_of;
  std::vector<NamedRoom> named;
  named.reserve(work.rooms.size());
  for (std::size_t i = 0; i < work.rooms.size(); ++i) {
    const Division* d = work.rooms[i].division;
    if (d != nullptr) named.push_back({hash_of(d->symbol), static_cast<int>(i), d->symbol});
  }
  std::sort(named.begin(), named.end());
  std::vector<int> from;
  std::vector<int> to;
  const auto rooms_of = [&](const std::string& symbol, std::vector<int>& rooms) {
    rooms.clear();
    const std::size_t h = hash_of(symbol);
    auto it = std::partition_point(named.begin(), named.end(),
                                   [&](const NamedRoom& e) { return e.hash < h; });
    for (; it != named.end() && it->hash == h; ++it)
      if (it->symbol == symbol) rooms.push_back(it->room);
  };
  for (const Transition& t : work.building->transitions) {
    if (t.kind != TransitionKind::kDoor) continue;
    rooms_of(t.from, from);
    rooms_of(t.to, to);
    if (from.empty() || to.empty()) {
      warn(work, "door '" + t.symbol + "' names a room that does not exist; ignored", t.where);
      continue;
    }
    int a = -1;
    int b = -1;
    for (int x : from)
      for (int y : to)
        if (a < 0 && x != y && work.rooms[x].level == work.rooms[y].level) {
          a = x;
          b = y;
        }
    if (a < 0) {
      warn(work, "door '" + t.symbol + "' joins rooms on different storeys (use a stair); ignored",
           t.where);
      continue;
    }
    if (work.parts[work.rooms[a].part].disposable() ||
        work.parts[work.rooms[b].part].disposable()) {
      warn(work, "door '" + t.symbol + "' touches a disposable part; ignored (fake-concave)",
           t.where);
      continue;
    }
    DoorRequest request;
    request.transition = &t;
    request.a = a;
    request.b = b;
    request.width =
        t.width > 0 ? t.width : door_width_between(work, work.rooms[a].part, work.rooms[b].part);
    out.push_back(request);
  }
  return out;
}

double longest_shared(const Work& work, int a, int b) {
  const WorkRoom& ra = work.rooms[a];
  const WorkRoom& rb = work.rooms[b];
  if (!ra.has_cell || !rb.has_cell) return 0;
  return longest_shared_segment(ra.cell, kernel::bounds(ra.cell), rb.cell, kernel::bounds(rb.cell));
}

bool door_fits(const Work& work, int a, int b, double width) {
  return longest_shared(work, a, b) >= width + 2 * work.clearance - 1e-9;
}

void fit_doors(Work& work, std::vector<DoorRequest>& doors, std::size_t start) {
  for (std::size_t i = start; i < doors.size(); ++i) {
    DoorRequest& d = doors[i];
    if (door_fits(work, d.a, d.b, d.width)) {
      d.accepted = true;
      continue;
    }
    // Fig. 4: lend between the two rooms first, then from each room's siblings.
    std::vector<int> sib_a = siblings(work, d.a);
    std::vector<int> sib_b = siblings(work, d.b);
    std::erase(sib_a, d.b);
    std::erase(sib_b, d.a);
    const bool ok =
        try_borrow(work, doors, i, d.a, {d.b}) || try_borrow(work, doors, i, d.b, {d.a}) ||
        try_borrow(work, doors, i, d.a, sib_a) || try_borrow(work, doors, i, d.b, sib_b);
    d.accepted = ok;
    d.borrowed = ok;
    if (!ok && d.transition != nullptr) {
      ++work.adaptations.transitions_dropped;
      const double got = longest_shared(work, d.a, d.b);
      warn(work,
           "door '" + d.transition->symbol + "' between '" + room_name(work, d.a) + "' and '" +
               room_name(work, d.b) + "' does not fit (" +
               (got > 0 ? "their longest shared wall is " + std::to_string(got).substr(0, 5) + " m"
                        : std::string("they do not touch")) +
               ", the door needs " + std::to_string(d.width + 2 * work.clearance).substr(0, 5) +
               " m even after weight borrowing); dropped",
           d.transition->where);
    }
  }
}

}  // namespace insula::lang::bldg::plan
