// One engine (issue 11): the same roof, stair, frame, slab and wall with openings built by the
// .bldg builder, a CGA grammar and a Lua program are the same solid (volume, face count, bounds),
// since all three reach the same kernel function (the .bldg builder directly, CGA and Lua through
// the shape registry's roof, stair, frame, slab and wall).
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "cga/derive_util.h"
#include "kernel/mesh.h"
#include "lang/bldg/builder.h"
#include "lang/bldg/floorplan.h"
#include "lua/run_util.h"

namespace insula {
namespace {

using kernel::Mesh;
using kernel::SemanticClass;
using kernel::Vec3;

// What "the same mesh" means across front-ends that place it differently: volume, face count and
// bounds (as built, or moved by `shift`).
struct Solid {
  double volume = 0;
  std::size_t faces = 0;
  Vec3 min;
  Vec3 max;
};

Solid measure(const Mesh& mesh, Vec3 shift = {0, 0, 0}) {
  const kernel::Bounds3 b = mesh.bounds();
  return {kernel::volume(mesh), mesh.face_count(), b.min + shift, b.max + shift};
}

void expect_same(const Solid& a, const Solid& b, const char* what) {
  EXPECT_NEAR(a.volume, b.volume, 1e-9) << what;
  EXPECT_EQ(a.faces, b.faces) << what;
  const auto near = [&](Vec3 p, Vec3 q, const char* end) {
    EXPECT_NEAR(p.x, q.x, 1e-9) << what << " " << end << " x";
    EXPECT_NEAR(p.y, q.y, 1e-9) << what << " " << end << " y";
    EXPECT_NEAR(p.z, q.z, 1e-9) << what << " " << end << " z";
  };
  near(a.min, b.min, "min");
  near(a.max, b.max, "max");
}

// The faces of `mesh` that `keep` selects, with only the vertices they use.
Mesh select(const Mesh& mesh, const std::function<bool(std::size_t)>& keep) {
  Mesh out;
  std::vector<std::uint32_t> id(mesh.vertex_count(), UINT32_MAX);
  std::vector<std::uint32_t> loop;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    if (!keep(f)) continue;
    loop.clear();
    for (std::uint32_t v : mesh.face(f)) {
      if (id[v] == UINT32_MAX) id[v] = out.add_vertex(mesh.position(v));
      loop.push_back(id[v]);
    }
    out.add_face(loop, mesh.tag(f));
  }
  return out;
}

// Every terminal of a CGA grammar over a rectangle lot [x0, x0 + w] x [y0, y0 + d], as one world
// mesh.
Mesh cga_mesh(const std::string& grammar, double x0, double y0, double w, double d) {
  auto program = lang::cga::testing::compile_text(grammar);
  if (!program) return {};
  lang::cga::Lot lot;
  lot.id = "lot";
  lot.polygons.push_back({{{x0, y0}, {x0 + w, y0}, {x0 + w, y0 + d}, {x0, y0 + d}}, {}});
  const std::vector<lang::cga::LotResult> r = lang::cga::testing::derive_all(*program, {lot});
  EXPECT_TRUE(r[0].ok) << lang::cga::testing::diagnostics_text(r[0]);
  for (const base::Diagnostic& diagnostic : r[0].diagnostics) {
    ADD_FAILURE() << base::render(diagnostic);
  }
  const shape::Scene scene = lang::cga::to_scene(*program, {lot}, r);
  Mesh out;
  for (const shape::Building& b : scene.buildings) {
    for (const shape::Part& p : b.parts) out.append(p.mesh);
  }
  return out;
}

// The world mesh of the shapes a Lua program labels "out".
Mesh lua_mesh(const std::string& code) {
  const lua::testing::Ran r = lua::testing::run(code);
  EXPECT_TRUE(r.ok()) << r.error();
  Mesh out;
  for (shape::ShapeId id : r.labelled("out")) {
    const shape::Shape& s = r.tree()[id];
    if (!s.mesh) continue;
    Mesh world = *s.mesh;
    for (Vec3& p : world.positions()) p = s.scope.to_world(p);
    out.append(world);
  }
  return out;
}

kernel::Polygon rect(double x0, double y0, double x1, double y1) {
  return {{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, {}};
}

lang::bldg::PlanWall wall(kernel::Vec2 a, kernel::Vec2 b, int left, double thickness) {
  lang::bldg::PlanWall w;
  w.a = a;
  w.b = b;
  w.left = left;
  w.right = lang::bldg::kExteriorSide;
  w.thickness = thickness;
  return w;
}

// A one-room 10 x 8 m building, `storeys` storeys of 3 m, roof `roof` `height` high.
lang::bldg::FloorPlan plan(lang::bldg::RoofKind roof, double height, int storeys = 1) {
  lang::bldg::FloorPlan p;
  p.outline = rect(0, 0, 10, 8);
  p.footprint = {p.outline};
  lang::bldg::PlanPart part;
  part.symbol = "p";
  part.roof = roof;
  part.roof_height = height;
  part.outline = p.outline;
  part.storeys = storeys;
  part.eaves = 3.0 * storeys;
  p.parts = {part};
  for (int level = 0; level < storeys; ++level) {
    lang::bldg::PlanStorey s;
    s.level = level;
    s.elevation = 3.0 * level;
    s.height = 3;
    lang::bldg::PlanRoom room;
    room.symbol = "r" + std::to_string(level);
    room.type = "hall";
    room.part = "p";
    room.cell = p.outline;
    room.area = 80;
    s.rooms = {room};
    s.walls = {wall({0, 0}, {10, 0}, 0, 0.3), wall({10, 0}, {10, 8}, 0, 0.3),
               wall({10, 8}, {0, 8}, 0, 0.3), wall({0, 8}, {0, 0}, 0, 0.3)};
    p.storeys.push_back(s);
  }
  return p;
}

lang::bldg::BuildResult build(const lang::bldg::FloorPlan& p,
                              const lang::bldg::BuilderOptions& options = {}) {
  lang::bldg::Building b;
  b.symbol = "house";
  return lang::bldg::build_building(b, p, lang::bldg::Restrictions{}, options);
}

// A window of room 0 in wall 0 (the south wall, y = 0), 1.2 x 1.2 m from x = 4, 0.9 m above the
// floor.
lang::bldg::PlanWindow south_window() {
  lang::bldg::PlanWindow window;
  window.room = 0;
  window.wall = 0;
  window.a = {4, 0};
  window.b = {5.2, 0};
  window.center = {4.6, 0};
  window.width = 1.2;
  window.sill = 0.9;
  window.height = 1.2;
  return window;
}

// A Lua prelude: `front`, the south face of the 10 x 8 m lot extruded 3 m.
constexpr const char* kLuaFacade = R"lua(
    local lot = component{polygon={{0, 0}, {10, 0}, {10, 8}, {0, 8}}}
    local front = comp(extrude(lot, 3)[1], "faces", "front")[1]
  )lua";

const Mesh& part_mesh(const lang::bldg::BuildResult& r, const std::string& name) {
  for (const shape::Part& p : r.building.parts) {
    if (p.name == name) return p.mesh;
  }
  ADD_FAILURE() << "no part " << name;
  static const Mesh kEmpty;
  return kEmpty;
}

// .bldg's Flat roof is CGA's roofFlat(overhang, thickness) and Lua's roof with a thickness: a
// slab 0.25 m thick over the outline grown by the builder's 0.3 m overhang, at the eaves (base
// 0.3 + 3 m).
TEST(OneEngine, FlatRoofIsTheSameSlab) {
  const auto r = build(plan(lang::bldg::RoofKind::kFlat, 0));
  const Solid bldg = measure(part_mesh(r, "roof p"));
  EXPECT_NEAR(bldg.volume, 10.6 * 8.6 * 0.25, 1e-9);  // mitred corners
  const Vec3 eaves{0, 0, 3.3};
  expect_same(bldg, measure(cga_mesh("Lot --> roofFlat(0.3, 0.25)", 0, 0, 10, 8), eaves), "cga");
  expect_same(bldg,
              measure(lua_mesh(R"lua(
    local lot = component{polygon={{0, 0}, {10, 0}, {10, 8}, {0, 8}}}
    roof(lot, "flat", {overhang=0.3, thickness=0.25, label="out"})
  )lua"),
                      eaves),
              "lua");
}

// .bldg's Gable, Hip and HoledMansard roofs are the registry's roof with closed = true and the
// same height (the builder passes its overhang; a holed mansard's compluvium through the solid).
TEST(OneEngine, PitchedRoofsAreTheSameClosedSolid) {
  const std::pair<lang::bldg::RoofKind, const char*> kinds[] = {
      {lang::bldg::RoofKind::kGable, "gable"},
      {lang::bldg::RoofKind::kHip, "hip"},
      {lang::bldg::RoofKind::kPyramid, "pyramid"}};
  for (const auto& [kind, name] : kinds) {
    const auto r = build(plan(kind, 2.5));
    const Mesh& roof = part_mesh(r, "roof p");
    EXPECT_TRUE(kernel::check(roof).closed) << name;
    const Solid bldg = measure(roof);
    EXPECT_NEAR(bldg.max.z, 3.3 + 2.5, 1e-9) << name;
    const Mesh lua = lua_mesh(std::string(R"lua(
      local lot = component{polygon={{0, 0}, {10, 0}, {10, 8}, {0, 8}}}
      roof(lot, ")lua") + name +
                              R"lua(", {overhang=0.3, closed=true, height=2.5, label="out"})
    )lua");
    expect_same(bldg, measure(lua, {0, 0, 3.3}), name);
  }
}

// A flight between two storeys: .bldg's stair (16 risers over 4 m, 3 m up from the lower floor's
// slab) is CGA's stair(3, 16) and Lua's stair over the flight's 1 x 4 m footprint.
TEST(OneEngine, StairIsTheSameFlight) {
  lang::bldg::FloorPlan p = plan(lang::bldg::RoofKind::kFlat, 0, 2);
  lang::bldg::PlanStair stair;
  stair.footprint = rect(1, 1, 2, 5);
  stair.foot = {1.5, 1};
  stair.head = {1.5, 5};
  stair.width = 1;
  stair.run = 4;
  stair.risers = 16;
  p.storeys.front().stairs.push_back(stair);
  const auto r = build(p);
  const Mesh& storey = part_mesh(r, "storey 0");
  const Mesh flight = select(
      storey, [&](std::size_t f) { return storey.tag(f).semantic == SemanticClass::kStair; });
  const Solid bldg = measure(flight);
  EXPECT_EQ(bldg.faces, 2U * 16 + 4);
  EXPECT_NEAR(bldg.volume, 1 * (4.0 / 16) * (3.0 / 16) * (16 * 17 / 2), 1e-9);
  const Vec3 floor{0, 0, 0.4};  // base 0.3 + slab 0.1
  expect_same(bldg, measure(cga_mesh("Lot --> stair(3, 16)", 1, 1, 1, 4), floor), "cga");
  expect_same(bldg,
              measure(lua_mesh(R"lua(
    stair(component{polygon={{1, 1}, {2, 1}, {2, 5}, {1, 5}}}, 3, 16, {label="out"})
  )lua"),
                      floor),
              "lua");
}

// A window 1.2 x 1.2 m, 0.9 m above the floor slab, in the 0.3 m south wall: .bldg's frame (posts,
// head, sill on both faces, the pane) is the registry's frame over the opening's rectangle of the
// facade, from CGA (extrude, comp, split) and from Lua (a face component).
TEST(OneEngine, WindowFrameIsTheSameFrame) {
  lang::bldg::FloorPlan p = plan(lang::bldg::RoofKind::kFlat, 0);
  p.storeys.front().windows.push_back(south_window());
  const auto r = build(p);
  EXPECT_EQ(r.stats.windows, 1U);
  const Mesh& storey = part_mesh(r, "storey 0");
  const Mesh frame = select(
      storey, [&](std::size_t f) { return storey.tag(f).semantic == SemanticClass::kWindow; });
  const Solid bldg = measure(frame);
  EXPECT_EQ(bldg.faces, 9U * 6);
  // The window's sill is 0.3 (base) + 0.1 (slab) + 0.9 above the ground; the facade is the wall's
  // outer face y = 0 (the wall stands inside, y in [0, 0.3]).
  const Mesh cga = cga_mesh(R"cga(
    Lot --> extrude(3) comp(f) { front: Facade }
    Facade --> split(x) { 4: X | 1.2: Column | ~1: X }
    Column --> split(y) { 1: X | 1.2: Window | ~1: X }
    Window --> frame("window", 0.3, 0.06, 0.04)
    X --> nil()
  )cga",
                            0, 0, 10, 8);
  expect_same(bldg, measure(cga, {0, 0, 0.3}), "cga");
  // Lua: the same facade face by the same operations.
  const Mesh lua = lua_mesh(R"lua(
    local lot = component{polygon={{0, 0}, {10, 0}, {10, 8}, {0, 8}}}
    local mass = extrude(lot, 3)[1]
    local front = comp(mass, "faces", "front")[1]
    local column = split(front, "x", 4, 1.2, "~1")[2]
    local opening = split(column, "y", 1, 1.2, "~1")[2]
    frame(opening, "window", 0.3, 0.06, 0.04, {label="out"})
  )lua");
  expect_same(bldg, measure(lua, {0, 0, 0.3}), "lua");
}

