#include "kernel/mesh_unify.h"

#include <gtest/gtest.h>

#include <set>
#include <vector>

#include "kernel/solids.h"

namespace insula::kernel {
namespace {

const FaceTag kWall{SemanticClass::kWallSurface, 0, 0};

Mesh box(Vec3 origin, Vec3 size, FaceTag tag = kWall) {
  Mesh m;
  add_box(m, origin, {size.x, 0, 0}, {0, size.y, 0}, {0, 0, size.z}, tag);
  return m;
}

Mesh two_boxes(double gap) {
  Mesh m = box({0, 0, 0}, {1, 1, 1});
  m.append(box({1 + gap, 0, 0}, {1, 1, 1}));
  return m;
}

bool simple_loops(const Mesh& m) {
  for (std::size_t f = 0; f < m.face_count(); ++f) {
    const auto loop = m.face(f);
    if (std::set<std::uint32_t>(loop.begin(), loop.end()).size() != loop.size()) return false;
  }
  return true;
}

TEST(MeshUnify, TwoCubesSharingAFaceBecomeOneBoxOfSixQuads) {
  const Mesh merged = two_boxes(0);
  ASSERT_EQ(merged.face_count(), 12U);
  const Mesh u = unify(merged, 1e-3);
  EXPECT_EQ(u.face_count(), 6U);
  EXPECT_EQ(u.vertex_count(), 8U);
  for (std::size_t f = 0; f < u.face_count(); ++f) EXPECT_EQ(u.face(f).size(), 4U) << f;
  const MeshCheck c = check(u);
  EXPECT_TRUE(c.closed);
  EXPECT_EQ(c.euler_characteristic, 2);
  EXPECT_NEAR(volume(u), 2.0, 1e-12);
  EXPECT_NEAR(surface_area(u), 10.0, 1e-12);
  EXPECT_TRUE(is_watertight(u));
}

TEST(MeshUnify, VerticesWeldWithinTheTolerance) {
  // A gap of 0.4 mm closes at 1 mm (the first vertex wins, so the left box keeps its corners) and
  // stays open at 0.1 mm: twelve faces, the touching pair no longer the same cycle.
  const Mesh welded = unify(two_boxes(4e-4), 1e-3);
  EXPECT_EQ(welded.face_count(), 6U);
  EXPECT_NEAR(volume(welded), 2.0004, 1e-9);
  EXPECT_TRUE(check(welded).closed);
  const Mesh apart = unify(two_boxes(4e-4), 1e-4);
  EXPECT_EQ(apart.face_count(), 12U);
  EXPECT_EQ(apart.vertex_count(), 16U);
  EXPECT_EQ(check(apart).components, 2U);
}

TEST(MeshUnify, DuplicateFacesAreKeptOnceAndOppositeFacesCancel) {
  Mesh m = box({0, 0, 0}, {1, 1, 1});
  // Face 0 again, over its own vertices and with another material: the first one stays.
  std::vector<Vec3> loop;
  for (std::uint32_t v : m.face(0)) loop.push_back(m.position(v));
  const FaceTag first = m.tag(0);
  m.add_polygon(loop, {SemanticClass::kGroundSurface, 7, 9});
  const Mesh u = unify(m, 1e-3);
  EXPECT_EQ(u.face_count(), 6U);
  for (std::size_t f = 0; f < u.face_count(); ++f) EXPECT_EQ(u.tag(f).material, first.material);
  EXPECT_TRUE(check(u).closed);

  Mesh sheet;
  const std::vector<Vec3> square = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  sheet.add_polygon(square, kWall);
  sheet.add_polygon(std::vector<Vec3>(square.rbegin(), square.rend()), kWall);
  EXPECT_TRUE(unify(sheet, 1e-3).empty());
}

TEST(MeshUnify, FacesOfOtherTagsAreNotJoinedAndKeepTheirTags) {
  Mesh m = box({0, 0, 0}, {1, 1, 1});
  Mesh right = box({1, 0, 0}, {1, 1, 1});
  for (std::size_t f = 0; f < right.face_count(); ++f) {
    if (face_normal(right, f).z > 0.5) right.tag(f) = {SemanticClass::kRoofSurface, 3, 4};
  }
  m.append(right);
  const Mesh u = unify(m, 1e-3);
  // The top stays two faces; the other five sides join. Closed: the top's middle vertices stay in
  // the joined front and back faces (three neighbours each), so no T-junction appears.
  ASSERT_EQ(u.face_count(), 7U);
  std::size_t roofs = 0;
  for (std::size_t f = 0; f < u.face_count(); ++f) {
    if (u.tag(f).semantic == SemanticClass::kRoofSurface) {
      ++roofs;
      EXPECT_EQ(u.tag(f).material, 3);
      EXPECT_EQ(u.tag(f).face_id, 4U);
      EXPECT_NEAR(face_area(u, f), 1.0, 1e-12);
    }
  }
  EXPECT_EQ(roofs, 1U);
  EXPECT_TRUE(check(u).closed);
  EXPECT_NEAR(volume(u), 2.0, 1e-12);
}

TEST(MeshUnify, ARegionWithAHoleStaysSeveralHoleFreeFaces) {
  // Eight unit squares around a missing centre: one polygon would need a hole.
  Mesh ring;
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 3; ++x) {
      if (x == 1 && y == 1) continue;
      const std::vector<Vec3> square = {{double(x), double(y), 0},
                                        {double(x + 1), double(y), 0},
                                        {double(x + 1), double(y + 1), 0},
                                        {double(x), double(y + 1), 0}};
      ring.add_polygon(square, kWall);
    }
  }
  const Mesh u = unify(ring, 1e-3);
  EXPECT_EQ(u.face_count(), 2U);
  EXPECT_TRUE(simple_loops(u));
  EXPECT_NEAR(surface_area(u), 8.0, 1e-12);
  const MeshCheck c = check(u);
  EXPECT_TRUE(c.oriented);
  // The outer square's 4 corners, the hole's 4 and the 2 outer vertices where the faces meet.
  EXPECT_EQ(c.boundary_edges, 10U);
}

