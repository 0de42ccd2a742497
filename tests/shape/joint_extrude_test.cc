#include <gtest/gtest.h>

#include "shape/component_ops.h"

namespace insula::shape {
namespace {

using kernel::SemanticClass;
using kernel::Vec3;

// A room box 4 (x) by 3 (up) by 5 (depth) standing on the ground: scope y = world +Z.
ShapeId room(ShapeTree& tree) {
  Scope scope;
  scope.x = {1, 0, 0};
  scope.y = {0, 0, 1};
  scope.z = {0, -1, 0};
  scope.size = {4, 3, 5};
  return tree.add_root(scope, box_mesh(scope.size, mass_box_tags()));
}

std::vector<ShapeId> faces(ShapeTree& tree, ShapeId id, FaceSelector selector) {
  std::vector<ShapeId> out;
  for (std::size_t f = 0; f < tree[id].mesh->face_count(); ++f) {
    if (!face_matches(selector, kernel::face_normal(*tree[id].mesh, f))) continue;
    out.push_back(face_component(tree, id, f).children.at(0));
  }
  return out;
}

double world_volume(const ShapeTree& tree, ShapeId id) {
  return kernel::volume(mesh_to_world(*tree[id].mesh, tree[id].scope));
}

TEST(JointExtrude, WallsAndFloorTileTheShellWithoutOverlap) {
  ShapeTree tree;
  const ShapeId r = room(tree);
  std::vector<ShapeId> f = faces(tree, r, FaceSelector::kSide);
  const std::vector<ShapeId> bottom = faces(tree, r, FaceSelector::kBottom);
  f.insert(f.end(), bottom.begin(), bottom.end());
  ASSERT_EQ(f.size(), 5U);
  const OpResult out = extrude_joint(tree, f, -0.1);
  ASSERT_TRUE(out.ok()) << out.error;
  ASSERT_EQ(out.children.size(), 5U);
  double total = 0;
  for (std::size_t i = 0; i < 5; ++i) {
    const ShapeId c = out.children[i];
    EXPECT_EQ(tree.parent(c), f[i]);
    EXPECT_TRUE(kernel::is_watertight(*tree[c].mesh)) << i;
    total += world_volume(tree, c);
  }
  // Mitred prisms tile the shell exactly (Fig. 6 right): room minus the inner box (open at top).
  EXPECT_NEAR(total, 4 * 3 * 5 - 3.8 * 2.9 * 4.8, 1e-9);
  // The floor prism's visible cap is a floor, the walls' interior walls.
  const kernel::Mesh& floor = *tree[out.children[4]].mesh;
  int floors = 0;
  for (std::size_t k = 0; k < floor.face_count(); ++k) {
    floors += floor.tag(k).semantic == SemanticClass::kFloorSurface ? 1 : 0;
  }
  EXPECT_EQ(floors, 1);
  EXPECT_NEAR(tree[out.children[4]].scope.size.z, 0.1, 1e-12);
}

TEST(JointExtrude, SeparateExtrusionOverlapsAtCorners) {
  // Fig. 6 left: each face alone grows straight, so the shell volume is exceeded by the corners.
  ShapeTree tree;
  const ShapeId r = room(tree);
  const std::vector<ShapeId> f = faces(tree, r, FaceSelector::kSide);
  double total = 0;
  for (ShapeId face : f) {
    const OpResult one = extrude_joint(tree, std::span(&face, 1), -0.1);
    total += world_volume(tree, one.children[0]);
  }
  EXPECT_NEAR(total, 2 * (4 * 3 * 0.1) + 2 * (5 * 3 * 0.1), 1e-9);
}

TEST(JointExtrude, OutwardFacadesGetExteriorClasses) {
  ShapeTree tree;
  const ShapeId r = room(tree);
  const std::vector<ShapeId> f = faces(tree, r, FaceSelector::kAll);
  const OpResult out = extrude_joint(tree, f, 0.3);
  ASSERT_TRUE(out.ok());
  double total = 0;
  for (ShapeId c : out.children) total += world_volume(tree, c);
  EXPECT_NEAR(total, 4.6 * 3.6 * 5.6 - 60, 1e-9);
  // The roof prism (top face) shows a roof surface.
  bool roof = false;
  for (ShapeId c : out.children) {
    for (std::size_t k = 0; k < tree[c].mesh->face_count(); ++k) {
      roof = roof || tree[c].mesh->tag(k).semantic == SemanticClass::kRoofSurface;
    }
  }
  EXPECT_TRUE(roof);
}

TEST(JointExtrude, Errors) {
  ShapeTree tree;
  const ShapeId r = room(tree);
  EXPECT_EQ(extrude_joint(tree, std::span(&r, 1), 1).error,
            "component " + std::to_string(r) + " is not flat");
  const std::vector<ShapeId> f = faces(tree, r, FaceSelector::kTop);
  EXPECT_EQ(extrude_joint(tree, f, 0).error, "distance must be finite and not 0");
}

}  // namespace
}  // namespace insula::shape