// A room's floor and ceiling slabs are the registry's slab over the room's clear floor (the cell
// minus the 0.3 m walls: 9.4 x 7.4 m), the floor on the storey's floor (0.3 m base), the ceiling
// under the storey's top (3.3 m).
TEST(OneEngine, FloorAndCeilingSlabsAreTheSameSlabs) {
  lang::bldg::BuilderOptions options;
  options.footers = false;
  const auto r = build(plan(lang::bldg::RoofKind::kFlat, 0), options);
  const Mesh& room = part_mesh(r, "r0");
  const auto below = [&](double z) {
    return [&room, z](std::size_t f) {
      for (std::uint32_t v : room.face(f)) {
        if (room.position(v).z > z) return false;
      }
      return true;
    };
  };
  const Solid floor = measure(select(room, below(1.5)));
  const Solid ceiling = measure(select(room, [&](std::size_t f) { return !below(1.5)(f); }));
  EXPECT_NEAR(floor.volume, 9.4 * 7.4 * 0.1, 1e-9);
  EXPECT_EQ(floor.faces + ceiling.faces, room.face_count());
  expect_same(floor,
              measure(cga_mesh("Lot --> slab(\"floor\", 0.1)", 0.3, 0.3, 9.4, 7.4), {0, 0, 0.3}),
              "cga floor");
  expect_same(ceiling,
              measure(cga_mesh("Lot --> slab(\"ceiling\", 0.1)", 0.3, 0.3, 9.4, 7.4), {0, 0, 3.3}),
              "cga ceiling");
  const std::string lot = "component{polygon={{0.3, 0.3}, {9.7, 0.3}, {9.7, 7.7}, {0.3, 7.7}}}";
  expect_same(floor,
              measure(lua_mesh("slab(" + lot + ", 'floor', 0.1, {label='out'})"), {0, 0, 0.3}),
              "lua floor");
  expect_same(ceiling,
              measure(lua_mesh("slab(" + lot + ", 'ceiling', 0.1, {label='out'})"), {0, 0, 3.3}),
              "lua ceiling");
}

