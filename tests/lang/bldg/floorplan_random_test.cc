// Floor-plan engine properties on 1,000 seeded random buildings (seed 000, §3.2-3.4 and the
// guarantees past it): room cells tile every storey, room areas follow their weights, doors sit on
// shared walls with at least the minimum width, openings sit on their walls, stairs lie inside
// both rooms, and every room is reachable from an entrance.
//
// The buildings come from a small generator in this file (rectangular outlines cut by the
// fake-concave technique into L, U, T and H shapes, nested containers with explicit and
// alternating orientations, one or two storeys, doors along the grammar order, windows and
// requested wall counts), so the test does not depend on the stochastic generator's choices.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "kernel/boolean2d.h"
#include "lang/bldg/floorplan.h"
#include "lang/bldg/plan_geometry.h"
#include "lang/bldg/stochastic.h"
#include "plan_test_util.h"

namespace insula::lang::bldg {
namespace {

using kernel::Polygon;
using kernel::Vec2;

// Room areas match their targets up to the boolean grid (1e-6 m along cuts of a few metres).
constexpr double kAreaTolerance = 5e-5;

using testing::Rng;

struct Generator {
  Rng rng;
  bool ask_walls = false;
  int counter = 0;

  Division rooms_tree(std::vector<Division> rooms) {
    if (rooms.size() <= 1) return rooms.empty() ? Division{} : rooms[0];
    Division d;
    d.symbol = "D" + std::to_string(counter++);
    const int o = rng.uniform(0, 5);
    d.orientation = o <= 3 ? Orientation::kAlternate
                           : (o == 4 ? Orientation::kHorizontal : Orientation::kVertical);
    if (rooms.size() <= 3 || rng.chance(0.3)) {
      d.children = std::move(rooms);
      return d;
    }
    const std::size_t cut =
        static_cast<std::size_t>(rng.uniform(1, static_cast<int>(rooms.size()) - 1));
    std::vector<Division> first(rooms.begin(), rooms.begin() + static_cast<std::ptrdiff_t>(cut));
    std::vector<Division> second(rooms.begin() + static_cast<std::ptrdiff_t>(cut), rooms.end());
    d.children.push_back(rooms_tree(std::move(first)));
    d.children.push_back(rooms_tree(std::move(second)));
    return d;
  }

  Floor floor(const std::string& part, int level, std::vector<std::string>& names) {
    std::vector<Division> rooms;
    const int n = rng.uniform(2, 6);
    for (int i = 0; i < n; ++i) {
      Division d;
      d.symbol = part + "_" + std::to_string(level) + "_" + std::to_string(i);
      Room r;
      r.type = "room";
      r.size = static_cast<SizeLabel>(rng.uniform(0, 2));
      r.windows = rng.uniform(0, 2);
      if (ask_walls && rng.chance(0.3)) r.walls = rng.uniform(3, 6);
      d.room = r;
      names.push_back(d.symbol);
      rooms.push_back(std::move(d));
    }
    Floor f;
    f.symbol = part + "_F" + std::to_string(level);
    f.layout = rooms_tree(std::move(rooms));
    return f;
  }

  PartNode part(const std::string& symbol, int floors, bool disposable,
                std::vector<std::vector<std::string>>& names) {
    PartNode n;
    n.symbol = symbol;
    BuildingPart p;
    p.disposable = disposable;
    p.height = disposable ? 0 : 2;
    p.roof = RoofKind::kHip;
    if (!disposable) {
      for (int level = 0; level < floors; ++level) {
        std::vector<std::string> floor_names;
        p.floors.push_back(floor(symbol, level, floor_names));
        names.push_back(floor_names);
      }
    }
    n.part = std::move(p);
    return n;
  }

  static PartNode container(const std::string& symbol, Orientation o, std::vector<PartNode> c) {
    PartNode n;
    n.symbol = symbol;
    n.orientation = o;
    n.children = std::move(c);
    return n;
  }

