// The bound operations of Lua component programs (seed 001 §3.4), each with exact counts, sizes,
// areas or volumes.
#include <gtest/gtest.h>

#include <cmath>

#include "kernel/mesh.h"
#include "run_util.h"

namespace insula::lua {
namespace {

using testing::run;

TEST(LuaOps, RootBoxAndPolygon) {
  const auto r = run(R"lua(
    local b = component{size={10, 2.5, 8}, position={1, 0, 2}, label="floor", level=0}
    local p = component{polygon={{0, 0}, {6, 0}, {6, 4}, {0, 4}}, holes={{{1, 1}, {1, 2}, {2, 2}, {2, 1}}},
                        elevation=3, labels={"lot", "yard"}}
    print(b.volume, b.size[1], b.size[2], b.origin[1], b.origin[2], b.origin[3], b.level, p.area,
          p.flat, #labels(p), has(p, "yard"), #roots())
  )lua");
  ASSERT_TRUE(r.ok()) << r.error();
  // position (x, up, depth) -> world (1, -2, 0): depth runs along world -Y.
  EXPECT_EQ(r.printed, std::vector<std::string>{
                           "200.0\t10.0\t2.5\t1.0\t-2.0\t0.0\t0\t23.0\ttrue\t2\ttrue\t2"});
}

TEST(LuaOps, SplitAbsoluteAndWeightedRelativeSizes) {
  const auto r = run(R"lua(
    local f = component{size={10, 3, 12}}
    local parts = split(f, "z", {label="a", rel=1}, {label="b", abs=2}, {label="c", rel=3, tag="x"},
                        {label="d", frac=0.25})
    local s = {}
    for _, c in ipairs(parts) do s[#s + 1] = c.size[3] end
    print(#parts, table.concat(s, " "), parts[3].tag, #query("c"), f.active)
    local g = component{size={6, 3, 3}}
    print(#split(g, 0, 1, "'0.5", "~1"))
  )lua");
  ASSERT_TRUE(r.ok()) << r.error();
  // 12 - 2 (abs) - 3 (a quarter) = 7 shared 1:3 by weight.
  EXPECT_EQ(r.printed, (std::vector<std::string>{"4\t1.75 2.0 5.25 3.0\tx\t1\tfalse", "3"}));
}

TEST(LuaOps, RegistryOperations) {
  const auto r = run(R"lua(
    local lot = component{polygon={{0, 0}, {10, 0}, {10, 8}, {0, 8}}}
    local mass = extrude(lot, 6, {label="mass"})[1]
    local faces = comp(mass, "faces", "side", {label="facade"})
    local tiles = repeatSplit(faces[1], "x", 3)
    local inner = offset(component{polygon={{0, 0}, {10, 0}, {10, 8}, {0, 8}}}, -1,
                         {pieces={{label="inside"}, {label="border"}}})
    local sb = setback(component{polygon={{0, 0}, {10, 0}, {10, 8}, {0, 8}}}, 2,
                       {edges="front", pieces={{label="strip"}, {label="rest"}}})
    local moved = translate(mass, 1, 2, 3)[1]
    local scaled = scale(component{size={2, 2, 2}}, 4, "'0.5", 1)[1]
    local roofed = roof(component{polygon={{0, 0}, {10, 0}, {10, 8}, {0, 8}}}, "gable", 45)[1]
    print(mass.volume, #faces, #tiles, tiles[1].size[1], query("inside")[1].area,
          query("border")[1].area, query("strip")[1].area, query("rest")[1].area,
          #query("mass"), moved.origin[3], scaled.size[1], scaled.size[2], scaled.size[3],
          roofed.size[2])
  )lua");
  ASSERT_TRUE(r.ok()) << r.error();
  // The 10 m front splits into 3 tiles of 3.33 m; inset 8 x 6 = 48 and border 80 - 48 = 32;
  // setback strip 10 x 2 = 20 and rest 60; transforms keep labels (translate y = world up);
  // scale takes meters (4, 1) and fractions ('0.5); gable at 45 degrees over an
  // 8 m span rises 4 m.
  ASSERT_EQ(r.printed.size(), 1U);
  EXPECT_EQ(r.printed[0],
            "480.0\t4\t3\t3.3333333333333\t48.0\t32.0\t20.0\t60.0\t2\t2.0\t4.0\t1.0\t1.0\t4.0");
}

TEST(LuaOps, ScatterFromTheRegistry) {
  // CityEngine's scatter reaches Lua through the registry: point components on the lot.
  const auto r = run(R"lua(
    local lot = component{polygon={{0, 0}, {10, 0}, {10, 8}, {0, 8}}}
    local points = scatter(lot, "surface", 12, "gaussian", {label="tree"})
    local inside = 0
    for _, p in ipairs(points) do
      if p.origin[1] >= 0 and p.origin[1] <= 10 and p.size[1] == 0 then inside = inside + 1 end
    end
    print(#points, #query("tree"), inside)
  )lua");
  ASSERT_TRUE(r.ok()) << r.error();
  EXPECT_EQ(r.printed, std::vector<std::string>{"12\t12\t12"});
}

TEST(LuaOps, SetbackEdgesTakesADepthPerEdge) {
  // The registry's per-edge setback (CGA's setback(float[])): 10 x 8, strips 1 m along the first
  // edge and 3 m along the third.
  const auto r = run(R"lua(
    local parts = setbackEdges(component{polygon={{0, 0}, {10, 0}, {10, 8}, {0, 8}}}, {1, 0, 3},
                               {pieces={{label="strip"}, {label="rest"}}})
    local strip = 0
    for _, s in ipairs(query("strip")) do strip = strip + s.area end
    print(#parts, strip, query("rest")[1].area)
  )lua");
  ASSERT_TRUE(r.ok()) << r.error();
  EXPECT_EQ(r.printed, (std::vector<std::string>{"3\t40.0\t40.0"}));
}

TEST(LuaOps, FacesBecomeTwoDimensionalComponents) {
  const auto r = run(R"lua(
    local room = component{size={4, 3, 5}, label="room"}
    local walls = {}
    for _, f in ipairs(fquery(room, "SIDE or BOTTOM")) do
      walls[#walls + 1] = component(room, {boundary=f, label="wall"})
    end
    local a = 0
    for _, w in ipairs(walls) do a = a + w.area end
    print(#walls, a, walls[1].flat, room.active, #query("wall and parent(room, 1)"))
  )lua");
  ASSERT_TRUE(r.ok()) << r.error();
  // Four sides 2 x (4 x 3) + 2 x (5 x 3) = 54 plus the 20 m2 floor; the room stays active.
  EXPECT_EQ(r.printed, std::vector<std::string>{"5\t74.0\ttrue\ttrue\t5"});
}

TEST(LuaOps, ChildBoxesAreClippedToTheirParent) {
  const auto r = run(R"lua(
    local f = component{size={10, 3, 10}}
    local e = component(f, {size={4, 5, 4}, position={8, 0, -1}, label="shaft"})
    print(e.size[1], e.size[2], e.size[3], e.volume)
  )lua");
  ASSERT_TRUE(r.ok()) << r.error();
  EXPECT_EQ(r.printed, std::vector<std::string>{"2.0\t3.0\t3.0\t18.0"});
}

TEST(LuaOps, AttributesAreInheritedAndMutable) {
  const auto r = run(R"lua(
    local f = component{size={10, 3, 10}, level=2, style="brick"}
    local parts = split(f, "x", 5, 5)
    set(parts[2], "style", "glass")
    parts[1].rooms = 3
    print(parts[1].level, parts[1].style, parts[2].style, get(parts[1], "rooms"), f.rooms,
          get(parts[2], "missing"))
    set(parts, "level", 7)
    print(parts[1].level, f.level)
  )lua");
  ASSERT_TRUE(r.ok()) << r.error();
  EXPECT_EQ(r.printed, (std::vector<std::string>{"2\tbrick\tglass\t3\tnil\tnil", "7\t2"}));
}

class Assets : public shape::AssetProvider {
 public:
  std::shared_ptr<const kernel::Mesh> find(std::string_view name,
                                           std::string& error) const override {
    if (name != "door01") {
      error = "asset '" + std::string(name) + "' not found";
      return nullptr;
    }
    auto mesh = std::make_shared<kernel::Mesh>();
    // A 1 x 2 x 0.1 slab (y up), offset to check that the scope is fitted to it.
    const kernel::Vec3 lo{5, 5, 5};
    mesh->add_polygon(
        std::vector<kernel::Vec3>{lo, lo + kernel::Vec3{1, 0, 0}, lo + kernel::Vec3{1, 2, 0},
                                  lo + kernel::Vec3{0, 2, 0.1}},
        {});
    return mesh;
  }
};

TEST(LuaOps, RegionsAndConnect) {
  Assets assets;
  RunOptions options;
  options.assets = &assets;
  options.seed = 7;
  const auto r = run(R"lua(
    local room = component{size={4, 3, 5}, label="room", level=1}
    local wall = component(room, {boundary=fquery(room, "FRONT")[1], label="wall"})
    local reg = region(wall, {label="door", min={0.5, 0, 0}, max={2.5, 0, 0}})
    local door = componentFromFile("door01")
    local placed = connect(door, reg, {position={1, 0, 0}, label="placed"})
    print(door.size[1], door.size[2], placed.parent.id, placed.level, has(placed, "door01"),
          placed.origin[1], placed.origin[2], placed.origin[3])
    local a = connect(door, reg)
    local b = connect(door, reg)
    print(a.origin[1] >= 0.5 and a.origin[1] <= 2.5, a.origin[1] ~= b.origin[1])
  )lua",
                     options);
  ASSERT_TRUE(r.ok()) << r.error();
  ASSERT_EQ(r.printed.size(), 2U);
  // The front wall of the room: x along world X, normal -Y (scope z = -world Y), origin at the
  // room's front-left corner (0, -5, 0); position 1 along the wall.
  EXPECT_EQ(r.printed[0], "1.0\t2.0\t1\t1\ttrue\t1.0\t-5.0\t0.0");
  EXPECT_EQ(r.printed[1], "true\ttrue");
  // Random placements are the same for the same seed.
  const auto again = run(R"lua(
    local room = component{size={4, 3, 5}}
    local wall = component(room, {boundary=fquery(room, "FRONT")[1]})
    local reg = region(wall, {label="door", min={0.5, 0, 0}, max={2.5, 0, 0}})
    print(connect(componentFromFile("door01"), reg).origin[1])
  )lua",
                         options);
  ASSERT_TRUE(again.ok()) << again.error();
  const auto third = run(R"lua(
    local room = component{size={4, 3, 5}}
    local wall = component(room, {boundary=fquery(room, "FRONT")[1]})
    local reg = region(wall, {label="door", min={0.5, 0, 0}, max={2.5, 0, 0}})
    print(connect(componentFromFile("door01"), reg).origin[1])
  )lua",
                         options);
  EXPECT_EQ(again.printed, third.printed);
  // The moved source is not exported; the placed copies are.
  const shape::Scene scene = collect_program(r.runtime->program());
  std::size_t doors = 0;
  for (const auto& b : scene.buildings) {
    for (const auto& p : b.parts) doors += p.name == "door01" ? 1 : 0;
  }
  EXPECT_EQ(doors, 3U);
}

TEST(LuaOps, OperationErrorsNameTheOperationAndLine) {
  EXPECT_EQ(run("local c = component{size={1, 1, 1}}\n\nextrude(c, 2)").error(),
            "test.lua:3:1: error[LUA003]: in extrude: needs a flat shape (a footprint or a "
            "face)");
  EXPECT_EQ(
      run("local c = component{size={1, 1, 1}}\nlocal x = split(c, 'x', {label='a'})").error(),
      "test.lua:2:11: error[LUA003]: in split: argument 3: a piece needs exactly one of abs, "
      "rel or frac");
  EXPECT_EQ(run("translate(42)").error(),
            "test.lua:1:1: error[LUA003]: in translate: argument 1: expected a component or a list "
            "of components, got number");
  EXPECT_EQ(run("componentFromFile('x')").error(),
            "test.lua:1:1: error[LUA003]: in componentFromFile: no asset folder was given "
            "(--assets DIR)");
  EXPECT_EQ(run("local c = component{size={1, 1, 1}}\nc.id = 3").error(),
            "test.lua:2:1: error[LUA003]: in set: field 'id' is read-only (use set(c, name, v))");
}

}  // namespace
}  // namespace insula::lua
