#include "shape/scope.h"

#include <gtest/gtest.h>

namespace insula::shape {
namespace {

using kernel::Vec3;

void expect_near(Vec3 a, Vec3 b, double tolerance = 1e-12) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

// A mass scope as extrusion makes it: x = world +X, y = world +Z (up), z = world -Y.
Scope mass_scope() {
  Scope s;
  s.origin = {1, 2, 3};
  s.x = {1, 0, 0};
  s.y = {0, 0, 1};
  s.z = {0, -1, 0};
  s.size = {10, 6, 8};
  return s;
}

TEST(Scope, LocalAndWorldRoundTrip) {
  const Scope s = mass_scope();
  expect_near(s.to_world({2, 3, 4}), {3, -2, 6});
  expect_near(s.to_local(s.to_world({2, 3, 4})), {2, 3, 4});
  expect_near(s.center(), {6, -2, 6});
  EXPECT_DOUBLE_EQ(s.volume(), 480);
  expect_near(s.corners()[7], s.to_world(s.size));
}

TEST(Scope, RotationKeepsFrameOrthonormalAndPivotFixed) {
  const Scope s = mass_scope();
  const Vec3 pivot = s.size * 0.5;
  const Scope r = rotated(s, Axis::kY, 90, pivot);
  expect_near(r.to_world(pivot), s.to_world(pivot), 1e-12);
  EXPECT_NEAR(dot(r.x, r.y), 0, 1e-12);
  EXPECT_NEAR(length(r.z), 1, 1e-12);
  expect_near(cross(r.x, r.y), r.z, 1e-12);
  // A right-handed quarter turn about up (world +Z here) takes x = +X to +Y.
  expect_near(r.x, {0, 1, 0}, 1e-12);
}

TEST(Scope, FitsPointsInGivenAxes) {
  const std::vector<Vec3> points = {{0, 0, 0}, {4, 0, 0}, {4, 2, 0}, {0, 2, 5}};
  const Scope s = fit_scope(points, {1, 0, 0}, {0, 0, 1}, {0, -1, 0});
  expect_near(s.size, {4, 5, 2});
  expect_near(s.origin, {0, 2, 0});
  for (const Vec3& p : points) {
    const Vec3 l = s.to_local(p);
    EXPECT_GE(l.x, -1e-12);
    EXPECT_LE(l.z, s.size.z + 1e-12);
  }
}

TEST(Scope, FaceScopeOfAWallHasNormalZAndHorizontalX) {
  kernel::Mesh m;
  // A wall in the plane y = 0 facing -y (outward), 4 wide and 3 high (z up in this space).
  m.add_polygon(std::vector<Vec3>{{0, 0, 0}, {4, 0, 0}, {4, 0, 3}, {0, 0, 3}}, {});
  Scope s;
  ASSERT_TRUE(face_scope(m, 0, {0, 0, 1}, {1, 0, 0}, s));
  expect_near(s.z, {0, -1, 0});
  expect_near(s.x, {1, 0, 0});
  expect_near(s.y, {0, 0, 1});
  expect_near(s.size, {4, 3, 0});
  expect_near(s.origin, {0, 0, 0});
}

TEST(Scope, MakeFrameRejectsParallelAxes) {
  Vec3 x;
  Vec3 y;
  Vec3 z;
  EXPECT_FALSE(make_frame({0, 0, 2}, {0, 0, 1}, x, y, z));
  EXPECT_TRUE(make_frame({1, 0, 1}, {0, 0, 1}, x, y, z));
  expect_near(x, {1, 0, 0});
  expect_near(y, {0, 1, 0});
}

}  // namespace
}  // namespace insula::shape
