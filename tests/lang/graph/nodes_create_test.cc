// Entity creation nodes (graph-format.md §11 "Entity creation"): geometry, order, node attributes,
// impulses and the lots of create.lots with W030.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "lang/graph/output.h"
#include "run_util.h"

namespace insula::lang::graph::testing {
namespace {

TEST(CreateNodes, RectangleFromItsOrigin) {
  const TestRun t = run_text(graph_text(R"(
    "nodes": [ { "id": "r", "type": "create.rectangle",
                 "params": { "width": 20, "depth": 10, "origin": [5, -5, 2] } } ])"));
  ASSERT_TRUE(t.ok()) << t.errors;
  const std::vector<EntityId> out = t.at("r.out");
  ASSERT_EQ(out.size(), 1U);
  EXPECT_DOUBLE_EQ(t.area(out[0]), 200.0);
  const shape::Scope s = t.scope(out[0]);
  EXPECT_EQ(s.origin, (kernel::Vec3{5, -5, 2}));
  EXPECT_EQ(s.x, (kernel::Vec3{1, 0, 0}));
  EXPECT_EQ(s.z, (kernel::Vec3{0, 0, 1}));
  EXPECT_DOUBLE_EQ(s.size.x, 20.0);
  EXPECT_DOUBLE_EQ(s.size.y, 10.0);
}

TEST(CreateNodes, CircleIsARegularPolygon) {
  const TestRun t = run_text(graph_text(R"(
    "nodes": [ { "id": "sq", "type": "create.circle", "params": { "radius": 1, "segments": 4 } },
               { "id": "c", "type": "create.circle", "params": { "radius": 2, "center": [10, 0, 0] } } ])"));
  ASSERT_TRUE(t.ok()) << t.errors;
  EXPECT_NEAR(t.area(t.at("sq.out").at(0)), 2.0, 1e-12);  // a square with diagonal 2
  const double n = 32;
  EXPECT_NEAR(t.area(t.at("c.out").at(0)), 0.5 * n * 4 * std::sin(2 * std::numbers::pi / n), 1e-9);
  const shape::Scope s = t.scope(t.at("c.out").at(0));
  EXPECT_NEAR(s.center().x, 10.0, 1e-9);
}

TEST(CreateNodes, PolygonVerticesAndElevation) {
  TestRun t = run_text(graph_text(R"(
    "nodes": [ { "id": "l", "type": "create.polygon",
                 "params": { "vertices": [[0,0,3], [4,0,3], [4,2,3], [2,2,3], [2,4,3], [0,4,3]] } } ])"));
  ASSERT_TRUE(t.ok()) << t.errors;
  EXPECT_DOUBLE_EQ(t.area(t.at("l.out").at(0)), 12.0);
  EXPECT_DOUBLE_EQ(t.scope(t.at("l.out").at(0)).origin.z, 3.0);
  t = run_text(graph_text(R"(
    "nodes": [ { "id": "l", "type": "create.polygon", "params": { "vertices": [[0,0], [4], [4,2]] } } ])"));
  ASSERT_FALSE(t.ok());
  EXPECT_TRUE(t.says("error[G052]: a vertex must be [x, y] or [x, y, z] (node 'l')")) << t.errors;
  t = run_text(graph_text(R"(
    "nodes": [ { "id": "l", "type": "create.polygon", "params": { "vertices": [[0,0], [4,2]] } } ])"));
  EXPECT_TRUE(t.says("error[G052]: a polygon needs at least 3 vertices (node 'l')")) << t.errors;
}

// Rows of cells from the origin, `gap` apart; index, ix, iy mapped to graph attributes.
TEST(CreateNodes, GridRowByRow) {
  const TestRun t = run_text(graph_text(R"(
    "attributes": { "i": { "type": "integer", "default": -1 }, "x": { "type": "integer", "default": -1 },
                    "y": { "type": "integer", "default": -1 } },
    "nodes": [ { "id": "g", "type": "create.grid",
                 "params": { "columns": 3, "rows": 2, "cell_width": 4, "cell_depth": 2, "gap": 1,
                             "origin": [10, 0, 0] },
                 "attributes": { "index": "i", "ix": "x", "iy": "y" } } ])"));
  ASSERT_TRUE(t.ok()) << t.errors;
  const std::vector<EntityId> cells = t.at("g.out");
  ASSERT_EQ(cells.size(), 6U);
  for (std::size_t k = 0; k < cells.size(); ++k) {
    EXPECT_DOUBLE_EQ(t.area(cells[k]), 8.0);
    EXPECT_EQ(t.attribute(cells[k], "i")->integer(), static_cast<std::int64_t>(k));
    EXPECT_EQ(t.attribute(cells[k], "x")->integer(), static_cast<std::int64_t>(k % 3));
    EXPECT_EQ(t.attribute(cells[k], "y")->integer(), static_cast<std::int64_t>(k / 3));
  }
  EXPECT_EQ(t.scope(cells[4]).origin, (kernel::Vec3{15, 3, 0}));
}

TEST(CreateNodes, PointsInOrder) {
  const TestRun t = run_text(graph_text(R"(
    "attributes": { "i": { "type": "integer", "default": -1 } },
    "nodes": [ { "id": "p", "type": "create.points", "params": { "points": [[1,2,3], [4,5,6]] },
                 "attributes": { "index": "i" } } ])"));
  ASSERT_TRUE(t.ok()) << t.errors;
  const std::vector<EntityId> out = t.at("p.out");
  ASSERT_EQ(out.size(), 2U);
  EXPECT_EQ(t.entity(out[0]).type, EntityType::kPoint);
  EXPECT_EQ(t.entity(out[1]).position, (kernel::Vec3{4, 5, 6}));
  EXPECT_EQ(t.attribute(out[1], "i")->integer(), 1);
}

// Carriers; as impulses, each makes the impulsed node run one round and pass on its attributes.
TEST(CreateNodes, EntitiesAndImpulses) {
  const TestRun t = run_text(graph_text(R"(
    "attributes": { "i": { "type": "integer", "default": -1 } },
    "nodes": [ { "id": "none", "type": "create.entity", "params": { "count": 0 } },
               { "id": "e", "type": "create.entity", "params": { "count": 3 },
                 "attributes": { "index": "i" } },
               { "id": "r", "type": "create.rectangle",
                 "params": { "width": "= 1 + @i", "depth": 1 } } ],
    "edges": [ "e.out -> r.impulse" ])"));
  ASSERT_TRUE(t.ok()) << t.errors;
  EXPECT_TRUE(t.at("none.out").empty());
  const std::vector<EntityId> out = t.at("r.out");
  ASSERT_EQ(out.size(), 3U);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_DOUBLE_EQ(t.area(out[k]), 1.0 + static_cast<double>(k));
    EXPECT_EQ(t.attribute(out[k], "i")->integer(), static_cast<std::int64_t>(k));
  }
  EXPECT_EQ(t.runs("r").rounds, 3U);
}

// Declared properties become attributes (a GeoJSON number into an integer attribute); others
// and degenerate lots are W030, once per message.
TEST(CreateNodes, LotsWithTheirProperties) {
  RunOptions options;
  std::string asked = "?";
  options.lots = [&asked](const std::string& file, std::vector<LotInput>& lots, std::string&) {
    asked = file;
    LotInput a;
    a.footprint.outer = {{0, 0}, {10, 0}, {10, 20}, {0, 20}};
    a.properties = {{"levels", 3.0}, {"zone", std::string("x")}, {"use", std::string("shop")}};
    LotInput flat;
    flat.footprint.outer = {{0, 0}, {1, 0}, {2, 0}};
    flat.id = "flat";
    LotInput b;
    b.footprint.outer = {{20, 0}, {25, 0}, {25, 5}, {20, 5}};
    b.properties = {{"zone", std::string("y")}};
    lots = {a, flat, b};
    return true;
  };
  const TestRun t = run_text(graph_text(R"(
    "attributes": { "levels": { "type": "integer", "default": 1 },
                    "use": { "type": "string", "default": "" },
                    "i": { "type": "integer", "default": -1 } },
    "nodes": [ { "id": "lots", "type": "create.lots", "attributes": { "index": "i" } } ])"),
                             options);
  ASSERT_TRUE(t.ok()) << t.errors;
  EXPECT_EQ(asked, "");
  const std::vector<EntityId> out = t.at("lots.out");
  ASSERT_EQ(out.size(), 2U);
  EXPECT_DOUBLE_EQ(t.area(out[0]), 200.0);
  EXPECT_EQ(t.attribute(out[0], "levels")->type(), ValueType::kInteger);
  EXPECT_EQ(t.attribute(out[0], "levels")->integer(), 3);
  EXPECT_EQ(t.attribute(out[0], "use")->text(), "shop");
  EXPECT_EQ(t.attribute(out[1], "levels"), nullptr);
  EXPECT_EQ(t.attribute(out[1], "i")->integer(), 2);  // the skipped lot keeps its number
  EXPECT_TRUE(
      t.says("warning[W030]: GeoJSON property 'zone' is not a declared attribute; ignored "
             "(node 'lots')"))
      << t.errors;
  EXPECT_EQ(t.errors.find("'zone'"), t.errors.rfind("'zone'")) << t.errors;
  EXPECT_TRUE(t.says("warning[W030]: lot 'flat': ")) << t.errors;
}

// A lot run with only some of its neighbours (a city tile by tile) keeps its number: its `index`,
// its seed (so its random values) and the ids of its buildings are the whole run's.
TEST(CreateNodes, NumberedLotsGiveWhatTheWholeRunGives) {
  std::vector<LotInput> all(5);
  for (std::size_t i = 0; i < all.size(); ++i) {
    const double x = 20.0 * static_cast<double>(i);
    all[i].footprint.outer = {{x, 0}, {x + 10, 0}, {x + 10, 10}, {x, 10}};
    all[i].id = i == 3 ? "" : "way/" + std::to_string(100 + i);
    all[i].number = static_cast<std::uint32_t>(i);
  }
  const std::string text = graph_text(R"json(
    "attributes": { "i": { "type": "integer", "default": -1 },
                    "h": { "type": "number", "default": 0 } },
    "nodes": [ { "id": "lots", "type": "create.lots", "attributes": { "index": "i" } },
               { "id": "tall", "type": "attr.set", "params": { "values": { "h": "= rand(3, 30)" } } },
               { "id": "mass", "type": "shape.extrude", "params": { "height": "= @h" } },
               { "id": "faces", "type": "shape.comp",
                 "augment": [ { "faces": "top", "out": "top" }, { "faces": "side", "out": "walls" } ] } ],
    "edges": [ "lots.out -> tall.in", "tall.out -> mass.in", "mass.out -> faces.in" ])json");
  const auto run_lots = [&text](std::vector<LotInput> lots) {
    RunOptions options;
    options.lots = [lots](const std::string&, std::vector<LotInput>& out, std::string&) {
      out = lots;
      return true;
    };
    return run_text(text, options);
  };
  const TestRun whole = run_lots(all);
  const TestRun some = run_lots({all[3], all[1]});
  ASSERT_TRUE(whole.ok()) << whole.errors;
  ASSERT_TRUE(some.ok()) << some.errors;
  const std::vector<EntityId> whole_tops = whole.at("faces.top");
  const std::vector<EntityId> some_tops = some.at("faces.top");
  ASSERT_EQ(whole_tops.size(), 5U);
  ASSERT_EQ(some_tops.size(), 2U);
  for (std::size_t k = 0; k < 2; ++k) {
    const EntityId w = whole_tops[k == 0 ? 3 : 1];
    EXPECT_EQ(some.attribute(some_tops[k], "i")->integer(), whole.attribute(w, "i")->integer());
    EXPECT_EQ(some.attribute(some_tops[k], "h")->number(), whole.attribute(w, "h")->number());
  }
  EXPECT_NE(whole.attribute(whole_tops[0], "h")->number(),
            whole.attribute(whole_tops[1], "h")->number());
  // A lot's shapes (its top and four walls) are one building, named after the lot; a lot without
  // an id is `lot_<number>`.
  const shape::Scene scene = to_scene(*some.run);
  std::vector<std::string> ids;
  for (const shape::Building& b : scene.buildings) ids.push_back(b.id);
  EXPECT_EQ(ids, (std::vector<std::string>{"lot_3", "way/101"}));
  EXPECT_EQ(scene.buildings[0].parts.size(), 2U);  // faces.top and faces.walls
}

// Two lots read as <lot>, and a lot's shapes that the graph numbers apart in `building` (a lot
// split into two houses) are two buildings: the lot's id, then `<lot>/2`.
TEST(CreateNodes, ALotsShapesNumberedApartAreBuildingsOfTheLot) {
  RunOptions options;
  options.lots = [](const std::string&, std::vector<LotInput>& lots, std::string&) {
    lots.resize(2);
    lots[0].footprint.outer = {{0, 0}, {20, 0}, {20, 10}, {0, 10}};
    lots[0].id = "way/1";
    lots[1].footprint.outer = {{30, 0}, {50, 0}, {50, 10}, {30, 10}};
    lots[1].id = "way/2";
    return true;
  };
  const TestRun t = run_text(graph_text(R"json(
    "attributes": { "building": { "type": "integer", "default": -1 } },
    "nodes": [ { "id": "lots", "type": "create.lots" },
               { "id": "houses", "type": "shape.split", "params": { "axis": "x" },
                 "augment": [ { "size": "~1", "out": "out" }, { "size": "~1", "out": "out" } ],
                 "attributes": { "index": "building" } },
               { "id": "mass", "type": "shape.extrude", "params": { "height": 6 } } ],
    "edges": [ "lots.out -> houses.in", "houses.out -> mass.in" ])json"),
                             options);
  ASSERT_TRUE(t.ok()) << t.errors;
  const shape::Scene scene = to_scene(*t.run);
  std::vector<std::string> ids;
  for (const shape::Building& b : scene.buildings) ids.push_back(b.id);
  EXPECT_EQ(ids, (std::vector<std::string>{"way/1", "way/1/2", "way/2", "way/2/2"}));
}

// An OpenStreetMap lot brings its `building` tag (yes, house); a graph that declares `building`
// keeps it, and two lots of equal tags stay two buildings, each with its tag (they were one
// building, `building=yes` grouping every lot's shapes together).
TEST(CreateNodes, LotsOfOneBuildingTagStayApartAndKeepTheirTag) {
  RunOptions options;
  options.lots = [](const std::string&, std::vector<LotInput>& lots, std::string&) {
    lots.resize(3);
    for (std::size_t i = 0; i < lots.size(); ++i) {
      const double x = 20.0 * static_cast<double>(i);
      lots[i].footprint.outer = {{x, 0}, {x + 10, 0}, {x + 10, 10}, {x, 10}};
      lots[i].id = "way/" + std::to_string(i + 1);
      lots[i].properties = {{"building", std::string(i == 2 ? "house" : "yes")}};
    }
    return true;
  };
  const TestRun t = run_text(graph_text(R"json(
    "attributes": { "building": { "type": "string", "default": "" } },
    "nodes": [ { "id": "lots", "type": "create.lots" },
               { "id": "mass", "type": "shape.extrude", "params": { "height": 6 } },
               { "id": "faces", "type": "shape.comp",
                 "augment": [ { "faces": "top", "out": "top" }, { "faces": "side", "out": "walls" } ] } ],
    "edges": [ "lots.out -> mass.in", "mass.out -> faces.in" ])json"),
                             options);
  ASSERT_TRUE(t.ok()) << t.errors;
  const shape::Scene scene = to_scene(*t.run);
  ASSERT_EQ(scene.buildings.size(), 3U);
  const std::vector<std::string> tags{"yes", "yes", "house"};
  for (std::size_t i = 0; i < 3; ++i) {
    const shape::Building& b = scene.buildings[i];
    EXPECT_EQ(b.id, "way/" + std::to_string(i + 1));
    EXPECT_EQ(b.parts.size(), 2U) << b.id;
    EXPECT_EQ(std::get<std::string>(b.attributes.at("building")), tags[i]) << b.id;
  }
}

// Real data does not follow the graph's types (OpenStreetMap's building=church for an integer
// `building`): the value is left out with W030 and the run goes on.
TEST(CreateNodes, LotPropertiesThatDoNotFitAreLeftOut) {
  RunOptions options;
  options.lots = [](const std::string&, std::vector<LotInput>& lots, std::string&) {
    LotInput a;
    a.footprint.outer = {{0, 0}, {10, 0}, {10, 20}, {0, 20}};
    a.properties = {{"building", std::string("church")}, {"levels", 2.0}};
    lots = {a};
    return true;
  };
  const TestRun t = run_text(graph_text(R"(
    "attributes": { "building": { "type": "integer", "default": -1 },
                    "levels": { "type": "integer", "default": 1 } },
    "nodes": [ { "id": "lots", "type": "create.lots" } ])"),
                             options);
  ASSERT_TRUE(t.ok()) << t.errors;
  const EntityId lot = t.at("lots.out").at(0);
  EXPECT_EQ(t.attribute(lot, "building"), nullptr);
  EXPECT_EQ(t.attribute(lot, "levels")->integer(), 2);
  EXPECT_TRUE(
      t.says("warning[W030]: GeoJSON property 'building' is not integer (church); ignored "
             "(node 'lots')"))
      << t.errors;
}

// A graph that numbers its lots in an attribute (lots.graph.json: `"index": "building"`) gets
// each lot's number there; an OpenStreetMap lot's tag of that name (`building=yes`) would be
// overwritten by it, so it is left out without a word. Other properties are read as ever.
TEST(CreateNodes, ThePropertyTheIndexWritesIsLeftToIt) {
  RunOptions options;
  options.lots = [](const std::string&, std::vector<LotInput>& lots, std::string&) {
    LotInput a;
    a.footprint.outer = {{0, 0}, {10, 0}, {10, 20}, {0, 20}};
    a.properties = {
        {"building", std::string("yes")}, {"levels", 2.0}, {"roof", std::string("hip")}};
    LotInput b = a;
    b.footprint.outer = {{20, 0}, {30, 0}, {30, 20}, {20, 20}};
    lots = {a, b};
    return true;
  };
  const TestRun t = run_text(graph_text(R"(
    "attributes": { "building": { "type": "integer", "default": -1 },
                    "levels": { "type": "integer", "default": 1 } },
    "nodes": [ { "id": "lots", "type": "create.lots", "attributes": { "index": "building" } } ])"),
                             options);
  ASSERT_TRUE(t.ok()) << t.errors;
  const std::vector<EntityId> lots = t.at("lots.out");
  ASSERT_EQ(lots.size(), 2U);
  EXPECT_EQ(t.attribute(lots[0], "building")->integer(), 0);
  EXPECT_EQ(t.attribute(lots[1], "building")->integer(), 1);
  EXPECT_EQ(t.attribute(lots[1], "levels")->integer(), 2);
  EXPECT_EQ(t.errors.find("'building'"), std::string::npos) << t.errors;
  EXPECT_TRUE(
      t.says("warning[W030]: GeoJSON property 'roof' is not a declared attribute; ignored "
             "(node 'lots')"))
      << t.errors;
}

TEST(CreateNodes, LotsWithoutAReader) {
  const TestRun t = run_text(graph_text(R"("nodes": [ { "id": "lots", "type": "create.lots" } ])"));
  ASSERT_FALSE(t.ok());
  EXPECT_TRUE(
      t.says("error[G052]: no lots: give --lot LOTS.geojson or the parameter 'file' "
             "(node 'lots')"))
      << t.errors;
}

}  // namespace
}  // namespace insula::lang::graph::testing