// A door (1 x 2.1 m, on the 0.1 m floor slab) and a window (1.2 x 1.2 m, 0.9 m above the slab)
// in the 0.3 m south wall, 3 m high: .bldg's wall is the registry's wall over the facade, from CGA
// (extrude, comp) and from Lua (a face component), with the openings in the facade's (u, v).
TEST(OneEngine, WallWithOpeningsIsTheSameWall) {
  lang::bldg::FloorPlan p = plan(lang::bldg::RoofKind::kFlat, 0);
  lang::bldg::PlanDoor door;
  door.room_a = 0;
  door.wall = 0;
  door.a = {1.5, 0};
  door.b = {2.5, 0};
  door.center = {2, 0};
  door.width = 1;
  door.height = 2.1;
  p.storeys.front().entrances.push_back(door);
  p.storeys.front().windows.push_back(south_window());
  lang::bldg::BuilderOptions options;
  options.frames = false;
  const auto r = build(p, options);
  EXPECT_EQ(r.stats.entrances, 1U);
  EXPECT_EQ(r.stats.windows, 1U);
  // The south wall is the storey's first: its faces carry the face ids 0 to 7 (one per side).
  const Mesh& storey = part_mesh(r, "storey 0");
  const Mesh south = select(storey, [&](std::size_t f) { return storey.tag(f).face_id < 8; });
  EXPECT_TRUE(kernel::check(south).closed);
  const Solid bldg = measure(south);
  EXPECT_NEAR(bldg.volume, 0.3 * (10 * 3 - 1 * 2.1 - 1.2 * 1.2), 1e-9);
  EXPECT_NEAR(bldg.min.y, 0, 1e-9);  // the wall stands inside, its face on the outline
  EXPECT_NEAR(bldg.max.y, 0.3, 1e-9);
  // The rim's 4 faces, 4 reveals per opening, the front and the back in 2 hole-free pieces each.
  EXPECT_EQ(bldg.faces, 4U + 2 * 4 + 2 * 2);
  const Vec3 floor{0, 0, 0.3};  // the storey stands on the 0.3 m base
  const Mesh cga = cga_mesh(R"cga(
    Lot --> extrude(3) comp(f) { front: Facade }
    Facade --> wall(0.3, 1.5, 0.1, 1, 2.1, 4, 1, 1.2, 1.2)
  )cga",
                            0, 0, 10, 8);
  expect_same(bldg, measure(cga, floor), "cga");
  const std::string facade = kLuaFacade;
  expect_same(bldg,
              measure(lua_mesh(facade + "wall(front, 0.3, {1.5, 0.1, 1, 2.1, 4, 1, 1.2, 1.2}, "
                                        "{label='out'})"),
                      floor),
              "lua");
  // Relative sizes are fractions of the facade (10 x 3 m): the same openings.
  expect_same(bldg,
              measure(lua_mesh(facade + "wall(front, 0.3, {\"'0.15\", 0.1, 1, 2.1, \"'0.4\", 1, "
                                        "\"'0.12\", \"'0.4\"}, {label='out'})"),
                      floor),
              "lua relative");
}

