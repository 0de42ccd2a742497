#include <gtest/gtest.h>

#include "shape/ops.h"

namespace insula::shape {
namespace {

using kernel::SemanticClass;
using kernel::Vec3;

void expect_near(Vec3 a, Vec3 b, double tolerance = 1e-9) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

// A 10 x 6 x 8 mass standing in world space like an extrusion makes it: x = +X, y = +Z (up),
// z = -Y (the front faces world -Y).
ShapeId mass(ShapeTree& tree) {
  Scope s{{0, 8, 0}, {1, 0, 0}, {0, 0, 1}, {0, -1, 0}, {10, 6, 8}};
  return tree.add_root(s, box_mesh(s.size, mass_box_tags()));
}

TEST(Comp, SelectorsFollowScopeDirections) {
  EXPECT_TRUE(face_matches(FaceSelector::kFront, {0, 0, 1}));
  EXPECT_TRUE(face_matches(FaceSelector::kBack, {0, 0, -1}));
  EXPECT_TRUE(face_matches(FaceSelector::kRight, {1, 0, 0}));
  EXPECT_TRUE(face_matches(FaceSelector::kLeft, {-1, 0, 0}));
  EXPECT_TRUE(face_matches(FaceSelector::kTop, {0, 1, 0}));
  EXPECT_TRUE(face_matches(FaceSelector::kBottom, {0, -1, 0}));
  EXPECT_TRUE(face_matches(FaceSelector::kSide, {0.6, 0, 0.8}));
  EXPECT_FALSE(face_matches(FaceSelector::kSide, {0, 1, 0}));
  // A 40-degree roof face counts as top; a 60-degree one as a side.
  EXPECT_TRUE(face_matches(FaceSelector::kTop, {0, 0.766, 0.643}));
  EXPECT_TRUE(face_matches(FaceSelector::kFront, {0, 0.5, 0.866}));
}

TEST(Comp, FrontFaceHasNormalZAndBottomEdgeX) {
  ShapeTree tree;
  const ShapeId root = mass(tree);
  const OpResult r = comp_faces(tree, root, FaceSelector::kFront);
  ASSERT_EQ(r.children.size(), 1U) << r.error;
  const Shape& front = tree[r.children[0]];
  expect_near(front.scope.z, {0, -1, 0});  // world direction of the mass's +z
  expect_near(front.scope.x, {1, 0, 0});
  expect_near(front.scope.y, {0, 0, 1});
  expect_near(front.scope.size, {10, 6, 0});
  expect_near(front.scope.origin, {0, 0, 0});
  EXPECT_TRUE(front.is_flat());
  EXPECT_NEAR(kernel::area(*front.outline), 60, 1e-9);
  EXPECT_EQ(front.mesh->tag(0).semantic, SemanticClass::kWallSurface);
  EXPECT_FALSE(tree[root].active);
}

TEST(Comp, SidesTopAndAll) {
  ShapeTree tree;
  const ShapeId root = mass(tree);
  EXPECT_EQ(comp_faces(tree, root, FaceSelector::kSide).children.size(), 4U);
  EXPECT_EQ(comp_faces(tree, root, FaceSelector::kAll).children.size(), 6U);
  const OpResult top = comp_faces(tree, root, FaceSelector::kTop);
  ASSERT_EQ(top.children.size(), 1U);
  const Shape& t = tree[top.children[0]];
  expect_near(t.scope.z, {0, 0, 1});
  expect_near(t.scope.x, {1, 0, 0});  // the parent's x for a face looking up
  expect_near(t.scope.size, {10, 8, 0});
  EXPECT_EQ(t.mesh->tag(0).semantic, SemanticClass::kRoofSurface);
  // Every face child's geometry lies in its scope's xy plane, inside [0, S].
  for (ShapeId c : comp_faces(tree, root, FaceSelector::kAll).children) {
    for (const Vec3& p : tree[c].mesh->positions()) {
      EXPECT_NEAR(p.z, 0, 1e-12);
      EXPECT_GE(p.x, -1e-9);
      EXPECT_LE(p.y, tree[c].scope.size.y + 1e-9);
    }
    expect_near(kernel::face_normal(*tree[c].mesh, 0), {0, 0, 1});
  }
}

TEST(Comp, EdgesAndVertices) {
  ShapeTree tree;
  const ShapeId root = mass(tree);
  const OpResult edges = comp_edges(tree, root);
  ASSERT_EQ(edges.children.size(), 12U);
  double total = 0;
  for (ShapeId e : edges.children) {
    total += tree[e].scope.size.x;
    EXPECT_EQ(tree[e].scope.size.y, 0);
    EXPECT_EQ(tree[e].mesh, nullptr);
    EXPECT_NEAR(dot(tree[e].scope.x, tree[e].scope.z), 0, 1e-12);
  }
  EXPECT_NEAR(total, 4 * (10 + 6 + 8), 1e-9);
  const OpResult vertices = comp_vertices(tree, root);
  ASSERT_EQ(vertices.children.size(), 8U);
  expect_near(tree[vertices.children[0]].scope.origin, {0, 8, 0});
  EXPECT_EQ(registry().run(tree, root, "comp", {{"type", std::string("edges")}}).children.size(),
            12U);
}

// A lot with a courtyard extrudes to a top stored as several faces (triangles, or quads framing
// the hole). comp gives it as one face with the hole, so a roof covers the whole building: each
// triangle of a real OpenStreetMap courtyard got a hip roof of its own.
TEST(Comp, ALogicalFaceOfSeveralPiecesIsOneComponent) {
  for (const bool rectangular_hole : {true, false}) {
    kernel::Polygon lot{{{0, 0}, {30, 0}, {30, 20}, {0, 20}}, {}};
    lot.holes.push_back(rectangular_hole ? kernel::Ring{{10, 5}, {10, 15}, {20, 15}, {20, 5}}
                                         : kernel::Ring{{10, 5}, {12, 15}, {22, 14}, {20, 5}});
    ShapeTree tree;
    const RootResult root = tree.create_root(lot);
    ASSERT_TRUE(root.ok()) << root.error;
    const OpResult mass = extrude(tree, root.id, 9);
    ASSERT_EQ(mass.children.size(), 1U) << mass.error;
    ASSERT_GT(tree[mass.children[0]].mesh->face_count(), 10U);  // the caps are several faces
    const OpResult top = comp_faces(tree, mass.children[0], FaceSelector::kTop);
    ASSERT_EQ(top.children.size(), 1U);
    const Shape& face = tree[top.children[0]];
    ASSERT_TRUE(face.is_flat());
    EXPECT_EQ(face.outline->outer.size(), 4U);
    ASSERT_EQ(face.outline->holes.size(), 1U);
    EXPECT_NEAR(kernel::area(*face.outline), kernel::area(lot), 1e-9);
    // Sides stay one component per wall: 4 outside, 4 around the court.
    EXPECT_EQ(comp_faces(tree, mass.children[0], FaceSelector::kSide).children.size(), 8U);
  }
}

}  // namespace
}  // namespace insula::shape
