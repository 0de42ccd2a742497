#include "kernel/boolean3d.h"

#include <gtest/gtest.h>

namespace insula::kernel {
namespace {

// An axis-aligned box with outward quads; walls tagged WallSurface, top RoofSurface, bottom Ground.
Mesh box(Vec3 lo, Vec3 hi) {
  Mesh m;
  for (int i = 0; i < 8; ++i) {
    m.add_vertex({i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z});
  }
  const FaceTag wall{SemanticClass::kWallSurface, 0, 7};
  m.add_face({0, 2, 3, 1}, {SemanticClass::kGroundSurface, 0, 1});
  m.add_face({4, 5, 7, 6}, {SemanticClass::kRoofSurface, 0, 2});
  m.add_face({0, 1, 5, 4}, wall);
  m.add_face({1, 3, 7, 5}, wall);
  m.add_face({3, 2, 6, 7}, wall);
  m.add_face({2, 0, 4, 6}, wall);
  return m;
}

void expect_solid(const Boolean3dResult& r, double expected_volume) {
  ASSERT_EQ(r.status, Boolean3dStatus::kOk) << r.message;
  EXPECT_TRUE(r.message.empty());
  const MeshCheck c = check(r.mesh);
  EXPECT_TRUE(c.closed);
  EXPECT_EQ(c.euler_characteristic, 2);
  EXPECT_NEAR(volume(r.mesh), expected_volume, 1e-9);
}

TEST(Boolean3d, CubeMinusCube) {
  const Mesh a = box({0, 0, 0}, {2, 2, 2});
  const Mesh b = box({1, 1, 1}, {3, 3, 3});
  const Boolean3dResult r = boolean3d(a, b, BooleanOp::kDifference);
  expect_solid(r, 8 - 1);
}

TEST(Boolean3d, UnionOfOverlappingCubes) {
  const Boolean3dResult r =
      boolean3d(box({0, 0, 0}, {2, 2, 2}), box({1, 1, 1}, {3, 3, 3}), BooleanOp::kUnion);
  expect_solid(r, 8 + 8 - 1);
}

TEST(Boolean3d, IntersectionOfOverlappingCubes) {
  const Boolean3dResult r =
      boolean3d(box({0, 0, 0}, {2, 2, 2}), box({1, 1, 1}, {3, 3, 3}), BooleanOp::kIntersection);
  expect_solid(r, 1);
}

TEST(Boolean3d, TagsFollowTheInputFaces) {
  // A slot cut through the top of a box: the cut faces are b's walls (inside a), the rest a's.
  const Boolean3dResult r =
      boolean3d(box({0, 0, 0}, {4, 4, 2}), box({1, -1, 1}, {3, 5, 3}), BooleanOp::kDifference);
  expect_solid(r, 32 - 2 * 4 * 1);
  double roof_area = 0;
  double ground_area = 0;
  for (std::size_t f = 0; f < r.mesh.face_count(); ++f) {
    if (r.mesh.tag(f).semantic == SemanticClass::kRoofSurface) roof_area += face_area(r.mesh, f);
    if (r.mesh.tag(f).semantic == SemanticClass::kGroundSurface) {
      ground_area += face_area(r.mesh, f);
    }
  }
  EXPECT_NEAR(ground_area, 16 + 8, 1e-9);  // a's ground and b's bottom (the slot floor)
  EXPECT_NEAR(roof_area, 16 - 8, 1e-9);    // a's top minus the slot
}

TEST(Boolean3d, OpenOperandIsReported) {
  Mesh open = box({0, 0, 0}, {1, 1, 1});
  Mesh missing;
  for (const Vec3& p : open.positions()) missing.add_vertex(p);
  for (std::size_t f = 1; f < open.face_count(); ++f) missing.add_face(open.face(f), open.tag(f));
  const Boolean3dResult r = boolean3d(box({0, 0, 0}, {1, 1, 1}), missing, BooleanOp::kUnion);
  EXPECT_EQ(r.status, Boolean3dStatus::kNotClosed);
  EXPECT_EQ(r.message, "second operand is not a closed, oriented 2-manifold");
  EXPECT_TRUE(r.mesh.empty());
}

TEST(Boolean3d, InsideOutOperandIsReported) {
  Mesh flipped = box({0, 0, 0}, {1, 1, 1});
  flipped.flip();
  const Boolean3dResult r = boolean3d(flipped, box({0, 0, 0}, {1, 1, 1}), BooleanOp::kUnion);
  EXPECT_EQ(r.status, Boolean3dStatus::kNotAVolume);
  EXPECT_EQ(r.message, "first operand does not bound a volume");
}

TEST(Boolean3d, SelfIntersectingOperandIsReported) {
  Mesh two = box({0, 0, 0}, {2, 2, 2});
  two.append(box({1, 1, 1}, {3, 3, 3}));  // two overlapping shells in one mesh
  const Boolean3dResult r = boolean3d(two, box({5, 5, 5}, {6, 6, 6}), BooleanOp::kUnion);
  EXPECT_EQ(r.status, Boolean3dStatus::kSelfIntersecting);
  EXPECT_EQ(r.message, "first operand intersects itself");
}

}  // namespace
}  // namespace insula::kernel
