#include <gtest/gtest.h>

#include "shape/component_ops.h"

namespace insula::shape {
namespace {

using kernel::Vec3;

ShapeId box(ShapeTree& tree, Vec3 size) {
  Scope scope;
  scope.size = size;
  return tree.add_root(scope, box_mesh(size, mass_box_tags()));
}

TEST(Instance, ChildInsideIsABoxInTheParentsSpace) {
  ShapeTree tree;
  const ShapeId p = box(tree, {10, 3, 8});
  const OpResult r = instance_box(tree, p, {4, 0, 2}, {2, 3, 1});
  ASSERT_TRUE(r.ok());
  const Shape& c = tree[r.children[0]];
  EXPECT_EQ(c.parent, p);
  EXPECT_NEAR(c.scope.origin.x, 4, 1e-12);
  EXPECT_NEAR(kernel::volume(*c.mesh), 6, 1e-12);
  EXPECT_TRUE(tree[p].active);  // instancing adds, it does not replace
}

TEST(Instance, ClippedByTheParentBoundary) {
  ShapeTree tree;
  const ShapeId p = box(tree, {10, 3, 8});
  const OpResult r = instance_box(tree, p, {8, 0, 6}, {4, 5, 4});
  ASSERT_TRUE(r.ok()) << r.error;
  const Shape& c = tree[r.children[0]];
  EXPECT_NEAR(c.scope.size.x, 2, 1e-12);
  EXPECT_NEAR(c.scope.size.y, 3, 1e-12);
  EXPECT_NEAR(c.scope.size.z, 2, 1e-12);
  EXPECT_NEAR(kernel::volume(*c.mesh), 12, 1e-9);
  EXPECT_TRUE(kernel::is_watertight(*c.mesh));
  // Without clipping the box is kept whole.
  const OpResult whole = instance_box(tree, p, {8, 0, 6}, {4, 5, 4}, false);
  EXPECT_NEAR(kernel::volume(*tree[whole.children[0]].mesh), 80, 1e-9);
  // Entirely outside: an error, nothing added.
  const std::size_t n = tree.size();
  EXPECT_EQ(instance_box(tree, p, {20, 0, 0}, {1, 1, 1}).error,
            "the component lies outside its parent");
  EXPECT_EQ(tree.size(), n);
}

TEST(Instance, FlatChildClippedByFlatParent) {
  ShapeTree tree;
  auto outline = std::make_shared<kernel::Polygon>(
      kernel::Polygon{{{0, 0}, {6, 0}, {6, 2}, {2, 2}, {2, 6}, {0, 6}}, {}});
  Scope scope;
  scope.size = {6, 6, 0};
  const ShapeId p = tree.add_root(scope, flat_mesh(*outline, {}), outline);
  const OpResult r = instance_box(tree, p, {1, 1, 0}, {4, 4, 0});
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_NEAR(kernel::area(*tree[r.children[0]].outline), 16 - 9, 1e-9);
}

TEST(Instance, FaceComponentKeepsTheFaceId) {
  ShapeTree tree;
  // Box sides carry no face id (mass_box_tags); name the +z side as a program would.
  auto tags = mass_box_tags();
  const std::uint32_t front = tree.face_id("front");
  tags[5].face_id = front;
  Scope scope;
  scope.size = {10, 3, 8};
  const ShapeId p = tree.add_root(scope, box_mesh(scope.size, tags));
  const OpResult r = face_component(tree, p, 5);  // +z
  ASSERT_TRUE(r.ok());
  const Shape& f = tree[r.children[0]];
  EXPECT_TRUE(f.is_flat());
  EXPECT_EQ(f.mesh->tag(0).face_id, front);
  EXPECT_EQ(tree.face_name(f.mesh->tag(0).face_id), "front");
  EXPECT_NEAR(kernel::area(*f.outline), 30, 1e-9);
}

TEST(Place, FurnitureAvoidsTheDoorAndSharesItsMesh) {
  ShapeTree tree;
  const ShapeId room = box(tree, {4, 3, 4});
  Region floor;
  floor.name = "floor";
  floor.min = {0.5, 0, 0.5};
  floor.max = {3.5, 0, 3.5};
  floor.max_degrees = {0, 360, 0};
  tree[room].regions.push_back(floor);
  const ShapeId door = instance_box(tree, room, {0, 0, 0}, {2, 2.1, 2}, false).children[0];
  const auto chair = normalized_asset(*box_mesh({0.5, 0.9, 0.5}, mass_box_tags()));
  PlaceOptions options;
  options.avoid = {door};
  std::vector<ShapeId> placed;
  for (std::uint64_t k = 0; k < 8; ++k) {
    options.draw = k;
    const Connected c = place_on_region(tree, room, 0, chair, options);
    ASSERT_TRUE(c.error.empty()) << c.error;
    EXPECT_FALSE(boxes_overlap(tree[c.id].scope, tree[door].scope));
    EXPECT_EQ(tree[c.id].mesh, chair);  // shared, not copied
    placed.push_back(c.id);
  }
  // Deterministic: the same draw gives the same place.
  ShapeTree again;
  const ShapeId room2 = box(again, {4, 3, 4});
  again[room2].regions.push_back(floor);
  const ShapeId door2 = instance_box(again, room2, {0, 0, 0}, {2, 2.1, 2}, false).children[0];
  options.avoid = {door2};
  options.draw = 0;
  const Connected c2 = place_on_region(again, room2, 0, chair, options);
  EXPECT_NEAR(length(again[c2.id].scope.origin - tree[placed[0]].scope.origin), 0, 1e-12);
  // A region fully covered by the door: no free place.
  options.avoid = {door2};
  options.clearance = 10;
  EXPECT_EQ(place_on_region(again, room2, 0, chair, options).error,
            "no free place in region 'floor'");
}

TEST(Place, BoxesOverlapWithClearance) {
  Scope a;
  a.size = {1, 1, 1};
  Scope b = a;
  b.origin = {1.5, 0, 0};
  EXPECT_FALSE(boxes_overlap(a, b));
  EXPECT_TRUE(boxes_overlap(a, b, 0.6));
  b.origin = {0.5, 0.5, 0.5};
  EXPECT_TRUE(boxes_overlap(a, b));
}

TEST(Connect, ConnectorSitsOnThePlacement) {
  ShapeTree tree;
  const ShapeId room = box(tree, {4, 3, 4});
  const auto lamp = normalized_asset(*box_mesh({0.4, 0.6, 0.2}, mass_box_tags()));
  const Connected c = connect_mesh(tree, room, {{2, 0, 2}, {0, 90, 0}}, lamp);
  ASSERT_TRUE(c.error.empty());
  const Scope& s = tree[c.id].scope;
  // Bottom centre of the placed box is at (2, 0, 2).
  const Vec3 connector = s.to_world({0.2, 0, 0.1});
  EXPECT_NEAR(connector.x, 2, 1e-12);
  EXPECT_NEAR(connector.y, 0, 1e-12);
  EXPECT_NEAR(connector.z, 2, 1e-12);
  EXPECT_NEAR(dot(s.x, Vec3{0, 0, -1}), 1, 1e-12);  // turned 90 degrees about y
}

}  // namespace
}  // namespace insula::shape