TEST(MeshUnify, DegenerateAndNonCoplanarFaces) {
  Mesh m;
  m.add_polygon(std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, kWall);
  // A sliver 0.1 mm wide along the quad's edge, and a face bent 1 cm out of the quad's plane.
  m.add_polygon(std::vector<Vec3>{{0, 0, 0}, {0.5, -1e-4, 0}, {1, 0, 0}}, kWall);
  m.add_polygon(std::vector<Vec3>{{1, 0, 0}, {2, 0, 0.01}, {2, 1, 0.01}, {1, 1, 0}}, kWall);
  const Mesh u = unify(m, 1e-3);
  EXPECT_EQ(u.face_count(), 2U);
  EXPECT_EQ(u.vertex_count(), 6U);
  // Within 2 cm the bent face is coplanar and joins.
  EXPECT_EQ(unify(m, 2e-2).face_count(), 1U);
}

TEST(MeshUnify, GroupsOfMeshesSharingEdges) {
  const auto quad = [](double x, double y) {
    Mesh m;
    m.add_polygon(std::vector<Vec3>{{x, y, 0}, {x + 1, y, 0}, {x + 1, y + 1, 0}, {x, y + 1, 0}},
                  kWall);
    return m;
  };
  // 0 and 2 share an edge through 3 (within 0.5 mm); 1 touches 0 only at a corner; 4 has no faces.
  const std::vector<Mesh> meshes = {quad(0, 0), quad(-1, 1), quad(2.0004, 0), quad(1, 0), Mesh{}};
  const std::vector<std::vector<std::size_t>> groups = group_by_shared_edges(meshes, 1e-3);
  const std::vector<std::vector<std::size_t>> expected = {{0, 2, 3}, {1}, {4}};
  EXPECT_EQ(groups, expected);
  const std::vector<std::vector<std::size_t>> strict = {{0, 3}, {1}, {2}, {4}};
  EXPECT_EQ(group_by_shared_edges(meshes, 1e-4), strict);
}

}  // namespace
}  // namespace insula::kernel
