// Room shape adaptation (seed 000, §3.4): "adding a wall implies the incorporation of a new segment
// that is attached considering the midpoints of two consecutive room's segments with the larger
// lengths, walls' removal consists ... in deleting a point unifying a pair of consecutive room's
// segments, whose lengths are the shorter", without disturbing placed doors and windows.
//
// The plan must stay a tiling (floorplan.h), so the space a change takes from a room goes to the
// neighbour sharing the longest boundary with it, or becomes a dead zone when no room borders it
// (a chamfered building corner); the space a removal adds (a reflex vertex) is taken from the rooms
// it covers, never from outside the storey. A cut stops short of any door or entrance on the two
// walls (by the door clearance), and is rejected when that leaves less than kMinCut of wall.
// Walls are removed first by sliding an edge (no new wall direction); the paper's vertex deletion
// draws a wall across a corner, so it is left out on an outline whose edges all run along x or y.
#include <algorithm>
#include <cmath>
#include <numeric>

#include "kernel/boolean2d.h"
#include "lang/bldg/plan_geometry.h"
#include "lang/bldg/plan_openings.h"
#include "lang/bldg/plan_stages.h"

namespace insula::lang::bldg::plan {
namespace {

using kernel::Polygon;
using kernel::Vec2;

constexpr double kMinCut = 0.5;     // shortest wall a cut may leave or make (m)
constexpr double kMinRoomArea = 1;  // a room never shrinks below this (m²)

// Distance from `v` along v->w to the nearest door or entrance on that edge of room `room`.
double free_from(const PlanStorey& storey, int room, Vec2 v, Vec2 w) {
  const Vec2 u = kernel::normalized(w - v);
  double best = kernel::length(w - v);
  auto consider = [&](const PlanDoor& d) {
    if (d.room_a != room && d.room_b != room) return;
    if (kernel::distance_to_segment(d.a, v, w) > 1e-5 ||
        kernel::distance_to_segment(d.b, v, w) > 1e-5)
      return;
    best = std::min(best, std::min(kernel::dot(d.a - v, u), kernel::dot(d.b - v, u)));
  };
  for (const PlanDoor& d : storey.doors) consider(d);
  for (const PlanDoor& d : storey.entrances) consider(d);
  return best;
}

// The one polygon of a boolean result, without holes (a room cell never gains a hole here).
std::optional<Polygon> single(const kernel::BooleanResult& r, std::size_t holes = 0) {
  if (!r.ok() || r.polygons.size() != 1 || r.polygons[0].holes.size() != holes) return std::nullopt;
  Polygon p = r.polygons[0];
  simplify(p);
  return p;
}

// The room other than `room` sharing the longest boundary with region `t`; -1 when none.
int taker_of(const PlanStorey& storey, int room, const Polygon& t) {
  int best = -1;
  double best_len = kLineTolerance;
  for (std::size_t j = 0; j < storey.rooms.size(); ++j) {
    if (static_cast<int>(j) == room) continue;
    const double len = shared_length(t, storey.rooms[j].cell);
    if (len > best_len) {
      best_len = len;
      best = static_cast<int>(j);
    }
  }
  return best;
}

// Gives region `t` (cut off room `room`) to the neighbour sharing most boundary with it, or to
// the dead zones. Returns the rooms changed, empty when it could not.
std::vector<int> give_away(PlanStorey& storey, int room, const Polygon& t, const std::string& why) {
  const int best = taker_of(storey, room, t);
  if (best < 0) {
    storey.dead_zones.push_back({t, why});
    return {room};
  }
  std::optional<Polygon> grown =
      single(kernel::unite({storey.rooms[best].cell}, {t}), storey.rooms[best].cell.holes.size());
  if (!grown) return {};
  storey.rooms[best].cell = *grown;
  return {room, best};
}

// Takes region `t` from the rooms it covers (for a room growing over a reflex vertex).
std::optional<std::vector<int>> take_from(PlanStorey& storey, int room, const Polygon& t) {
  std::vector<Polygon> cells;
  for (const PlanRoom& r : storey.rooms) cells.push_back(r.cell);
  for (const PlanDeadZone& z : storey.dead_zones) cells.push_back(z.cell);
  if (!covers(cells, t)) return std::nullopt;  // would reach outside the storey
  std::vector<int> changed = {room};
  for (std::size_t j = 0; j < storey.rooms.size(); ++j) {
    if (static_cast<int>(j) == room || !overlaps(storey.rooms[j].cell, t)) continue;
    std::optional<Polygon> shrunk =
        single(kernel::subtract({storey.rooms[j].cell}, {t}), storey.rooms[j].cell.holes.size());
    if (!shrunk || kernel::area(*shrunk) < kMinRoomArea) return std::nullopt;
    storey.rooms[j].cell = *shrunk;
    changed.push_back(static_cast<int>(j));
  }
  for (std::size_t z = 0; z < storey.dead_zones.size(); ++z) {
    if (!overlaps(storey.dead_zones[z].cell, t)) continue;
    kernel::BooleanResult rest = kernel::subtract({storey.dead_zones[z].cell}, {t});
    if (!rest.ok()) return std::nullopt;
    std::string why = storey.dead_zones[z].reason;
    storey.dead_zones.erase(storey.dead_zones.begin() + static_cast<std::ptrdiff_t>(z));
    for (Polygon& p : rest.polygons) storey.dead_zones.push_back({p, why});
    --z;
  }
  return changed;
}

struct Corner {
  std::size_t k;  // vertex index in the outer ring
  double score;   // length of the two edges meeting there
};

std::vector<Corner> corners(const kernel::Ring& ring, bool longest_first) {
  std::vector<Corner> out;
  const std::size_t n = ring.size();
  for (std::size_t k = 0; k < n; ++k) {
    const Vec2 p = ring[(k + n - 1) % n];
    const Vec2 v = ring[k];
    const Vec2 q = ring[(k + 1) % n];
    out.push_back({k, kernel::length(v - p) + kernel::length(q - v)});
  }
  std::stable_sort(out.begin(), out.end(), [&](const Corner& a, const Corner& b) {
    return longest_first ? a.score > b.score : a.score < b.score;
  });
  return out;
}

// One attempt on a copy of the storey; committed only when every opening stays on its wall.
bool commit_if_intact(PlanStorey& storey, PlanStorey& trial, const std::vector<int>& changed,
                      double clearance) {
  if (changed.empty() || !openings_intact(trial, changed, clearance)) return false;
  storey = std::move(trial);
  return true;
}

bool add_wall(PlanStorey& storey, int room, double clearance) {
  const kernel::Ring ring = storey.rooms[room].cell.outer;
  const std::size_t n = ring.size();
  for (const Corner& c : corners(ring, true)) {
    const Vec2 p = ring[(c.k + n - 1) % n];
    const Vec2 v = ring[c.k];
    const Vec2 q = ring[(c.k + 1) % n];
    if (kernel::cross(v - p, q - v) <= 1e-12) continue;  // only a convex corner can be cut
    // The paper's midpoints, pulled back toward the corner to spare doors on the two walls.
    const double d1 =
        std::min(kernel::length(v - p) / 2, free_from(storey, room, v, p) - clearance);
    const double d2 =
        std::min(kernel::length(q - v) / 2, free_from(storey, room, v, q) - clearance);
    if (d1 < kMinCut || d2 < kMinCut) continue;
    const Vec2 m1 = v + kernel::normalized(p - v) * d1;
    const Vec2 m2 = v + kernel::normalized(q - v) * d2;
    Polygon t{{m1, v, m2}, {}};
    kernel::normalize(t);
    if (!covers({storey.rooms[room].cell}, t)) continue;  // a concave room: the cut leaves it
    PlanStorey trial = storey;
    std::optional<Polygon> cut = single(kernel::subtract({trial.rooms[room].cell}, {t}),
                                        trial.rooms[room].cell.holes.size());
    if (!cut || kernel::area(*cut) < kMinRoomArea) continue;
    trial.rooms[room].cell = *cut;
    const std::vector<int> changed =
        give_away(trial, room, t, "corner cut off room '" + storey.rooms[room].symbol + "' (§3.4)");
    if (commit_if_intact(storey, trial, changed, clearance)) return true;
  }
  return false;
}

// Every edge of the outline runs along x or y (to 1e-9 of its length).
bool axis_parallel(const Polygon& outline) {
  const auto ring_ok = [](const kernel::Ring& ring) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Vec2 d = ring[(i + 1) % ring.size()] - ring[i];
      const double eps = 1e-9 * kernel::length(d);
      if (std::abs(d.x) > eps && std::abs(d.y) > eps) return false;
    }
    return true;
  };
  if (!ring_ok(outline.outer)) return false;
  for (const kernel::Ring& hole : outline.holes)
    if (!ring_ok(hole)) return false;
  return true;
}

