#include "kernel/convex_hull.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace insula::kernel {
namespace {

std::vector<Vec3> cube_corners() {
  std::vector<Vec3> points;
  for (int i = 0; i < 8; ++i)
    points.push_back({double(i & 1), double((i >> 1) & 1), double(i >> 2)});
  return points;
}

void expect_convex_solid(const Mesh& mesh) {
  const MeshCheck c = check(mesh);
  EXPECT_TRUE(c.closed);
  EXPECT_EQ(c.euler_characteristic, 2);
  EXPECT_EQ(c.components, 1U);
  EXPECT_TRUE(is_watertight(mesh));
  // Convex: every vertex lies behind (or on) every face's plane.
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const Vec3 n = face_normal(mesh, f);
    const Vec3 on = mesh.position(mesh.face(f)[0]);
    for (Vec3 p : mesh.positions()) EXPECT_LE(dot(p - on, n), 1e-9);
  }
}

TEST(ConvexHull2d, SquareWithInteriorAndCollinearPoints) {
  const std::vector<Vec2> points{{1, 1}, {0, 0}, {2, 0},     {1, 0}, {2, 2},
                                 {0, 2}, {0, 1}, {0.5, 1.5}, {2, 2}};
  const Hull2Result r = convex_hull_2d(points);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.ring, (Ring{{0, 0}, {2, 0}, {2, 2}, {0, 2}}));
  EXPECT_NEAR(signed_area(r.ring), 4, 1e-12);
}

TEST(ConvexHull2d, DegenerateInput) {
  const std::vector<Vec2> line{{0, 0}, {1, 1}, {2, 2}, {3, 3}};
  EXPECT_EQ(convex_hull_2d(line).status, HullStatus::kCollinear);
  const std::vector<Vec2> two{{0, 0}, {1, 1}, {0, 0}};
  EXPECT_EQ(convex_hull_2d(two).status, HullStatus::kTooFewPoints);
  EXPECT_EQ(convex_hull_2d({}).status, HullStatus::kTooFewPoints);
  const std::vector<Vec2> bad{{0, 0}, {1, NAN}, {0, 1}};
  EXPECT_EQ(convex_hull_2d(bad).status, HullStatus::kNonFinite);
  EXPECT_TRUE(convex_hull_2d(line).ring.empty());
}

TEST(ConvexHull2d, RandomPointsAreAllInside) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-5, 5);
  std::vector<Vec2> points(500);
  for (Vec2& p : points) p = {u(rng), u(rng)};
  const Hull2Result r = convex_hull_2d(points);
  ASSERT_TRUE(r.ok());
  EXPECT_GT(signed_area(r.ring), 0);
  for (std::size_t i = 0; i < r.ring.size(); ++i) {
    const Vec2 a = r.ring[i];
    const Vec2 b = r.ring[(i + 1) % r.ring.size()];
    for (Vec2 p : points) EXPECT_GE(cross(b - a, p - a), -1e-12);
  }
}

TEST(MinAreaRectangle, LongerSideOfATurnedRectangleWithInteriorPoints) {
  // A 10 x 4 rectangle turned by 30 degrees, listed from a short side, with points inside.
  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
  const Vec2 along{c, s}, across{-s, c};
  std::vector<Vec2> points;
  for (const Vec2 q : {Vec2{0, 0}, Vec2{0, 4}, Vec2{10, 4}, Vec2{10, 0}, Vec2{3, 1}, Vec2{7, 2}}) {
    points.push_back(along * q.x + across * q.y);
  }
  const std::optional<Vec2> d = min_area_rectangle_direction(points);
  ASSERT_TRUE(d.has_value());
  EXPECT_NEAR(std::fabs(dot(*d, along)), 1, 1e-12);
  EXPECT_FALSE(min_area_rectangle_direction(std::vector<Vec2>{{1, 1}}).has_value());
}

TEST(ConvexHull3d, CubeCornersAndInteriorPointsMergeToSixFaces) {
  std::vector<Vec3> points = cube_corners();
  points.push_back({0.5, 0.5, 0.5});
  points.push_back({0.2, 0.7, 0.1});
  points.push_back({0.5, 0.5, 1});  // on the top face
  points.push_back({1, 0.5, 0});    // on an edge
  const Hull3Result r = convex_hull_3d(points);
  ASSERT_TRUE(r.ok()) << hull_status_message(r.status);
  expect_convex_solid(r.mesh);
  EXPECT_NEAR(volume(r.mesh), 1, 1e-12);
  EXPECT_EQ(r.mesh.face_count(), 6U);
  EXPECT_EQ(r.mesh.vertex_count(), 8U);
  for (std::size_t f = 0; f < 6; ++f) {
    EXPECT_EQ(r.mesh.face(f).size(), 4U);
    EXPECT_NEAR(face_area(r.mesh, f), 1, 1e-12);
    EXPECT_EQ(r.mesh.tag(f).face_id, f);
  }
}

