// The building-element operations (shape/building_ops.h) and roof's closed/height/thickness
// parameters: exact solids and exact errors.
#include <gtest/gtest.h>

#include <string>

#include "kernel/mesh.h"
#include "shape/building_ops.h"
#include "shape/ops.h"

namespace insula::shape {
namespace {

using kernel::SemanticClass;

const kernel::Polygon kLot{{{0, 0}, {10, 0}, {10, 8}, {0, 8}}, {}};

OpResult run(ShapeTree& tree, ShapeId id, const std::string& op,
             const std::vector<ArgInput>& args) {
  return registry().run(tree, id, op, args);
}

const kernel::Mesh& child_mesh(const ShapeTree& tree, const OpResult& r) {
  return *tree[r.children.at(0)].mesh;
}

TEST(BuildingOps, StairStepsFollowMaxRiseAndTheSolidIsClosed) {
  ShapeTree tree;
  const ShapeId lot = tree.create_root({{{0, 0}, {1, 0}, {1, 4}, {0, 4}}, {}}).id;
  const OpResult r = run(tree, lot, "stair", {{"height", 3.0}});
  ASSERT_TRUE(r.ok()) << r.error;
  const kernel::Mesh& m = child_mesh(tree, r);
  // ceil(3 / 0.18) = 17 steps: 2 * 17 + 4 faces, volume run * rise * width * n (n + 1) / 2.
  EXPECT_EQ(m.face_count(), 38U);
  EXPECT_NEAR(kernel::volume(m), (4.0 / 17) * (3.0 / 17) * 17 * 18 / 2, 1e-9);
  EXPECT_TRUE(kernel::check(m).closed);
  EXPECT_NEAR(tree[r.children[0]].scope.size.y, 3, 1e-12);  // y is up
}

TEST(BuildingOps, DoorFrameWithALeafAndWindowFrameWithAPane) {
  ShapeTree tree;
  const ShapeId door = tree.create_root({{{0, 0}, {1, 0}, {1, 2}, {0, 2}}, {}}).id;
  const OpResult d =
      run(tree, door, "frame", {{"kind", std::string("door")}, {"thickness", 0.2}, {"leaf", 0.04}});
  ASSERT_TRUE(d.ok()) << d.error;
  // Two posts and a head per face, then the leaf, at most a quarter of the wall thick (0.04).
  const kernel::Mesh& dm = child_mesh(tree, d);
  EXPECT_EQ(dm.face_count(), 7U * 6);
  const double post = 0.06 * 2.06 * 0.04;
  const double head = 1.0 * 0.06 * 0.04;
  EXPECT_NEAR(kernel::volume(dm), 2 * (2 * post + head) + 1 * 2 * 0.04, 1e-12);
  const OpResult w = run(tree, tree.create_root(kLot).id, "frame", {});
  ASSERT_TRUE(w.ok()) << w.error;
  EXPECT_EQ(child_mesh(tree, w).face_count(), 9U * 6);  // 8 frame boxes and the pane
}

TEST(BuildingOps, CeilingSlabHangsUnderTheShape) {
  ShapeTree tree;
  const ShapeId lot = tree.create_root(kLot).id;
  const OpResult r = run(tree, lot, "slab", {{"kind", std::string("ceiling")}, {"thickness", 0.2}});
  ASSERT_TRUE(r.ok()) << r.error;
  const Shape& s = tree[r.children[0]];
  EXPECT_NEAR(s.scope.origin.z, -0.2, 1e-12);
  EXPECT_NEAR(kernel::volume(*s.mesh), 80 * 0.2, 1e-9);
  double ceiling = 0;
  for (std::size_t f = 0; f < s.mesh->face_count(); ++f) {
    if (s.mesh->tag(f).semantic == SemanticClass::kCeilingSurface) {
      ceiling += kernel::face_area(*s.mesh, f);
    }
  }
  EXPECT_NEAR(ceiling, 80, 1e-9);
}

TEST(BuildingOps, ClosedRoofsAreSolidsOfTheAskedHeight) {
  for (const char* type : {"gable", "hip", "holed_mansard"}) {
    ShapeTree tree;
    const ShapeId lot = tree.create_root(kLot).id;
    const OpResult r =
        run(tree, lot, "roof", {{"type", std::string(type)}, {"closed", true}, {"height", 2.0}});
    ASSERT_TRUE(r.ok()) << type << ": " << r.error;
    const kernel::Mesh& m = child_mesh(tree, r);
    EXPECT_TRUE(kernel::check(m).closed) << type;
    EXPECT_GT(kernel::volume(m), 0) << type;
    EXPECT_NEAR(tree[r.children[0]].scope.size.y, 2, 1e-9) << type;
  }
  ShapeTree tree;
  const OpResult flat = run(tree, tree.create_root(kLot).id, "roof",
                            {{"type", std::string("flat")}, {"thickness", 0.25}});
  ASSERT_TRUE(flat.ok()) << flat.error;
  EXPECT_NEAR(kernel::volume(child_mesh(tree, flat)), 80 * 0.25, 1e-9);
}

TEST(BuildingOps, Errors) {
  ShapeTree tree;
  const ShapeId lot = tree.create_root(kLot).id;
  const ShapeId mass = extrude(tree, lot, 3).children.at(0);
  EXPECT_EQ(run(tree, mass, "stair", {{"height", 3.0}}).error,
            "stair: needs a flat shape (a footprint or a face)");
  EXPECT_EQ(run(tree, mass, "slab", {}).error, "slab: needs a flat shape (a footprint or a face)");
  ShapeTree other;
  const ShapeId flat = other.create_root(kLot).id;
  EXPECT_EQ(run(other, flat, "roof", {{"type", std::string("flat")}, {"closed", true}}).error,
            "roof: a closed flat roof needs a thickness > 0");
  EXPECT_FALSE(run(other, flat, "frame", {{"thickness", 0.0}}).ok());
  EXPECT_FALSE(run(other, flat, "stair", {}).ok());  // height is required
}

}  // namespace
}  // namespace insula::shape