// Removes two walls without a new wall direction: an edge whose neighbours run the same way (the
// end of a wing, or the bottom of a notch) slides along them until the shorter one vanishes. A
// wing's end gives the strip it sweeps to the neighbour sharing most boundary with it (never to a
// dead zone: the space stays in a room); a notch's bottom takes the strip from the rooms it
// covers. Smallest strip first.
bool slide_wall(PlanStorey& storey, int room, double clearance) {
  const kernel::Ring ring = storey.rooms[room].cell.outer;
  const std::size_t n = ring.size();
  if (n <= 4) return false;
  struct Slide {
    std::size_t k;  // the edge ring[k] -> ring[k + 1]
    Vec2 shift;
    double area;
  };
  std::vector<Slide> slides;
  for (std::size_t k = 0; k < n; ++k) {
    const Vec2 p = ring[(k + n - 1) % n];
    const Vec2 a = ring[k];
    const Vec2 b = ring[(k + 1) % n];
    const Vec2 c = ring[(k + 2) % n];
    const Vec2 u = kernel::normalized(p - a);
    const Vec2 w = kernel::normalized(c - b);
    if (std::abs(kernel::cross(u, w)) > 1e-9 || kernel::dot(u, w) <= 0) continue;
    const Vec2 shift = u * std::min(kernel::length(p - a), kernel::length(c - b));
    slides.push_back({k, shift, std::abs(kernel::cross(b - a, shift))});
  }
  std::stable_sort(slides.begin(), slides.end(),
                   [](const Slide& x, const Slide& y) { return x.area < y.area; });
  for (const Slide& s : slides) {
    const Vec2 a = ring[s.k];
    const Vec2 b = ring[(s.k + 1) % n];
    if (free_from(storey, room, a, b) < kernel::length(b - a)) continue;  // the edge holds a door
    Polygon t{{a, b, b + s.shift, a + s.shift}, {}};
    kernel::normalize(t);
    if (kernel::area(t) < 1e-9) continue;
    const Vec2 p = ring[(s.k + n - 1) % n];
    const bool wing = kernel::cross(a - p, b - a) > 0;  // convex ends: the strip is the room's
    PlanStorey trial = storey;
    Polygon& cell = trial.rooms[room].cell;
    std::vector<int> changed;
    if (wing) {
      if (!covers({cell}, t)) continue;
      const int taker = taker_of(trial, room, t);
      std::optional<Polygon> cut = single(kernel::subtract({cell}, {t}), cell.holes.size());
      if (taker < 0 || !cut || kernel::area(*cut) < kMinRoomArea) continue;
      cell = *cut;
      changed = give_away(trial, room, t, "");
    } else {
      std::optional<std::vector<int>> taken = take_from(trial, room, t);
      if (!taken) continue;
      std::optional<Polygon> grown = single(kernel::unite({cell}, {t}), cell.holes.size());
      if (!grown) continue;
      cell = *grown;
      changed = *taken;
    }
    if (wall_count(cell) >= static_cast<int>(n)) continue;
    if (commit_if_intact(storey, trial, changed, clearance)) return true;
  }
  return false;
}