TEST(ConvexHull3d, TrianglesWhenNotMerging) {
  HullOptions options;
  options.merge_coplanar = false;
  options.tag = {SemanticClass::kWallSurface, 2, 100};
  std::vector<Vec3> points = cube_corners();
  points.push_back({0.5, 0.5, 0.5});
  const Hull3Result r = convex_hull_3d(points, options);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.mesh.face_count(), 12U);
  EXPECT_NEAR(volume(r.mesh), 1, 1e-12);
  EXPECT_TRUE(check(r.mesh).closed);
  EXPECT_EQ(r.mesh.tag(11).face_id, 111U);
  EXPECT_EQ(r.mesh.tag(0).semantic, SemanticClass::kWallSurface);
}

TEST(ConvexHull3d, RandomSphereSamplesContainEveryPoint) {
  std::mt19937 rng(11);
  std::normal_distribution<double> g(0, 1);
  std::vector<Vec3> points;
  for (int i = 0; i < 2000; ++i) {
    const Vec3 d = normalized(Vec3{g(rng), g(rng), g(rng)});
    points.push_back(d * (i % 3 == 0 ? 0.5 : 1.0) + Vec3{100, -20, 3});
  }
  const Hull3Result r = convex_hull_3d(points);
  ASSERT_TRUE(r.ok());
  expect_convex_solid(r.mesh);
  const double sphere = 4.0 / 3 * M_PI;
  EXPECT_LT(volume(r.mesh), sphere);
  EXPECT_GT(volume(r.mesh), 0.95 * sphere);
}

TEST(ConvexHull3d, RotatedBoxFarFromOrigin) {
  // A 3 x 2 x 1 box turned 30 degrees about z, 500 km from the origin (projected coordinates).
  std::vector<Vec3> points;
  const double c = std::cos(M_PI / 6);
  const double s = std::sin(M_PI / 6);
  for (Vec3 q : cube_corners()) {
    const Vec3 p{q.x * 3, q.y * 2, q.z};
    points.push_back({500000 + c * p.x - s * p.y, 4000000 + s * p.x + c * p.y, p.z});
  }
  const Hull3Result r = convex_hull_3d(points);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.mesh.face_count(), 6U);
  EXPECT_NEAR(volume(r.mesh), 6, 1e-6);
  EXPECT_TRUE(check(r.mesh).closed);
}

TEST(ConvexHull3d, DegenerateInputHasAStatus) {
  EXPECT_EQ(convex_hull_3d({}).status, HullStatus::kTooFewPoints);
  const std::vector<Vec3> three{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  EXPECT_EQ(convex_hull_3d(three).status, HullStatus::kTooFewPoints);
  const std::vector<Vec3> same(10, Vec3{1, 2, 3});
  EXPECT_EQ(convex_hull_3d(same).status, HullStatus::kTooFewPoints);
  const std::vector<Vec3> line{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}, {0.5, 0.5, 0.5}};
  EXPECT_EQ(convex_hull_3d(line).status, HullStatus::kCollinear);
  const std::vector<Vec3> flat{{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}, {0.5, 0.5, 1}};
  EXPECT_EQ(convex_hull_3d(flat).status, HullStatus::kCoplanar);
  const std::vector<Vec3> bad{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, INFINITY}};
  EXPECT_EQ(convex_hull_3d(bad).status, HullStatus::kNonFinite);
  EXPECT_TRUE(convex_hull_3d(flat).mesh.empty());
  EXPECT_EQ(hull_status_message(HullStatus::kCoplanar), "all points lie in one plane");
}

TEST(ConvexHull3d, TetrahedronAndDuplicates) {
  std::vector<Vec3> points{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  points.insert(points.end(), points.begin(), points.end());
  const Hull3Result r = convex_hull_3d(points);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.mesh.face_count(), 4U);
  EXPECT_EQ(r.mesh.vertex_count(), 4U);
  EXPECT_NEAR(volume(r.mesh), 1.0 / 6, 1e-12);
}

TEST(ConvexHull3d, GridPointsWithManyCoplanarOnes) {
  // A 5 x 5 x 5 lattice: most points lie on hull faces or edges; the hull is still the cube.
  std::vector<Vec3> points;
  for (int i = 0; i < 125; ++i)
    points.push_back({double(i % 5), double(i / 5 % 5), double(i / 25)});
  const Hull3Result r = convex_hull_3d(points);
  ASSERT_TRUE(r.ok()) << hull_status_message(r.status);
  expect_convex_solid(r.mesh);
  EXPECT_NEAR(volume(r.mesh), 64, 1e-9);
  EXPECT_EQ(r.mesh.face_count(), 6U);
}

}  // namespace
}  // namespace insula::kernel
