#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "shape/ops.h"

namespace insula::shape {
namespace {

using kernel::SemanticClass;

TEST(Roof, GableOverAFootprintRisesAlongScopeY) {
  ShapeTree tree;
  const RootResult root = tree.create_root({{{0, 0}, {12, 0}, {12, 8}, {0, 8}}, {}});
  const OpResult r =
      registry().run(tree, root.id, "roof", {{"type", std::string("gable")}, {"pitch", 45.0}});
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(r.warning, "");
  const Shape& roof = tree[r.children[0]];
  // The ridge runs along the long side: height = half the depth * tan(45 degrees).
  EXPECT_NEAR(roof.scope.size.y, 4, 1e-9);
  EXPECT_NEAR(roof.scope.size.x, 12, 1e-9);
  EXPECT_NEAR(roof.scope.y.z, 1, 1e-12);  // scope y is world up
  double roof_area = 0;
  for (std::size_t f = 0; f < roof.mesh->face_count(); ++f) {
    if (roof.mesh->tag(f).semantic == SemanticClass::kRoofSurface) {
      roof_area += kernel::face_area(*roof.mesh, f);
    }
  }
  EXPECT_NEAR(roof_area, 12 * 8 / std::cos(std::numbers::pi / 4), 1e-6);
}

// CGA roofGable reaches the kernel's gable: a square footprint gets two slopes and two gable
// walls, not a hip with a warning (issue 12 item 6).
TEST(Roof, GableOverASquareFootprintIsAGable) {
  ShapeTree tree;
  const RootResult root = tree.create_root({{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {}});
  const OpResult r =
      registry().run(tree, root.id, "roof", {{"type", std::string("gable")}, {"pitch", 45.0}});
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(r.warning, "");
  const kernel::Mesh& mesh = *tree[r.children[0]].mesh;
  int slopes = 0, gables = 0;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    slopes += mesh.tag(f).semantic == SemanticClass::kRoofSurface ? 1 : 0;
    gables += mesh.tag(f).semantic == SemanticClass::kWallSurface ? 1 : 0;
  }
  EXPECT_EQ(slopes, 2);
  EXPECT_EQ(gables, 2);
  EXPECT_NEAR(tree[r.children[0]].scope.size.y, 5, 1e-9);
}

TEST(Roof, HipOnTheTopFaceOfAMass) {
  ShapeTree tree;
  const RootResult root = tree.create_root({{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {}});
  const ShapeId mass = extrude(tree, root.id, 6).children[0];
  const ShapeId top = comp_faces(tree, mass, FaceSelector::kTop).children[0];
  kernel::RoofSpec pyramid;
  pyramid.type = kernel::RoofType::kPyramid;
  pyramid.pitch_deg = 45;
  const OpResult r = roof(tree, top, pyramid);
  ASSERT_TRUE(r.ok()) << r.error;
  const Shape& roof = tree[r.children[0]];
  const kernel::Bounds3 b = mesh_to_world(*roof.mesh, roof.scope).bounds();
  EXPECT_NEAR(b.min.z, 6, 1e-9);   // the eave sits on the top face
  EXPECT_NEAR(b.max.z, 11, 1e-9);  // apex 5 m above at 45 degrees
}

TEST(Roof, NeedsAFlatShape) {
  ShapeTree tree;
  Scope s;
  s.size = {2, 2, 2};
  const ShapeId box = tree.add_root(s, box_mesh(s.size, mass_box_tags()));
  EXPECT_EQ(registry().run(tree, box, "roof", {}).error,
            "roof: needs a flat shape (a footprint or a face)");
}

}  // namespace
}  // namespace insula::shape
