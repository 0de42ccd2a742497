// Shape (mesh) operation nodes (graph-format.md §11): each registry wrapper on a shape whose
// result is computable by hand, node attributes, output ports and W040 failures.
#include <gtest/gtest.h>

#include <map>

#include "run_util.h"
#include "shape/ops.h"

namespace insula::lang::graph::testing {
namespace {

// A 20 x 10 lot extruded 12 high, then `rest` (nodes and edges after `mass`).
std::string box(const std::string& nodes, const std::string& edges,
                const std::string& attributes = "{}") {
  return graph_text(R"("attributes": )" + attributes + R"(,
    "nodes": [
      { "id": "lot", "type": "create.rectangle", "params": { "width": 20, "depth": 10 } },
      { "id": "mass", "type": "shape.extrude", "params": { "height": 12 } }, )" +
                    nodes + R"( ],
    "edges": [ "lot.out -> mass.in", )" +
                    edges + "]");
}

TEST(ShapeNodes, ExtrudeAndItsFailure) {
  const TestRun t = run_text(box(R"({ "id": "again", "type": "shape.extrude",
                                      "params": { "height": 1 } })",
                                 R"("mass.out -> again.in")"));
  ASSERT_TRUE(t.ok()) << t.errors;
  EXPECT_EQ(t.runs("mass").rounds, 1U);
  EXPECT_TRUE(t.at("again.out").empty());
  EXPECT_EQ(t.failed("again"), 1U);
  EXPECT_TRUE(
      t.says("warning[W040]: node 'again': 1 entity dropped; extrude: needs a flat shape "
             "(a footprint or a face)\n"))
      << t.errors;
}

