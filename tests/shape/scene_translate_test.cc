#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "kernel/transform.h"
#include "shape/ops.h"
#include "shape/scene.h"

namespace insula::shape {
namespace {

using kernel::Vec2;
using kernel::Vec3;

constexpr Vec3 kOffset{640000, 5780000, 2};
constexpr Vec2 kOffset2{kOffset.x, kOffset.y};

// A building of three parts (a mesh with a uv map, an instance of a shared box, an empty one) and
// a storey plan with a room, a wall, a door and a stair.
Building sample() {
  Building b;
  const std::shared_ptr<const kernel::Mesh> box = box_mesh({2, 3, 4}, mass_box_tags());
  Part own{"own", PartKind::kRoom, {}, *box};
  own.uv = UvMap{{0.5, 0, 0}, 0.25, {0, 0, 1}, 0};
  Part shared{"shared", PartKind::kFurniture, {}, {}, box, kernel::translation({5, 1, 0})};
  b.parts = {std::move(own), std::move(shared), Part{"empty", PartKind::kOther, {}, {}}};
  StoreyPlan plan;
  plan.elevation = 3;
  const kernel::Polygon square{{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{{1, 1}, {1, 2}, {2, 2}}}};
  plan.rooms.push_back({"hall", "hall", square, 16});
  plan.walls.push_back({square, true});
  plan.openings.push_back({PlanOpeningKind::kDoor, {1, 0}, {2, 0}, {0, 1}});
  plan.stairs.push_back({square, {1, 1}, {1, 3}});
  b.plans.push_back(plan);
  return b;
}

void expect_moved(const kernel::Polygon& moved, const kernel::Polygon& was) {
  ASSERT_EQ(moved.outer.size(), was.outer.size());
  ASSERT_EQ(moved.holes.size(), was.holes.size());
  for (std::size_t i = 0; i < was.outer.size(); ++i) {
    EXPECT_EQ(moved.outer[i], was.outer[i] + kOffset2);
  }
  for (std::size_t h = 0; h < was.holes.size(); ++h) {
    for (std::size_t i = 0; i < was.holes[h].size(); ++i) {
      EXPECT_EQ(moved.holes[h][i], was.holes[h][i] + kOffset2);
    }
  }
}

TEST(TranslateBuilding, MovesMeshesInstancesUvMapsAndPlans) {
  const Building was = sample();
  Building b = sample();
  const std::shared_ptr<const kernel::Mesh> shared = b.parts[1].instance_of;
  const std::vector<Vec3> shared_positions = shared->positions();
  translate(b, kOffset);

  const kernel::Mesh& mesh = b.parts[0].mesh;
  ASSERT_EQ(mesh.vertex_count(), was.parts[0].mesh.vertex_count());
  for (std::uint32_t v = 0; v < mesh.vertex_count(); ++v) {
    const Vec3 p = was.parts[0].mesh.position(v);
    EXPECT_EQ(mesh.position(v), p + kOffset);
    // The texture stays on the surface: the moved point has the coordinates the point had.
    const Vec2 uv = b.parts[0].uv->at(p + kOffset);
    const Vec2 uv_was = was.parts[0].uv->at(p);
    EXPECT_NEAR(uv.x, uv_was.x, 1e-9);
    EXPECT_NEAR(uv.y, uv_was.y, 1e-9);
  }
  // The instance keeps its shared mesh; its placement moves.
  EXPECT_EQ(b.parts[1].instance_of, shared);
  EXPECT_EQ(shared->positions(), shared_positions);
  EXPECT_TRUE(b.parts[1].mesh.empty());
  EXPECT_EQ(b.parts[1].instance_transform.t, (Vec3{5, 1, 0} + kOffset));
  EXPECT_EQ(b.parts[1].instance_transform.x, was.parts[1].instance_transform.x);
  EXPECT_FALSE(b.parts[1].uv.has_value());
  EXPECT_TRUE(b.parts[2].mesh.empty());

  const StoreyPlan& plan = b.plans[0];
  const StoreyPlan& plan_was = was.plans[0];
  EXPECT_EQ(plan.elevation, plan_was.elevation + kOffset.z);
  expect_moved(plan.rooms[0].outline, plan_was.rooms[0].outline);
  EXPECT_EQ(plan.rooms[0].area, plan_was.rooms[0].area);
  expect_moved(plan.walls[0].outline, plan_was.walls[0].outline);
  expect_moved(plan.stairs[0].outline, plan_was.stairs[0].outline);
  const Vec2 by = kOffset2;
  EXPECT_EQ(plan.openings[0].a, plan_was.openings[0].a + by);
  EXPECT_EQ(plan.openings[0].b, plan_was.openings[0].b + by);
  EXPECT_EQ(plan.openings[0].swing, plan_was.openings[0].swing);  // a direction
  EXPECT_EQ(plan.stairs[0].up_from, plan_was.stairs[0].up_from + by);
  EXPECT_EQ(plan.stairs[0].up_to, plan_was.stairs[0].up_to + by);
}

}  // namespace
}  // namespace insula::shape