// The wall's openings are four sizes each, never floating; an opening that does not fit is left
// out with a warning, as the .bldg builder leaves it out.
TEST(OneEngine, WallOpeningErrors) {
  const std::string facade = kLuaFacade;
  const auto error = [&](const std::string& call) {
    return lua::testing::run(facade + call).error();
  };
  EXPECT_EQ(error("wall(front, 0.3, {1, 0.1, 1})"),
            "test.lua:4:3: error[LUA003]: in wall: openings take four sizes each (u, sill, width, "
            "height); got 3");
  EXPECT_EQ(error("wall(front, 0.3, {1, 0.1, '~1', 2})"),
            "test.lua:4:3: error[LUA003]: in wall: opening sizes are meters or relative ('), not "
            "floating (~); got ~1");
  // The second window overlaps the first: the wall is the box minus the first alone.
  const Mesh skipped = lua_mesh(facade +
                                "wall(front, 0.3, {4, 1, 1.2, 1.2, 4.5, 1.5, 1, 1}, "
                                "{label='out'})");
  EXPECT_NEAR(kernel::volume(skipped), 0.3 * (10 * 3 - 1.2 * 1.2), 1e-9);
  // CGA names the opening it left out.
  auto program = lang::cga::testing::compile_text(R"cga(
    Lot --> extrude(3) comp(f) { front: Facade }
    Facade --> wall(0.3, 4, 1, 1.2, 1.2, 4.5, 1.5, 1, 1)
  )cga");
  ASSERT_NE(program, nullptr);
  const auto r =
      lang::cga::testing::derive_all(*program, {lang::cga::testing::rectangle_lot(10, 8)});
  EXPECT_EQ(lang::cga::testing::diagnostics_text(r[0]),
            "test.cga:3:16: warning[CGA604]: wall: opening 1 overlaps opening 0 (left out)\n"
            "note: in lot 'lot'\n");
}

}  // namespace
}  // namespace insula
