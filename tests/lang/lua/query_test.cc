// Queries of Lua component programs (seed 001 §3.3), one test per kind, with exact counts.
#include <gtest/gtest.h>

#include "run_util.h"

namespace insula::lua {
namespace {

using testing::run;

// Fig. 3's floor: 10 x 2.5 x 10, two 2 m corridors between living spaces split into apartments.
constexpr const char* kFloor = R"lua(
  floor = component{label="floor", size={10, 2.5, 10}}
  split(floor, "z", {label="living space", rel=1}, {label="corridor", abs=2},
        {label="corridor", abs=2}, {label="living space", rel=1})
  for c in query("'living space'") do
    split(c, "x", {label="apartment", rel=1}, {label="apartment", rel=1, kind="large"})
  end
)lua";

std::string with_floor(const std::string& rest) {
  return std::string(kFloor) + rest;
}

TEST(LuaQuery, LabelExpressions) {
  const auto r = run(with_floor(R"lua(
    print(#query("apartment"), #query("corridor"), #query("apartment or corridor"),
          #query("'living space' and not apartment"), #query("not (apartment or corridor)"))
  )lua"));
  ASSERT_TRUE(r.ok()) << r.error();
  // 1 floor + 4 pieces + 4 apartments = 9 components; "not (...)" leaves floor and 2 spaces.
  EXPECT_EQ(r.printed, std::vector<std::string>{"4\t2\t6\t2\t3"});
}

TEST(LuaQuery, IteratesInCreationOrderAndIndexes) {
  const auto r = run(with_floor(R"lua(
    local ids = {}
    for c in query("apartment") do ids[#ids + 1] = c.id end
    local q = query("apartment")
    print(table.concat(ids, ","), q[1].id, q[4].id, #q)
    for i, c in ipairs(q) do assert(c == q[i]) end
  )lua"));
  ASSERT_TRUE(r.ok()) << r.error();
  EXPECT_EQ(r.printed, std::vector<std::string>{"5,6,7,8\t5\t8\t4"});
}

TEST(LuaQuery, AttributeTestsSeeInheritedValues) {
  const auto r = run(with_floor(R"lua(
    floor.level = 3
    print(#query("level == 3"), #query("level >= 3 and apartment"), #query("kind == 'large'"),
          #query("kind != 'large'"), #query("level < 3"))
  )lua"));
  ASSERT_TRUE(r.ok()) << r.error();
  // Every one of the 9 components inherits level 3; 2 apartments set kind = "large".
  EXPECT_EQ(r.printed, std::vector<std::string>{"9\t4\t2\t7\t0"});
}

TEST(LuaQuery, ParentMatchesAnyAncestorOrWithinDepth) {
  const auto r = run(with_floor(R"lua(
    print(#query("parent(floor)"), #query("parent(floor, 1)"), #query("parent('living space')"),
          #query("child(apartment)"), #query("leaf()"), #query("active()"))
  )lua"));
  ASSERT_TRUE(r.ok()) << r.error();
  EXPECT_EQ(r.printed, std::vector<std::string>{"8\t4\t4\t2\t6\t6"});
}

TEST(LuaQuery, SourcesLimitTheSearchToTheirSubtrees) {
  const auto r = run(with_floor(R"lua(
    local spaces = query("'living space'")
    print(#query("apartment", spaces[1]), #query(spaces, "apartment"),
          #query(spaces[1], "apartment or 'living space'"), #query("floor", spaces))
  )lua"));
  ASSERT_TRUE(r.ok()) << r.error();
  EXPECT_EQ(r.printed, std::vector<std::string>{"2\t4\t3\t0"});
}

TEST(LuaQuery, OcclusionAndFig3DoorWalls) {
  const auto r = run(with_floor(R"lua(
    for c in query("apartment or corridor") do
      for _, f in ipairs(fquery(c, "SIDE")) do component(c, {label="wall", boundary=f}) end
    end
    print(#query("wall"), #query("wall and occlusion(corridor) > 0"),
          #query("wall and not parent(corridor) and occlusion(corridor) > 0"),
          #query("wall and occlusion(corridor) >= 1"))
    local a = query("apartment")[1]
    print(occlusion(a, query("apartment")), occlusion(query("corridor")[1], "corridor"))
  )lua"));
  ASSERT_TRUE(r.ok()) << r.error();
  // 6 boxes x 4 sides = 24 walls. Touching a corridor: the 8 corridor walls (inside their own
  // corridor) and 6 apartment or corridor walls facing one: the 4 apartments' inner walls plus
  // the two corridors' shared walls are already counted, so 8 + 4 = 12; without the corridor's
  // own: 4. Fully covered: same 12.
  ASSERT_EQ(r.printed.size(), 2U);
  EXPECT_EQ(r.printed[0], "24\t12\t4\t12");
  // Boxes only touch: no volume is covered.
  EXPECT_EQ(r.printed[1], "0.0\t0.0");
}

TEST(LuaQuery, Proximity) {
  const auto r = run(with_floor(R"lua(
    local a = query("apartment")[1]
    local near = proximity(a, 5.01, "apartment")
    print(#near, near[1].id, #query("apartment and near(corridor, 4)"),
          #proximity(a, 100))
  )lua"));
  ASSERT_TRUE(r.ok()) << r.error();
  // Apartment centres: (2.5, 2), (7.5, 2), (2.5, 8), (7.5, 8) in floor space: the one 5 m away
  // is the neighbour in x (id 6); corridor centres are 3 m from every apartment centre.
  EXPECT_EQ(r.printed, std::vector<std::string>{"1\t6\t4\t8"});
}

TEST(LuaQuery, FaceQueries) {
  const auto r = run(R"lua(
    local b = component{size={4, 3, 2}}
    setFaceId(b, "FRONT", "entrance")
    local parts = split(b, "x", 1, 3)
    print(#fquery(b, "SIDE"), #fquery(b, "TOP or BOTTOM"), #fquery(b, "ALL"),
          #fquery(b, "entrance"), #fquery(parts, "entrance"), #fquery(parts, "SIDE and not entrance"),
          fquery(b, "TOP")[1].area, fquery(parts[2], "entrance")[1].area)
  )lua");
  ASSERT_TRUE(r.ok()) << r.error();
  // The front face id is carried to the faces split from it (§3.1.1).
  EXPECT_EQ(r.printed, std::vector<std::string>{"4\t2\t6\t1\t2\t6\t8.0\t9.0"});
}

TEST(LuaQuery, RegionQueries) {
  const auto r = run(R"lua(
    local a = component{size={4, 3, 4}, label="a"}
    local b = component{size={4, 3, 4}, position={10, 0, 0}, label="b"}
    region(a, {label="door", min={1, 0, 4}, max={3, 0, 4}})
    region(a, {label="window"})
    region(b, {label="door"})
    print(#rquery("door"), #rquery("door or window"), #rquery("not door"), #rquery("door", a),
          rquery("door")[2].component.id)
  )lua");
  ASSERT_TRUE(r.ok()) << r.error();
  EXPECT_EQ(r.printed, std::vector<std::string>{"2\t3\t1\t1\t1"});
}

TEST(LuaQuery, SyntaxErrorsNameTheColumn) {
  const auto r = run("local x = 1\nquery(\"room and (corridor\")\n");
  EXPECT_EQ(r.error(),
            "test.lua:2:1: error[LUA003]: in query: expected ')', found end of query (column 19 "
            "of \"room and (corridor\")");
  const auto f = run("fquery(component{size={1,1,1}}, \"SIDE or\")");
  EXPECT_EQ(f.error(),
            "test.lua:1:1: error[LUA003]: in fquery: expected a label or '(', found end of query "
            "(column 8 of \"SIDE or\")");
  const auto u = run("query('wall and occlusion(corridor)')");
  EXPECT_EQ(u.error(),
            "test.lua:1:1: error[LUA003]: in query: expected a comparison after occlusion(...), "
            "found end of query (column 29 of \"wall and occlusion(corridor)\")");
}

}  // namespace
}  // namespace insula::lua
