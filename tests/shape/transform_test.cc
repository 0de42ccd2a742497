#include <gtest/gtest.h>

#include "shape/ops.h"

namespace insula::shape {
namespace {

using kernel::Vec3;

void expect_near(Vec3 a, Vec3 b, double tolerance = 1e-9) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

ShapeId box(ShapeTree& tree, Vec3 size) {
  Scope s;
  s.size = size;
  return tree.add_root(s, box_mesh(size, mass_box_tags()));
}

TEST(Translate, MovesAlongScopeAxesAndSharesGeometry) {
  ShapeTree tree;
  Scope s{{1, 1, 1}, {0, 1, 0}, {-1, 0, 0}, {0, 0, 1}, {2, 2, 2}};
  const ShapeId root = tree.add_root(s, box_mesh(s.size, mass_box_tags()));
  tree.add_label(root, "Door");
  const OpResult r = translate(tree, root, {3, 0, 1});
  ASSERT_EQ(r.children.size(), 1U);
  const Shape& c = tree[r.children[0]];
  expect_near(c.scope.origin, {1, 4, 2});
  EXPECT_EQ(c.mesh, tree[root].mesh);  // shared, not copied
  EXPECT_TRUE(tree.has_label(c.id, "Door"));
  EXPECT_FALSE(tree[root].active);
}

TEST(Rotate, QuarterTurnAboutCenterKeepsCenter) {
  ShapeTree tree;
  const ShapeId root = box(tree, {4, 2, 2});
  const Vec3 before = tree[root].scope.center();
  const OpResult r = rotate(tree, root, {0, 90, 0}, Pivot::kCenter);
  const Scope& s = tree[r.children[0]].scope;
  expect_near(s.center(), before);
  expect_near(s.x, {0, 0, -1});
  expect_near(s.z, {1, 0, 0});
  // Rotation about the origin keeps the origin.
  const OpResult o = registry().run(tree, root, "rotate", {{"z", 90.0}});
  ASSERT_TRUE(o.ok()) << o.error;
  expect_near(tree[o.children[0]].scope.origin, {0, 0, 0});
  expect_near(tree[o.children[0]].scope.x, {0, 1, 0});
}

TEST(Scale, AbsoluteAndRelativeSizesStretchGeometry) {
  ShapeTree tree;
  const ShapeId root = box(tree, {2, 3, 4});
  const OpResult r = scale(tree, root, {4, SizeMode::kAbsolute}, {0.5, SizeMode::kRelative},
                           {1, SizeMode::kRelative});
  ASSERT_TRUE(r.ok()) << r.error;
  const Shape& c = tree[r.children[0]];
  expect_near(c.scope.size, {4, 1.5, 4});
  EXPECT_NEAR(kernel::volume(*c.mesh), 24, 1e-9);
  EXPECT_TRUE(kernel::is_watertight(*c.mesh));
  EXPECT_EQ(scale(tree, root, {1, SizeMode::kFloating}, {1, SizeMode::kRelative},
                  {1, SizeMode::kRelative})
                .error,
            "sizes cannot be floating (~)");
}

TEST(Center, CentersInTheParentScopeOnChosenAxes) {
  ShapeTree tree;
  const ShapeId root = box(tree, {10, 4, 6});
  const ShapeId small = scale(tree, root, {2, SizeMode::kAbsolute}, {2, SizeMode::kAbsolute},
                              {2, SizeMode::kAbsolute})
                            .children[0];
  const OpResult r = center(tree, small, "xz");
  const Scope& s = tree[r.children[0]].scope;
  expect_near(s.origin, {4, 0, 2});
  EXPECT_EQ(center(tree, root, "xyz").error, "a root shape has no parent to center in");
}

}  // namespace
}  // namespace insula::shape
