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

TEST(Extrude, FootprintBecomesAMassWithYUpAndFrontAtPlusZ) {
  ShapeTree tree;
  const RootResult root = tree.create_root({{{0, 0}, {10, 0}, {10, 8}, {0, 8}}, {}});
  const OpResult r = registry().run(tree, root.id, "extrude", {{"height", 6.0}});
  ASSERT_TRUE(r.ok()) << r.error;
  const Shape& m = tree[r.children[0]];
  expect_near(m.scope.x, {1, 0, 0});
  expect_near(m.scope.y, {0, 0, 1});
  expect_near(m.scope.z, {0, -1, 0});
  expect_near(m.scope.size, {10, 6, 8});
  expect_near(m.scope.origin, {0, 8, 0});
  EXPECT_NEAR(kernel::volume(*m.mesh), 480, 1e-9);
  EXPECT_TRUE(kernel::is_watertight(*m.mesh));
  // The footprint's first edge (y = 0 in the world) is the front: comp front finds it.
  const OpResult front = comp_faces(tree, m.id, FaceSelector::kFront);
  ASSERT_EQ(front.children.size(), 1U);
  const Scope& f = tree[front.children[0]].scope;
  expect_near(f.origin, {0, 0, 0});
  expect_near(f.size, {10, 6, 0});
  const OpResult top = comp_faces(tree, m.id, FaceSelector::kTop);
  ASSERT_EQ(top.children.size(), 1U);
  EXPECT_EQ(tree[top.children[0]].mesh->tag(0).semantic, SemanticClass::kRoofSurface);
}

TEST(Extrude, FaceExtrudesAlongItsNormal) {
  ShapeTree tree;
  const RootResult root = tree.create_root({{{0, 0}, {10, 0}, {10, 8}, {0, 8}}, {}});
  const ShapeId mass = extrude(tree, root.id, 6).children[0];
  const ShapeId front = comp_faces(tree, mass, FaceSelector::kFront).children[0];
  const OpResult r = extrude(tree, front, 0.5);
  ASSERT_TRUE(r.ok()) << r.error;
  const Shape& slab = tree[r.children[0]];
  // The slab grows out of the facade, towards world -Y.
  const kernel::Mesh world = mesh_to_world(*slab.mesh, slab.scope);
  const kernel::Bounds3 b = world.bounds();
  expect_near(b.min, {0, -0.5, 0});
  expect_near(b.max, {10, 0, 6});
  EXPECT_NEAR(kernel::volume(world), 30, 1e-9);
}

TEST(Extrude, HoledFootprintAndErrors) {
  ShapeTree tree;
  kernel::Polygon court = {{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {}};
  court.holes.push_back({{3, 3}, {3, 7}, {7, 7}, {7, 3}});
  const RootResult root = tree.create_root(court);
  const OpResult r = extrude(tree, root.id, 3);
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_NEAR(kernel::volume(*tree[r.children[0]].mesh), 84 * 3, 1e-9);
  EXPECT_EQ(extrude(tree, root.id, 0).error, "height must be > 0");
  EXPECT_EQ(extrude(tree, r.children[0], 1).error, "needs a flat shape (a footprint or a face)");
}

}  // namespace
}  // namespace insula::shape
