// The CGA engine's compact split / repeat / comp give exactly the scopes and geometry of the shape
// layer's operations (shape::split, shape::repeat, shape::comp_faces on a ShapeTree): the same
// operation from a grammar and from the shape API (design.md, "one engine").
#include <gtest/gtest.h>

#include <functional>

#include "derive_util.h"
#include "lang/cga/derive.h"
#include "shape/collect.h"
#include "shape/ops.h"

namespace insula::lang::cga {
namespace {

using shape::Axis;
using shape::ShapeId;
using shape::ShapeTree;
using shape::SizeMode;
using shape::SizeSpec;

const kernel::Polygon kLot = {{{0, 0}, {10, 0}, {10, 8}, {0, 8}}, {}};

// A mass of 6 m over the 10 x 8 lot, as the shape API builds it.
ShapeId mass(ShapeTree& tree) {
  const ShapeId root = tree.create_root(kLot).id;
  return shape::extrude(tree, root, 6).children.front();
}

// Compares the grammar's terminals with the tree's leaves: scopes bit for bit, world meshes
// (positions, loops, tags) bit for bit, in order.
void expect_same(const std::string& grammar, const ShapeTree& tree) {
  auto p = testing::compile_text(grammar);
  ASSERT_TRUE(p);
  Lot lot;
  lot.id = "lot";
  lot.polygons = {kLot};
  const std::vector<LotResult> r = testing::derive_all(*p, {lot});
  ASSERT_TRUE(r[0].ok) << testing::diagnostics_text(r[0]);

  const std::vector<ShapeId> leaves = tree.leaves();
  ASSERT_EQ(r[0].terminals_store.size(), leaves.size());
  for (std::size_t i = 0; i < leaves.size(); ++i) {
    const shape::Scope& a = r[0].terminals_store[i].scope;
    const shape::Scope& b = tree[leaves[i]].scope;
    EXPECT_EQ(a.origin, b.origin) << i;
    EXPECT_EQ(a.x, b.x) << i;
    EXPECT_EQ(a.y, b.y) << i;
    EXPECT_EQ(a.z, b.z) << i;
    EXPECT_EQ(a.size, b.size) << i;
  }
  const shape::Scene ours = to_scene(*p, {lot}, r);
  const shape::Scene theirs = shape::collect(tree);
  ASSERT_EQ(ours.buildings.size(), 1U);
  ASSERT_EQ(theirs.buildings.size(), 1U);
  const auto& x = ours.buildings[0].parts;
  const auto& y = theirs.buildings[0].parts;
  ASSERT_EQ(x.size(), y.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    EXPECT_EQ(x[i].mesh.positions(), y[i].mesh.positions()) << "part " << i;
    ASSERT_EQ(x[i].mesh.face_count(), y[i].mesh.face_count()) << "part " << i;
    for (std::size_t f = 0; f < x[i].mesh.face_count(); ++f) {
      const auto la = x[i].mesh.face(f);
      const auto lb = y[i].mesh.face(f);
      EXPECT_TRUE(std::equal(la.begin(), la.end(), lb.begin(), lb.end())) << i << " " << f;
      EXPECT_EQ(x[i].mesh.tag(f).semantic, y[i].mesh.tag(f).semantic) << i << " " << f;
      EXPECT_EQ(x[i].mesh.tag(f).face_id, y[i].mesh.tag(f).face_id) << i << " " << f;
    }
  }
}

TEST(DeriveEquivalence, SplitOfABoxAndOfItsPieces) {
  ShapeTree tree;
  const ShapeId m = mass(tree);
  const std::vector<SizeSpec> floors = {
      {2, SizeMode::kAbsolute}, {1, SizeMode::kFloating}, {1.5, SizeMode::kAbsolute}};
  const auto pieces = shape::split(tree, m, Axis::kY, floors).children;
  // The middle floor splits again along x (a box cut twice: cut tags on both axes).
  const std::vector<SizeSpec> bays = {{0.25, SizeMode::kRelative}, {1, SizeMode::kFloating}};
  shape::split(tree, pieces[1], Axis::kX, bays);
  expect_same(R"(
Lot --> extrude(6) Mass
Mass --> split("y"){ 2: A | ~1: B | 1.5: C }
B --> split("x"){ '0.25: D | ~1: E }
)",
              tree);
}

TEST(DeriveEquivalence, RepeatOfABox) {
  ShapeTree tree;
  shape::repeat(tree, mass(tree), Axis::kX, 3);
  expect_same("Lot --> extrude(6) Mass\nMass --> RR(\"X\", 3){ Bay }\n", tree);
}

TEST(DeriveEquivalence, CompFacesThenSplitOfTheFrontFace) {
  ShapeTree tree;
  const auto faces = shape::comp_faces(tree, mass(tree), shape::FaceSelector::kAll);
  // Every face is a leaf but the front one (+z), which is split along x.
  ShapeId front = shape::kNoShape;
  const ShapeId parent = tree[faces.children.front()].parent;
  for (std::size_t i = 0; i < faces.children.size(); ++i) {
    const kernel::Vec3 normal = kernel::face_normal(*tree[parent].mesh, faces.pieces[i]);
    if (shape::face_matches(shape::FaceSelector::kFront, normal)) front = faces.children[i];
  }
  ASSERT_NE(front, shape::kNoShape);
  const std::vector<SizeSpec> parts = {{1, SizeMode::kAbsolute}, {1, SizeMode::kFloating}};
  shape::split(tree, front, Axis::kX, parts);
  expect_same(R"(
Lot --> extrude(6) Mass
Mass --> comp("f"){ front: Front | all: Face }
Front --> split("x"){ 1: A | ~1: B }
)",
              tree);
}

}  // namespace
}  // namespace insula::lang::cga
