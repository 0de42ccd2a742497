// FaceTriangulator: strictly convex faces take a shortcut that must give exactly the triangles of
// kernel::triangulate (so output does not depend on the path), concave faces stay right.
#include "io/triangulated.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "kernel/triangulate.h"

namespace insula::io {
namespace {

using kernel::Vec2;
using kernel::Vec3;

// A face of `corners` in the plane through `origin` spanned by `u` and `v` (right-handed).
kernel::Mesh planar_face(const std::vector<Vec2>& corners, Vec3 origin, Vec3 u, Vec3 v) {
  kernel::Mesh mesh;
  std::vector<std::uint32_t> loop;
  for (Vec2 c : corners) loop.push_back(mesh.add_vertex(origin + u * c.x + v * c.y));
  mesh.add_face(loop, {});
  return mesh;
}

std::vector<Vec2> regular(int n, double radius, double phase) {
  std::vector<Vec2> out;
  for (int k = 0; k < n; ++k) {
    const double a = phase + 2 * std::numbers::pi * k / n;
    out.push_back({radius * std::cos(a), radius * std::sin(a)});
  }
  return out;
}

// What kernel::triangulate makes of the face, in the same 2D frame (x along u, y along v).
std::vector<CornerTriangle> reference(const std::vector<Vec2>& corners) {
  kernel::Triangulation result;
  EXPECT_TRUE(kernel::triangulate(kernel::Polygon{corners, {}}, result));
  std::vector<CornerTriangle> out;
  for (const auto& t : result.triangles) out.push_back({t[0], t[1], t[2]});
  return out;
}

double area_2d(const std::vector<Vec2>& c, const std::vector<CornerTriangle>& triangles) {
  double total = 0;
  for (const auto& t : triangles)
    total += 0.5 * kernel::cross(c[t[1]] - c[t[0]], c[t[2]] - c[t[0]]);
  return total;
}

TEST(FaceTriangulator, ConvexFacesMatchTheKernelTriangulator) {
  FaceTriangulator triangulator;
  for (int n = 4; n <= 13; ++n) {
    const std::vector<Vec2> corners = regular(n, 7.5, 0.3 * n);
    // A wall far from the origin (normal -y projects to (x, z), the corners' own frame) and a
    // floor at the origin.
    const kernel::Mesh wall = planar_face(corners, {455000, 5428000, 12}, {1, 0, 0}, {0, 0, 1});
    const kernel::Mesh floor = planar_face(corners, {0, 0, 0}, {1, 0, 0}, {0, 1, 0});
    for (const kernel::Mesh* mesh : {&wall, &floor}) {
      std::vector<CornerTriangle> triangles;
      ASSERT_TRUE(triangulator.triangulate(*mesh, 0, kernel::face_normal(*mesh, 0), triangles));
      EXPECT_EQ(triangles, reference(corners)) << n;
      EXPECT_EQ(triangles.size(), static_cast<std::size_t>(n - 2)) << n;
      EXPECT_NEAR(area_2d(corners, triangles), kernel::signed_area(corners), 1e-9) << n;
    }
  }
}

TEST(FaceTriangulator, ConcaveAndStraightCornersUseTheKernel) {
  FaceTriangulator triangulator;
  const std::vector<std::vector<Vec2>> faces = {
      {{0, 0}, {6, 0}, {6, 2}, {2, 2}, {2, 5}, {0, 5}},  // L: reflex corner
      {{0, 0}, {2, 0}, {4, 0}, {4, 3}, {0, 3}},          // a vertex splitting an edge
  };
  for (const auto& corners : faces) {
    const kernel::Mesh mesh = planar_face(corners, {0, 0, 0}, {1, 0, 0}, {0, 1, 0});
    std::vector<CornerTriangle> triangles;
    ASSERT_TRUE(triangulator.triangulate(mesh, 0, kernel::face_normal(mesh, 0), triangles));
    EXPECT_EQ(triangles, reference(corners));
    EXPECT_NEAR(area_2d(corners, triangles), kernel::signed_area(corners), 1e-12);
  }
}

TEST(FaceTriangulator, DegenerateFacesGiveNothing) {
  FaceTriangulator triangulator;
  const kernel::Mesh line = planar_face({{0, 0}, {1, 0}, {2, 0}, {3, 0}}, {}, {1, 0, 0}, {0, 1, 0});
  std::vector<CornerTriangle> triangles;
  EXPECT_FALSE(triangulator.triangulate(line, 0, kernel::face_normal(line, 0), triangles));
  EXPECT_TRUE(triangles.empty());
}

}  // namespace
}  // namespace insula::io
