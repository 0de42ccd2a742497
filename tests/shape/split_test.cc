#include <gtest/gtest.h>

#include "kernel/extrude.h"
#include "shape/ops.h"

namespace insula::shape {
namespace {

using kernel::SemanticClass;
using kernel::Vec3;

// A 10 x 9 x 6 box mass (x, y up, z).
ShapeId box_shape(ShapeTree& tree) {
  Scope scope;
  scope.size = {10, 9, 6};
  const auto tags = mass_box_tags();
  return tree.add_root(scope, box_mesh(scope.size, tags));
}

std::vector<SizeSpec> sizes(std::initializer_list<SizeSpec> list) {
  return list;
}

TEST(ResolveSizes, AbsoluteRelativeAndFloating) {
  const auto p = resolve_sizes(10, sizes({{2, SizeMode::kAbsolute},
                                          {0.3, SizeMode::kRelative},
                                          {1, SizeMode::kFloating},
                                          {3, SizeMode::kFloating}}));
  ASSERT_EQ(p.size(), 4U);
  EXPECT_DOUBLE_EQ(p[0].size, 2);
  EXPECT_DOUBLE_EQ(p[1].size, 3);
  EXPECT_DOUBLE_EQ(p[2].size, 1.25);
  EXPECT_DOUBLE_EQ(p[3].size, 3.75);
  EXPECT_DOUBLE_EQ(p[3].start + p[3].size, 10);
}

TEST(ResolveSizes, WithoutFloatingOverflowIsCutAndShortfallStaysEmpty) {
  const auto over = resolve_sizes(5, sizes({{2, SizeMode::kAbsolute},
                                            {2, SizeMode::kAbsolute},
                                            {2, SizeMode::kAbsolute},
                                            {2, SizeMode::kAbsolute}}));
  ASSERT_EQ(over.size(), 3U);
  EXPECT_DOUBLE_EQ(over[2].size, 1);
  const auto under = resolve_sizes(5, sizes({{2, SizeMode::kAbsolute}}));
  ASSERT_EQ(under.size(), 1U);
  // Floating pieces get nothing when absolute ones already fill the scope: left out.
  const auto none = resolve_sizes(4, sizes({{4, SizeMode::kAbsolute}, {1, SizeMode::kFloating}}));
  ASSERT_EQ(none.size(), 1U);
  EXPECT_EQ(none[0].entry, 0U);
}

TEST(Split, BoxIntoFloorsKeepsVolumeAndTagsCuts) {
  ShapeTree tree;
  const ShapeId root = box_shape(tree);
  const OpResult r =
      split(tree, root, Axis::kY, sizes({{3, SizeMode::kAbsolute}, {1, SizeMode::kFloating}}));
  ASSERT_TRUE(r.ok()) << r.error;
  ASSERT_EQ(r.children.size(), 2U);
  EXPECT_FALSE(tree[root].active);
  const Shape& ground = tree[r.children[0]];
  const Shape& upper = tree[r.children[1]];
  EXPECT_DOUBLE_EQ(ground.scope.size.y, 3);
  EXPECT_DOUBLE_EQ(upper.scope.size.y, 6);
  EXPECT_DOUBLE_EQ(upper.scope.origin.y, 3);
  EXPECT_NEAR(kernel::volume(*ground.mesh) + kernel::volume(*upper.mesh), 540, 1e-9);
  EXPECT_TRUE(kernel::is_watertight(*upper.mesh));
  std::array<kernel::FaceTag, 6> tags;
  ASSERT_TRUE(is_box(*upper.mesh, upper.scope.size, &tags));
  EXPECT_EQ(tags[2].semantic, SemanticClass::kFloorSurface);  // cut face below the upper floor
  EXPECT_EQ(tags[3].semantic, SemanticClass::kRoofSurface);   // the parent's top
  ASSERT_TRUE(is_box(*ground.mesh, ground.scope.size, &tags));
  EXPECT_EQ(tags[2].semantic, SemanticClass::kGroundSurface);
  EXPECT_EQ(tags[3].semantic, SemanticClass::kCeilingSurface);
}

TEST(Split, NonBoxMeshIsCutIntoClosedPieces) {
  // An L-shaped prism standing in scope space: footprint in x/z, height along y.
  const kernel::Polygon l = {{{0, 0}, {6, 0}, {6, 2}, {2, 2}, {2, 5}, {0, 5}}, {}};
  auto prism = kernel::extrude(l, 0, 3);
  ASSERT_TRUE(prism.ok());
  // Lay it down: (x, y, z) -> (x, z, y) would mirror; use (x, z, -y) shifted by 5 in z instead.
  kernel::Mesh mesh =
      kernel::transformed(prism.mesh, kernel::frame({0, 0, 5}, {1, 0, 0}, {0, 0, -1}, {0, 1, 0}));
  ShapeTree tree;
  Scope scope;
  scope.size = {6, 3, 5};
  const ShapeId root = tree.add_root(scope, std::make_shared<kernel::Mesh>(mesh));
  const OpResult r =
      split(tree, root, Axis::kX,
            sizes({{1, SizeMode::kFloating}, {1, SizeMode::kFloating}, {1, SizeMode::kFloating}}));
  ASSERT_TRUE(r.ok()) << r.error;
  ASSERT_EQ(r.children.size(), 3U);
  double total = 0;
  for (ShapeId c : r.children) {
    EXPECT_TRUE(kernel::is_watertight(*tree[c].mesh));
    EXPECT_DOUBLE_EQ(tree[c].scope.size.x, 2);
    total += kernel::volume(*tree[c].mesh);
  }
  EXPECT_NEAR(total, kernel::area(l) * 3, 1e-9);
  EXPECT_NEAR(kernel::volume(*tree[r.children[0]].mesh), 2 * 5 * 3, 1e-9);
  EXPECT_NEAR(kernel::volume(*tree[r.children[2]].mesh), 2 * 2 * 3, 1e-9);
  // The cut faces are interior walls.
  bool found = false;
  const kernel::Mesh& m = *tree[r.children[1]].mesh;
  for (std::size_t f = 0; f < m.face_count(); ++f) {
    found = found || m.tag(f).semantic == SemanticClass::kInteriorWallSurface;
  }
  EXPECT_TRUE(found);
}

TEST(Split, FlatShapesSplitInTheirPlane) {
  ShapeTree tree;
  const RootResult rect = tree.create_root({{{0, 0}, {8, 0}, {8, 4}, {0, 4}}, {}});
  const OpResult r = split(tree, rect.id, Axis::kX,
                           sizes({{0.25, SizeMode::kRelative}, {1, SizeMode::kFloating}}));
  ASSERT_EQ(r.children.size(), 2U);
  EXPECT_NEAR(kernel::area(*tree[r.children[0]].outline), 8, 1e-12);
  EXPECT_NEAR(kernel::surface_area(*tree[r.children[1]].mesh), 24, 1e-12);
  // A triangle is cut by the plane splitter (open pieces, one face each).
  const RootResult tri = tree.create_root({{{0, 0}, {8, 0}, {0, 4}}, {}});
  const OpResult t =
      split(tree, tri.id, Axis::kX, sizes({{4, SizeMode::kAbsolute}, {1, SizeMode::kFloating}}));
  ASSERT_EQ(t.children.size(), 2U) << t.error;
  ASSERT_NE(tree[t.children[1]].outline, nullptr);
  EXPECT_NEAR(
      kernel::area(*tree[t.children[0]].outline) + kernel::area(*tree[t.children[1]].outline), 16,
      1e-9);
  EXPECT_EQ(split(tree, tri.id, Axis::kZ, sizes({{1, SizeMode::kFloating}})).error,
            "the scope has size 0 along the split axis");
}

TEST(Repeat, FitsWholePiecesAndFillsExactly) {
  ShapeTree tree;
  const ShapeId root = box_shape(tree);
  const OpResult r = repeat(tree, root, Axis::kX, 3);
  ASSERT_EQ(r.children.size(), 3U);
  for (ShapeId c : r.children) EXPECT_NEAR(tree[c].scope.size.x, 10.0 / 3, 1e-12);
  EXPECT_NEAR(tree[r.children[2]].scope.origin.x + tree[r.children[2]].scope.size.x, 10, 1e-12);
  EXPECT_EQ(r.pieces, (std::vector<std::uint32_t>{0, 0, 0}));
  // Larger than the scope: one piece.
  ShapeTree other;
  EXPECT_EQ(repeat(other, box_shape(other), Axis::kZ, 100).children.size(), 1U);
  EXPECT_EQ(repeat(other, 0, Axis::kZ, 0).error, "size must be > 0");
}

}  // namespace
}  // namespace insula::shape
