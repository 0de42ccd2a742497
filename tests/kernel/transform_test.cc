#include "kernel/transform.h"

#include <gtest/gtest.h>

namespace insula::kernel {
namespace {

void expect_near(Vec3 actual, Vec3 expected, double tolerance = 1e-12) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
  EXPECT_NEAR(actual.z, expected.z, tolerance);
}

Mesh unit_cube() {
  Mesh m;
  for (int i = 0; i < 8; ++i) {
    m.add_vertex({double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
  }
  m.add_face({0, 2, 3, 1}, {SemanticClass::kGroundSurface, 0, 0});
  m.add_face({4, 5, 7, 6}, {SemanticClass::kRoofSurface, 0, 1});
  m.add_face({0, 1, 5, 4}, {SemanticClass::kWallSurface, 0, 2});
  m.add_face({1, 3, 7, 5}, {SemanticClass::kWallSurface, 0, 3});
  m.add_face({3, 2, 6, 7}, {SemanticClass::kWallSurface, 0, 4});
  m.add_face({2, 0, 4, 6}, {SemanticClass::kWallSurface, 0, 5});
  return m;
}

TEST(Transform, QuarterTurnsAreExact) {
  const Transform r = rotation({0, 0, 1}, 90);
  EXPECT_EQ(apply_point(r, {1, 0, 0}), (Vec3{0, 1, 0}));
  EXPECT_EQ(apply_point(r, {0, 1, 5}), (Vec3{-1, 0, 5}));
  EXPECT_EQ(apply_point(rotation({0, 0, 1}, -270), {1, 0, 0}), (Vec3{0, 1, 0}));
  EXPECT_EQ(apply_point(rotation({1, 0, 0}, 180), {0, 1, 0}), (Vec3{0, -1, 0}));
  EXPECT_EQ(apply_point(rotation({0, 1, 0}, 90), {0, 0, 1}), (Vec3{1, 0, 0}));
}

TEST(Transform, RotationAboutDiagonalCyclesAxes) {
  // 120 degrees about (1,1,1) maps x -> y -> z -> x.
  const Transform r = rotation({1, 1, 1}, 120);
  expect_near(apply_vector(r, {1, 0, 0}), {0, 1, 0});
  expect_near(apply_vector(r, {0, 1, 0}), {0, 0, 1});
  EXPECT_NEAR(determinant(r), 1.0, 1e-12);
}

TEST(Transform, RotationAboutPivotKeepsPivot) {
  const Transform r = rotation_about({2, 3, 0}, {0, 0, 1}, 90);
  EXPECT_EQ(apply_point(r, {2, 3, 7}), (Vec3{2, 3, 7}));
  EXPECT_EQ(apply_point(r, {3, 3, 0}), (Vec3{2, 4, 0}));
}

TEST(Transform, ComposeAppliesInnerFirst) {
  const Transform t = translation({10, 0, 0});
  const Transform s = scaling({2, 3, 4});
  EXPECT_EQ(apply_point(t * s, {1, 1, 1}), (Vec3{12, 3, 4}));
  EXPECT_EQ(apply_point(s * t, {1, 1, 1}), (Vec3{22, 3, 4}));
  EXPECT_EQ(apply_vector(t * s, {1, 1, 1}), (Vec3{2, 3, 4}));
}

TEST(Transform, InverseUndoesGeneralAffineMap) {
  const Transform m = translation({1, -2, 3}) * rotation({0.3, -1, 2}, 37) * scaling({2, 0.5, -3});
  const auto inv = inverse(m);
  ASSERT_TRUE(inv.has_value());
  const Vec3 p{0.25, 7, -4};
  expect_near(apply_point(*inv, apply_point(m, p)), p, 1e-12);
  expect_near(apply_point(m * *inv, p), p, 1e-12);
  EXPECT_NEAR(determinant(m) * determinant(*inv), 1.0, 1e-12);
  EXPECT_NEAR(determinant(m), -3.0, 1e-12);
}

TEST(Transform, SingularOrNonFiniteHasNoInverse) {
  EXPECT_FALSE(inverse(scaling({1, 0, 1})).has_value());
  EXPECT_FALSE(inverse(translation({NAN, 0, 0})).has_value());
  EXPECT_TRUE(inverse(identity_transform()).has_value());
}

TEST(Transform, ZeroAxisRotationIsIdentity) {
  EXPECT_EQ(rotation({0, 0, 0}, 45), identity_transform());
}

TEST(Transform, FrameMapsUnitCornerOntoScopeCorner) {
  // A scope with origin P, axes X Y Z and size S: local (1,1,1) is its far corner.
  const Transform scope = frame({5, 5, 0}, Vec3{0, 1, 0} * 4, Vec3{0, 0, 1} * 3, Vec3{1, 0, 0} * 2);
  EXPECT_EQ(apply_point(scope, {1, 1, 1}), (Vec3{7, 9, 3}));
  EXPECT_NEAR(determinant(scope), 24.0, 1e-12);
}

TEST(Transform, NormalsUseInverseTranspose) {
  // A shear maps the plane x = y onto a plane whose normal is not the sheared normal.
  const Transform shear{{1, 0, 0}, {1, 1, 0}, {0, 0, 1}, {}};
  const Vec3 n = apply_normal(shear, normalized(Vec3{1, -1, 0}));
  const Vec3 a = apply_vector(shear, {1, 1, 0});
  const Vec3 b = apply_vector(shear, {0, 0, 1});
  EXPECT_NEAR(dot(n, a), 0.0, 1e-12);
  EXPECT_NEAR(dot(n, b), 0.0, 1e-12);
  EXPECT_NEAR(length(n), 1.0, 1e-12);
  // Mirroring keeps an outward normal outward: the +x normal of a face at x = 1 maps to -x.
  expect_near(apply_normal(scaling({-1, 1, 1}), {1, 0, 0}), {-1, 0, 0});
}

TEST(Transform, MeshTransformScalesVolumeAndKeepsTags) {
  const Mesh cube = unit_cube();
  const Mesh moved = transformed(cube, translation({1, 2, 3}) * scaling({2, 3, 4}));
  EXPECT_NEAR(volume(moved), 24.0, 1e-12);
  EXPECT_TRUE(is_watertight(moved));
  EXPECT_EQ(moved.tag(1).semantic, SemanticClass::kRoofSurface);
  expect_near(face_normal(moved, 1), {0, 0, 1});
  EXPECT_EQ(moved.bounds().min, (Vec3{1, 2, 3}));
}

TEST(Transform, MirrorFlipsFacesToStayOutward) {
  const Mesh mirrored = transformed(unit_cube(), scaling({-1, 1, 1}));
  EXPECT_NEAR(volume(mirrored), 1.0, 1e-12);
  EXPECT_TRUE(check(mirrored).closed);
  EXPECT_TRUE(is_watertight(mirrored));
  // The bottom face still faces down.
  expect_near(face_normal(mirrored, 0), {0, 0, -1});
}

}  // namespace
}  // namespace insula::kernel