TEST(ShapeNodes, ExtrudeVolume) {
  const TestRun t = run_text(graph_text(R"(
    "nodes": [ { "id": "lot", "type": "create.rectangle", "params": { "width": 20, "depth": 10 } },
               { "id": "mass", "type": "shape.extrude", "params": { "height": 12 } } ],
    "edges": [ "lot.out -> mass.in" ])"));
  ASSERT_TRUE(t.ok()) << t.errors;
  EXPECT_DOUBLE_EQ(t.volume(t.at("mass.out").at(0)), 2400.0);
  // A mass's scope has y up (CGA's convention) and z out of its front.
  const shape::Scope s = t.scope(t.at("mass.out").at(0));
  EXPECT_DOUBLE_EQ(s.size.y, 12.0);
  EXPECT_EQ(s.y, (kernel::Vec3{0, 0, 1}));
}

// Slices in order, each to its port; a zero-size slice is dropped but keeps its index.
TEST(ShapeNodes, SplitSlicesToTheirPorts) {
  const TestRun t = run_text(graph_text(R"(
    "attributes": { "i": { "type": "integer", "default": -1 }, "n": { "type": "integer", "default": -1 } },
    "nodes": [ { "id": "lot", "type": "create.rectangle", "params": { "width": 10, "depth": 4 } },
               { "id": "cut", "type": "shape.split", "params": { "axis": "x" },
                 "augment": [ { "size": 2, "out": "a" }, { "size": 0, "out": "zero" },
                              { "size": "~1", "out": "b" }, { "size": "'0.3", "out": "a" } ],
                 "attributes": { "index": "i", "count": "n" } } ],
    "edges": [ "lot.out -> cut.in" ])"));
  ASSERT_TRUE(t.ok()) << t.errors;
  const std::vector<EntityId> a = t.at("cut.a");
  ASSERT_EQ(a.size(), 2U);
  EXPECT_DOUBLE_EQ(t.area(a[0]), 8.0);
  EXPECT_DOUBLE_EQ(t.area(a[1]), 12.0);
  EXPECT_EQ(t.attribute(a[1], "i")->integer(), 3);
  EXPECT_EQ(t.attribute(a[1], "n")->integer(), 4);
  EXPECT_TRUE(t.at("cut.zero").empty());
  ASSERT_EQ(t.at("cut.b").size(), 1U);
  EXPECT_DOUBLE_EQ(t.area(t.at("cut.b")[0]), 20.0);
  EXPECT_DOUBLE_EQ(t.scope(t.at("cut.b")[0]).origin.x, 2.0);
}

TEST(ShapeNodes, RepeatFitsWholePieces) {
  const TestRun t = run_text(graph_text(R"(
    "attributes": { "i": { "type": "integer", "default": -1 }, "n": { "type": "integer", "default": -1 } },
    "nodes": [ { "id": "lot", "type": "create.rectangle", "params": { "width": 10, "depth": 4 } },
               { "id": "rep", "type": "shape.repeat", "params": { "axis": "x", "size": 3 },
                 "attributes": { "index": "i", "count": "n" } } ],
    "edges": [ "lot.out -> rep.in" ])"));
  ASSERT_TRUE(t.ok()) << t.errors;
  const std::vector<EntityId> out = t.at("rep.out");
  ASSERT_EQ(out.size(), 3U);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_NEAR(t.area(out[k]), 40.0 / 3, 1e-9);
    EXPECT_EQ(t.attribute(out[k], "i")->integer(), static_cast<std::int64_t>(k));
    EXPECT_EQ(t.attribute(out[k], "n")->integer(), 3);
  }
}

// Each face goes to the first item it matches, with `face` naming the item; unmatched faces
// are dropped.
TEST(ShapeNodes, CompFirstMatchWins) {
  const TestRun t = run_text(
      box(R"({ "id": "faces", "type": "shape.comp",
               "augment": [ { "faces": "front", "out": "front" }, { "faces": "side", "out": "sides" },
                            { "faces": "top", "out": "top" } ],
               "attributes": { "face": "f", "index": "i", "count": "n" } })",
          R"("mass.out -> faces.in")",
          R"({ "f": { "type": "string", "default": "" }, "i": { "type": "integer", "default": -1 },
               "n": { "type": "integer", "default": -1 } })"));
  ASSERT_TRUE(t.ok()) << t.errors;
  ASSERT_EQ(t.at("faces.front").size(), 1U);
  EXPECT_DOUBLE_EQ(t.area(t.at("faces.front")[0]), 240.0);
  const std::vector<EntityId> sides = t.at("faces.sides");
  ASSERT_EQ(sides.size(), 3U);  // the front went to the first item
  double total = 0;
  for (std::size_t k = 0; k < sides.size(); ++k) {
    total += t.area(sides[k]);
    EXPECT_EQ(t.attribute(sides[k], "f")->text(), "side");
    EXPECT_EQ(t.attribute(sides[k], "i")->integer(), static_cast<std::int64_t>(k));
    EXPECT_EQ(t.attribute(sides[k], "n")->integer(), 3);
  }
  EXPECT_DOUBLE_EQ(total, 240.0 + 2 * 120.0);
  ASSERT_EQ(t.at("faces.top").size(), 1U);
  EXPECT_DOUBLE_EQ(t.area(t.at("faces.top")[0]), 200.0);
  EXPECT_EQ(t.run->results.size(), 5U);  // the bottom matched nothing
}

