#include "kernel/plane_split.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "kernel/extrude.h"
#include "kernel/transform.h"

namespace insula::kernel {
namespace {

constexpr FaceTag kCap{SemanticClass::kClosureSurface, 7, 99};

Ring rect(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

Mesh prism(const Polygon& footprint, double height) {
  ExtrudeResult r = extrude(footprint, 0, height);
  EXPECT_TRUE(r.ok()) << extrude_status_message(r.status);
  return std::move(r.mesh);
}

Mesh unit_cube() {
  return prism({rect(0, 0, 1, 1), {}}, 1);
}

// U opening towards +y: arms x in [0,3] and [6,9] for y in [2,6], base y in [0,2].
Mesh u_prism() {
  return prism({{{0, 0}, {9, 0}, {9, 6}, {6, 6}, {6, 2}, {3, 2}, {3, 6}, {0, 6}}, {}}, 4);
}

Mesh courtyard_prism() {
  Ring hole = rect(3, 3, 7, 7);
  std::reverse(hole.begin(), hole.end());
  return prism({rect(0, 0, 10, 10), {hole}}, 2);
}

SplitOptions capped() {
  SplitOptions options;
  options.cap_tag = kCap;
  return options;
}

struct Solid {
  int euler;
  std::size_t components;
  double volume;
};

void expect_solid(const Mesh& mesh, Solid expected) {
  const MeshCheck c = check(mesh);
  EXPECT_TRUE(c.closed) << "boundary " << c.boundary_edges << " non-manifold "
                        << c.non_manifold_edges;
  EXPECT_EQ(c.euler_characteristic, expected.euler);
  EXPECT_EQ(c.components, expected.components);
  EXPECT_NEAR(volume(mesh), expected.volume, 1e-9);
}

std::size_t count_tag(const Mesh& mesh, SemanticClass semantic) {
  std::size_t n = 0;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) n += mesh.tag(f).semantic == semantic;
  return n;
}

TEST(PlaneSplit, CubeCutBelowTheMiddle) {
  const SplitResult r = split(unit_cube(), {{0, 0, 1}, 0.25}, capped());
  ASSERT_TRUE(r.ok()) << split_status_message(r.status);
  expect_solid(r.negative, {2, 1, 0.25});
  expect_solid(r.positive, {2, 1, 0.75});
  EXPECT_TRUE(is_watertight(r.negative));
  EXPECT_TRUE(is_watertight(r.positive));
  EXPECT_EQ(r.negative.face_count(), 6U);
  EXPECT_EQ(r.cap_loops, 2U);
  // Tags carried over: the ground stays below, walls keep their ids, the cap gets the given tag.
  EXPECT_EQ(count_tag(r.negative, SemanticClass::kGroundSurface), 1U);
  EXPECT_EQ(count_tag(r.negative, SemanticClass::kRoofSurface), 0U);
  EXPECT_EQ(count_tag(r.positive, SemanticClass::kRoofSurface), 1U);
  EXPECT_EQ(count_tag(r.negative, SemanticClass::kWallSurface), 4U);
  for (std::size_t f = 0; f < r.negative.face_count(); ++f) {
    const FaceTag& tag = r.negative.tag(f);
    if (tag.semantic == SemanticClass::kClosureSurface) {
      EXPECT_EQ(tag.face_id, 99U);
      EXPECT_EQ(tag.material, 7);
      EXPECT_NEAR(face_normal(r.negative, f).z, 1.0, 1e-12);
      EXPECT_NEAR(face_area(r.negative, f), 1.0, 1e-12);
    }
    if (tag.semantic == SemanticClass::kWallSurface) {
      EXPECT_GE(tag.face_id, 2U);
      EXPECT_NEAR(face_area(r.negative, f), 0.25, 1e-12);
    }
  }
  EXPECT_EQ(count_tag(r.positive, SemanticClass::kClosureSurface), 1U);
}

TEST(PlaneSplit, DiagonalCutThroughEdgesGivesTwoTriangularPrisms) {
  // x + y = 1 passes exactly through two vertical edges of the cube.
  const SplitResult r = split(unit_cube(), {{1, 1, 0}, 1}, capped());
  ASSERT_TRUE(r.ok());
  expect_solid(r.negative, {2, 1, 0.5});
  expect_solid(r.positive, {2, 1, 0.5});
  EXPECT_EQ(r.negative.face_count(), 5U);
  EXPECT_EQ(r.positive.face_count(), 5U);
  EXPECT_EQ(r.negative.vertex_count(), 6U);
}

TEST(PlaneSplit, PlaneOnAFaceLeavesTheSolidWhole) {
  const SplitResult top = split(unit_cube(), {{0, 0, 1}, 1}, capped());
  ASSERT_TRUE(top.ok());
  expect_solid(top.negative, {2, 1, 1});
  EXPECT_EQ(top.negative.face_count(), 6U);
  EXPECT_TRUE(top.positive.empty());
  EXPECT_EQ(top.cap_loops, 0U);
  const SplitResult bottom = split(unit_cube(), {{0, 0, 1}, 0}, capped());
  EXPECT_TRUE(bottom.negative.empty());
  EXPECT_EQ(bottom.positive.face_count(), 6U);
  const SplitResult away = split(unit_cube(), {{0, 0, -1}, 5}, capped());
  EXPECT_TRUE(away.negative.empty() != away.positive.empty());
  EXPECT_EQ(away.negative.face_count(), 6U);  // -z <= 5 everywhere
}

TEST(PlaneSplit, UPrismCutThroughBothArms) {
  // y = 4 crosses both arms: the far side is two separate blocks.
  const SplitResult r = split(u_prism(), {{0, 1, 0}, 4}, capped());
  ASSERT_TRUE(r.ok()) << split_status_message(r.status);
  expect_solid(r.negative, {2, 1, (18 + 12) * 4});
  expect_solid(r.positive, {4, 2, 12 * 4});
  EXPECT_EQ(r.cap_loops, 4U);
  // The non-convex U-shaped caps were each cut into three pieces (base side one, arms two).
  EXPECT_EQ(count_tag(r.negative, SemanticClass::kRoofSurface), 1U);
  EXPECT_EQ(count_tag(r.positive, SemanticClass::kRoofSurface), 2U);
  EXPECT_EQ(count_tag(r.positive, SemanticClass::kClosureSurface), 2U);
}

TEST(PlaneSplit, UPrismCutHorizontally) {
  const SplitResult r = split(u_prism(), {{0, 0, 1}, 1.5}, capped());
  ASSERT_TRUE(r.ok());
  expect_solid(r.negative, {2, 1, 42 * 1.5});
  expect_solid(r.positive, {2, 1, 42 * 2.5});
  // The cap is one non-convex octagon.
  for (std::size_t f = 0; f < r.negative.face_count(); ++f) {
    if (r.negative.tag(f).semantic == SemanticClass::kClosureSurface) {
      EXPECT_EQ(r.negative.face(f).size(), 8U);
      EXPECT_NEAR(face_area(r.negative, f), 42, 1e-9);
    }
  }
}

TEST(PlaneSplit, CourtyardCutHorizontallyHasCapsWithHoles) {
  const SplitResult r = split(courtyard_prism(), {{0, 0, 1}, 0.5}, capped());
  ASSERT_TRUE(r.ok()) << split_status_message(r.status);
  expect_solid(r.negative, {0, 1, 84 * 0.5});
  expect_solid(r.positive, {0, 1, 84 * 1.5});
  EXPECT_EQ(r.cap_loops, 4U);
  double cap_area = 0;
  for (std::size_t f = 0; f < r.positive.face_count(); ++f) {
    if (r.positive.tag(f).semantic != SemanticClass::kClosureSurface) continue;
    cap_area += face_area(r.positive, f);
    EXPECT_NEAR(face_normal(r.positive, f).z, -1.0, 1e-12);
  }
  EXPECT_NEAR(cap_area, 84, 1e-9);
}

TEST(PlaneSplit, CourtyardCutVerticallyThroughTheHoleGivesTwoUs) {
  const SplitResult r = split(courtyard_prism(), {{1, 0, 0}, 5}, capped());
  ASSERT_TRUE(r.ok());
  expect_solid(r.negative, {2, 1, 42 * 2});
  expect_solid(r.positive, {2, 1, 42 * 2});
  EXPECT_EQ(count_tag(r.negative, SemanticClass::kClosureSurface), 2U);
}

TEST(PlaneSplit, CoplanarStepFaceStaysWithThePartItBounds) {
  // An L profile in the XZ plane: a 2 x 1 x 1 block with a 1 x 1 x 1 block on its left half. The
  // block's top at z = 1 right of x = 1 lies in the cutting plane.
  Mesh l = prism({{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, {}}, 1);
  transform_mesh(l, rotation({1, 0, 0}, 90));
  ASSERT_NEAR(volume(l), 3, 1e-12);
  const SplitResult r = split(l, {{0, 0, 1}, 1}, capped());
  ASSERT_TRUE(r.ok());
  expect_solid(r.negative, {2, 1, 2});
  expect_solid(r.positive, {2, 1, 1});
  double cap_area = 0;
  double step_area = 0;
  for (std::size_t f = 0; f < r.negative.face_count(); ++f) {
    if (face_normal(r.negative, f).z < 0.5) continue;
    (r.negative.tag(f).semantic == SemanticClass::kClosureSurface ? cap_area : step_area) +=
        face_area(r.negative, f);
  }
  EXPECT_NEAR(cap_area, 1, 1e-12);
  EXPECT_NEAR(step_area, 1, 1e-12);
}

TEST(PlaneSplit, VertexOnThePlaneSplitsOctahedronAtItsEquator) {
  Mesh m;
  const Vec3 p[6] = {{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (Vec3 v : p) m.add_vertex(v);
  for (std::uint32_t i = 0; i < 4; ++i) {
    m.add_face({i, (i + 1) % 4, 4}, {SemanticClass::kRoofSurface, 0, i});
    m.add_face({(i + 1) % 4, i, 5}, {SemanticClass::kGroundSurface, 0, 4 + i});
  }
  ASSERT_NEAR(volume(m), 4.0 / 3, 1e-12);
  const SplitResult r = split(m, {{0, 0, 1}, 1e-9}, capped());
  ASSERT_TRUE(r.ok());
  expect_solid(r.negative, {2, 1, 2.0 / 3});
  expect_solid(r.positive, {2, 1, 2.0 / 3});
  EXPECT_EQ(r.positive.face_count(), 5U);
}

TEST(PlaneSplit, PinchedCrossSectionSplitsIntoLobes) {
  // A V notch from the south whose apex (2, 1) touches the plane y = 1.
  const Mesh notch = prism({{{0, 0}, {1, 0}, {2, 1}, {3, 0}, {4, 0}, {4, 2}, {0, 2}}, {}}, 1);
  const SplitResult r = split(notch, {{0, 1, 0}, 1}, capped());
  EXPECT_NEAR(volume(r.negative) + volume(r.positive), volume(notch), 1e-9);
  EXPECT_NEAR(volume(r.positive), 4, 1e-9);
  expect_solid(r.positive, {2, 1, 4});
  // Below: two prisms meeting along the apex edge; the cut faces fall into their two lobes, the
  // cap is one rectangle over both (the apex edge lies on its boundary).
  EXPECT_TRUE(check(r.negative).closed);
  EXPECT_EQ(check(r.negative).components, 1U);
  EXPECT_NEAR(volume(r.negative), 3, 1e-9);
  EXPECT_EQ(count_tag(r.negative, SemanticClass::kRoofSurface), 2U);
  EXPECT_EQ(count_tag(r.negative, SemanticClass::kGroundSurface), 2U);
  for (std::size_t f = 0; f < r.negative.face_count(); ++f) {
    if (r.negative.tag(f).semantic != SemanticClass::kClosureSurface) continue;
    EXPECT_NEAR(face_area(r.negative, f), 4, 1e-12);
    EXPECT_EQ(r.negative.face(f).size(), 6U);
  }
  EXPECT_EQ(count_tag(r.negative, SemanticClass::kClosureSurface), 1U);
}

TEST(PlaneSplit, ObliqueCutsConserveVolume) {
  const Mesh solids[] = {unit_cube(), u_prism(), courtyard_prism()};
  for (const Mesh& m : solids) {
    const Bounds3 b = m.bounds();
    const Vec3 center = (b.min + b.max) / 2;
    for (Vec3 n : {Vec3{0.3, -0.2, 1}, Vec3{1, 2, 0.5}, Vec3{-1, 0.1, 0.05}}) {
      const SplitResult r = split(m, {n, dot(n, center) + 0.1}, capped());
      ASSERT_TRUE(r.ok()) << split_status_message(r.status);
      EXPECT_NEAR(volume(r.negative) + volume(r.positive), volume(m), 1e-9);
      EXPECT_TRUE(check(r.negative).closed);
      EXPECT_TRUE(check(r.positive).closed);
      EXPECT_GT(volume(r.negative), 0);
      EXPECT_GT(volume(r.positive), 0);
    }
  }
}

// Star-shaped prisms (some with a hole, some tilted) cut by axis-aligned planes, planes through a
// vertex and oblique planes: both parts stay closed and the volume is conserved.
TEST(PlaneSplit, RandomCutsOfStarPrisms) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(0, 1);
  for (int iter = 0; iter < 600; ++iter) {
    const int n = 5 + iter % 12;
    Polygon star;
    for (int i = 0; i < n; ++i) {
      const double a = 2 * M_PI * i / n;
      const double r = iter % 2 ? (i % 2 ? 4 : 10) : 4 + 6 * u(rng);
      // Quarter-metre grid, so cuts often pass exactly through vertices and along edges.
      star.outer.push_back(
          {std::round(r * std::cos(a) * 4) / 4, std::round(r * std::sin(a) * 4) / 4});
    }
    if (iter % 3 == 0) star.holes.push_back({{-1, -1}, {-1, 1}, {1, 1}, {1, -1}});
    Mesh m = prism(star, 1 + 3 * u(rng));
    if (iter % 4 == 1) transform_mesh(m, rotation({u(rng), u(rng), u(rng)}, 360 * u(rng)));
    const Vec3 vertex = m.position(static_cast<std::uint32_t>(rng() % m.vertex_count()));
    const Vec3 random_normal = normalized(Vec3{u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5});
    Plane plane;
    switch (iter % 5) {
      case 0:
        plane = {{0, 0, 1}, std::round(u(rng) * 4) / 2};
        break;
      case 1:
        plane = {{1, 0, 0}, std::round((u(rng) * 20 - 10) * 4) / 4};
        break;
      case 2:
        plane = {random_normal, dot(random_normal, vertex)};
        break;
      case 3:
        plane = {{0, 1, 0}, vertex.y};
        break;
      default:
        plane = {random_normal, (u(rng) - 0.5) * 5};
        break;
    }
    const SplitResult r = split(m, plane, capped());
    ASSERT_TRUE(r.ok()) << "iteration " << iter << ": " << split_status_message(r.status);
    EXPECT_NEAR(volume(r.negative) + volume(r.positive), volume(m), 1e-9 * volume(m))
        << "iteration " << iter;
    EXPECT_TRUE(r.negative.empty() || check(r.negative).closed) << "iteration " << iter;
    EXPECT_TRUE(r.positive.empty() || check(r.positive).closed) << "iteration " << iter;
  }
}

TEST(PlaneSplit, OpenMeshWithoutCapping) {
  const Mesh cube = unit_cube();
  Mesh open;
  for (Vec3 p : cube.positions()) open.add_vertex(p);
  for (std::size_t f = 0; f < cube.face_count(); ++f) {
    if (cube.tag(f).semantic != SemanticClass::kRoofSurface)
      open.add_face(cube.face(f), cube.tag(f));
  }
  SplitOptions options;
  options.cap = false;
  const SplitResult r = split(open, {{0, 0, 1}, 0.5}, options);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(check(r.negative).boundary_edges, 4U);
  EXPECT_EQ(check(r.positive).boundary_edges, 8U);
  EXPECT_EQ(r.positive.face_count(), 4U);
  EXPECT_NEAR(surface_area(r.negative) + surface_area(r.positive), 5, 1e-12);
  // Capping a mesh with a missing wall: the cut edges cannot close into a loop.
  Mesh no_wall;
  for (Vec3 p : cube.positions()) no_wall.add_vertex(p);
  for (std::size_t f = 0; f < cube.face_count(); ++f) {
    if (f != 2) no_wall.add_face(cube.face(f), cube.tag(f));
  }
  const SplitResult capped_open = split(no_wall, {{0, 0, 1}, 0.5}, capped());
  EXPECT_EQ(capped_open.status, SplitStatus::kOpenCut);
  EXPECT_EQ(capped_open.negative.face_count(), 4U);
}

TEST(PlaneSplit, InvalidInput) {
  EXPECT_EQ(split(unit_cube(), {{0, 0, 0}, 1}).status, SplitStatus::kInvalidPlane);
  EXPECT_EQ(split(unit_cube(), {{0, NAN, 1}, 1}).status, SplitStatus::kInvalidPlane);
  EXPECT_EQ(split(unit_cube(), {{0, 0, 1}, INFINITY}).status, SplitStatus::kInvalidPlane);
  Mesh bad = unit_cube();
  bad.positions()[0].x = NAN;
  EXPECT_EQ(split(bad, {{0, 0, 1}, 0.5}).status, SplitStatus::kNonFiniteInput);
  const SplitResult empty = split(Mesh{}, {{0, 0, 1}, 0});
  EXPECT_TRUE(empty.ok());
  EXPECT_TRUE(empty.negative.empty() && empty.positive.empty());
}

TEST(PlaneSplit, UnnormalisedPlane) {
  const SplitResult r = split(unit_cube(), {{0, 0, 4}, 1}, capped());
  EXPECT_NEAR(volume(r.negative), 0.25, 1e-12);
}

TEST(PlaneSplit, SlabsAlongAnAxis) {
  const Mesh u = u_prism();
  const double cuts[] = {-1, 1, 2, 2, 5};
  const SlabResult r = split_into_slabs(u, {0, 1, 0}, cuts, capped());
  ASSERT_TRUE(r.ok()) << split_status_message(r.status);
  ASSERT_EQ(r.pieces.size(), 6U);
  EXPECT_TRUE(r.pieces[0].empty());
  expect_solid(r.pieces[1], {2, 1, 9 * 1 * 4});
  expect_solid(r.pieces[2], {2, 1, 9 * 1 * 4});
  EXPECT_TRUE(r.pieces[3].empty());
  expect_solid(r.pieces[4], {4, 2, 6 * 3 * 4});
  expect_solid(r.pieces[5], {4, 2, 6 * 1 * 4});
  double total = 0;
  for (const Mesh& piece : r.pieces) total += volume(piece);
  EXPECT_NEAR(total, volume(u), 1e-9);
  const double descending[] = {3, 1};
  EXPECT_EQ(split_into_slabs(u, {0, 1, 0}, descending).status, SplitStatus::kInvalidPositions);
  const double one[] = {1};
  EXPECT_EQ(split_into_slabs(u, {0, 0, 0}, one).status, SplitStatus::kInvalidPlane);
}

}  // namespace
}  // namespace insula::kernel