  Building make() {
    Building b;
    b.symbol = "B";
    ask_walls = rng.chance(0.25);
    const int floors = rng.chance(0.3) ? 2 : 1;
    std::vector<std::vector<std::string>> names;  // per kept floor: its rooms
    std::vector<int> floor_level;
    auto kept = [&](const std::string& s) {
      const std::size_t before = names.size();
      PartNode p = part(s, floors, false, names);
      for (std::size_t i = before; i < names.size(); ++i)
        floor_level.push_back(static_cast<int>(i - before));
      return p;
    };
    auto gap = [&](const std::string& s) { return part(s, 0, true, names); };
    const auto H = Orientation::kHorizontal;
    const auto V = Orientation::kVertical;
    switch (rng.uniform(0, 4)) {
      case 0:  // convex, 1-3 parts side by side
        if (rng.chance(0.3)) {
          b.layout = kept("A");
        } else {
          std::vector<PartNode> ps;
          const int n = rng.uniform(2, 3);
          for (int i = 0; i < n; ++i)
            ps.push_back(kept(std::string(1, static_cast<char>('A' + i))));
          b.layout = container("root", H, std::move(ps));
        }
        break;
      case 1: {  // L
        std::vector<PartNode> col;
        col.push_back(kept("B"));
        col.push_back(gap("g"));
        std::vector<PartNode> ps;
        ps.push_back(kept("A"));
        ps.push_back(container("col", V, std::move(col)));
        b.layout = container("root", H, std::move(ps));
        break;
      }
      case 2: {  // U
        std::vector<PartNode> col;
        col.push_back(kept("B"));
        col.push_back(gap("g"));
        std::vector<PartNode> ps;
        ps.push_back(kept("A"));
        ps.push_back(container("col", V, std::move(col)));
        ps.push_back(kept("C"));
        b.layout = container("root", H, std::move(ps));
        break;
      }
      case 3: {  // T
        std::vector<PartNode> row;
        row.push_back(gap("g1"));
        row.push_back(kept("B"));
        row.push_back(gap("g2"));
        std::vector<PartNode> ps;
        ps.push_back(container("row", H, std::move(row)));
        ps.push_back(kept("A"));
        b.layout = container("root", V, std::move(ps));
        break;
      }
      default: {  // H
        std::vector<PartNode> col;
        col.push_back(gap("g1"));
        col.push_back(kept("B"));
        col.push_back(gap("g2"));
        std::vector<PartNode> ps;
        ps.push_back(kept("A"));
        ps.push_back(container("col", V, std::move(col)));
        ps.push_back(kept("C"));
        b.layout = container("root", H, std::move(ps));
        break;
      }
    }
    // The outline is sized from the ground rooms (14-24 m² each, plus the disposable parts'
    // share: they weigh one medium room each), aspect 1 to 1.8.
    double rooms_area = 0;
    for (std::size_t i = 0; i < names.size(); ++i)
      if (floor_level[i] == 0)
        rooms_area += static_cast<double>(names[i].size()) * rng.real(14, 24);
    const double aspect = rng.real(1, 1.8);
    const double area = rooms_area * 1.35;
    const double w = std::sqrt(area * aspect);
    b.outline = plan::rectangle(0, 0, w, area / w);
    // Doors along the grammar order inside each floor, one across parts on the ground, an
    // entrance, and a stair per part with an upper floor.
    int t = 0;
    auto add = [&](TransitionKind kind, const std::string& from, const std::string& to) {
      Transition tr;
      tr.symbol = "t" + std::to_string(t++);
      tr.kind = kind;
      tr.from = from;
      tr.to = to;
      b.transitions.push_back(tr);
    };
    for (const std::vector<std::string>& f : names)
      for (std::size_t i = 0; i + 1 < f.size(); ++i)
        if (rng.chance(0.8)) add(TransitionKind::kDoor, f[i], f[i + 1]);
    std::vector<std::size_t> ground;
    for (std::size_t i = 0; i < names.size(); ++i)
      if (floor_level[i] == 0) ground.push_back(i);
    for (std::size_t i = 0; i + 1 < ground.size(); ++i)
      add(TransitionKind::kDoor, names[ground[i]].back(), names[ground[i + 1]].front());
    add(TransitionKind::kEntrance, names[0][0], "");
    for (std::size_t i = 0; i + 1 < names.size(); ++i)
      if (floor_level[i + 1] == floor_level[i] + 1)
        add(TransitionKind::kStair, names[i][rng.uniform(0, static_cast<int>(names[i].size()) - 1)],
            names[i + 1][0]);
    return b;
  }
};

bool on_boundary(const Polygon& cell, Vec2 p) {
  return kernel::locate(cell, p, 1e-5) == kernel::PointLocation::kBoundary;
}

// Everything the properties check for one plan; returns a description of the first violation.
std::string check(const Building& b, const FloorPlan& plan, const Restrictions& r,
                  bool check_areas) {
  // Tiling: every storey's cells and dead zones make exactly the parts present at that level.
  for (const PlanStorey& s : plan.storeys) {
    std::vector<Polygon> region;
    for (const PlanPart& p : plan.parts)
      if (!p.disposable && p.storeys > s.level) region.push_back(p.outline);
    std::vector<Polygon> cells;
    double sum = 0;
    for (const PlanRoom& room : s.rooms) {
      cells.push_back(room.cell);
      sum += kernel::area(room.cell);
      if (!room.cell.holes.empty() && b.outline.holes.empty()) return room.symbol + " has holes";
    }
    for (const PlanDeadZone& z : s.dead_zones) {
      cells.push_back(z.cell);
      sum += kernel::area(z.cell);
    }
    const double want = plan::area_of(kernel::union_all(region));
    if (std::abs(sum - want) > 1e-6 * want) return "storey cells overlap or leave gaps";
    const kernel::BooleanResult x =
        kernel::exclusive_or(kernel::union_all(cells), kernel::union_all(region));
    if (plan::area_of(x.polygons) > 1e-6 * want)
      return "storey cells do not tile the parts: xor " +
             std::to_string(plan::area_of(x.polygons)) + " of " + std::to_string(want) + " level " +
             std::to_string(s.level) + " dead " + std::to_string(s.dead_zones.size());
    for (const PlanRoom& room : s.rooms)
      if (check_areas && std::abs(room.area - room.target_area) > kAreaTolerance)
        return room.symbol + " area " + std::to_string(room.area) + " target " +
               std::to_string(room.target_area);
    // Doors on the wall the two rooms share, at least the minimum width.
    for (const PlanDoor& d : s.doors) {
      const Polygon& ca = s.rooms[d.room_a].cell;
      const Polygon& cb = s.rooms[d.room_b].cell;
      for (Vec2 p : {d.a, d.b, d.center})
        if (!on_boundary(ca, p) || !on_boundary(cb, p)) return "door off the shared wall";
      if (d.width < r.door_min_width - 1e-12) return "door narrower than the minimum";
      if (std::abs(kernel::length(d.b - d.a) - d.width) > 1e-9) return "door ends off its width";
      if (d.wall < 0) return "door without a wall";
      const PlanWall& w = s.walls[d.wall];
      if (!((w.left == d.room_a && w.right == d.room_b) ||
            (w.left == d.room_b && w.right == d.room_a)))
        return "door on a wall between other rooms";
      if (kernel::distance_to_segment(d.a, w.a, w.b) > 1e-6 ||
          kernel::distance_to_segment(d.b, w.a, w.b) > 1e-6)
        return "door sticks out of its wall: door " + std::to_string(d.a.x) + "," +
               std::to_string(d.a.y) + " " + std::to_string(d.b.x) + "," + std::to_string(d.b.y) +
               " wall " + std::to_string(w.a.x) + "," + std::to_string(w.a.y) + " " +
               std::to_string(w.b.x) + "," + std::to_string(w.b.y) + (d.added ? " added" : "");
    }
    for (const PlanDoor& d : s.entrances)
      if (d.wall < 0 || !s.walls[d.wall].exterior()) return "entrance not on an exterior wall";
    for (const PlanWindow& w : s.windows)
      if (w.wall < 0 || !s.walls[w.wall].exterior() || !on_boundary(s.rooms[w.room].cell, w.a) ||
          !on_boundary(s.rooms[w.room].cell, w.b))
        return "window not on an exterior wall of its room: wall " + std::to_string(w.wall) +
               (w.wall >= 0 ? " right " + std::to_string(s.walls[w.wall].right) : std::string()) +
               " on boundary " + std::to_string(on_boundary(s.rooms[w.room].cell, w.a)) +
               std::to_string(on_boundary(s.rooms[w.room].cell, w.b));
    for (const PlanStair& st : s.stairs) {
      if (!plan::covers({s.rooms[st.lower_room].cell}, st.footprint))
        return "stair outside its room";
      if (!plan::covers({plan.storeys[s.level + 1].rooms[st.upper_room].cell}, st.footprint))
        return "stair outside the room above";
    }
  }
  // Reachability, recomputed here from doors and stairs.
  const std::vector<std::vector<bool>> seen = testing::reached_rooms(plan);
  std::size_t unreachable = 0;
  for (const auto& level : seen) unreachable += std::count(level.begin(), level.end(), false);
  if (unreachable != plan.unreachable_rooms.size()) return "unreachable rooms misreported";
  // A room reported unreachable must be so for the reason given.
  for (const PlanUnreachable& u : plan.unreachable_rooms) {
    if (seen[u.storey][u.room]) return "reachable room reported unreachable";
    const PlanStorey& s = plan.storeys[u.storey];
    const double need = plan.parts[s.rooms[u.room].part_index].door_width +
                        2 * (0.5 * r.outer_wall_thickness + 0.1);
    double longest = 0;
    for (std::size_t v = 0; v < s.rooms.size(); ++v)
      if (seen[u.storey][v])
        for (const plan::EdgePiece& p :
             plan::shared_segments(s.rooms[u.room].cell, s.rooms[v].cell))
          longest = std::max(longest, p.length());
    const bool short_walls =
        u.reason.rfind("its longest wall", 0) == 0 || u.reason.rfind("it shares no wall", 0) == 0;
    if (short_walls && longest >= need) return "reason contradicted: " + u.reason;
    if (u.reason.rfind("no stair fits", 0) == 0 &&
        std::any_of(seen[u.storey].begin(), seen[u.storey].end(), [](bool x) { return x; }))
      return "reason contradicted: " + u.reason;
  }
  return "";
}

TEST(FloorPlanRandom, ThousandBuildingsKeepEveryProperty) {
  const Restrictions r;
  int failures = 0;
  int rooms = 0;
  int doors = 0;
  int borrowed_or_added = 0;
  int stairs = 0;
  int with_unreachable = 0;
  for (std::uint64_t seed = 1; seed <= 1000; ++seed) {
    Generator g{Rng{seed}};
    const Building b = g.make();
    const base::Result<FloorPlan> result = make_floor_plan(b, r);
    if (!result.ok()) {
      // A building whose thin parts hold no stair cannot be made whole: the one failure allowed,
      // with its reason (docs/bldg-floorplan.md, "Rooms that fit").
      ASSERT_EQ(result.diagnostics()[0].code, "PLAN007")
          << "seed " << seed << ": " << result.diagnostics()[0].message;
      ++with_unreachable;
      continue;
    }
    const FloorPlan& plan = result.value();
    bool walls_asked = false;
    for (const PlanStorey& s : plan.storeys) {
      rooms += static_cast<int>(s.rooms.size());
      doors += static_cast<int>(s.doors.size());
      stairs += static_cast<int>(s.stairs.size());
      for (const PlanDoor& d : s.doors) borrowed_or_added += d.added ? 1 : 0;
      for (const PlanRoom& room : s.rooms) walls_asked = walls_asked || room.walls_asked >= 3;
    }
    // Areas follow weights exactly unless room shape adaptation moved space between rooms.
    const std::string why = check(b, plan, r, !walls_asked);
    if (!plan.unreachable_rooms.empty()) ++with_unreachable;
    if (!why.empty()) {
      ++failures;
      ADD_FAILURE() << "seed " << seed << ": " << why;
      if (failures > 10) break;
    }
  }
  EXPECT_EQ(failures, 0);
  // Every room is reachable except in buildings whose generated parts are too thin for a door or
  // a stair (a 2 m deep part holding six rooms); those are reported with a checked reason. At
  // the time of writing: 3 of 1,000.
  EXPECT_LE(with_unreachable, 5);
  // The generator really exercises the engine.
  EXPECT_GT(rooms, 5000);
  EXPECT_GT(doors, 4000);
  EXPECT_GT(stairs, 200);
  RecordProperty("rooms", rooms);
  RecordProperty("added_doors", borrowed_or_added);
}

// The same properties on buildings of the stochastic generator (§4.3, stochastic.h): every shape,
// 1-5 parts, Table 2's room ranges. Its rooms are connected in its nominal layout, so the engine
// must reach every room.
TEST(FloorPlanRandom, StochasticBuildingsKeepEveryProperty) {
  const Restrictions r;
  const RandomShape shapes[] = {RandomShape::kConvex, RandomShape::kL, RandomShape::kU,
                                RandomShape::kT, RandomShape::kH};
  int failures = 0;
  int with_unreachable = 0;
  int rooms = 0;
  for (std::uint64_t i = 0; i < 300; ++i) {
    RandomSpec spec;
    spec.shape = shapes[i % 5];
    spec.parts = static_cast<int>(i / 5 % 5) + 1;
    spec.rooms_min = 3 + 2 * static_cast<int>(i % 3);
    spec.rooms_max = spec.rooms_min + 4;
    const Building b = random_building(spec, batch_seed(7, i));
    const base::Result<FloorPlan> result = make_floor_plan(b, r);
    ASSERT_TRUE(result.ok()) << "building " << i << ": " << result.diagnostics()[0].message;
    for (const PlanStorey& s : result->storeys) rooms += static_cast<int>(s.rooms.size());
    bool walls_asked = false;
    for (const PlanStorey& s : result->storeys)
      for (const PlanRoom& room : s.rooms) walls_asked = walls_asked || room.walls_asked >= 3;
    if (!result->unreachable_rooms.empty()) {
      ++with_unreachable;
      ADD_FAILURE() << "building " << i << " (" << random_shape_name(spec.shape) << ", "
                    << spec.parts << " parts): '" << result->unreachable_rooms[0].symbol
                    << "' unreachable: " << result->unreachable_rooms[0].reason;
    }
    const std::string why = check(b, result.value(), r, !walls_asked);
    if (!why.empty()) {
      ADD_FAILURE() << "building " << i << ": " << why;
      if (++failures > 10) break;
    }
  }
  EXPECT_EQ(failures, 0);
  EXPECT_EQ(with_unreachable, 0);
  EXPECT_GT(rooms, 3000);
}

// Odd footprints (past the paper's convex restriction polygon, §5): star-shaped concave outlines,
// some with a courtyard, under the same random programs. Cells may fall apart and cuts snap onto
// inner corners, so areas are not compared; everything else is.
TEST(FloorPlanRandom, ConcaveAndHoledOutlinesKeepTheTiling) {
  const Restrictions r;
  int failures = 0;
  int with_unreachable = 0;
  for (std::uint64_t seed = 1; seed <= 200; ++seed) {
    Generator g{Rng{seed * 7919}};
    Building b = g.make();
    const kernel::Bounds2 box = kernel::bounds(b.outline);
    const Vec2 c = (box.min + box.max) * 0.5;
    const double radius = 0.5 * std::max(box.max.x - box.min.x, box.max.y - box.min.y) * 1.1;
    Polygon star;
    const int n = g.rng.uniform(5, 12);
    for (int i = 0; i < n; ++i) {
      const double a = 6.283185307179586 * (i + g.rng.real(0.1, 0.9)) / n;
      const double rad = radius * g.rng.real(0.6, 1.0);
      star.outer.push_back({c.x + rad * std::cos(a), c.y + rad * std::sin(a)});
    }
    if (g.rng.chance(0.4)) {
      const double h = radius * 0.2;
      star.holes.push_back(
          {{c.x - h, c.y - h}, {c.x - h, c.y + h}, {c.x + h, c.y + h}, {c.x + h, c.y - h}});
    }
    b.outline = star;
    const base::Result<FloorPlan> result = make_floor_plan(b, r);
    if (!result.ok()) {
      // Only a lot that cannot hold the program may fail (a part squeezed out, a storey no stair
      // reaches), and it says why.
      ASSERT_EQ(result.diagnostics()[0].code, "PLAN007") << "seed " << seed;
      ++with_unreachable;
      continue;
    }
    if (!result->unreachable_rooms.empty()) ++with_unreachable;
    const std::string why = check(b, result.value(), r, false);
    if (!why.empty()) {
      ADD_FAILURE() << "seed " << seed << ": " << why;
      if (++failures > 10) break;
    }
  }
  EXPECT_EQ(failures, 0);
  EXPECT_LE(with_unreachable, 20);
  RecordProperty("with_unreachable", with_unreachable);
}

}  // namespace
}  // namespace insula::lang::bldg
