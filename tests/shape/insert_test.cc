#include <gtest/gtest.h>

#include <map>

#include "../common/map_assets.h"
#include "shape/ops.h"

namespace insula::shape {
namespace {

using kernel::Vec3;

using testing::MapAssets;

// A 1 x 2 x 0.5 box asset whose corner sits at (-0.5, 0, -0.25).
std::shared_ptr<const kernel::Mesh> door() {
  auto box = box_mesh({1, 2, 0.5}, mass_box_tags());
  return std::make_shared<kernel::Mesh>(
      kernel::transformed(*box, kernel::translation({-0.5, 0, -0.25})));
}

TEST(Insert, AssetFillsTheScope) {
  MapAssets assets;
  assets.meshes["door"] = door();
  ShapeTree tree;
  Scope s;
  s.size = {2, 3, 1};
  const ShapeId root = tree.add_root(s);
  const OpResult r =
      registry().run(tree, root, "insert", {{"", std::string("door")}}, Context{&assets});
  ASSERT_TRUE(r.ok()) << r.error;
  const Shape& c = tree[r.children[0]];
  const kernel::Bounds3 b = c.mesh->bounds();
  EXPECT_NEAR(b.min.x, 0, 1e-12);
  EXPECT_NEAR(b.max.x, 2, 1e-12);
  EXPECT_NEAR(b.max.y, 3, 1e-12);
  EXPECT_NEAR(b.max.z, 1, 1e-12);
  EXPECT_NEAR(kernel::volume(*c.mesh), 6, 1e-9);
}

TEST(Insert, ZeroSizeAxesKeepProportions) {
  ShapeTree tree;
  Scope s;
  s.size = {2, 0, 0};  // only the width is given
  const ShapeId root = tree.add_root(s);
  const OpResult r = insert(tree, root, *door());
  ASSERT_TRUE(r.ok());
  const Shape& c = tree[r.children[0]];
  EXPECT_NEAR(c.scope.size.x, 2, 1e-12);
  EXPECT_NEAR(c.scope.size.y, 4, 1e-12);
  EXPECT_NEAR(c.scope.size.z, 1, 1e-12);
}

TEST(Insert, MissingProviderOrAsset) {
  MapAssets assets;
  ShapeTree tree;
  const ShapeId root = tree.add_root(Scope{});
  EXPECT_EQ(registry().run(tree, root, "insert", {{"asset", std::string("x")}}).error,
            "insert: no asset provider");
  EXPECT_EQ(
      registry().run(tree, root, "insert", {{"asset", std::string("x")}}, Context{&assets}).error,
      "insert: cannot open 'x.obj'");
  // An empty asset (a provider's "inserts nothing") makes a child without geometry.
  const OpResult empty = insert(tree, root, kernel::Mesh{});
  ASSERT_TRUE(empty.ok()) << empty.error;
  ASSERT_EQ(empty.children.size(), 1U);
  EXPECT_EQ(tree[empty.children[0]].mesh, nullptr);
}

// The asset's placement in the parent's scope space: the child's mesh moved by its scope.
kernel::Bounds3 placed(const ShapeTree& tree, const OpResult& r) {
  const Shape& c = tree[r.children.at(0)];
  return mesh_to_world(*c.mesh, c.scope).bounds();
}

void expect_box(const kernel::Bounds3& b, Vec3 min, Vec3 max) {
  EXPECT_NEAR(b.min.x, min.x, 1e-12);
  EXPECT_NEAR(b.min.y, min.y, 1e-12);
  EXPECT_NEAR(b.min.z, min.z, 1e-12);
  EXPECT_NEAR(b.max.x, max.x, 1e-12);
  EXPECT_NEAR(b.max.y, max.y, 1e-12);
  EXPECT_NEAR(b.max.z, max.z, 1e-12);
}

OpResult insert_into(ShapeTree& tree, Vec3 size, const kernel::Mesh& asset,
                     const InsertOptions& options = {}) {
  Scope s;
  s.size = size;
  return insert(tree, tree.add_root(s), asset, options);
}

// CityEngine's zero scope sizes (docs/cityengine-dialect.md, "i (insert)"), on the door box
// (-0.5, 0, -0.25) .. (0.5, 2, 0.25).
TEST(Insert, AllThreeZeroKeepSizeAndPosition) {
  ShapeTree tree;
  const OpResult r = insert_into(tree, {0, 0, 0}, *door());
  ASSERT_TRUE(r.ok());
  expect_box(placed(tree, r), {-0.5, 0, -0.25}, {0.5, 2, 0.25});
  EXPECT_NEAR(tree[r.children[0]].scope.origin.x, -0.5, 1e-12);
  EXPECT_NEAR(tree[r.children[0]].scope.size.y, 2, 1e-12);
}

TEST(Insert, TwoZeroScaleUniformlyAndMoveByTheScaledOffset) {
  ShapeTree tree;
  const OpResult r = insert_into(tree, {2, 0, 0}, *door());
  ASSERT_TRUE(r.ok());
  expect_box(placed(tree, r), {0, 0, -0.5}, {2, 4, 0.5});
}

TEST(Insert, OneZeroTakesTheMeanScaleInPlace) {
  ShapeTree tree;
  const OpResult r = insert_into(tree, {1, 4, 0}, *door());  // scales 1 and 2: z by 1.5
  ASSERT_TRUE(r.ok());
  expect_box(placed(tree, r), {0, 0, 0}, {1, 4, 0.75});
}

TEST(Insert, KeepSizeModes) {
  ShapeTree tree;
  InsertOptions keep;
  keep.mode = InsertMode::kKeepSizeAndPosition;
  const OpResult r = insert_into(tree, {5, 5, 5}, *door(), keep);
  ASSERT_TRUE(r.ok());
  expect_box(placed(tree, r), {-0.5, 0, -0.25}, {0.5, 2, 0.25});

  InsertOptions align;
  align.mode = InsertMode::kKeepSizeAlignPosition;
  const OpResult a = insert_into(tree, {3, 1, 2}, *door(), align);
  ASSERT_TRUE(a.ok());
  expect_box(placed(tree, a), {1, 0, 0.75}, {2, 2, 1.25});  // centred in x and z, on y = 0
}

// A z-up box 1 x 2 wide and 3 tall stands 3 tall on scope y after the -90 degree turn.
TEST(Insert, ZUpAssetsAreTurned) {
  const auto tall = box_mesh({1, 2, 3}, mass_box_tags());
  MapAssets assets;
  assets.meshes["tall"] = tall;
  ShapeTree tree;
  const ShapeId root = tree.add_root(Scope{});
  const OpResult r = registry().run(tree, root, "insert",
                                    {{"", std::string("tall")},
                                     {"", std::string("zup")},
                                     {"", std::string("alignsizeandposition")}},
                                    Context{&assets});
  ASSERT_TRUE(r.ok()) << r.error;
  const Vec3 size = tree[r.children[0]].scope.size;
  EXPECT_NEAR(size.x, 1, 1e-12);
  EXPECT_NEAR(size.y, 3, 1e-12);
  EXPECT_NEAR(size.z, 2, 1e-12);
  EXPECT_NEAR(kernel::volume(*tree[r.children[0]].mesh), 6, 1e-9);
  EXPECT_NE(registry()
                .run(tree, root, "insert", {{"", std::string("tall")}, {"", std::string("xup")}},
                     Context{&assets})
                .error,
            "");
}

// numericalCleanup merges vertices closer than 1e-6 of the diagonal; noCleanup keeps them.
TEST(Insert, Cleanup) {
  kernel::Mesh split;  // two triangles of a unit square whose shared corners differ by 1e-9
  split.add_face(
      {split.add_vertex({0, 0, 0}), split.add_vertex({1, 0, 0}), split.add_vertex({1, 1, 0})}, {});
  split.add_face(
      {split.add_vertex({0, 0, 1e-9}), split.add_vertex({1, 1, 1e-9}), split.add_vertex({0, 1, 0})},
      {});
  ShapeTree tree;
  const OpResult clean = insert_into(tree, {1, 1, 0}, split);
  ASSERT_TRUE(clean.ok());
  EXPECT_EQ(tree[clean.children[0]].mesh->vertex_count(), 4U);
  InsertOptions keep;
  keep.cleanup = false;
  const OpResult raw = insert_into(tree, {1, 1, 0}, split, keep);
  EXPECT_EQ(tree[raw.children[0]].mesh->vertex_count(), 6U);
}

}  // namespace
}  // namespace insula::shape
