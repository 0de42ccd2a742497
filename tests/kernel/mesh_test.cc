#include "kernel/mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace insula::kernel {
namespace {

// A unit cube with outward faces sharing 8 vertices.
Mesh unit_cube() {
  Mesh m;
  for (int i = 0; i < 8; ++i)
    m.add_vertex({double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
  const FaceTag wall{SemanticClass::kWallSurface, 0, 0};
  m.add_face({0, 2, 3, 1}, {SemanticClass::kGroundSurface, 0, 1});
  m.add_face({4, 5, 7, 6}, {SemanticClass::kRoofSurface, 0, 2});
  m.add_face({0, 1, 5, 4}, wall);
  m.add_face({1, 3, 7, 5}, wall);
  m.add_face({3, 2, 6, 7}, wall);
  m.add_face({2, 0, 4, 6}, wall);
  return m;
}

TEST(Mesh, CubeIsClosedWithUnitVolumeAndEulerTwo) {
  const Mesh cube = unit_cube();
  const MeshCheck c = check(cube);
  EXPECT_TRUE(c.closed);
  EXPECT_EQ(c.euler_characteristic, 2);
  EXPECT_EQ(c.components, 1U);
  EXPECT_NEAR(volume(cube), 1.0, 1e-12);
  EXPECT_NEAR(surface_area(cube), 6.0, 1e-12);
  EXPECT_EQ(cube.triangle_count(), 12U);
  EXPECT_TRUE(is_watertight(cube));
}

// The same cube numbered differently (vertices reversed, faces reversed in order, loops rotated)
// gives the same canonical mesh, and the canonical mesh is still the closed unit cube.
TEST(Mesh, CanonicalOrderDependsOnlyOnGeometry) {
  const Mesh cube = unit_cube();
  Mesh shuffled;
  for (int i = 7; i >= 0; --i) shuffled.add_vertex(cube.position(static_cast<std::uint32_t>(i)));
  for (std::size_t f = cube.face_count(); f-- > 0;) {
    std::vector<std::uint32_t> loop;
    for (std::uint32_t v : cube.face(f)) loop.push_back(7 - v);
    std::rotate(loop.begin(), loop.begin() + 1, loop.end());
    shuffled.add_face(loop, cube.tag(f));
  }
  const Mesh a = canonical_order(cube);
  const Mesh b = canonical_order(shuffled);
  ASSERT_EQ(a.vertex_count(), 8U);
  ASSERT_EQ(a.face_count(), b.face_count());
  for (std::uint32_t v = 0; v < 8; ++v) {
    EXPECT_EQ(a.position(v).x, b.position(v).x);
    EXPECT_EQ(a.position(v).y, b.position(v).y);
    EXPECT_EQ(a.position(v).z, b.position(v).z);
  }
  for (std::size_t f = 0; f < a.face_count(); ++f) {
    const auto fa = a.face(f);
    const auto fb = b.face(f);
    EXPECT_TRUE(std::equal(fa.begin(), fa.end(), fb.begin(), fb.end())) << f;
    EXPECT_EQ(a.tag(f).semantic, b.tag(f).semantic);
  }
  EXPECT_EQ(a.position(0).x + a.position(0).y + a.position(0).z, 0.0);  // (0,0,0) first
  EXPECT_TRUE(is_watertight(a));
  EXPECT_NEAR(volume(a), 1.0, 1e-12);
}

TEST(Mesh, FlippedCubeHasNegativeVolume) {
  Mesh cube = unit_cube();
  cube.flip();
  EXPECT_NEAR(volume(cube), -1.0, 1e-12);
  EXPECT_TRUE(check(cube).closed);
  EXPECT_FALSE(is_watertight(cube));
}

TEST(Mesh, MissingFaceLeavesFourBoundaryEdges) {
  const Mesh cube = unit_cube();
  Mesh open;
  for (Vec3 p : cube.positions()) open.add_vertex(p);
  for (std::size_t f = 1; f < cube.face_count(); ++f) open.add_face(cube.face(f), cube.tag(f));
  const MeshCheck c = check(open);
  EXPECT_FALSE(c.closed);
  EXPECT_EQ(c.boundary_edges, 4U);
  EXPECT_EQ(c.euler_characteristic, 1);
}

TEST(Mesh, WeldJoinsSeparatePolygonsIntoAClosedShell) {
  const Mesh cube = unit_cube();
  Mesh soup;
  for (std::size_t f = 0; f < cube.face_count(); ++f) {
    std::vector<Vec3> loop;
    for (auto v : cube.face(f)) loop.push_back(cube.position(v) + Vec3{1e-9, 0, 0});
    soup.add_polygon(loop, cube.tag(f));
  }
  EXPECT_FALSE(check(soup).closed);
  const Mesh welded = weld(soup, 1e-6);
  EXPECT_EQ(welded.vertex_count(), 8U);
  EXPECT_TRUE(check(welded).closed);
  EXPECT_TRUE(is_watertight(soup, 1e-6));
}

TEST(Mesh, FaceNormalPointsOutOfTheRoof) {
  const Mesh cube = unit_cube();
  const Vec3 n = face_normal(cube, 1);
  EXPECT_NEAR(n.z, 1.0, 1e-12);
  EXPECT_EQ(cube.tag(1).semantic, SemanticClass::kRoofSurface);
}

}  // namespace
}  // namespace insula::kernel
