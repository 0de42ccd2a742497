// shape.unify and shape.adjacency_merge (graph-format.md §11; seed 003, Fig. 6) on small graphs.
#include <gtest/gtest.h>

#include "kernel/mesh.h"
#include "run_util.h"

namespace insula::lang::graph::testing {
namespace {

std::string graph(const std::string& body) {
  return R"({"format": "insula-graph", "version": 1, )" + body + "}";
}

const kernel::Mesh& mesh(const TestRun& t, EntityId e) {
  return *t.run->tree[t.run->entities[e].shape].mesh;
}

// A grid of boxes 4 x 3 x 5 m, `gap` apart, into adjacency_merge.
TestRun boxes(int columns, double gap) {
  return run_text(graph(R"(
    "attributes": { "row": { "type": "integer", "default": -1 },
                    "cell": { "type": "integer", "default": -1 } },
    "nodes": [
      { "id": "grid", "type": "create.grid",
        "params": { "columns": )" +
                        std::to_string(columns) + R"(, "rows": 1, "cell_width": 4,
                    "cell_depth": 3, "gap": )" +
                        std::to_string(gap) + R"( },
        "attributes": { "iy": "row", "index": "cell" } },
      { "id": "mass", "type": "shape.extrude", "params": { "height": 5 } },
      { "id": "merged", "type": "shape.adjacency_merge" } ],
    "edges": [ "grid.out -> mass.in", "mass.out -> merged.in" ])"));
}

TEST(MergeNodes, AdjacentBoxesBecomeOneBoxOfSixFaces) {
  const TestRun t = boxes(2, 0);
  ASSERT_TRUE(t.ok()) << t.errors;
  const std::vector<EntityId> out = t.at("merged.out");
  ASSERT_EQ(out.size(), 1U);
  EXPECT_NEAR(t.volume(out[0]), 120.0, 1e-9);
  EXPECT_NEAR(t.area(out[0]), 2 * (8 * 3 + 8 * 5 + 3 * 5), 1e-9);
  EXPECT_EQ(mesh(t, out[0]).face_count(), 6U);
  EXPECT_EQ(mesh(t, out[0]).vertex_count(), 8U);
  EXPECT_TRUE(kernel::check(mesh(t, out[0])).closed);
  // Attributes the group shares stay; the cell numbers differ and go.
  ASSERT_NE(t.attribute(out[0], "row"), nullptr);
  EXPECT_EQ(t.attribute(out[0], "row")->integer(), 0);
  EXPECT_EQ(t.attribute(out[0], "cell"), nullptr);
}

TEST(MergeNodes, SeparatedBoxesStaySeparateShapesInOrder) {
  const TestRun t = boxes(3, 1);
  ASSERT_TRUE(t.ok()) << t.errors;
  const std::vector<EntityId> out = t.at("merged.out");
  ASSERT_EQ(out.size(), 3U);
  for (std::size_t i = 0; i < out.size(); ++i) {
    EXPECT_NEAR(t.volume(out[i]), 60.0, 1e-9);
    EXPECT_EQ(mesh(t, out[i]).face_count(), 6U);
    ASSERT_NE(t.attribute(out[i], "cell"), nullptr);
    EXPECT_EQ(t.attribute(out[i], "cell")->integer(), static_cast<std::int64_t>(i));
    // World scopes: the i-th box starts 5 m after the previous one.
    EXPECT_NEAR(t.run->tree[t.run->entities[out[i]].shape].scope.origin.x, 5.0 * i, 1e-12);
  }
}

// Fig. 6's use: façade tiles of all four sides, merged by adjacency, are one shape whose tiles
// join into one face per side (the corners are shared edges, not coplanar).
TEST(MergeNodes, FacadeTilesAroundCornersJoinPerSide) {
  const TestRun t = run_text(graph(R"(
    "nodes": [
      { "id": "lot", "type": "create.rectangle", "params": { "width": 8, "depth": 3 } },
      { "id": "mass", "type": "shape.extrude", "params": { "height": 5 } },
      { "id": "faces", "type": "shape.comp", "augment": [ { "faces": "side", "out": "side" } ] },
      { "id": "tiles", "type": "shape.repeat", "params": { "axis": "x", "size": 1 } },
      { "id": "merged", "type": "shape.adjacency_merge" } ],
    "edges": [ "lot.out -> mass.in", "mass.out -> faces.in", "faces.side -> tiles.in",
               "tiles.out -> merged.in" ])"));
  ASSERT_TRUE(t.ok()) << t.errors;
  const std::vector<EntityId> out = t.at("merged.out");
  ASSERT_EQ(out.size(), 1U);
  EXPECT_EQ(mesh(t, out[0]).face_count(), 4U);
  EXPECT_NEAR(t.area(out[0]), 2 * (8 + 3) * 5, 1e-9);
  const kernel::MeshCheck c = kernel::check(mesh(t, out[0]));
  EXPECT_TRUE(c.oriented);
  EXPECT_EQ(c.boundary_edges, 8U);  // the top and bottom rings, one edge per side each
}

// A box split in two and merged back has 12 faces; unify welds it into the box's 6.
TEST(MergeNodes, UnifyJoinsASplitBox) {
  const TestRun t = run_text(graph(R"(
    "attributes": { "tagged": { "type": "bool", "default": false } },
    "nodes": [
      { "id": "lot", "type": "create.rectangle", "params": { "width": 8, "depth": 3 } },
      { "id": "mass", "type": "shape.extrude", "params": { "height": 5 } },
      { "id": "cut", "type": "shape.split", "params": { "axis": "x" },
        "augment": [ { "size": "'0.5", "out": "part" }, { "size": "'0.5", "out": "part" } ] },
      { "id": "mark", "type": "attr.set", "params": { "values": { "tagged": true } } },
      { "id": "merge", "type": "shape.merge" },
      { "id": "unify", "type": "shape.unify" } ],
    "edges": [ "lot.out -> mass.in", "mass.out -> cut.in", "cut.part -> mark.in",
               "mark.out -> merge.in", "merge.out -> unify.in" ])"));
  ASSERT_TRUE(t.ok()) << t.errors;
  const std::vector<EntityId> out = t.at("unify.out");
  ASSERT_EQ(out.size(), 1U);
  const EntityId merged = t.run->entities[out[0]].parent;
  EXPECT_EQ(mesh(t, merged).face_count(), 12U);
  EXPECT_EQ(mesh(t, out[0]).face_count(), 6U);
  EXPECT_NEAR(t.volume(out[0]), 120.0, 1e-9);
  EXPECT_TRUE(kernel::is_watertight(mesh(t, out[0])));
  // unify derives from its input: same scope, same attributes.
  EXPECT_EQ(t.run->tree[t.run->entities[out[0]].shape].scope.origin,
            t.run->tree[t.run->entities[merged].shape].scope.origin);
  ASSERT_NE(t.attribute(out[0], "tagged"), nullptr);
  EXPECT_TRUE(t.attribute(out[0], "tagged")->boolean());
}

}  // namespace
}  // namespace insula::lang::graph::testing
