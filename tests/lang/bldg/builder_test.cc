// The 3D builder on hand-made floor plans (no floor-plan engine involved): exact clear-floor and
// slab areas, opening volumes, wall and roof counts, closed solids, roof heights for every roof
// kind, the HipGlued merge (§4.6), stairs and stairwells, entrance steps, footers, colours.
#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "kernel/mesh.h"
#include "lang/bldg/builder.h"
#include "lang/bldg/floorplan.h"

namespace insula::lang::bldg {
namespace {

using kernel::SemanticClass;
using kernel::Vec2;

kernel::Polygon rect(double x0, double y0, double x1, double y1) {
  return {{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, {}};
}

PlanWall wall(Vec2 a, Vec2 b, int left, int right, double thickness) {
  PlanWall w;
  w.a = a;
  w.b = b;
  w.left = left;
  w.right = right;
  w.thickness = thickness;
  return w;
}

PlanRoom room(std::string symbol, std::string type, kernel::Polygon cell) {
  PlanRoom r;
  r.symbol = std::move(symbol);
  r.type = std::move(type);
  r.part = "p";
  r.area = kernel::area(cell);
  r.cell = std::move(cell);
  return r;
}

PlanPart part(std::string symbol, kernel::Polygon outline, RoofKind roof, double height,
              double eaves = 3, int storeys = 1) {
  PlanPart p;
  p.symbol = std::move(symbol);
  p.roof = roof;
  p.roof_height = height;
  p.outline = std::move(outline);
  p.storeys = storeys;
  p.eaves = eaves;
  return p;
}

// A 10 x 8 m storey cut in two 5 x 8 rooms at x = 5: walls, a door between the rooms, an entrance
// into `a` through the south wall, a window in the east wall of `b`.
PlanStorey two_rooms(int level, double elevation, bool openings = true) {
  PlanStorey s;
  s.level = level;
  s.elevation = elevation;
  s.height = 3;
  s.rooms = {room(level == 0 ? "a" : "a1", "kitchen", rect(0, 0, 5, 8)),
             room(level == 0 ? "b" : "b1", "bedroom", rect(5, 0, 10, 8))};
  s.walls = {
      wall({0, 0}, {5, 0}, 0, kExteriorSide, 0.3),  wall({5, 0}, {5, 8}, 0, 1, 0.12),
      wall({5, 8}, {0, 8}, 0, kExteriorSide, 0.3),  wall({0, 8}, {0, 0}, 0, kExteriorSide, 0.3),
      wall({5, 0}, {10, 0}, 1, kExteriorSide, 0.3), wall({10, 0}, {10, 8}, 1, kExteriorSide, 0.3),
      wall({10, 8}, {5, 8}, 1, kExteriorSide, 0.3)};
  if (!openings) return s;
  PlanDoor door;
  door.room_a = 0;
  door.room_b = 1;
  door.wall = 1;
  door.a = {5, 3.5};
  door.b = {5, 4.5};
  door.center = {5, 4};
  door.width = 1;
  door.height = 2.1;
  s.doors.push_back(door);
  if (level == 0) {
    PlanDoor entrance = door;
    entrance.room_b = kExteriorSide;
    entrance.wall = 0;
    entrance.a = {2, 0};
    entrance.b = {3, 0};
    entrance.center = {2.5, 0};
    s.entrances.push_back(entrance);
  }
  PlanWindow window;
  window.room = 1;
  window.wall = 5;
  window.a = {10, 3};
  window.b = {10, 4.2};
  window.center = {10, 3.6};
  window.width = 1.2;
  window.sill = 0.9;
  window.height = 1.2;
  s.windows.push_back(window);
  return s;
}

FloorPlan one_storey(RoofKind roof = RoofKind::kHip, double height = 2, bool openings = true) {
  FloorPlan plan;
  plan.outline = rect(0, 0, 10, 8);
  plan.footprint = {plan.outline};
  plan.parts = {part("p", plan.outline, roof, height)};
  plan.storeys = {two_rooms(0, 0, openings)};
  return plan;
}

Building building() {
  Building b;
  b.symbol = "house";
  b.name = "House";
  return b;
}

const shape::Part* find_part(const BuildResult& r, const std::string& name) {
  for (const shape::Part& p : r.building.parts) {
    if (p.name == name) return &p;
  }
  return nullptr;
}

double area_of(const kernel::Mesh& mesh, SemanticClass semantic) {
  double total = 0;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    if (mesh.tag(f).semantic == semantic) total += kernel::face_area(mesh, f);
  }
  return total;
}

std::size_t faces_of(const kernel::Mesh& mesh, SemanticClass semantic) {
  std::size_t n = 0;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) n += mesh.tag(f).semantic == semantic;
  return n;
}

double top_of(const kernel::Mesh& mesh) {
  return mesh.bounds().max.z;
}

// Every solid the builder makes is closed and outward: each part is a union of closed,
// consistently oriented, manifold shells of positive volume.
void expect_closed(const BuildResult& r) {
  for (const shape::Part& p : r.building.parts) {
    const kernel::MeshCheck c = kernel::check(p.mesh);
    EXPECT_TRUE(c.closed) << p.name;
    EXPECT_TRUE(c.oriented) << p.name;
    EXPECT_EQ(c.non_manifold_edges, 0U) << p.name;
    EXPECT_GT(kernel::volume(p.mesh), 0) << p.name;
  }
}

TEST(Builder, CountsWallsOpeningsRoomsAndRoofs) {
  const BuildResult r = build_building(building(), one_storey(), Restrictions{});
  EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
  EXPECT_EQ(r.stats.storeys, 1U);
  EXPECT_EQ(r.stats.rooms, 2U);
  EXPECT_EQ(r.stats.walls, 7U);
  EXPECT_EQ(r.stats.doors, 1U);
  EXPECT_EQ(r.stats.entrances, 1U);
  EXPECT_EQ(r.stats.windows, 1U);
  EXPECT_EQ(r.stats.roofs, 1U);
  EXPECT_EQ(r.building.id, "house");
  // base, storey 0, two rooms, the roof.
  ASSERT_EQ(r.building.parts.size(), 5U);
  EXPECT_EQ(find_part(r, "storey 0")->kind, shape::PartKind::kStorey);
  EXPECT_EQ(find_part(r, "a")->kind, shape::PartKind::kRoom);
  EXPECT_EQ(find_part(r, "roof p")->kind, shape::PartKind::kBuildingPart);
  std::size_t vertices = 0;
  for (const shape::Part& p : r.building.parts) vertices += p.mesh.vertex_count();
  EXPECT_EQ(r.stats.vertices, vertices);
  expect_closed(r);
}

TEST(Builder, ClearFloorIsTheCellMinusTheWalls) {
  const BuildResult r = build_building(building(), one_storey(), Restrictions{});
  // x from 0.3 (outer wall) to 5 - 0.06 (half the inner wall), y from 0.3 to 7.7.
  const double clear = (5 - 0.3 - 0.06) * (8 - 0.6);
  for (const char* name : {"a", "b"}) {
    const shape::Part* p = find_part(r, name);
    ASSERT_NE(p, nullptr);
    EXPECT_NEAR(std::get<double>(p->attributes.at("area")), clear, 1e-3) << name;
    EXPECT_NEAR(area_of(p->mesh, SemanticClass::kFloorSurface), clear, 1e-6) << name;
    EXPECT_NEAR(area_of(p->mesh, SemanticClass::kCeilingSurface), clear, 1e-6) << name;
    EXPECT_EQ(std::get<double>(p->attributes.at("storey")), 0);
  }
  EXPECT_EQ(std::get<std::string>(find_part(r, "a")->attributes.at("type")), "kitchen");
  // Floor slab top at base + slab, ceiling slab below the storey's top.
  const shape::Part* a = find_part(r, "a");
  EXPECT_NEAR(a->mesh.bounds().min.z, 0.3, 1e-9);
  EXPECT_NEAR(a->mesh.bounds().max.z, 3.3, 1e-9);
}

TEST(Builder, DoorsAndWindowsAreHolesThroughTheWalls) {
  BuilderOptions options;
  options.frames = false;
  const BuildResult with = build_building(building(), one_storey(), Restrictions{}, options);
  const BuildResult without =
      build_building(building(), one_storey(RoofKind::kHip, 2, false), Restrictions{}, options);
  const double v_with = kernel::volume(find_part(with, "storey 0")->mesh);
  const double v_without = kernel::volume(find_part(without, "storey 0")->mesh);
  // Door 1 x 2.1 through 0.12 m, entrance 1 x 2.1 and window 1.2 x 1.2 through 0.3 m.
  EXPECT_NEAR(v_without - v_with, 1 * 2.1 * 0.12 + 1 * 2.1 * 0.3 + 1.2 * 1.2 * 0.3, 1e-6);
  EXPECT_GT(faces_of(find_part(with, "storey 0")->mesh, SemanticClass::kJamb), 0U);
  EXPECT_EQ(faces_of(find_part(without, "storey 0")->mesh, SemanticClass::kJamb), 0U);
}

TEST(Builder, FramesAndPanesCarryDoorAndWindowSemantics) {
  const BuildResult r = build_building(building(), one_storey(), Restrictions{});
  const kernel::Mesh& storey = find_part(r, "storey 0")->mesh;
  // Door frames: two posts and a head per face, two faces, two doors: 12 boxes of 6 faces.
  EXPECT_EQ(faces_of(storey, SemanticClass::kDoor), 12U * 6U);
  // Window: four pieces per face, two faces, plus the pane.
  EXPECT_EQ(faces_of(storey, SemanticClass::kWindow), 9U * 6U);
}

TEST(Builder, PlanHasRoomsWallsWithDoorGapsAndOpenings) {
  const BuildResult r = build_building(building(), one_storey(), Restrictions{});
  ASSERT_EQ(r.building.plans.size(), 1U);
  const shape::StoreyPlan& plan = r.building.plans.front();
  EXPECT_EQ(plan.name, "storey 0");
  EXPECT_NEAR(plan.elevation, 0.3, 1e-12);
  ASSERT_EQ(plan.rooms.size(), 2U);
  EXPECT_EQ(plan.rooms[0].name, "a");
  EXPECT_NEAR(plan.rooms[0].area, 4.64 * 7.4, 1e-6);
  // Seven walls, two of them cut in two by a door.
  EXPECT_EQ(plan.walls.size(), 9U);
  EXPECT_EQ(std::count_if(plan.walls.begin(), plan.walls.end(),
                          [](const shape::PlanWall& w) { return w.exterior; }),
            7);
  ASSERT_EQ(plan.openings.size(), 3U);
  std::multiset<shape::PlanOpeningKind> kinds;
  for (const auto& o : plan.openings) kinds.insert(o.kind);
  EXPECT_EQ(kinds.count(shape::PlanOpeningKind::kDoor), 1U);
  EXPECT_EQ(kinds.count(shape::PlanOpeningKind::kEntrance), 1U);
  EXPECT_EQ(kinds.count(shape::PlanOpeningKind::kWindow), 1U);
  for (const auto& o : plan.openings) {
    if (o.kind != shape::PlanOpeningKind::kEntrance) continue;
    // Hinged on the inner face of the south wall, swinging north into the room.
    EXPECT_NEAR(o.a.y, 0.3, 1e-12);
    EXPECT_NEAR(o.swing.y, 1, 1e-12);
  }
}

TEST(Builder, EntranceStepsClimbToTheThreshold) {
  const BuildResult r = build_building(building(), one_storey(), Restrictions{});
  const kernel::Mesh& base = find_part(r, "base")->mesh;
  EXPECT_NEAR(area_of(base, SemanticClass::kGroundSurface), 80, 1e-9);  // the plinth
  double top = 0;
  double south = 0;
  for (std::size_t f = 0; f < base.face_count(); ++f) {
    if (base.tag(f).semantic != SemanticClass::kStair) continue;
    for (std::uint32_t v : base.face(f)) {
      top = std::max(top, base.position(v).z);
      south = std::min(south, base.position(v).y);
    }
  }
  // Base 0.3 + slab 0.1 = 0.4 m in ceil(0.4 / 0.15) = 3 steps of 0.3 m, outside the south wall.
  EXPECT_NEAR(top, 0.4, 1e-9);
  EXPECT_NEAR(south, -0.9, 1e-9);
}

TEST(Builder, FootersLeaveTheDoorGapFree) {
  const BuildResult r = build_building(building(), one_storey(), Restrictions{});
  const kernel::Mesh& a = find_part(r, "a")->mesh;
  std::size_t footer_faces = 0;
  for (std::size_t f = 0; f < a.face_count(); ++f) {
    if (a.tag(f).material == 0 || a.tag(f).semantic != SemanticClass::kInteriorWallSurface)
      continue;
    ++footer_faces;
    for (std::uint32_t v : a.face(f)) {
      const kernel::Vec3 p = a.position(v);
      // Nothing inside the door gap (y 3.5..4.5 by the inner wall at x = 4.94).
      EXPECT_FALSE(p.x > 4.8 && p.y > 3.5 + 1e-6 && p.y < 4.5 - 1e-6) << p.x << " " << p.y;
    }
  }
  EXPECT_GT(footer_faces, 0U);
}

TEST(Builder, EveryRoofKindReachesItsHeight) {
  for (const RoofKind kind : {RoofKind::kHip, RoofKind::kGable, RoofKind::kPyramid,
                              RoofKind::kMansard, RoofKind::kHoledMansard, RoofKind::kHipGlued}) {
    const BuildResult r = build_building(building(), one_storey(kind, 2.5), Restrictions{});
    const shape::Part* roof = find_part(r, "roof p");
    ASSERT_NE(roof, nullptr) << static_cast<int>(kind);
    // Plinth 0.3 + storey 3 + roof 2.5.
    EXPECT_NEAR(top_of(roof->mesh), 5.8, 1e-9) << static_cast<int>(kind);
    EXPECT_GT(area_of(roof->mesh, SemanticClass::kRoofSurface), 80) << static_cast<int>(kind);
    expect_closed(r);
    EXPECT_TRUE(r.warnings.empty()) << static_cast<int>(kind) << ": " << r.warnings.front();
  }
  const BuildResult flat =
      build_building(building(), one_storey(RoofKind::kFlat, 1), Restrictions{});
  // A 0.25 m slab over the outline plus 0.3 m of overhang all round.
  const kernel::Mesh& slab = find_part(flat, "roof p")->mesh;
  EXPECT_NEAR(area_of(slab, SemanticClass::kRoofSurface), 10.6 * 8.6, 1e-6);
  EXPECT_NEAR(kernel::volume(slab), 10.6 * 8.6 * 0.25, 1e-6);
  EXPECT_NEAR(top_of(slab), 3.3 + 0.25, 1e-9);
  const BuildResult none =
      build_building(building(), one_storey(RoofKind::kNone, 1), Restrictions{});
  EXPECT_EQ(find_part(none, "roof p"), nullptr);
  EXPECT_EQ(none.stats.roofs, 0U);
}

TEST(Builder, CompluviumOpensTheRoofAndTheCeilingsBelow) {
  const BuildResult r =
      build_building(building(), one_storey(RoofKind::kHoledMansard, 2), Restrictions{});
  const kernel::Mesh& roof = find_part(r, "roof p")->mesh;
  EXPECT_EQ(faces_of(roof, SemanticClass::kOuterFloorSurface), 0U);  // no floor in the opening
  const double closure = area_of(roof, SemanticClass::kClosureSurface);
  EXPECT_GT(closure, 10);
  EXPECT_LT(closure, 80 - 1);  // the footprint less the opening
  // Both rooms reach under the opening: their ceilings lose exactly its share of the clear floor.
  const double clear = 4.64 * 7.4;
  const double ceilings = area_of(find_part(r, "a")->mesh, SemanticClass::kCeilingSurface) +
                          area_of(find_part(r, "b")->mesh, SemanticClass::kCeilingSurface);
  EXPECT_LT(ceilings, 2 * clear - 1);
  EXPECT_NEAR(area_of(find_part(r, "a")->mesh, SemanticClass::kFloorSurface), clear, 1e-6);
  expect_closed(r);
}

FloorPlan parts_only(std::vector<PlanPart> parts) {
  FloorPlan plan;
  for (const PlanPart& p : parts) plan.footprint.push_back(p.outline);
  plan.parts = std::move(parts);
  return plan;
}

TEST(Builder, HipGluedPartsInContactShareOneRoof) {
  // Two parts meeting along x = 5 with the micrometre gap a treemap may leave, one part apart.
  const FloorPlan plan = parts_only({part("w", rect(0, 0, 5, 8), RoofKind::kHipGlued, 2),
                                     part("e", rect(5.000001, 0, 12, 8), RoofKind::kHipGlued, 2),
                                     part("far", rect(20, 0, 26, 6), RoofKind::kHipGlued, 2)});
  const BuildResult r = build_building(building(), plan, Restrictions{});
  EXPECT_EQ(r.stats.roofs, 2U);
  const shape::Part* merged = find_part(r, "roof w+e");
  ASSERT_NE(merged, nullptr);
  // The closure under the merged roof is the united outline (no overhang: a free-standing roof
  // would have one, but this one's parts touch each other only).
  EXPECT_NEAR(area_of(merged->mesh, SemanticClass::kClosureSurface), 12 * 8, 1e-3);
  EXPECT_NEAR(top_of(merged->mesh), 5.3, 1e-9);
  EXPECT_NE(find_part(r, "roof far"), nullptr);
  expect_closed(r);
}

// An outline whose ring touches itself (its vertex (5, 0) lies on its own bottom edge), as parts
// and lots cut from real OpenStreetMap outlines have them: it is not a simple polygon, and the roof
// was dropped with a warning, the plinth without one. Both are built on its simple pieces.
TEST(Builder, RoofAndPlinthStandOnAnOutlineThatTouchesItself) {
  const kernel::Polygon pinched{{{0, 0}, {10, 0}, {10, 8}, {6, 8}, {5, 0}, {4, 8}, {0, 8}}, {}};
  const BuildResult r = build_building(
      building(), parts_only({part("p", pinched, RoofKind::kHip, 2)}), Restrictions{});
  for (const std::string& w : r.warnings) EXPECT_EQ(w.find("no roof"), std::string::npos) << w;
  for (const std::string& w : r.warnings) EXPECT_EQ(w.find("plinth"), std::string::npos) << w;
  EXPECT_GE(r.stats.roofs, 1U);
  double closure = 0;
  for (const shape::Part& p : r.building.parts) {
    if (p.name.rfind("roof p", 0) == 0) closure += area_of(p.mesh, SemanticClass::kClosureSurface);
  }
  EXPECT_NEAR(closure, kernel::area(pinched), 0.05);  // the 1 mm the pinch may be opened by
  const shape::Part* base = find_part(r, "base");
  ASSERT_NE(base, nullptr);
  EXPECT_NEAR(area_of(base->mesh, SemanticClass::kGroundSurface), kernel::area(pinched), 0.05);
  expect_closed(r);
}

TEST(Builder, OtherRoofsOfTouchingPartsStaySeparate) {
  const FloorPlan plan = parts_only({part("w", rect(0, 0, 5, 8), RoofKind::kHip, 2),
                                     part("e", rect(5, 0, 12, 8), RoofKind::kHip, 2)});
  const BuildResult r = build_building(building(), plan, Restrictions{});
  EXPECT_EQ(r.stats.roofs, 2U);
  // Touching parts get no overhang: each closure is exactly its outline.
  EXPECT_NEAR(area_of(find_part(r, "roof w")->mesh, SemanticClass::kClosureSurface), 40, 1e-6);
  EXPECT_NEAR(area_of(find_part(r, "roof e")->mesh, SemanticClass::kClosureSurface), 56, 1e-6);
}

TEST(Builder, LowerGluedPartIsRaisedToTheCommonEaves) {
  const FloorPlan plan = parts_only({part("w", rect(0, 0, 5, 8), RoofKind::kHipGlued, 2, 3, 1),
                                     part("e", rect(5, 0, 12, 8), RoofKind::kHipGlued, 2, 6, 2)});
  const BuildResult r = build_building(building(), plan, Restrictions{});
  const shape::Part* merged = find_part(r, "roof w+e");
  ASSERT_NE(merged, nullptr);
  EXPECT_NEAR(merged->mesh.bounds().min.z, 3.3, 1e-9);  // the filler starts on the lower part
  EXPECT_NEAR(top_of(merged->mesh), 8.3, 1e-9);
  expect_closed(r);
}

TEST(Builder, StairsClimbToTheUpperFloorThroughAStairwell) {
  FloorPlan plan = one_storey();
  plan.parts.front().storeys = 2;
  plan.parts.front().eaves = 6;
  plan.storeys.push_back(two_rooms(1, 3));
  PlanStair stair;
  stair.lower_room = 0;
  stair.upper_room = 0;
  stair.footprint = rect(1, 1, 2, 5);
  stair.foot = {1.5, 1};
  stair.head = {1.5, 5};
  stair.width = 1;
  stair.run = 4;
  stair.risers = 16;
  plan.storeys.front().stairs.push_back(stair);
  const BuildResult r = build_building(building(), plan, Restrictions{});
  EXPECT_EQ(r.stats.stairs, 1U);
  const kernel::Mesh& storey = find_part(r, "storey 0")->mesh;
  double top = 0;
  for (std::size_t f = 0; f < storey.face_count(); ++f) {
    if (storey.tag(f).semantic != SemanticClass::kStair) continue;
    for (std::uint32_t v : storey.face(f)) top = std::max(top, storey.position(v).z);
  }
  EXPECT_NEAR(top, 0.3 + 3 + 0.1, 1e-9);  // the upper floor's top
  const double clear = 4.64 * 7.4;
  EXPECT_NEAR(area_of(find_part(r, "a1")->mesh, SemanticClass::kFloorSurface), clear - 4, 1e-6);
  EXPECT_NEAR(area_of(find_part(r, "a")->mesh, SemanticClass::kCeilingSurface), clear - 4, 1e-6);
  EXPECT_NEAR(area_of(find_part(r, "a")->mesh, SemanticClass::kFloorSurface), clear, 1e-6);
  ASSERT_EQ(r.building.plans.size(), 2U);
  EXPECT_EQ(r.building.plans[0].stairs.size(), 1U);
  EXPECT_NEAR(r.building.plans[1].elevation, 3.3, 1e-12);
  EXPECT_EQ(r.building.plans[1].stairs.size(), 1U);  // drawn over its stairwell
  EXPECT_NEAR(top_of(find_part(r, "roof p")->mesh), 0.3 + 6 + 2, 1e-9);
  expect_closed(r);
}

TEST(Builder, RestrictionColoursOverrideTheirClass) {
  Restrictions rules;
  rules.colors = {{"RoofSurface", {0.1F, 0.2F, 0.3F, 1.0F}}, {"NoSuchClass", {1, 1, 1, 1}}};
  const BuildResult r = build_building(building(), one_storey(), rules);
  const shape::Scene scene = to_scene(r);
  const kernel::Mesh& roof = find_part(r, "roof p")->mesh;
  for (std::size_t f = 0; f < roof.face_count(); ++f) {
    if (roof.tag(f).semantic != SemanticClass::kRoofSurface) continue;
    EXPECT_EQ(scene.material_for(roof.tag(f)).rgba[2], 0.3F);
  }
  EXPECT_EQ(scene.materials.size(), r.materials.size());
  EXPECT_EQ(scene.buildings.size(), 1U);
}

TEST(Builder, BadOpeningsAreLeftOutWithAWarning) {
  FloorPlan plan = one_storey();
  plan.storeys.front().windows.front().b = {10, 9};  // reaches past the wall's end
  plan.storeys.front().windows.front().width = 6;
  const BuildResult r = build_building(building(), plan, Restrictions{});
  EXPECT_EQ(r.stats.windows, 0U);
  ASSERT_EQ(r.warnings.size(), 1U);
  EXPECT_NE(r.warnings.front().find("window in the wall of room 'b' left out"), std::string::npos)
      << r.warnings.front();
  expect_closed(r);
}

}  // namespace
}  // namespace insula::lang::bldg
