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

std::vector<double> widths(const ShapeTree& tree, const OpResult& r, Axis axis) {
  std::vector<double> out;
  for (ShapeId c : r.children) out.push_back(tree[c].scope.extent(axis));
  return out;
}

TEST(SlicePieces, FourLeftOverPolicies) {
  // 10 m in slices of 3 m: three slices and 1 m left over.
  const auto first = slice_pieces(10, 3, LeftOver::kFirst);
  ASSERT_EQ(first.size(), 3U);
  EXPECT_DOUBLE_EQ(first[0].size, 4);
  EXPECT_DOUBLE_EQ(first[1].size, 3);
  EXPECT_DOUBLE_EQ(first[2].start, 7);
  const auto last = slice_pieces(10, 3, LeftOver::kLast);
  EXPECT_DOUBLE_EQ(last[0].size, 3);
  EXPECT_DOUBLE_EQ(last[2].size, 4);
  const auto both = slice_pieces(10, 3, LeftOver::kBoth);
  EXPECT_DOUBLE_EQ(both[0].size, 3.5);
  EXPECT_DOUBLE_EQ(both[1].size, 3);
  EXPECT_DOUBLE_EQ(both[2].size, 3.5);
  const auto spread = slice_pieces(10, 3, LeftOver::kSpread);
  for (const Piece& p : spread) EXPECT_NEAR(p.size, 10.0 / 3, 1e-12);
  // Shorter than one slice: one piece of everything.
  const auto one = slice_pieces(2, 3, LeftOver::kLast);
  ASSERT_EQ(one.size(), 1U);
  EXPECT_DOUBLE_EQ(one[0].size, 2);
}

TEST(Slice, StoreysOfABoxKeepTheVolume) {
  ShapeTree tree;
  const ShapeId b = box(tree, {10, 10, 6});
  const OpResult r = slice(tree, b, Axis::kY, 3, LeftOver::kLast);
  ASSERT_TRUE(r.ok()) << r.error;
  const auto w = widths(tree, r, Axis::kY);
  ASSERT_EQ(w.size(), 3U);
  EXPECT_DOUBLE_EQ(w[0], 3);
  EXPECT_DOUBLE_EQ(w[2], 4);
  double volume = 0;
  for (ShapeId c : r.children) volume += kernel::volume(*tree[c].mesh);
  EXPECT_NEAR(volume, 600, 1e-9);
  EXPECT_NEAR(tree[r.children[2]].scope.origin.y, 6, 1e-12);
}

TEST(Slice, RejectsNonPositiveSize) {
  ShapeTree tree;
  const ShapeId b = box(tree, {10, 3, 6});
  EXPECT_FALSE(slice(tree, b, Axis::kX, 0, LeftOver::kFirst).ok());
  EXPECT_EQ(tree.size(), 1U);
}

Constraint plane_at_x(double x, ConstraintKind kind, double distance) {
  Constraint c;
  c.kind = kind;
  c.box.origin = {x, -100, -100};
  c.box.size = {0, 200, 200};
  c.distance = distance;
  return c;
}

TEST(Constraints, SnapMovesTheNearestBoundaryByTheExactAmount) {
  ShapeTree tree;
  const ShapeId b = box(tree, {12, 3, 6});
  // Slices at 4 and 8; a snap plane at 4.3 within 0.5 m pulls the first boundary 0.3 m.
  const Constraint c = plane_at_x(4.3, ConstraintKind::kSnap, 0.5);
  const OpResult r = slice(tree, b, Axis::kX, 4, LeftOver::kFirst, std::span(&c, 1));
  ASSERT_TRUE(r.ok());
  const auto w = widths(tree, r, Axis::kX);
  ASSERT_EQ(w.size(), 3U);
  EXPECT_NEAR(w[0], 4.3, 1e-12);
  EXPECT_NEAR(w[1], 3.7, 1e-12);
  EXPECT_NEAR(w[2], 4, 1e-12);
  // Out of reach: nothing moves.
  ShapeTree tree2;
  const ShapeId b2 = box(tree2, {12, 3, 6});
  const Constraint far = plane_at_x(4.6, ConstraintKind::kSnap, 0.5);
  const auto w2 =
      widths(tree2, slice(tree2, b2, Axis::kX, 4, LeftOver::kFirst, std::span(&far, 1)), Axis::kX);
  EXPECT_NEAR(w2[0], 4, 1e-12);
}

TEST(Constraints, RepelPushesWallsOutOfAWindowWithItsMargin) {
  ShapeTree tree;
  const ShapeId b = box(tree, {12, 3, 6});
  // A window box [3.5, 4.7] on the front with a 0.2 m margin: the boundary at 4 leaves for 3.3
  // (0.7 m down beats 0.9 m up).
  Constraint window;
  window.kind = ConstraintKind::kRepel;
  window.box.origin = {3.5, 1, 6};
  window.box.size = {1.2, 1.5, 0};
  window.distance = 0.2;
  std::vector<SizeSpec> sizes{{4, SizeMode::kAbsolute}, {1, SizeMode::kFloating}};
  const OpResult r = split_constrained(tree, b, Axis::kX, sizes, std::span(&window, 1));
  ASSERT_TRUE(r.ok());
  const auto w = widths(tree, r, Axis::kX);
  ASSERT_EQ(w.size(), 2U);
  EXPECT_NEAR(w[0], 3.3, 1e-12);
  EXPECT_NEAR(w[1], 8.7, 1e-12);
  EXPECT_EQ(r.pieces[1], 1U);
}

TEST(Constraints, OnlyActOnComponentsTheyOverlapAcross) {
  ShapeTree tree;
  const ShapeId b = box(tree, {12, 3, 6});
  Constraint c = plane_at_x(4.3, ConstraintKind::kSnap, 0.5);
  c.box.origin.y = 10;  // above the box
  c.box.size.y = 2;
  const auto w =
      widths(tree, slice(tree, b, Axis::kX, 4, LeftOver::kFirst, std::span(&c, 1)), Axis::kX);
  EXPECT_NEAR(w[0], 4, 1e-12);
}

TEST(Constraints, SliceAtStoreyPlanes) {
  ShapeTree tree;
  const ShapeId shaft = box(tree, {3, 9, 3});
  std::vector<Constraint> floors;
  for (double y : {0.0, 3.0, 6.0, 9.0}) {
    Constraint c;
    c.box.origin = {-1, y, -1};
    c.box.size = {5, 0, 5};
    floors.push_back(c);
  }
  const OpResult r = slice_at(tree, shaft, Axis::kY, floors);
  ASSERT_TRUE(r.ok()) << r.error;
  const auto w = widths(tree, r, Axis::kY);
  ASSERT_EQ(w.size(), 3U);
  for (double h : w) EXPECT_NEAR(h, 3, 1e-12);
  EXPECT_EQ(r.pieces[2], 2U);
}

TEST(Slice, RegistryEntryBindsThePolicy) {
  ShapeTree tree;
  const ShapeId b = box(tree, {10, 3, 6});
  const OpResult r = registry().run(
      tree, b, "slice", {{"", std::string("x")}, {"", 3.0}, {"leftover", std::string("both")}});
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_DOUBLE_EQ(tree[r.children[0]].scope.size.x, 3.5);
  const OpResult bad = registry().run(
      tree, b, "slice", {{"", std::string("x")}, {"", 3.0}, {"", std::string("mid")}});
  EXPECT_EQ(bad.error,
            "slice: parameter 'leftover' must be one of first, last, both, spread; got 'mid'");
}

}  // namespace
}  // namespace insula::shape
