#include "shape/shape_tree.h"

#include <gtest/gtest.h>

#include "kernel/polygon.h"

namespace insula::shape {
namespace {

using kernel::Vec3;

kernel::Polygon rectangle(double w, double h) {
  return {{{0, 0}, {w, 0}, {w, h}, {0, h}}, {}};
}

void expect_near(Vec3 a, Vec3 b, double tolerance = 1e-12) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(ShapeTree, RootFromFootprintFollowsFirstEdge) {
  ShapeTree tree;
  // Clockwise input: normalisation makes it counter-clockwise first.
  const kernel::Polygon cw = {{{0, 0}, {0, 6}, {10, 6}, {10, 0}}, {}};
  const RootResult root = tree.create_root(cw, 2.5);
  ASSERT_TRUE(root.ok()) << root.error;
  const Shape& s = tree[root.id];
  EXPECT_TRUE(s.is_flat());
  expect_near(s.scope.z, {0, 0, 1});
  expect_near(cross(s.scope.z, s.scope.x), s.scope.y);
  EXPECT_NEAR(s.scope.size.z, 0, 1e-12);
  EXPECT_NEAR(s.scope.size.x * s.scope.size.y, 60, 1e-9);
  EXPECT_NEAR(s.scope.origin.z, 2.5, 1e-12);
  // The outline lies inside [0, S] and keeps the footprint's area.
  EXPECT_NEAR(kernel::area(*s.outline), 60, 1e-9);
  for (kernel::Vec2 p : s.outline->outer) {
    EXPECT_GE(p.x, -1e-9);
    EXPECT_GE(p.y, -1e-9);
    EXPECT_LE(p.x, s.scope.size.x + 1e-9);
    EXPECT_LE(p.y, s.scope.size.y + 1e-9);
  }
  ASSERT_EQ(s.mesh->face_count(), 1U);
  expect_near(kernel::face_normal(*s.mesh, 0), {0, 0, 1});
}

TEST(ShapeTree, RootAlignsWithLongestEdgeWhenAsked) {
  ShapeTree tree;
  const kernel::Polygon p = {{{0, 0}, {3, 0}, {3, 12}, {0, 12}}, {}};
  const RootResult root = tree.create_root(p, 0, RootAlignment::kLongestEdge);
  ASSERT_TRUE(root.ok());
  expect_near(tree[root.id].scope.x, {0, 1, 0});
  expect_near(tree[root.id].scope.size, {12, 3, 0});
  // y = z cross x points into the footprint: from the edge x = 3 towards x = 0.
  expect_near(tree[root.id].scope.y, {-1, 0, 0});
  expect_near(tree[root.id].scope.origin, {3, 0, 0});
}

TEST(ShapeTree, RejectsBadFootprints) {
  ShapeTree tree;
  EXPECT_EQ(tree.create_root({{{0, 0}, {1, 0}}, {}}).error, "footprint has fewer than 3 vertices");
  EXPECT_EQ(tree.create_root({{{0, 0}, {1, 0}, {2, 0}}, {}}).error, "footprint has zero area");
  EXPECT_EQ(tree.create_root({{{0, 0}, {1, 0}, {1, std::nan("")}}, {}}).error,
            "footprint has a non-finite coordinate");
  EXPECT_EQ(tree.size(), 0U);
}

TEST(ShapeTree, HoledFootprintMeshKeepsItsArea) {
  ShapeTree tree;
  kernel::Polygon p = rectangle(10, 10);
  p.holes.push_back({{4, 4}, {4, 6}, {6, 6}, {6, 4}});
  const RootResult root = tree.create_root(p);
  ASSERT_TRUE(root.ok());
  EXPECT_NEAR(kernel::surface_area(*tree[root.id].mesh), 96, 1e-9);
  EXPECT_EQ(tree[root.id].outline->holes.size(), 1U);
}

TEST(ShapeTree, AttributesInheritLabelsDoNot) {
  ShapeTree tree;
  const ShapeId root = tree.add_root(Scope{});
  const ShapeId child = tree.add_child(root, Scope{});
  const ShapeId grandchild = tree.add_child(child, Scope{});
  tree.add_label(root, "building");
  tree.set_attribute(root, "floors", 3.0);
  tree.set_attribute(root, "style", std::string("gothic"));
  tree.set_attribute(child, "floors", 2.0);
  EXPECT_EQ(std::get<double>(*tree.attribute(grandchild, "floors")), 2.0);
  EXPECT_EQ(std::get<std::string>(*tree.attribute(grandchild, "style")), "gothic");
  EXPECT_EQ(tree.attribute(grandchild, "missing"), nullptr);
  EXPECT_TRUE(tree.has_label(root, "building"));
  EXPECT_FALSE(tree.has_label(child, "building"));
  const AttributeMap resolved = tree.resolved_attributes(grandchild);
  ASSERT_EQ(resolved.size(), 2U);
  EXPECT_EQ(std::get<double>(resolved.at("floors")), 2.0);
  // Overriding a value on the same shape replaces it instead of adding an entry.
  tree.set_attribute(child, "floors", 5.0);
  EXPECT_EQ(tree[child].attributes.size(), 1U);
}

TEST(ShapeTree, NavigationLeavesActiveAndTruncate) {
  ShapeTree tree(99);
  const ShapeId root = tree.add_root(Scope{});
  const ShapeId a = tree.add_child(root, Scope{});
  const ShapeId b = tree.add_child(root, Scope{});
  const ShapeId a1 = tree.add_child(a, Scope{});
  tree.deactivate(root);
  tree.deactivate(a);
  EXPECT_EQ(tree.subtree(root), (std::vector<ShapeId>{root, a, a1, b}));
  EXPECT_EQ(tree.leaves(), (std::vector<ShapeId>{b, a1}));
  EXPECT_EQ(tree.active(), (std::vector<ShapeId>{b, a1}));
  EXPECT_EQ(tree.root_of(a1), root);
  EXPECT_EQ(tree[b].child_index, 1U);
  tree.truncate(2);
  EXPECT_EQ(tree.size(), 2U);
  EXPECT_EQ(tree.children(root), (std::vector<ShapeId>{a}));
  EXPECT_TRUE(tree[a].children.empty());
}

TEST(ShapeTree, SeedsDependOnTreeSeedAndPositionOnly) {
  ShapeTree first(5);
  ShapeTree second(5);
  const ShapeId r1 = first.add_root(Scope{});
  const ShapeId r2 = second.add_root(Scope{});
  first.add_child(r1, Scope{});
  const ShapeId c1 = first.add_child(r1, Scope{});
  second.add_child(r2, Scope{});
  const ShapeId c2 = second.add_child(r2, Scope{});
  EXPECT_EQ(first[c1].seed, second[c2].seed);
  EXPECT_EQ(first.rng(c1).next(), second.rng(c2).next());
  EXPECT_NE(first[c1].seed, first[first.children(r1)[0]].seed);
  EXPECT_NE(ShapeTree(6).add_root(Scope{}), kNoShape);
}

TEST(ShapeTree, ShapesStaySmall) {
  // design.md: a comparable interpreter spends 3.4 KB per shape; ours must stay far below.
  EXPECT_LE(sizeof(Shape), 320U);
  ShapeTree tree;
  const ShapeId root = tree.add_root(Scope{});
  for (int i = 0; i < 100; ++i) tree.add_label(tree.add_child(root, Scope{}), "tile");
  const MemoryStats m = tree.memory_stats();
  EXPECT_EQ(m.shapes, 101U);
  EXPECT_LE((m.shape_bytes + m.heap_bytes) / m.shapes, 400U);
}

TEST(ShapeTree, FaceIdsAreInternedNames) {
  ShapeTree tree;
  const std::uint32_t front = tree.face_id("front center");
  EXPECT_NE(front, 0U);
  EXPECT_EQ(tree.face_id("front center"), front);
  EXPECT_EQ(tree.face_name(front), "front center");
  EXPECT_EQ(tree.face_name(0), "");
}

}  // namespace
}  // namespace insula::shape