bool remove_wall(PlanStorey& storey, int room, double clearance, bool axis_only) {
  if (slide_wall(storey, room, clearance)) return true;
  // The paper's vertex deletion draws a wall across the corner: not on an axis-parallel outline.
  if (axis_only) return false;
  const kernel::Ring ring = storey.rooms[room].cell.outer;
  const std::size_t n = ring.size();
  if (n <= 3) return false;
  for (const Corner& c : corners(ring, false)) {
    const Vec2 p = ring[(c.k + n - 1) % n];
    const Vec2 v = ring[c.k];
    const Vec2 q = ring[(c.k + 1) % n];
    // Both walls meeting at the vertex disappear: they must hold no door.
    if (free_from(storey, room, p, v) < kernel::length(v - p) ||
        free_from(storey, room, v, q) < kernel::length(q - v))
      continue;
    Polygon t{{p, v, q}, {}};
    kernel::normalize(t);
    if (kernel::area(t) < 1e-9) continue;
    PlanStorey trial = storey;
    const bool convex = kernel::cross(v - p, q - v) > 0;
    std::vector<int> changed;
    if (convex) {
      if (!covers({trial.rooms[room].cell}, t)) continue;  // the new wall would leave the room
      std::optional<Polygon> cut = single(kernel::subtract({trial.rooms[room].cell}, {t}),
                                          trial.rooms[room].cell.holes.size());
      if (!cut || kernel::area(*cut) < kMinRoomArea) continue;
      trial.rooms[room].cell = *cut;
      changed = give_away(trial, room, t,
                          "vertex removed from room '" + storey.rooms[room].symbol + "' (§3.4)");
    } else {
      std::optional<std::vector<int>> taken = take_from(trial, room, t);
      if (!taken) continue;
      std::optional<Polygon> grown =
          single(kernel::unite({trial.rooms[room].cell}, {t}), trial.rooms[room].cell.holes.size());
      if (!grown) continue;
      trial.rooms[room].cell = *grown;
      changed = *taken;
    }
    if (wall_count(trial.rooms[room].cell) >= static_cast<int>(n)) continue;
    if (commit_if_intact(storey, trial, changed, clearance)) return true;
  }
  return false;
}

}  // namespace

void adapt_room_shapes(Work& work, FloorPlan& plan) {
  const bool axis_only = axis_parallel(plan.outline);
  for (PlanStorey& storey : plan.storeys) {
    for (int pass = 0; pass < 2; ++pass) {
      for (std::size_t i = 0; i < storey.rooms.size(); ++i) {
        const int asked = storey.rooms[i].walls_asked;
        if (asked < 3) continue;
        for (int guard = 0; guard < 16; ++guard) {
          const int have = wall_count(storey.rooms[i].cell);
          if (have == asked) break;
          const bool ok = have < asked
                              ? add_wall(storey, static_cast<int>(i), work.clearance)
                              : remove_wall(storey, static_cast<int>(i), work.clearance, axis_only);
          if (!ok) break;
        }
      }
    }
    for (const PlanRoom& room : storey.rooms) {
      const int have = wall_count(room.cell);
      if (room.walls_asked >= 3 && have != room.walls_asked)
        warn(work,
             "room '" + room.symbol + "' asks for " + std::to_string(room.walls_asked) +
                 " walls; it has " + std::to_string(have) +
                 " (no corner could change without moving a door or leaving the storey)",
             room.where);
    }
  }
}

}  // namespace insula::lang::bldg::plan
