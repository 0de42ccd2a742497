#include <gtest/gtest.h>

#include <algorithm>
#include <array>

#include "shape/component_ops.h"

namespace insula::shape {
namespace {

using kernel::Vec3;

ShapeId box_at(ShapeTree& tree, Vec3 origin, Vec3 size) {
  Scope scope;
  scope.origin = origin;
  scope.size = size;
  return tree.add_root(scope, box_mesh(size, mass_box_tags()));
}

// A box whose sides carry named face ids (§3.1.1), as a program names them; box_mesh's side order
// is -x, +x, -y, +y, -z, +z. mass_box_tags itself leaves the face ids 0.
std::array<kernel::FaceTag, 6> named_tags(ShapeTree& tree) {
  auto tags = mass_box_tags();
  const char* names[6] = {"left", "right", "bottom", "top", "back", "front"};
  for (std::size_t i = 0; i < 6; ++i) tags[i].face_id = tree.face_id(names[i]);
  return tags;
}

ShapeId named_box_at(ShapeTree& tree, Vec3 origin, Vec3 size) {
  Scope scope;
  scope.origin = origin;
  scope.size = size;
  return tree.add_root(scope, box_mesh(size, named_tags(tree)));
}

ShapeId rect_at(ShapeTree& tree, Vec3 origin, double w, double h) {
  Scope scope;
  scope.origin = origin;
  scope.size = {w, h, 0};
  auto outline =
      std::make_shared<kernel::Polygon>(kernel::Polygon{{{0, 0}, {w, 0}, {w, h}, {0, h}}, {}});
  return tree.add_root(scope, flat_mesh(*outline, {kernel::SemanticClass::kFloorSurface, 0, 7}),
                       outline);
}

double world_volume(const ShapeTree& tree, ShapeId id) {
  return kernel::volume(mesh_to_world(*tree[id].mesh, tree[id].scope));
}

TEST(ComponentBoolean, SubtractShaftFromApartmentIsAChildWithTheHole) {
  // Fig. 2/3: an elevator shaft (taller, spanning storeys) cut from a 5 x 2.5 x 4 apartment.
  ShapeTree tree;
  const ShapeId apt = named_box_at(tree, {0, 0, 0}, {5, 2.5, 4});
  const ShapeId shaft = box_at(tree, {4, -1, 2}, {2, 6, 1});
  const std::vector<ShapeId> cutters{shaft};
  const OpResult r = subtract_components(tree, apt, cutters);
  ASSERT_TRUE(r.ok()) << r.error;
  ASSERT_EQ(r.children.size(), 1U);
  const ShapeId room = r.children[0];
  EXPECT_EQ(tree.parent(room), apt);  // §3.4.3: a child of the component cut
  EXPECT_NEAR(world_volume(tree, room), 5 * 2.5 * 4 - 1 * 2.5 * 1, 1e-9);
  EXPECT_TRUE(kernel::is_watertight(*tree[room].mesh));
  // The shaft notches the +x side: an 8-sided section, 8 sides + floor + ceiling.
  EXPECT_EQ(tree[room].mesh->face_count(), 10U);
  // Faces keep the ids of the faces they come from: the +x wall ("right") survives in part.
  bool has_right = false;
  for (std::size_t f = 0; f < tree[room].mesh->face_count(); ++f) {
    has_right = has_right || tree.face_name(tree[room].mesh->tag(f).face_id) == "right";
  }
  EXPECT_TRUE(has_right);
  EXPECT_NEAR(tree[room].scope.size.x, 5, 1e-12);
}

TEST(ComponentBoolean, CutterOutsideLeavesACopy) {
  ShapeTree tree;
  const ShapeId apt = box_at(tree, {0, 0, 0}, {5, 2.5, 4});
  const ShapeId far = box_at(tree, {20, 0, 0}, {1, 2.5, 1});
  const std::vector<ShapeId> cutters{far};
  const OpResult r = subtract_components(tree, apt, cutters);
  ASSERT_EQ(r.children.size(), 1U);
  EXPECT_NEAR(world_volume(tree, r.children[0]), 50, 1e-9);
}

TEST(ComponentBoolean, UnionAndIntersectionAreRoots) {
  ShapeTree tree;
  const ShapeId a = box_at(tree, {0, 0, 0}, {4, 3, 4});
  const ShapeId b = box_at(tree, {2, 0, 2}, {4, 3, 4});
  const std::vector<ShapeId> ab{a, b};
  const std::size_t roots = tree.roots().size();
  const OpResult u = unite_components(tree, ab);
  ASSERT_TRUE(u.ok()) << u.error;
  ASSERT_EQ(u.children.size(), 1U);
  EXPECT_EQ(tree.parent(u.children[0]), kNoShape);
  EXPECT_NEAR(world_volume(tree, u.children[0]), 3 * (16 + 16 - 4), 1e-9);
  const OpResult i = intersect_components(tree, ab);
  ASSERT_EQ(i.children.size(), 1U);
  EXPECT_NEAR(world_volume(tree, i.children[0]), 3 * 4, 1e-9);
  EXPECT_EQ(tree.roots().size(), roots + 2);
}

TEST(ComponentBoolean, UnionKeepsCoplanarFacesWithDifferentIdsApart) {
  // §3.1.1: a union only merges faces sharing the same id. A and B stand side by side; their
  // fronts (+z) carry the ids "front" and "shop", their backs (-z) the same id "back".
  ShapeTree tree;
  const ShapeId a = named_box_at(tree, {0, 0, 0}, {4, 3, 4});
  Scope scope;
  scope.origin = {4, 0, 0};
  scope.size = {4, 3, 4};
  auto tags = named_tags(tree);
  tags[5].face_id = tree.face_id("shop");
  const ShapeId b = tree.add_root(scope, box_mesh(scope.size, tags));
  const std::vector<ShapeId> ab{a, b};
  const OpResult u = unite_components(tree, ab);
  ASSERT_EQ(u.children.size(), 1U);
  const kernel::Mesh& m = *tree[u.children[0]].mesh;
  std::vector<std::uint32_t> front;
  int back = 0;
  for (std::size_t f = 0; f < m.face_count(); ++f) {
    const Vec3 n = kernel::face_normal(m, f);
    if (n.z > 0.5) front.push_back(m.tag(f).face_id);
    if (n.z < -0.5) ++back;
  }
  std::sort(front.begin(), front.end());
  std::vector<std::uint32_t> expected{tree.face_id("front"), tree.face_id("shop")};
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(front, expected);
  EXPECT_EQ(back, 1);  // same id: merged into one face
  EXPECT_NEAR(world_volume(tree, u.children[0]), 96, 1e-9);
  EXPECT_TRUE(kernel::is_watertight(m));
}

TEST(ComponentBoolean, DifferentHeightsGoThroughCorefinement) {
  // The cutter only reaches half way up: not a prism cut, CGAL's general boolean.
  ShapeTree tree;
  const ShapeId a = box_at(tree, {0, 0, 0}, {4, 4, 4});
  const ShapeId b = box_at(tree, {1, 2, 1}, {2, 4, 2});
  const std::vector<ShapeId> cutters{b};
  const OpResult r = subtract_components(tree, a, cutters);
  ASSERT_TRUE(r.ok()) << r.error;
  ASSERT_EQ(r.children.size(), 1U);
  EXPECT_NEAR(world_volume(tree, r.children[0]), 64 - 8, 1e-6);
  EXPECT_TRUE(kernel::is_watertight(*tree[r.children[0]].mesh));
}

TEST(ComponentBoolean, FlatComponentsCoplanar) {
  ShapeTree tree;
  const ShapeId a = rect_at(tree, {0, 0, 0}, 4, 4);
  const ShapeId b = rect_at(tree, {1, 1, 0}, 2, 2);
  const std::vector<ShapeId> cut{b};
  const OpResult r = subtract_components(tree, a, cut);
  ASSERT_TRUE(r.ok()) << r.error;
  ASSERT_EQ(r.children.size(), 1U);
  const Shape& ring = tree[r.children[0]];
  ASSERT_TRUE(ring.is_flat());
  EXPECT_NEAR(kernel::area(*ring.outline), 12, 1e-9);
  EXPECT_EQ(ring.outline->holes.size(), 1U);
  EXPECT_EQ(ring.mesh->tag(0).face_id, 7U);
  // Two disjoint pieces from a union are two roots.
  const ShapeId c = rect_at(tree, {10, 0, 0}, 1, 1);
  const std::vector<ShapeId> ac{a, c};
  const OpResult u = unite_components(tree, ac);
  ASSERT_EQ(u.children.size(), 2U);
  EXPECT_NEAR(kernel::area(*tree[u.children[0]].outline), 16, 1e-9);
  // Not coplanar: an error naming both.
  const ShapeId up = rect_at(tree, {0, 0, 1}, 1, 1);
  const std::vector<ShapeId> bad{a, up};
  EXPECT_EQ(unite_components(tree, bad).error, "component " + std::to_string(up) +
                                                   " is not flat and coplanar with component " +
                                                   std::to_string(a));
}

}  // namespace
}  // namespace insula::shape