TEST(ShapeNodes, OffsetInsideAndBorder) {
  const TestRun t = run_text(graph_text(R"(
    "nodes": [ { "id": "lot", "type": "create.rectangle", "params": { "width": 10, "depth": 10 } },
               { "id": "in", "type": "shape.offset", "params": { "distance": -1 } } ],
    "edges": [ "lot.out -> in.in" ])"));
  ASSERT_TRUE(t.ok()) << t.errors;
  ASSERT_EQ(t.at("in.inside").size(), 1U);
  EXPECT_NEAR(t.area(t.at("in.inside")[0]), 64.0, 1e-9);
  ASSERT_EQ(t.at("in.border").size(), 1U);
  EXPECT_NEAR(t.area(t.at("in.border")[0]), 36.0, 1e-9);
}

TEST(ShapeNodes, SetbackStripAndRest) {
  const TestRun t = run_text(graph_text(R"(
    "nodes": [ { "id": "lot", "type": "create.rectangle", "params": { "width": 10, "depth": 10 } },
               { "id": "back", "type": "shape.setback", "params": { "distance": 2 } } ],
    "edges": [ "lot.out -> back.in" ])"));
  ASSERT_TRUE(t.ok()) << t.errors;
  ASSERT_EQ(t.at("back.strip").size(), 1U);
  EXPECT_NEAR(t.area(t.at("back.strip")[0]), 20.0, 1e-9);
  EXPECT_NEAR(t.scope(t.at("back.strip")[0]).origin.y, 0.0, 1e-9);  // the front edge is y = 0
  ASSERT_EQ(t.at("back.rest").size(), 1U);
  EXPECT_NEAR(t.area(t.at("back.rest")[0]), 80.0, 1e-9);
}

// A hip roof on a square at 45 degrees is a pyramid half the side high.
TEST(ShapeNodes, HipRoofIsAPyramid) {
  const TestRun t = run_text(graph_text(R"(
    "nodes": [ { "id": "lot", "type": "create.rectangle", "params": { "width": 10, "depth": 10 } },
               { "id": "roof", "type": "shape.roof", "params": { "pitch": 45 } } ],
    "edges": [ "lot.out -> roof.in" ])"));
  ASSERT_TRUE(t.ok()) << t.errors;
  ASSERT_EQ(t.at("roof.out").size(), 1U);
  EXPECT_NEAR(t.volume(t.at("roof.out")[0]), 100.0 * 5 / 3, 1e-9);
  EXPECT_NEAR(t.scope(t.at("roof.out")[0]).size.y, 5.0, 1e-9);
}

class Assets : public shape::AssetProvider {
 public:
  std::shared_ptr<const kernel::Mesh> find(std::string_view name,
                                           std::string& error) const override {
    if (name == "cube") return shape::box_mesh({1, 1, 1}, shape::mass_box_tags());
    error = "cannot open '" + std::string(name) + ".obj'";
    return nullptr;
  }
};

TEST(ShapeNodes, InsertFillsTheScope) {
  const std::string text = graph_text(R"json(
    "nodes": [ { "id": "lot", "type": "create.rectangle", "params": { "width": 2, "depth": 3 } },
               { "id": "mass", "type": "shape.extrude", "params": { "height": 4 } },
               { "id": "put", "type": "shape.insert", "params": { "asset": "= if(sx() > 1, 'cube', 'sphere')" } } ],
    "edges": [ "lot.out -> mass.in", "mass.out -> put.in" ])json");
  Assets assets;
  RunOptions options;
  options.assets = &assets;
  TestRun t = run_text(text, options);
  ASSERT_TRUE(t.ok()) << t.errors;
  ASSERT_EQ(t.at("put.out").size(), 1U);
  EXPECT_NEAR(t.volume(t.at("put.out")[0]), 24.0, 1e-9);
  t = run_text(text);
  ASSERT_TRUE(t.ok()) << t.errors;
  EXPECT_EQ(t.failed("put"), 1U);
  EXPECT_TRUE(t.says("warning[W040]: node 'put': 1 entity dropped; insert: no asset provider\n"))
      << t.errors;
}

// The shape takes the target's scope, scaled on the chosen axes only.
TEST(ShapeNodes, FitScope) {
  const TestRun t = run_text(graph_text(R"(
    "nodes": [ { "id": "unit", "type": "create.rectangle", "params": { "width": 1, "depth": 1 } },
               { "id": "cube", "type": "shape.extrude", "params": { "height": 1 } },
               { "id": "big", "type": "create.rectangle", "params": { "width": 2, "depth": 3, "origin": [10, 0, 0] } },
               { "id": "target", "type": "shape.extrude", "params": { "height": 4 } },
               { "id": "copy", "type": "flow.copy", "params": { "count": 2 } },
               { "id": "all", "type": "shape.fit_scope" },
               { "id": "xy", "type": "shape.fit_scope", "params": { "axes": "xy" } } ],
    "edges": [ "unit.out -> cube.in", "big.out -> target.in", "target.out -> copy.in",
               "cube.out -> all.in", "cube.out -> xy.in", "copy.out -> all.target", "copy.out -> xy.target" ])"));
  ASSERT_TRUE(t.ok()) << t.errors;
  ASSERT_EQ(t.at("all.out").size(), 1U);
  EXPECT_NEAR(t.volume(t.at("all.out")[0]), 24.0, 1e-9);
  // The target's scope: y up, z out of its front (-Y), so its origin is the corner (10, 3, 0).
  EXPECT_EQ(t.scope(t.at("all.out")[0]).origin, (kernel::Vec3{10, 3, 0}));
  ASSERT_EQ(t.at("xy.out").size(), 1U);
  EXPECT_NEAR(t.volume(t.at("xy.out")[0]), 2.0 * 4.0 * 1.0, 1e-9);  // x 2, y (up) 4, z kept
  EXPECT_DOUBLE_EQ(t.scope(t.at("xy.out")[0]).size.z, 1.0);
  EXPECT_EQ(t.run->unprocessed.at("all.target"), 1U);  // two copies arrive, one is used
  EXPECT_EQ(t.run->unprocessed.at("xy.target"), 1U);
}

// A target without extent (a point) places the shape at its position, unscaled.
TEST(ShapeNodes, FitScopeToAPoint) {
  const TestRun t = run_text(graph_text(R"(
    "nodes": [ { "id": "unit", "type": "create.rectangle", "params": { "width": 2, "depth": 1 } },
               { "id": "cube", "type": "shape.extrude", "params": { "height": 3 } },
               { "id": "here", "type": "create.points", "params": { "points": [[5, 6, 7]] } },
               { "id": "fit", "type": "shape.fit_scope" } ],
    "edges": [ "unit.out -> cube.in", "cube.out -> fit.in", "here.out -> fit.target" ])"));
  ASSERT_TRUE(t.ok()) << t.errors;
  ASSERT_EQ(t.at("fit.out").size(), 1U);
  EXPECT_NEAR(t.volume(t.at("fit.out")[0]), 6.0, 1e-9);
  const shape::Scope s = t.scope(t.at("fit.out")[0]);
  EXPECT_EQ(s.origin, (kernel::Vec3{5, 6, 7}));
  EXPECT_NEAR(s.size.x * s.size.y * s.size.z, 6.0, 1e-9);
}

// All faces in one shape; attributes every input shares are kept, others dropped.
TEST(ShapeNodes, MergeKeepsCommonAttributes) {
  const TestRun t = run_text(graph_text(R"(
    "attributes": { "same": { "type": "integer", "default": 0 }, "own": { "type": "integer", "default": 0 } },
    "nodes": [ { "id": "cells", "type": "create.grid",
                 "params": { "columns": 2, "rows": 1, "cell_width": 2, "cell_depth": 2, "gap": 1 },
                 "attributes": { "index": "own" } },
               { "id": "mark", "type": "attr.set", "params": { "values": { "same": 7 } } },
               { "id": "mass", "type": "shape.extrude", "params": { "height": "= 1 + @own" } },
               { "id": "one", "type": "shape.merge" } ],
    "edges": [ "cells.out -> mark.in", "mark.out -> mass.in", "mass.out -> one.in" ])"));
  ASSERT_TRUE(t.ok()) << t.errors;
  ASSERT_EQ(t.at("one.out").size(), 1U);
  const EntityId m = t.at("one.out")[0];
  EXPECT_NEAR(t.volume(m), 4.0 + 8.0, 1e-9);
  EXPECT_EQ(measure(t.run->entities, t.run->tree, m).faces, 12U);
  EXPECT_EQ(t.attribute(m, "same")->integer(), 7);
  EXPECT_EQ(t.attribute(m, "own"), nullptr);
  const shape::Scope s = t.scope(m);
  EXPECT_NEAR(s.size.x, 5.0, 1e-9);
  EXPECT_NEAR(s.size.z, 2.0, 1e-9);
}

TEST(ShapeNodes, SetMaterial) {
  const TestRun t = run_text(graph_text(R"(
    "nodes": [ { "id": "lot", "type": "create.rectangle", "params": { "width": 2, "depth": 3 } },
               { "id": "paint", "type": "shape.set_material",
                 "params": { "material": "brick", "color": [0.5, 0.25, 0] } } ],
    "edges": [ "lot.out -> paint.in" ])"));
  ASSERT_TRUE(t.ok()) << t.errors;
  const std::uint16_t m = t.entity(t.at("paint.out").at(0)).material;
  ASSERT_GT(m, 0U);
  ASSERT_LT(m, t.run->materials.size());
  EXPECT_EQ(t.run->materials[m].name, "brick");
  EXPECT_FLOAT_EQ(t.run->materials[m].rgba[1], 0.25F);
  EXPECT_DOUBLE_EQ(t.area(t.at("paint.out")[0]), 6.0);
}

TEST(ShapeNodes, OpReachesAnyRegistryOperation) {
  TestRun t = run_text(graph_text(R"(
    "attributes": { "i": { "type": "integer", "default": -1 } },
    "nodes": [ { "id": "lot", "type": "create.rectangle", "params": { "width": 2, "depth": 3 } },
               { "id": "up", "type": "shape.op", "params": { "op": "extrude", "args": { "height": 5 } },
                 "attributes": { "index": "i" } } ],
    "edges": [ "lot.out -> up.in" ])"));
  ASSERT_TRUE(t.ok()) << t.errors;
  EXPECT_NEAR(t.volume(t.at("up.out").at(0)), 30.0, 1e-9);
  EXPECT_EQ(t.attribute(t.at("up.out")[0], "i")->integer(), 0);
  t = run_text(graph_text(R"(
    "nodes": [ { "id": "lot", "type": "create.rectangle", "params": { "width": 2, "depth": 3 } },
               { "id": "up", "type": "shape.op", "params": { "op": "extrud" } } ],
    "edges": [ "lot.out -> up.in" ])"));
  ASSERT_FALSE(t.ok());
  EXPECT_TRUE(t.says("error[G052]: unknown operation 'extrud' (node 'up')")) << t.errors;
}

// Scope space moves along the shape's own axes; world space along the world's.
TEST(ShapeNodes, TranslateRotateScaleShapes) {
  const TestRun t = run_text(graph_text(R"(
    "nodes": [ { "id": "lot", "type": "create.rectangle", "params": { "width": 2, "depth": 1 } },
               { "id": "turn", "type": "actor.rotate", "params": { "z": 90 } },
               { "id": "local", "type": "actor.translate", "params": { "x": 5 } },
               { "id": "world", "type": "actor.translate", "params": { "x": 5, "space": "world" } },
               { "id": "grow", "type": "actor.scale", "params": { "x": 4, "y": "'3" } } ],
    "edges": [ "lot.out -> turn.in", "turn.out -> local.in", "turn.out -> world.in",
               "lot.out -> grow.in" ])"));
  ASSERT_TRUE(t.ok()) << t.errors;
  const shape::Scope turned = t.scope(t.at("local.out").at(0));
  EXPECT_NEAR(turned.x.y, 1.0, 1e-12);  // scope x now points along world +y
  EXPECT_NEAR(turned.origin.x, 0.0, 1e-12);
  EXPECT_NEAR(turned.origin.y, 5.0, 1e-12);
  const shape::Scope world = t.scope(t.at("world.out").at(0));
  EXPECT_NEAR(world.origin.x, 5.0, 1e-12);
  EXPECT_NEAR(world.origin.y, 0.0, 1e-12);
  EXPECT_NEAR(t.area(t.at("world.out")[0]), 2.0, 1e-12);
  EXPECT_NEAR(t.area(t.at("grow.out").at(0)), 12.0, 1e-12);
}

// Points and paths move directly; a point cannot be rotated (W040).
TEST(ShapeNodes, TransformsOfPointsAndPaths) {
  const TestRun t = run_text(graph_text(R"(
    "nodes": [ { "id": "p", "type": "create.points", "params": { "points": [[1, 2, 3]] } },
               { "id": "street", "type": "path.create", "params": { "points": [[0, 0], [10, 0]] } },
               { "id": "move", "type": "actor.translate", "params": { "x": 1, "y": -1, "z": 2 } },
               { "id": "shift", "type": "actor.translate", "params": { "y": 5, "space": "world" } },
               { "id": "turn", "type": "actor.rotate", "params": { "z": 90 } } ],
    "edges": [ "p.out -> move.in", "p.out -> turn.in", "street.out -> shift.in" ])"));
  ASSERT_TRUE(t.ok()) << t.errors;
  EXPECT_EQ(t.entity(t.at("move.out").at(0)).position, (kernel::Vec3{2, 1, 5}));
  const PathGeometry& path = *t.entity(t.at("shift.out").at(0)).path;
  EXPECT_EQ(path.vertices[1], (kernel::Vec3{10, 5, 0}));
  EXPECT_TRUE(t.at("turn.out").empty());
  EXPECT_EQ(t.failed("turn"), 1U);
  EXPECT_TRUE(
      t.says("warning[W040]: node 'turn': 1 entity dropped; rotate needs a shape; a point "
             "can only be translated\n"))
      << t.errors;
}

}  // namespace
}  // namespace insula::lang::graph::testing
