// Path (street) nodes (graph-format.md §11 "Path (street) operations"): networks, their
// surfaces (roads and blocks with areas and order), merging and decomposition.
#include <gtest/gtest.h>

#include "run_util.h"

namespace insula::lang::graph::testing {
namespace {

TEST(PathNodes, CreateOpenAndClosed) {
  const TestRun t = run_text(graph_text(R"json(
    "attributes": { "len": { "type": "number", "default": 0 } },
    "nodes": [ { "id": "open", "type": "path.create", "params": { "points": [[0,0], [10,0], [10,10,2], [0,10]] } },
               { "id": "ring", "type": "path.create",
                 "params": { "points": [[0,0], [10,0], [10,10], [0,10]], "closed": true } },
               { "id": "measure", "type": "attr.set", "params": { "values": { "len": "= perimeter() " } } } ],
    "edges": [ "open.out -> measure.in", "ring.out -> measure.in" ])json"));
  ASSERT_TRUE(t.ok()) << t.errors;
  const std::vector<EntityId> out = t.at("measure.out");
  ASSERT_EQ(out.size(), 2U);
  const PathGeometry& open = *t.entity(out[0]).path;
  ASSERT_EQ(open.vertices.size(), 4U);
  EXPECT_EQ(open.vertices[2], (kernel::Vec3{10, 10, 2}));
  EXPECT_EQ(open.edges.size(), 3U);
  EXPECT_EQ(t.entity(out[1]).path->edges.size(), 4U);
  EXPECT_NEAR(t.attribute(out[1], "len")->number(), 40.0, 1e-12);
  const TestRun bad = run_text(graph_text(R"json(
    "nodes": [ { "id": "p", "type": "path.create", "params": { "points": [[0,0], [1]] } } ])json"));
  ASSERT_FALSE(bad.ok());
  EXPECT_TRUE(bad.says("error[G052]: a path point must be [x, y] or [x, y, z]; got [1] (node 'p')"))
      << bad.errors;
}

// Vertices row by row from the origin; edges to the right and upper neighbours.
TEST(PathNodes, Grid) {
  const TestRun t = run_text(graph_text(R"json(
    "nodes": [ { "id": "g", "type": "path.grid",
                 "params": { "columns": 3, "rows": 2, "spacing_x": 10, "spacing_y": 20, "origin": [5, 0, 1] } } ])json"));
  ASSERT_TRUE(t.ok()) << t.errors;
  const PathGeometry& g = *t.entity(t.at("g.out").at(0)).path;
  ASSERT_EQ(g.vertices.size(), 6U);
  EXPECT_EQ(g.vertices[4], (kernel::Vec3{15, 20, 1}));
  EXPECT_EQ(g.edges.size(), 7U);  // 2 x 2 along x, 3 along y
}

// A 3 x 3 street grid 50 m apart, 10 m wide: four 40 x 40 blocks by lowest then leftmost
// corner, each starting at that corner; one road surface, the 110 x 110 square without them.
TEST(PathNodes, ToShapesBlocksAndRoads) {
  const TestRun t = run_text(graph_text(R"json(
    "attributes": { "i": { "type": "integer", "default": -1 } },
    "nodes": [ { "id": "g", "type": "path.grid",
                 "params": { "columns": 3, "rows": 3, "spacing_x": 50, "spacing_y": 50 } },
               { "id": "s", "type": "path.to_shapes", "attributes": { "index": "i" } } ],
    "edges": [ "g.out -> s.in" ])json"));
  ASSERT_TRUE(t.ok()) << t.errors;
  const std::vector<EntityId> blocks = t.at("s.blocks");
  ASSERT_EQ(blocks.size(), 4U);
  const kernel::Vec3 corners[] = {{5, 5, 0}, {55, 5, 0}, {5, 55, 0}, {55, 55, 0}};
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_NEAR(t.area(blocks[k]), 1600.0, 1e-9);
    EXPECT_EQ(t.attribute(blocks[k], "i")->integer(), static_cast<std::int64_t>(k));
    const shape::Scope s = t.scope(blocks[k]);
    EXPECT_NEAR(kernel::length(s.origin - corners[k]), 0.0, 1e-9);
    EXPECT_NEAR(s.x.x, 1.0, 1e-12);  // along the first (lower) edge
  }
  const std::vector<EntityId> roads = t.at("s.roads");
  ASSERT_EQ(roads.size(), 1U);
  EXPECT_NEAR(t.area(roads[0]), 110.0 * 110.0 - 4 * 1600.0, 1e-6);
}

// Only the roads: one straight street with square ends.
TEST(PathNodes, Buffer) {
  const TestRun t = run_text(graph_text(R"json(
    "nodes": [ { "id": "p", "type": "path.create", "params": { "points": [[0,0], [100,0]] } },
               { "id": "b", "type": "path.buffer", "params": { "width": 10 } } ],
    "edges": [ "p.out -> b.in" ])json"));
  ASSERT_TRUE(t.ok()) << t.errors;
  ASSERT_EQ(t.at("b.out").size(), 1U);
  EXPECT_NEAR(t.area(t.at("b.out")[0]), 110.0 * 10.0, 1e-9);
}

// One network: a crossing splits both streets, ends within the tolerance are welded.
TEST(PathNodes, MergeAndDecompose) {
  const TestRun t = run_text(graph_text(R"json(
    "attributes": { "i": { "type": "integer", "default": -1 } },
    "nodes": [ { "id": "a", "type": "path.create", "params": { "points": [[0,0], [10,0]] } },
               { "id": "b", "type": "path.create", "params": { "points": [[5,-5], [5,5]] } },
               { "id": "c", "type": "path.create", "params": { "points": [[10.0005,0], [20,0]] } },
               { "id": "m", "type": "path.merge" },
               { "id": "d", "type": "path.decompose", "attributes": { "index": "i" } } ],
    "edges": [ "a.out -> m.in", "b.out -> m.in", "c.out -> m.in", "m.out -> d.in" ])json"));
  ASSERT_TRUE(t.ok()) << t.errors;
  EXPECT_EQ(t.runs("m").executions, 1U);
  const std::vector<EntityId> edges = t.at("d.edges");
  const std::vector<EntityId> vertices = t.at("d.vertices");
  EXPECT_EQ(edges.size(), 5U);     // a and b split at (5, 0), c joined to a's end
  EXPECT_EQ(vertices.size(), 6U);  // 0,0 10,0 5,-5 5,5 5,0 20,0
  double length = 0;
  for (std::size_t k = 0; k < edges.size(); ++k) {
    const PathGeometry& p = *t.entity(edges[k]).path;
    ASSERT_EQ(p.edges.size(), 1U);
    length += kernel::length(p.vertices[p.edges[0][1]] - p.vertices[p.edges[0][0]]);
    EXPECT_EQ(t.attribute(edges[k], "i")->integer(), static_cast<std::int64_t>(k));
  }
  EXPECT_NEAR(length, 10 + 10 + 10, 1e-3);
  for (std::size_t k = 0; k < vertices.size(); ++k) {
    EXPECT_EQ(t.entity(vertices[k]).type, EntityType::kPoint);
    EXPECT_EQ(t.attribute(vertices[k], "i")->integer(), static_cast<std::int64_t>(k));
  }
}

}  // namespace
}  // namespace insula::lang::graph::testing
