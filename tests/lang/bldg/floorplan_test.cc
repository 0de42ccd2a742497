// Floor-plan engine (seed 000, §3.2-3.4): small hand-made buildings with exact expected areas,
// door positions, fake-concave notches, concave and holed outlines, borrowing and stairs.
#include "lang/bldg/floorplan.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "kernel/boolean2d.h"
#include "lang/bldg/plan_geometry.h"
#include "lang/bldg/plan_treemap.h"
#include "lang/bldg/plan_weights.h"

namespace insula::lang::bldg {
namespace {

using kernel::Polygon;
using kernel::Vec2;

// Room areas match their targets up to the boolean grid: 1e-6 m along cuts of a few metres.
constexpr double kAreaTolerance = 2e-5;

Division room(const std::string& symbol, SizeLabel size = SizeLabel::kMedium, int walls = 0,
              int windows = 0, bool entrance = false, const std::string& type = "room") {
  Division d;
  d.symbol = symbol;
  d.room = Room{type, size, walls, windows, entrance};
  return d;
}

Division group(const std::string& symbol, Orientation o, std::vector<Division> children) {
  Division d;
  d.symbol = symbol;
  d.orientation = o;
  d.children = std::move(children);
  return d;
}

Floor floor_of(const std::string& symbol, Division layout) {
  Floor f;
  f.symbol = symbol;
  f.layout = std::move(layout);
  return f;
}

PartNode part(const std::string& symbol, std::vector<Floor> floors, bool disposable = false,
              RoofKind roof = RoofKind::kHip) {
  PartNode n;
  n.symbol = symbol;
  BuildingPart p;
  p.roof = roof;
  p.height = disposable ? 0 : 2;
  p.disposable = disposable;
  p.floors = std::move(floors);
  n.part = std::move(p);
  return n;
}

PartNode parts(const std::string& symbol, Orientation o, std::vector<PartNode> children) {
  PartNode n;
  n.symbol = symbol;
  n.orientation = o;
  n.children = std::move(children);
  return n;
}

Transition link(const std::string& symbol, TransitionKind kind, const std::string& from,
                const std::string& to = "", double width = 0) {
  Transition t;
  t.symbol = symbol;
  t.kind = kind;
  t.from = from;
  t.to = to;
  t.width = width;
  return t;
}

Polygon rect(double x0, double y0, double x1, double y1) {
  return plan::rectangle(x0, y0, x1, y1);
}

Building building_of(Polygon outline, PartNode layout, std::vector<Transition> transitions = {}) {
  Building b;
  // Moved in: copying the literals trips GCC 12's false -Wrestrict once this helper is inlined
  // into enough tests.
  b.symbol = std::string(1, 'B');
  b.name = std::string("test");
  b.outline = std::move(outline);
  b.layout = std::move(layout);
  b.transitions = std::move(transitions);
  return b;
}

FloorPlan plan_of(const Building& b, const Restrictions& r = {}) {
  base::Result<FloorPlan> result = make_floor_plan(b, r);
  EXPECT_TRUE(result.ok()) << (result.diagnostics().empty() ? "" : result.diagnostics()[0].message);
  return result.ok() ? result.value() : FloorPlan{};
}

bool has_warning(const FloorPlan& plan, const std::string& fragment) {
  return std::any_of(plan.warnings.begin(), plan.warnings.end(), [&](const PlanWarning& w) {
    return w.message.find(fragment) != std::string::npos;
  });
}

// Room cells and dead zones tile the storey: no overlap and the union is the footprint.
void expect_tiling(const FloorPlan& plan, const PlanStorey& storey,
                   const std::vector<Polygon>& region) {
  std::vector<Polygon> cells;
  double sum = 0;
  for (const PlanRoom& r : storey.rooms) {
    cells.push_back(r.cell);
    sum += kernel::area(r.cell);
  }
  for (const PlanDeadZone& z : storey.dead_zones) {
    cells.push_back(z.cell);
    sum += kernel::area(z.cell);
  }
  const double region_area = plan::area_of(region);
  EXPECT_NEAR(plan::area_of(kernel::union_all(cells)), region_area, 1e-6 * region_area);
  EXPECT_NEAR(sum, region_area, 1e-6 * region_area) << "cells overlap or leave gaps";
  const kernel::BooleanResult x = kernel::exclusive_or(cells, region);
  EXPECT_LT(plan::area_of(x.polygons), 1e-6 * region_area);
  (void)plan;
}

TEST(PlanWeights, GrowthFactorsOfFig3) {
  // Additive growth from 0.001: k = 250 rounds reach 1 (0.002 + 0.004 k >= 1).
  const std::vector<double> w = plan::distribute_weights({SizeLabel::kSmall, SizeLabel::kBig}, {});
  ASSERT_EQ(w.size(), 2u);
  EXPECT_NEAR(w[0], 0.376 / 1.002, 1e-12);
  EXPECT_NEAR(w[1], 0.626 / 1.002, 1e-12);
  const std::vector<double> three =
      plan::distribute_weights({SizeLabel::kMedium, SizeLabel::kMedium, SizeLabel::kMedium}, {});
  for (double x : three) EXPECT_NEAR(x, 1.0 / 3, 1e-12);
  EXPECT_TRUE(plan::distribute_weights({}, {}).empty());
}

TEST(PlanTreemap, ExactAreasOnConcaveRegion) {
  // An L: 10 x 10 minus the top-right 5 x 5 (75 m²), cut along x in weights 1 : 2.
  Polygon l{{{0, 0}, {10, 0}, {10, 5}, {5, 5}, {5, 10}, {0, 10}}, {}};
  const auto cells = plan::split_region({l}, {1, 2}, true, 0.01);
  ASSERT_EQ(cells.size(), 2u);
  EXPECT_NEAR(plan::area_of(cells[0]), 25, 1e-6);
  EXPECT_NEAR(plan::area_of(cells[1]), 50, 1e-6);
  // 25 m² of a 10 m tall strip: the cut is at x = 2.5.
  EXPECT_NEAR(plan::bounds_of(cells[0]).max.x, 2.5, 1e-6);
}

TEST(PlanTreemap, SlabOfAUFallsApart) {
  // A U opening upward: a horizontal slab across the arms gives two pieces.
  Polygon u{{{0, 0}, {9, 0}, {9, 9}, {6, 9}, {6, 3}, {3, 3}, {3, 9}, {0, 9}}, {}};
  const auto cells = plan::split_region({u}, {5, 1}, false, 0.01);
  EXPECT_EQ(cells[0].size(), 1u);
  EXPECT_EQ(cells[1].size(), 2u);  // the tops of both arms, above y = 7.25
  EXPECT_NEAR(plan::area_of(cells[0]), 52.5, 1e-6);
  EXPECT_NEAR(plan::area_of(cells[1]), 10.5, 1e-6);
}

TEST(PlanTreemap, CutNearAnInnerCornerSnapsOntoIt) {
  // Equal halves of the U would cut at y = 3.75, 0.75 m above the inner corner (y = 3): the cut
  // moves onto the corner instead of leaving a 0.75 m sliver under the courtyard of the U.
  Polygon u{{{0, 0}, {9, 0}, {9, 9}, {6, 9}, {6, 3}, {3, 3}, {3, 9}, {0, 9}}, {}};
  const auto cells = plan::split_region({u}, {1, 1}, false, 0.01);
  EXPECT_NEAR(plan::area_of(cells[0]), 27, 1e-6);
  EXPECT_NEAR(plan::area_of(cells[1]), 36, 1e-6);
  EXPECT_NEAR(plan::bounds_of(cells[0]).max.y, 3, 1e-9);
}

TEST(FloorPlan, TwoRoomsExactAreasDoorAndEntrance) {
  const Building b =
      building_of(rect(0, 0, 10, 6),
                  part("P", {floor_of("F", group("D", Orientation::kHorizontal,
                                                 {room("a", SizeLabel::kSmall, 0, 0, true),
                                                  room("b", SizeLabel::kBig)}))}),
                  {link("d1", TransitionKind::kDoor, "a", "b")});
  const FloorPlan plan = plan_of(b);
  ASSERT_EQ(plan.storeys.size(), 1u);
  const PlanStorey& s = plan.storeys[0];
  ASSERT_EQ(s.rooms.size(), 2u);
  EXPECT_NEAR(s.rooms[0].area, 60 * 0.376 / 1.002, kAreaTolerance);
  EXPECT_NEAR(s.rooms[1].area, 60 * 0.626 / 1.002, kAreaTolerance);
  EXPECT_NEAR(s.rooms[0].target_area, s.rooms[0].area, kAreaTolerance);
  const double cut = 10 * 0.376 / 1.002;
  EXPECT_NEAR(plan::bounds_of({s.rooms[0].cell}).max.x, cut, 1e-6);
  // Door width: the default 0.9 m, centred on the 6 m wall.
  EXPECT_DOUBLE_EQ(plan.parts[0].door_width, 0.9);
  ASSERT_EQ(s.doors.size(), 1u);
  EXPECT_NEAR(s.doors[0].center.x, cut, 1e-6);
  EXPECT_NEAR(s.doors[0].center.y, 3, 1e-6);
  EXPECT_NEAR(s.doors[0].width, 0.9, 1e-12);
  EXPECT_EQ(s.doors[0].symbol, "d1");
  EXPECT_GE(s.doors[0].wall, 0);
  // Entrance on a's longest open-air wall: the west wall x = 0, 6 m long.
  ASSERT_EQ(s.entrances.size(), 1u);
  EXPECT_NEAR(s.entrances[0].center.x, 0, 1e-9);
  EXPECT_NEAR(s.entrances[0].center.y, 3, 1e-9);
  EXPECT_EQ(s.rooms[0].neighbors, std::vector<int>{1});
  EXPECT_TRUE(plan.unreachable_rooms.empty());
  // Walls: a has 4 pieces (3 exterior + shared), b has 3 exterior: 7 in all, 1 inner.
  EXPECT_EQ(s.walls.size(), 7u);
  EXPECT_EQ(std::count_if(s.walls.begin(), s.walls.end(),
                          [](const PlanWall& w) { return !w.exterior(); }),
            1);
  expect_tiling(plan, s, {b.outline});
}

// Doors are 0.9 m and entrances 1.0 m whatever the building's size (the paper's share of the
// perimeter gave 2 m doors on this 100 m outline), unless a transition or the rules say otherwise.
TEST(FloorPlan, DoorWidthsAreAbsoluteUnlessStated) {
  const Building b = building_of(
      rect(0, 0, 30, 20),
      part("P", {floor_of(
                    "F", group("D", Orientation::kHorizontal, {room("a"), room("b"), room("c")}))}),
      {link("d1", TransitionKind::kDoor, "a", "b"),
       link("d2", TransitionKind::kDoor, "b", "c", 1.4),
       link("e1", TransitionKind::kEntrance, "a")});
  const auto widths = [&](const Restrictions& r) {
    const FloorPlan plan = plan_of(b, r);
    std::vector<double> out;
    const PlanStorey& s = plan.storeys[0];
    for (const char* symbol : {"d1", "d2"})
      for (const PlanDoor& d : s.doors)
        if (d.symbol == symbol) out.push_back(d.width);
    for (const PlanDoor& d : s.entrances) out.push_back(d.width);
    return out;
  };
  EXPECT_EQ(widths({}), (std::vector<double>{0.9, 1.4, 1.0}));
  Restrictions stated;
  stated.door_width = 1.1;
  stated.entrance_width = 1.3;
  EXPECT_EQ(widths(stated), (std::vector<double>{1.1, 1.4, 1.3}));
  Restrictions paper;  // §3.3: 2 % of the part's 100 m perimeter
  paper.door_width_fraction = 0.02;
  const std::vector<double> w = widths(paper);
  ASSERT_EQ(w.size(), 3u);
  EXPECT_NEAR(w[0], 2.0, 1e-9);
  EXPECT_EQ(w[1], 1.4);
  EXPECT_NEAR(w[2], 2.0, 1e-9);
}

TEST(FloorPlan, AxisAlternatesPerDepth) {
  // A floor's root starts across the longer side (x on this square's tie); its child container
  // cuts along y.
  const Building b =
      building_of(rect(0, 0, 8, 8),
                  part("P", {floor_of("F", group("D", Orientation::kAlternate,
                                                 {room("a"), group("E", Orientation::kAlternate,
                                                                   {room("b"), room("c")})}))}));
  const FloorPlan plan = plan_of(b);
  const PlanStorey& s = plan.storeys[0];
  // Weights 1/3 each: a gets the left third (x in [0, 8/3]); b and c split the rest along y.
  const kernel::Bounds2 ba = plan::bounds_of({s.rooms[0].cell});
  EXPECT_NEAR(ba.max.x, 8.0 / 3, 1e-6);
  EXPECT_NEAR(ba.max.y, 8, 1e-9);
  const kernel::Bounds2 bb = plan::bounds_of({s.rooms[1].cell});
  EXPECT_NEAR(bb.max.y, 4, 1e-6);
  EXPECT_NEAR(bb.min.x, 8.0 / 3, 1e-6);
  // A tall outline starts along y.
  const Building tall = building_of(
      rect(0, 0, 6, 9), part("P", {floor_of("F", group("D", Orientation::kAlternate,
                                                       {room("a"), room("b"), room("c")}))}));
  const FloorPlan tall_plan = plan_of(tall);
  EXPECT_NEAR(plan::bounds_of({tall_plan.storeys[0].rooms[0].cell}).max.y, 3, 1e-6);
}

TEST(FloorPlan, ConcaveOutlineTiles) {
  Polygon l{{{0, 0}, {12, 0}, {12, 6}, {6, 6}, {6, 12}, {0, 12}}, {}};
  const Building b = building_of(
      l,
      part("P", {floor_of("F", group("D", Orientation::kHorizontal,
                                     {room("a", SizeLabel::kMedium, 0, 0, true), room("b"),
                                      room("c")}))}),
      {link("d1", TransitionKind::kDoor, "a", "b"), link("d2", TransitionKind::kDoor, "b", "c")});
  const FloorPlan plan = plan_of(b);
  const PlanStorey& s = plan.storeys[0];
  ASSERT_EQ(s.rooms.size(), 3u);
  for (const PlanRoom& r : s.rooms) EXPECT_NEAR(r.area, 36, kAreaTolerance) << r.symbol;
  EXPECT_EQ(s.doors.size(), 2u);
  EXPECT_TRUE(plan.unreachable_rooms.empty());
  expect_tiling(plan, s, {l});
}

TEST(FloorPlan, HoledOutlineCourtyard) {
  Polygon o = rect(0, 0, 20, 20);
  o.holes.push_back({{7, 7}, {7, 13}, {13, 13}, {13, 7}});
  const Building b = building_of(
      o,
      part("P", {floor_of("F", group("D", Orientation::kHorizontal,
                                     {room("w", SizeLabel::kMedium, 0, 0, true),
                                      group("M", Orientation::kVertical, {room("s"), room("n")}),
                                      room("e")}))}),
      {link("d1", TransitionKind::kDoor, "w", "s"), link("d2", TransitionKind::kDoor, "w", "n"),
       link("d3", TransitionKind::kDoor, "s", "e")});
  const FloorPlan plan = plan_of(b);
  const PlanStorey& s = plan.storeys[0];
  expect_tiling(plan, s, {o});
  // Four equal weights over 364 m²: w and e take 91 m² each, the column s + n the rest.
  EXPECT_NEAR(s.rooms[0].area, 91, kAreaTolerance);
  EXPECT_NEAR(s.rooms[3].area, 91, kAreaTolerance);
  // The courtyard's walls are exterior walls: 24 m of them.
  double court = 0;
  for (const PlanWall& w : s.walls) {
    const Vec2 m = (w.a + w.b) * 0.5;
    if (w.exterior() && m.x > 6.9 && m.x < 13.1 && m.y > 6.9 && m.y < 13.1)
      court += kernel::length(w.b - w.a);
  }
  EXPECT_NEAR(court, 24, 1e-6);
  EXPECT_TRUE(plan.unreachable_rooms.empty());
  // The entrance opens on the street, not on the enclosed courtyard.
  ASSERT_EQ(s.entrances.size(), 1u);
  const Vec2 e = s.entrances[0].center;
  EXPECT_TRUE(e.x < 1e-9 || e.y < 1e-9 || e.x > 20 - 1e-9 || e.y > 20 - 1e-9);
}

TEST(FloorPlan, FakeConcaveL) {
  // Left part (2 rooms) beside a column of a kept part (bottom) and a disposable part (top).
  const Building b = building_of(
      rect(0, 0, 12, 10),
      parts("root", Orientation::kHorizontal,
            {part("left",
                  {floor_of("F1", group("D1", Orientation::kVertical,
                                        {room("a", SizeLabel::kMedium, 0, 0, true), room("b")}))}),
             parts("col", Orientation::kVertical,
                   {part("right", {floor_of("F2", room("c"))}),
                    part("void", {floor_of("F3", room("x"))}, true)})}),
      {link("d1", TransitionKind::kDoor, "a", "b"), link("d2", TransitionKind::kDoor, "a", "c"),
       link("d3", TransitionKind::kDoor, "b", "x")});
  const FloorPlan plan = plan_of(b);
  ASSERT_EQ(plan.parts.size(), 3u);
  EXPECT_TRUE(plan.parts[2].disposable);
  EXPECT_EQ(plan.parts[2].storeys, 0);
  const PlanStorey& s = plan.storeys[0];
  ASSERT_EQ(s.rooms.size(), 3u);  // x was suppressed with its part
  EXPECT_EQ(find_room(s, "x"), -1);
  // Four ground rooms of equal weight: the left part takes half the width, c a quarter.
  ASSERT_EQ(plan.footprint.size(), 1u);
  EXPECT_NEAR(kernel::area(plan.footprint[0]), 90, 1e-6);
  EXPECT_EQ(plan.footprint[0].outer.size(), 6u);  // an L
  EXPECT_NEAR(s.rooms[find_room(s, "c")].area, 30, kAreaTolerance);
  EXPECT_TRUE(has_warning(plan, "disposable"));
  EXPECT_EQ(s.doors.size(), 2u);  // a-b and a-c (across parts); b-x ignored
  expect_tiling(plan, s, plan.footprint);
  EXPECT_TRUE(plan.unreachable_rooms.empty());
}

TEST(FloorPlan, FakeConcaveUHasNotch) {
  const Building b = building_of(
      rect(0, 0, 15, 9),
      parts("root", Orientation::kHorizontal,
            {part("A", {floor_of("FA", room("a", SizeLabel::kMedium, 0, 1, true))}),
             parts("mid", Orientation::kVertical,
                   {part("B", {floor_of("FB", room("b"))}), part("gap", {}, true)}),
             part("C", {floor_of("FC", room("c", SizeLabel::kMedium, 0, 2))})}),
      {link("d1", TransitionKind::kDoor, "a", "b"), link("d2", TransitionKind::kDoor, "b", "c")});
  const FloorPlan plan = plan_of(b);
  ASSERT_EQ(plan.footprint.size(), 1u);
  EXPECT_EQ(plan.footprint[0].outer.size(), 8u);  // a U
  const PlanStorey& s = plan.storeys[0];
  expect_tiling(plan, s, plan.footprint);
  EXPECT_EQ(s.windows.size(), 3u);
  for (const PlanWindow& w : s.windows) {
    ASSERT_GE(w.wall, 0);
    EXPECT_TRUE(s.walls[w.wall].exterior());
  }
  EXPECT_TRUE(plan.unreachable_rooms.empty());
}

TEST(FloorPlan, BorrowingMakesDoorFit) {
  // b is the small room of four stacked in a 6 m column: 1 m tall, too short for a 0.9 m door
  // with 0.25 m clearances. Its siblings lend it weight (Fig. 4).
  const Building b = building_of(
      rect(0, 0, 10, 6),
      part("P", {floor_of("F", group("D", Orientation::kHorizontal,
                                     {room("a", SizeLabel::kBig, 0, 0, true),
                                      group("col", Orientation::kVertical,
                                            {room("b", SizeLabel::kSmall),
                                             room("c", SizeLabel::kBig), room("d", SizeLabel::kBig),
                                             room("e", SizeLabel::kBig)})}))}),
      {link("d1", TransitionKind::kDoor, "a", "b")});
  Restrictions r;
  FloorPlanOptions no_repair;
  no_repair.guarantee_reachability = false;
  const base::Result<FloorPlan> result = make_floor_plan(b, r, no_repair);
  ASSERT_TRUE(result.ok());
  const PlanStorey& s = result->storeys[0];
  const int ib = find_room(s, "b");
  ASSERT_EQ(s.doors.size(), 1u);
  EXPECT_EQ(s.doors[0].symbol, "d1");
  const kernel::Bounds2 bb = plan::bounds_of({s.rooms[ib].cell});
  EXPECT_GE(bb.max.y - bb.min.y, 0.9 + 2 * 0.25 - 1e-9);
  // b borrowed: its weight is above what Fig. 3 gave it (1.5 / 11.5 of the floor).
  EXPECT_GT(s.rooms[ib].weight, 1.5 / 11.5 + 0.01);
  // Areas match targets up to the boolean grid (1e-6 m along a cut of a few metres).
  EXPECT_NEAR(s.rooms[ib].area, s.rooms[ib].target_area, kAreaTolerance);
}

TEST(FloorPlan, DoorBetweenRoomsThatDoNotTouchIsDropped) {
  const Building b =
      building_of(rect(0, 0, 12, 4),
                  part("P", {floor_of("F", group("D", Orientation::kHorizontal,
                                                 {room("a", SizeLabel::kMedium, 0, 0, true),
                                                  room("b"), room("c")}))}),
                  {link("d1", TransitionKind::kDoor, "a", "c")});
  FloorPlanOptions no_repair;
  no_repair.guarantee_reachability = false;
  const base::Result<FloorPlan> result = make_floor_plan(b, {}, no_repair);
  ASSERT_TRUE(result.ok());
  EXPECT_TRUE(result->storeys[0].doors.empty());
  EXPECT_TRUE(has_warning(result.value(), "'d1'"));
  // Without the guarantee b and c are unreachable, with the reason.
  ASSERT_EQ(result->unreachable_rooms.size(), 2u);
  EXPECT_EQ(result->unreachable_rooms[0].symbol, "b");
  EXPECT_EQ(result->unreachable_rooms[0].reason,
            "its walls shared with reachable rooms are taken by other openings or stairs");
  // With it, doors a-b and b-c are added.
  const FloorPlan fixed = plan_of(b);
  EXPECT_TRUE(fixed.unreachable_rooms.empty());
  EXPECT_EQ(fixed.storeys[0].doors.size(), 2u);
  for (const PlanDoor& d : fixed.storeys[0].doors) EXPECT_TRUE(d.added);
}

TEST(FloorPlan, MissingEntranceIsAdded) {
  const Building b = building_of(
      rect(0, 0, 8, 3), part("P", {floor_of("F", group("D", Orientation::kHorizontal,
                                                       {room("a"), room("b", SizeLabel::kBig)}))}));
  const FloorPlan plan = plan_of(b);
  ASSERT_EQ(plan.storeys[0].entrances.size(), 1u);
  EXPECT_TRUE(plan.storeys[0].entrances[0].added);
  EXPECT_EQ(plan.storeys[0].entrances[0].room_a, 1);  // b has the longest open-air wall
  EXPECT_TRUE(has_warning(plan, "no entrance"));
  EXPECT_TRUE(plan.unreachable_rooms.empty());
}

TEST(FloorPlan, TwoStoreysWithStair) {
  const Building b = building_of(
      rect(0, 0, 12, 8),
      part("P",
           {floor_of("G", group("D0", Orientation::kAlternate,
                                {room("hall", SizeLabel::kMedium, 0, 0, true), room("kitchen")})),
            floor_of("U", group("D1", Orientation::kAlternate,
                                {room("bed", SizeLabel::kBig), room("bath", SizeLabel::kSmall)}))}),
      {link("d1", TransitionKind::kDoor, "hall", "kitchen"),
       link("s1", TransitionKind::kStair, "hall", "bed"),
       link("d2", TransitionKind::kDoor, "bed", "bath")});
  const FloorPlan plan = plan_of(b);
  ASSERT_EQ(plan.storeys.size(), 2u);
  EXPECT_DOUBLE_EQ(plan.storeys[1].elevation, 3.0);
  EXPECT_DOUBLE_EQ(plan.parts[0].eaves, 6.0);
  ASSERT_EQ(plan.storeys[0].stairs.size(), 1u);
  const PlanStair& st = plan.storeys[0].stairs[0];
  EXPECT_EQ(st.symbol, "s1");
  EXPECT_EQ(st.risers, 16);  // ceil(3 / 0.19)
  EXPECT_NEAR(st.run, 15 * 0.27, 1e-9);
  const PlanRoom& lower = plan.storeys[0].rooms[st.lower_room];
  const PlanRoom& upper = plan.storeys[1].rooms[st.upper_room];
  EXPECT_EQ(lower.symbol, "hall");
  EXPECT_EQ(upper.symbol, "bed");
  EXPECT_TRUE(plan::covers({lower.cell}, st.footprint));
  EXPECT_TRUE(plan::covers({upper.cell}, st.footprint));
  EXPECT_NEAR(kernel::area(st.footprint), 1.0 * 15 * 0.27, 1e-9);
  EXPECT_NEAR(kernel::length(st.head - st.foot), st.run, 1e-9);
  EXPECT_TRUE(plan.unreachable_rooms.empty());
  for (const PlanStorey& s : plan.storeys) expect_tiling(plan, s, {b.outline});
}

TEST(FloorPlan, UpperStoreyWithoutStairGetsOne) {
  const Building b = building_of(
      rect(0, 0, 10, 8), part("P", {floor_of("G", room("hall", SizeLabel::kMedium, 0, 0, true)),
                                    floor_of("U", room("loft"))}));
  const FloorPlan plan = plan_of(b);
  ASSERT_EQ(plan.storeys[0].stairs.size(), 1u);
  EXPECT_TRUE(plan.storeys[0].stairs[0].added);
  EXPECT_TRUE(plan.unreachable_rooms.empty());
}

TEST(FloorPlan, RoomShapeAdaptationAddsAndRemovesWalls) {
  const Building b = building_of(
      rect(0, 0, 12, 8),
      part("P", {floor_of("F", group("D", Orientation::kHorizontal,
                                     {room("a", SizeLabel::kMedium, 5, 0, true), room("b"),
                                      room("c", SizeLabel::kMedium, 6)}))}),
      {link("d1", TransitionKind::kDoor, "a", "b"), link("d2", TransitionKind::kDoor, "b", "c")});
  const FloorPlan plan = plan_of(b);
  const PlanStorey& s = plan.storeys[0];
  EXPECT_EQ(s.rooms[0].walls, 5);
  EXPECT_EQ(s.rooms[2].walls, 6);
  EXPECT_EQ(s.doors.size(), 2u);
  expect_tiling(plan, s, {b.outline});
  // Doors stayed on their walls.
  for (const PlanDoor& d : s.doors) {
    EXPECT_EQ(kernel::locate(s.rooms[d.room_a].cell, d.center, 1e-6),
              kernel::PointLocation::kBoundary);
    EXPECT_EQ(kernel::locate(s.rooms[d.room_b].cell, d.center, 1e-6),
              kernel::PointLocation::kBoundary);
  }
  EXPECT_TRUE(plan.unreachable_rooms.empty());
}

TEST(FloorPlan, InvalidOutlineIsAnError) {
  Building b = building_of(Polygon{{{0, 0}, {4, 4}, {4, 0}, {0, 4}}, {}},
                           part("P", {floor_of("F", room("a"))}));
  b.where = {3, 1};
  FloorPlanOptions o;
  o.file = "x.bldg";
  const base::Result<FloorPlan> r = make_floor_plan(b, {}, o);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.diagnostics()[0].code, "PLAN004");
  EXPECT_EQ(r.diagnostics()[0].span.line, 3u);
  Building empty = building_of(Polygon{}, part("P", {floor_of("F", room("a"))}));
  EXPECT_EQ(make_floor_plan(empty, {}).diagnostics()[0].code, "PLAN003");
}

}  // namespace
}  // namespace insula::lang::bldg
