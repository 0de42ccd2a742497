#include "shape/collect.h"

#include <gtest/gtest.h>

#include "shape/ops.h"

namespace insula::shape {
namespace {

TEST(Collect, OneBuildingPerRootOnePartPerLeafInWorldSpace) {
  ShapeTree tree;
  const RootResult a = tree.create_root({{{100, 50}, {110, 50}, {110, 58}, {100, 58}}, {}});
  const RootResult b = tree.create_root({{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {}});
  tree.set_attribute(a.id, "id", std::string("townhall"));
  tree.set_attribute(a.id, "levels", 2.0);
  const ShapeId mass = extrude(tree, a.id, 6).children[0];
  const OpResult floors =
      split(tree, mass, Axis::kY,
            std::vector<SizeSpec>{{1, SizeMode::kFloating}, {1, SizeMode::kFloating}});
  tree.add_label(floors.children[0], "GroundFloor");
  tree.set_attribute(floors.children[1], "levels", 1.0);
  extrude(tree, b.id, 3);

  const Scene scene = collect(tree);
  ASSERT_EQ(scene.buildings.size(), 2U);
  const Building& hall = scene.buildings[0];
  EXPECT_EQ(hall.id, "townhall");
  EXPECT_EQ(scene.buildings[1].id, "building_1");
  ASSERT_EQ(hall.parts.size(), 2U);
  EXPECT_EQ(hall.parts[0].name, "GroundFloor");
  EXPECT_EQ(hall.parts[1].name, "shape_" + std::to_string(floors.children[1]));
  EXPECT_EQ(std::get<double>(hall.parts[0].attributes.at("levels")), 2.0);
  EXPECT_EQ(std::get<double>(hall.parts[1].attributes.at("levels")), 1.0);
  const kernel::Bounds3 upper = hall.parts[1].mesh.bounds();
  EXPECT_NEAR(upper.min.x, 100, 1e-9);
  EXPECT_NEAR(upper.min.y, 50, 1e-9);
  EXPECT_NEAR(upper.min.z, 3, 1e-9);
  EXPECT_NEAR(upper.max.z, 6, 1e-9);
  EXPECT_NEAR(kernel::volume(hall.parts[1].mesh), 240, 1e-9);
  EXPECT_TRUE(kernel::is_watertight(hall.parts[1].mesh));
}

TEST(Collect, ByLabel) {
  ShapeTree tree;
  const RootResult a = tree.create_root({{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {}});
  tree.add_label(a.id, "Lot");
  extrude(tree, a.id, 3);
  CollectOptions options;
  options.labels = {"Lot"};
  const Scene scene = collect(tree, options);
  ASSERT_EQ(scene.buildings.size(), 1U);
  ASSERT_EQ(scene.buildings[0].parts.size(), 1U);
  EXPECT_EQ(scene.buildings[0].parts[0].name, "Lot");
  EXPECT_NEAR(kernel::surface_area(scene.buildings[0].parts[0].mesh), 16, 1e-9);
}

}  // namespace
}  // namespace insula::shape
