// Stairs between storeys (past seed 000, which lists several storeys with stairs as open in §5): a
// straight flight whose footprint lies inside both the lower and the upper room (shrunk clear of
// the walls), with a landing at its foot in the lower room and at its head in the upper room, and
// out of the approach of every door on both storeys. Candidates run along each wall of the two
// rooms' overlap, both ways, sliding in 25 cm steps; a steep flight (ladder-like, as in Roman
// upper floors) is tried when a comfortable one does not fit.
#include <algorithm>
#include <cmath>

#include "kernel/boolean2d.h"
#include "lang/bldg/plan_geometry.h"
#include "lang/bldg/plan_openings.h"
#include "lang/bldg/plan_stages.h"
#include "lang/bldg/plan_transitions.h"

namespace insula::lang::bldg::plan {
namespace {

using kernel::Polygon;
using kernel::Vec2;

struct Flight {
  double riser_max;
  double tread;
  double landing;   // free floor before the first and after the last step (m)
  double approach;  // free floor kept in front of every door, both sides (m)
};
// Comfortable, steep, then ladder-like (the Roman upper floors' wooden stairs) with less room
// around it.
constexpr Flight kFlights[] = {
    {0.19, 0.27, 0.6, 0.9}, {0.22, 0.2, 0.6, 0.9}, {0.25, 0.14, 0.4, 0.6}};

std::vector<Polygon> door_zones(const PlanStorey& storey, double approach) {
  std::vector<Polygon> out;
  auto add = [&](const PlanDoor& d) {
    const Vec2 u = kernel::normalized(d.b - d.a);
    const Vec2 n = kernel::perp(u);
    out.push_back(oriented_rectangle(d.a - n * approach, u, n, d.width, 2 * approach));
  };
  for (const PlanDoor& d : storey.doors) add(d);
  for (const PlanDoor& d : storey.entrances) add(d);
  return out;
}

// How far a placement's rectangle is shrunk on every side before it is tested against rooms and
// obstacles. The rooms of a lot rounded to millimetres are not quite rectangles, so a landing set
// against a wall of one room can lie a hundredth of a millimetre outside the same wall as seen
// from the room above; tested at its full size, whether the stair fitted turned on such noise
// (a 9.8 m house got its stair at some rotations and not at others). A millimetre is far below
// the clearance already kept from walls (half a wall and 2 cm).
constexpr double kFitSlack = 0.001;

// The rectangle oriented_rectangle() makes, kFitSlack smaller on every side.
Polygon tested_rectangle(Vec2 from, Vec2 along, Vec2 inward, double length, double depth) {
  return oriented_rectangle(from + along * kFitSlack + inward * kFitSlack, along, inward,
                            length - 2 * kFitSlack, depth - 2 * kFitSlack);
}

// Obstacles are rectangles (door approaches, flights and stairwells).
bool clear(const std::vector<Polygon>& obstacles, const Polygon& p) {
  return std::none_of(obstacles.begin(), obstacles.end(),
                      [&](const Polygon& o) { return convex_overlap(o, p); });
}

std::optional<PlanStair> fit_flight(const std::vector<Polygon>& region, const Polygon& lower,
                                    const Polygon& upper, const std::vector<Polygon>& obstacles,
                                    double width, double run, int risers, double landing) {
  for (const Polygon& piece : region) {
    const kernel::Ring& ring = piece.outer;
    const std::size_t n = ring.size();
    std::vector<std::size_t> edges(n);
    for (std::size_t i = 0; i < n; ++i) edges[i] = i;
    std::stable_sort(edges.begin(), edges.end(), [&](std::size_t a, std::size_t b) {
      return kernel::length(ring[(a + 1) % n] - ring[a]) >
             kernel::length(ring[(b + 1) % n] - ring[b]);
    });
    for (std::size_t e : edges) {
      const Vec2 p = ring[e];
      const Vec2 q = ring[(e + 1) % n];
      const double len = kernel::length(q - p);
      if (len < run) continue;
      const Vec2 u = (q - p) / len;
      const Vec2 inward = kernel::perp(u);  // counter-clockwise ring: the inside is on the left
      for (double s = 0; s + run <= len + 1e-9; s += 0.25) {
        for (int dir = 0; dir < 2; ++dir) {
          const Vec2 start = p + u * s;
          const Polygon foot_print = tested_rectangle(start, u, inward, run, width);
          if (!convex_inside(piece, foot_print.outer) || !clear(obstacles, foot_print)) continue;
          // Ascent along +u (dir 0) or -u (dir 1).
          const Vec2 foot =
              dir == 0 ? start + inward * (width / 2) : start + u * run + inward * (width / 2);
          const Vec2 head = dir == 0 ? foot + u * run : foot - u * run;
          const Vec2 up = kernel::normalized(head - foot);
          const Polygon foot_landing = tested_rectangle(foot - up * landing - inward * (width / 2),
                                                        up, inward, landing, width);
          const Polygon head_landing =
              tested_rectangle(head - inward * (width / 2), up, inward, landing, width);
          if (!convex_inside(lower, foot_landing.outer) ||
              !convex_inside(upper, head_landing.outer))
            continue;
          if (!clear(obstacles, foot_landing) || !clear(obstacles, head_landing)) continue;
          PlanStair stair;
          stair.footprint = oriented_rectangle(start, u, inward, run, width);
          stair.foot = foot;
          stair.head = head;
          stair.width = width;
          stair.run = run;
          stair.risers = risers;
          return stair;
        }
      }
    }
  }
  return std::nullopt;
}

}  // namespace

bool add_stair(Work& work, FloorPlan& plan, int level, int lower, int upper,
               const std::string& symbol, Location where, bool added) {
  if (level + 1 >= static_cast<int>(plan.storeys.size())) return false;
  PlanStorey& below = plan.storeys[level];
  const PlanStorey& above = plan.storeys[level + 1];
  const Restrictions& r = *work.restrictions;
  const double margin = 0.5 * std::max(r.outer_wall_thickness, r.inner_wall_thickness) + 0.02;
  const kernel::BooleanResult overlap =
      kernel::intersect({below.rooms[lower].cell}, {above.rooms[upper].cell});
  if (!overlap.ok() || overlap.polygons.empty()) return false;
  const kernel::BooleanResult region = kernel::offset(overlap.polygons, -margin);
  const kernel::BooleanResult lower_clear = kernel::offset({below.rooms[lower].cell}, -margin);
  const kernel::BooleanResult upper_clear = kernel::offset({above.rooms[upper].cell}, -margin);
  if (!region.ok() || region.polygons.empty() || lower_clear.polygons.empty() ||
      upper_clear.polygons.empty())
    return false;
  std::vector<Polygon> stairs = stair_keep_out(plan, level);
  for (const Polygon& s : stair_keep_out(plan, level + 1)) stairs.push_back(s);
  const double width = r.stair_width > 0 ? r.stair_width : 1.0;
  for (const Flight& f : kFlights) {
    std::vector<Polygon> obstacles = door_zones(below, f.approach);
    for (Polygon& z : door_zones(above, f.approach)) obstacles.push_back(std::move(z));
    obstacles.insert(obstacles.end(), stairs.begin(), stairs.end());
    const int risers = std::max(2, static_cast<int>(std::ceil(below.height / f.riser_max - 1e-9)));
    const double run = (risers - 1) * f.tread;
    std::optional<PlanStair> stair =
        fit_flight(region.polygons, lower_clear.polygons[largest(lower_clear.polygons)],
                   upper_clear.polygons[largest(upper_clear.polygons)], obstacles, width, run,
                   risers, f.landing);
    if (!stair) continue;
    stair->symbol = symbol;
    stair->where = where;
    stair->lower_room = lower;
    stair->upper_room = upper;
    stair->added = added;
    below.stairs.push_back(*stair);
    return true;
  }
  return false;
}

void place_stairs(Work& work, FloorPlan& plan) {
  for (const Transition& t : work.building->transitions) {
    if (t.kind != TransitionKind::kStair) continue;
    int lower = -1;
    int upper = -1;
    for (int a : rooms_named(work, t.from))
      for (int b : rooms_named(work, t.to)) {
        if (lower >= 0) break;
        const int la = work.rooms[a].level;
        const int lb = work.rooms[b].level;
        if (lb == la + 1) {
          lower = a;
          upper = b;
        } else if (la == lb + 1) {
          lower = b;
          upper = a;
        }
      }
    if (lower < 0 || work.rooms[lower].plan_index < 0 || work.rooms[upper].plan_index < 0) {
      warn(work,
           "stair '" + t.symbol + "' must join a room to a room of the storey just above; ignored",
           t.where);
      continue;
    }
    if (!add_stair(work, plan, work.rooms[lower].level, work.rooms[lower].plan_index,
                   work.rooms[upper].plan_index, t.symbol, t.where, false)) {
      ++work.adaptations.transitions_dropped;
      warn(work,
           "stair '" + t.symbol + "' does not fit inside both '" + t.from + "' and '" + t.to +
               "' clear of their doors; dropped",
           t.where);
    }
  }
}

}  // namespace insula::lang::bldg::plan
