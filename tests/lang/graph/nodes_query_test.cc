// Context-aware nodes (graph-format.md §11 "Context-aware operations") on scenes whose answers
// follow by hand; each query skips the entity's own ancestors and descendants (§9.10).
#include <gtest/gtest.h>

#include "run_util.h"

namespace insula::lang::graph::testing {
namespace {

// Initial centroids are the first k entities; the centres are the clusters' means.
TEST(QueryNodes, KMeans) {
  const TestRun t = run_text(graph_text(R"json(
    "attributes": { "c": { "type": "integer", "default": -1 }, "m": { "type": "vec3", "default": [0, 0, 0] } },
    "nodes": [ { "id": "p", "type": "create.points",
                 "params": { "points": [[0,0,0], [10,0,0], [1,0,0], [11,0,0], [2,0,0], [5,0,0]] } },
               { "id": "k", "type": "query.kmeans", "params": { "k": 2 },
                 "attributes": { "cluster": "c", "center": "m" } } ],
    "edges": [ "p.out -> k.in" ])json"));
  ASSERT_TRUE(t.ok()) << t.errors;
  const std::vector<EntityId> out = t.at("k.out");
  ASSERT_EQ(out.size(), 6U);
  // 5 is as far from 0 as from 10 at first: the tie goes to cluster 0, whose centre becomes 2.
  const std::int64_t want[] = {0, 1, 0, 1, 0, 0};
  for (std::size_t i = 0; i < 6; ++i) {
    EXPECT_EQ(t.attribute(out[i], "c")->integer(), want[i]) << i;
    EXPECT_NEAR(t.attribute(out[i], "m")->vec().x, want[i] == 0 ? 2.0 : 10.5, 1e-12) << i;
  }
}

// Two 10 x 10 lots cast rays up (+z); a box 5 m above the first is hit 5 m up, a box far
// away is missed.
TEST(QueryNodes, RayCast) {
  const TestRun t = run_text(graph_text(R"json(
    "attributes": { "hit": { "type": "bool", "default": false }, "d": { "type": "number", "default": 0 },
                    "at": { "type": "vec3", "default": [0, 0, 0] } },
    "nodes": [ { "id": "lots", "type": "create.grid",
                 "params": { "columns": 2, "rows": 1, "cell_width": 10, "cell_depth": 10, "gap": 40 } },
               { "id": "above", "type": "create.rectangle", "params": { "width": 10, "depth": 10, "origin": [0, 0, 5] } },
               { "id": "far", "type": "create.rectangle", "params": { "width": 10, "depth": 10, "origin": [200, 0, 0] } },
               { "id": "boxes", "type": "shape.extrude", "params": { "height": 1 } },
               { "id": "ray", "type": "query.ray_cast",
                 "attributes": { "hit": "hit", "hit_distance": "d", "hit_position": "at" } } ],
    "edges": [ "above.out -> boxes.in", "far.out -> boxes.in", "lots.out -> ray.sources",
               "boxes.out -> ray.targets" ])json"));
  ASSERT_TRUE(t.ok()) << t.errors;
  const std::vector<EntityId> sources = t.at("ray.sources");
  ASSERT_EQ(sources.size(), 2U);
  EXPECT_TRUE(t.attribute(sources[0], "hit")->boolean());
  EXPECT_NEAR(t.attribute(sources[0], "d")->number(), 5.0, 1e-9);
  EXPECT_NEAR(kernel::length(t.attribute(sources[0], "at")->vec() - kernel::Vec3{5, 5, 5}), 0,
              1e-9);
  EXPECT_FALSE(t.attribute(sources[1], "hit")->boolean());
  EXPECT_DOUBLE_EQ(t.attribute(sources[1], "d")->number(), -1.0);
  ASSERT_EQ(t.at("ray.hit").size(), 1U);
  EXPECT_NEAR(t.scope(t.at("ray.hit")[0]).origin.x, 0.0, 1e-9);
  ASSERT_EQ(t.at("ray.miss").size(), 1U);
  EXPECT_NEAR(t.scope(t.at("ray.miss")[0]).origin.x, 200.0, 1e-9);
}

// A 10 m cube's walls against boxes: one beside its +x wall covering half its width, one beside
// its -x wall half its height, one 15 m out (beyond `distance`); the cube itself is skipped.
TEST(QueryNodes, Occlusion) {
  const TestRun t = run_text(graph_text(R"json(
    "attributes": { "o": { "type": "number", "default": -1 } },
    "nodes": [ { "id": "lot", "type": "create.rectangle", "params": { "width": 10, "depth": 10 } },
               { "id": "mass", "type": "shape.extrude", "params": { "height": 10 } },
               { "id": "walls", "type": "shape.comp", "augment": [ { "faces": "side", "out": "side" } ] },
               { "id": "b", "type": "create.rectangle", "params": { "width": 5, "depth": 5, "origin": [12, 0, 0] } },
               { "id": "c", "type": "create.rectangle", "params": { "width": 5, "depth": 5, "origin": [25, 5, 0] } },
               { "id": "bc", "type": "shape.extrude", "params": { "height": 10 } },
               { "id": "d", "type": "create.rectangle", "params": { "width": 5, "depth": 10, "origin": [-8, 0, 0] } },
               { "id": "low", "type": "shape.extrude", "params": { "height": 5 } },
               { "id": "occ", "type": "query.occlusion", "attributes": { "occlusion": "o" } } ],
    "edges": [ "lot.out -> mass.in", "mass.out -> walls.in", "mass.out -> occ.occluders",
               "b.out -> bc.in", "c.out -> bc.in", "d.out -> low.in", "bc.out -> occ.occluders",
               "low.out -> occ.occluders", "walls.side -> occ.shapes" ])json"));
  ASSERT_TRUE(t.ok()) << t.errors;
  const auto normal = [&](EntityId e) { return t.scope(e).z; };
  std::size_t seen = 0;
  for (const std::string port : {"occ.occluded", "occ.visible"}) {
    for (EntityId e : t.at(port)) {
      ++seen;
      const kernel::Vec3 n = normal(e);
      const double o = t.attribute(e, "o")->number();
      if (n.x > 0.5 || n.x < -0.5) {
        EXPECT_NEAR(o, 0.5, 1e-9) << n.x;
        EXPECT_EQ(port, "occ.occluded");
      } else {
        EXPECT_NEAR(o, 0.0, 1e-9) << n.y;
        EXPECT_EQ(port, "occ.visible");
      }
    }
  }
  EXPECT_EQ(seen, 4U);
}

// A street along the cube's front: only the front wall is oriented to it; a low wall between
// them hides it.
TEST(QueryNodes, IsOrientedTo) {
  const TestRun t = run_text(graph_text(R"json(
    "attributes": { "yes": { "type": "bool", "default": false } },
    "nodes": [ { "id": "lot", "type": "create.rectangle", "params": { "width": 10, "depth": 10 } },
               { "id": "mass", "type": "shape.extrude", "params": { "height": 10 } },
               { "id": "walls", "type": "shape.comp", "augment": [ { "faces": "side", "out": "side" } ] },
               { "id": "street", "type": "path.create", "params": { "points": [[0, -10], [10, -10]] } },
               { "id": "fence", "type": "create.rectangle", "params": { "width": 20, "depth": 3, "origin": [-5, -6, 0] } },
               { "id": "f3", "type": "shape.extrude", "params": { "height": 3 } },
               { "id": "open", "type": "query.is_oriented_to", "attributes": { "oriented": "yes" } },
               { "id": "hidden", "type": "query.is_oriented_to" } ],
    "edges": [ "lot.out -> mass.in", "mass.out -> walls.in", "walls.side -> open.shapes",
               "walls.side -> hidden.shapes", "street.out -> open.streets", "street.out -> hidden.streets",
               "mass.out -> open.occluders", "fence.out -> f3.in", "f3.out -> hidden.occluders" ])json"));
  ASSERT_TRUE(t.ok()) << t.errors;
  const std::vector<EntityId> oriented = t.at("open.oriented");
  ASSERT_EQ(oriented.size(), 1U);
  EXPECT_NEAR(t.scope(oriented[0]).z.y, -1.0, 1e-12);  // the wall facing -y
  EXPECT_TRUE(t.attribute(oriented[0], "yes")->boolean());
  EXPECT_EQ(t.at("open.other").size(), 3U);
  for (EntityId e : t.at("open.other")) EXPECT_FALSE(t.attribute(e, "yes")->boolean());
  EXPECT_TRUE(t.at("hidden.oriented").empty());
  EXPECT_EQ(t.at("hidden.other").size(), 4U);
}

// Ground-plane distance to the nearest target (a lot or a point) and its index.
TEST(QueryNodes, Distance) {
  const TestRun t = run_text(graph_text(R"json(
    "attributes": { "d": { "type": "number", "default": -1 }, "n": { "type": "integer", "default": -1 } },
    "nodes": [ { "id": "p", "type": "create.points", "params": { "points": [[15,5,0], [5,5,7], [5,-20,0]] } },
               { "id": "lot", "type": "create.rectangle", "params": { "width": 10, "depth": 10 } },
               { "id": "post", "type": "create.points", "params": { "points": [[5,-25,0]] } },
               { "id": "near", "type": "query.distance", "attributes": { "distance": "d", "nearest": "n" } } ],
    "edges": [ "p.out -> near.in", "lot.out -> near.targets", "post.out -> near.targets" ])json"));
  ASSERT_TRUE(t.ok()) << t.errors;
  const std::vector<EntityId> out = t.at("near.out");
  ASSERT_EQ(out.size(), 3U);
  EXPECT_NEAR(t.attribute(out[0], "d")->number(), 5.0, 1e-12);
  EXPECT_EQ(t.attribute(out[0], "n")->integer(), 0);
  EXPECT_NEAR(t.attribute(out[1], "d")->number(), 0.0, 1e-12);  // inside the lot
  EXPECT_EQ(t.attribute(out[1], "n")->integer(), 0);
  EXPECT_NEAR(t.attribute(out[2], "d")->number(), 5.0, 1e-12);
  EXPECT_EQ(t.attribute(out[2], "n")->integer(), 1);
}

}  // namespace
}  // namespace insula::lang::graph::testing
