// CityEngine's scatter in the registry (docs/operations-cityengine.md, "scatter"): point shapes on
// the faces, inside a closed mesh or inside the scope, drawn from the shape's seed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "kernel/mesh_sample.h"
#include "shape/ops.h"

namespace insula::shape {
namespace {

using kernel::Polygon;
using kernel::Vec3;

void expect_near(Vec3 a, Vec3 b, double tolerance = 1e-9) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

// An L: [0, 10] x [0, 5] and [0, 4] x [0, 10] (70 m²).
const Polygon kL = {{{0, 0}, {10, 0}, {10, 5}, {4, 5}, {4, 10}, {0, 10}}, {}};

bool in_l(double x, double y, double tolerance = 1e-9) {
  const auto in = [&](double x0, double x1, double y0, double y1) {
    return x >= x0 - tolerance && x <= x1 + tolerance && y >= y0 - tolerance && y <= y1 + tolerance;
  };
  return in(0, 10, 0, 5) || in(0, 4, 0, 10);
}

ShapeId lot(ShapeTree& tree, const Polygon& footprint) {
  const RootResult r = tree.create_root(footprint);
  EXPECT_TRUE(r.ok()) << r.error;
  return r.id;
}

// A 4 x 2 x 3 box mass whose scope is turned and moved, so scope and world differ.
ShapeId box(ShapeTree& tree) {
  Scope scope;
  scope.origin = {5, -2, 1};
  scope.x = {0, 1, 0};
  scope.y = {0, 0, 1};
  scope.z = {1, 0, 0};
  scope.size = {4, 2, 3};
  return tree.add_root(scope, box_mesh(scope.size, mass_box_tags()));
}

OpResult scatter_args(ShapeTree& tree, ShapeId id, std::vector<ArgInput> args) {
  return registry().run(tree, id, "scatter", args);
}

std::vector<Vec3> origins(const ShapeTree& tree, const OpResult& r) {
  std::vector<Vec3> out;
  for (ShapeId c : r.children) out.push_back(tree[c].scope.origin);
  return out;
}

// Distance from a scope-space point to the surface of the box [0, size].
double distance_to_box_surface(Vec3 p, Vec3 size) {
  const double inside = std::min({p.x, size.x - p.x, p.y, size.y - p.y, p.z, size.z - p.z});
  return std::abs(inside);
}

TEST(Scatter, SurfacePointsLieOnAFlatLotFacingUp) {
  ShapeTree tree;
  const ShapeId l = lot(tree, kL);
  const OpResult r = scatter_args(tree, l, {{"", std::string("surface")}, {"", 200.0}});
  ASSERT_TRUE(r.ok()) << r.error;
  ASSERT_EQ(r.children.size(), 200U);
  EXPECT_FALSE(tree[l].active);
  for (ShapeId c : r.children) {
    const Shape& s = tree[c];
    EXPECT_FALSE(s.mesh);
    EXPECT_FALSE(s.outline);
    expect_near(s.scope.size, {});
    EXPECT_NEAR(s.scope.origin.z, 0, 1e-9);
    EXPECT_TRUE(in_l(s.scope.origin.x, s.scope.origin.y))
        << s.scope.origin.x << " " << s.scope.origin.y;
    // CityEngine: on a surface the child's y is the normal; x keeps the lot's x.
    expect_near(s.scope.y, {0, 0, 1});
    expect_near(s.scope.x, tree[l].scope.x);
    expect_near(s.scope.z, kernel::cross(s.scope.x, s.scope.y));
  }
}

TEST(Scatter, SurfacePointsOnABoxByAreaWithTheFaceNormalAsY) {
  ShapeTree tree;
  const ShapeId b = box(tree);
  const Scope scope = tree[b].scope;
  const OpResult r = scatter_args(tree, b, {{"", std::string("surface")}, {"", 5200.0}});
  ASSERT_TRUE(r.ok()) << r.error;
  ASSERT_EQ(r.children.size(), 5200U);
  int on_left_or_right = 0;  // faces x = 0 and x = 4: 2 x 6 m² of 52 m²
  for (ShapeId c : r.children) {
    const Vec3 p = scope.to_local(tree[c].scope.origin);
    ASSERT_LT(distance_to_box_surface(p, scope.size), 1e-9);
    // The face the point is on gives the outward normal its scope y must be.
    Vec3 normal;
    if (std::abs(p.x) < 1e-9) normal = {-1, 0, 0};
    if (std::abs(p.x - 4) < 1e-9) normal = {1, 0, 0};
    if (std::abs(p.y) < 1e-9) normal = {0, -1, 0};
    if (std::abs(p.y - 2) < 1e-9) normal = {0, 1, 0};
    if (std::abs(p.z) < 1e-9) normal = {0, 0, -1};
    if (std::abs(p.z - 3) < 1e-9) normal = {0, 0, 1};
    expect_near(tree[c].scope.y, scope.direction_to_world(normal));
    on_left_or_right += std::abs(normal.x) > 0;
  }
  // Expected 1200, standard deviation about 30.
  EXPECT_GT(on_left_or_right, 1050);
  EXPECT_LT(on_left_or_right, 1350);
}

TEST(Scatter, VolumePointsLieInsideAClosedConcaveMass) {
  ShapeTree tree;
  const ShapeId l = lot(tree, kL);
  const OpResult mass = registry().run(tree, l, "extrude", {{"", 6.0}});
  ASSERT_EQ(mass.children.size(), 1U);
  const ShapeId m = mass.children[0];
  const OpResult r = scatter_args(
      tree, m, {{"", std::string("volume")}, {"", 300.0}, {"", std::string("uniform")}});
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_TRUE(r.warning.empty()) << r.warning;
  ASSERT_EQ(r.children.size(), 300U);
  for (ShapeId c : r.children) {
    const Vec3 p = tree[c].scope.origin;
    EXPECT_TRUE(in_l(p.x, p.y, 0)) << p.x << " " << p.y;
    EXPECT_GE(p.z, 0);
    EXPECT_LE(p.z, 6);
    // Not rotated: the mass's own axes.
    expect_near(tree[c].scope.y, tree[m].scope.y);
    expect_near(tree[c].scope.x, tree[m].scope.x);
  }
}

TEST(Scatter, VolumeOnAnOpenMeshFallsBackToTheSurface) {
  ShapeTree tree;
  const ShapeId l = lot(tree, kL);
  const OpResult r = scatter_args(tree, l, {{"", std::string("volume")}, {"", 50.0}});
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(r.warning, "the mesh is not closed: points placed on its surface instead of inside");
  ASSERT_EQ(r.children.size(), 50U);
  for (ShapeId c : r.children) EXPECT_NEAR(tree[c].scope.origin.z, 0, 1e-9);
}

TEST(Scatter, ScopePointsLieInTheScopeWithTheShapesAxes) {
  ShapeTree tree;
  const ShapeId b = box(tree);
  const Scope scope = tree[b].scope;
  const OpResult r = scatter_args(tree, b, {{"", std::string("scope")}, {"", 400.0}});
  ASSERT_TRUE(r.ok()) << r.error;
  ASSERT_EQ(r.children.size(), 400U);
  for (ShapeId c : r.children) {
    const Vec3 p = scope.to_local(tree[c].scope.origin);
    EXPECT_GE(p.x, -1e-9);
    EXPECT_LE(p.x, 4 + 1e-9);
    EXPECT_GE(p.y, -1e-9);
    EXPECT_LE(p.y, 2 + 1e-9);
    EXPECT_GE(p.z, -1e-9);
    EXPECT_LE(p.z, 3 + 1e-9);
    expect_near(tree[c].scope.x, scope.x);
    expect_near(tree[c].scope.y, scope.y);
    expect_near(tree[c].scope.z, scope.z);
  }
  // A mirrored scope (negative width) spans [-2, 0] on x.
  Scope mirrored;
  mirrored.size = {-2, 1, 1};
  const OpResult m =
      scatter_args(tree, tree.add_root(mirrored),
                   {{"", std::string("scope")}, {"", 50.0}, {"", std::string("gaussian")}});
  ASSERT_EQ(m.children.size(), 50U);
  for (ShapeId c : m.children) {
    EXPECT_LE(tree[c].scope.origin.x, 0);
    EXPECT_GE(tree[c].scope.origin.x, -2);
  }
  // A flat shape's CityEngine axes: y its normal, z along its -y.
  const ShapeId l = lot(tree, kL);
  const OpResult f = scatter_args(tree, l, {{"", std::string("scope")}, {"", 3.0}});
  ASSERT_EQ(f.children.size(), 3U);
  expect_near(tree[f.children[0]].scope.y, tree[l].scope.z);
  expect_near(tree[f.children[0]].scope.z, -tree[l].scope.y);
}

TEST(Scatter, TheSeedDecidesThePoints) {
  for (const char* domain : {"surface", "volume", "scope"}) {
    ShapeTree a(7);
    ShapeTree b(7);
    ShapeTree c(8);
    const std::vector<ArgInput> args = {{"", std::string(domain)}, {"", 40.0}};
    const OpResult ra = scatter_args(a, box(a), args);
    const OpResult rb = scatter_args(b, box(b), args);
    const OpResult rc = scatter_args(c, box(c), args);
    ASSERT_EQ(ra.children.size(), 40U);
    EXPECT_EQ(origins(a, ra), origins(b, rb)) << domain;
    EXPECT_NE(origins(a, ra), origins(c, rc)) << domain;
  }
}

double mean_distance_to(const ShapeTree& tree, const OpResult& r, Vec3 centre) {
  double sum = 0;
  for (ShapeId c : r.children) sum += kernel::length(tree[c].scope.origin - centre);
  return sum / static_cast<double>(r.children.size());
}

TEST(Scatter, GaussianPointsClusterAroundTheMean) {
  ShapeTree tree;
  const Polygon square = {{{0, 0}, {100, 0}, {100, 100}, {0, 100}}, {}};
  const OpResult u =
      scatter_args(tree, lot(tree, square),
                   {{"", std::string("surface")}, {"", 500.0}, {"", std::string("uniform")}});
  const OpResult g =
      scatter_args(tree, lot(tree, square),
                   {{"", std::string("surface")}, {"", 500.0}, {"", std::string("gaussian")}});
  ASSERT_EQ(u.children.size(), 500U);
  ASSERT_EQ(g.children.size(), 500U);
  const double du = mean_distance_to(tree, u, {50, 50, 0});
  const double dg = mean_distance_to(tree, g, {50, 50, 0});
  EXPECT_NEAR(du, 38.3, 3);         // the mean distance to a square's centre: 0.383 of its side
  EXPECT_NEAR(dg, 16 * 1.2533, 2);  // '0.16 of 100 m per axis: 16 sqrt(pi / 2)
  // On the left side (x = 0 of the scope), 1 m deviation: every point within 6 m of (0, 50).
  const OpResult left = scatter_args(tree, lot(tree, square),
                                     {{"", std::string("surface")},
                                      {"", 200.0},
                                      {"", std::string("gaussian")},
                                      {"", std::string("left")},
                                      {"", 1.0}});
  ASSERT_EQ(left.children.size(), 200U);
  for (ShapeId c : left.children) {
    EXPECT_LT(kernel::length(tree[c].scope.origin - Vec3{0, 50, 0}), 6);
    EXPECT_GE(tree[c].scope.origin.x, -1e-9);  // on the lot
  }
  // Inside a box: the cluster around its top centre stays in the scope.
  const ShapeId b = box(tree);
  const Scope scope = tree[b].scope;
  const OpResult top = scatter_args(tree, b,
                                    {{"", std::string("scope")},
                                     {"", 100.0},
                                     {"", std::string("gaussian")},
                                     {"", std::string("top")}});
  ASSERT_EQ(top.children.size(), 100U);
  double mean_y = 0;
  for (ShapeId c : top.children) {
    const Vec3 p = scope.to_local(tree[c].scope.origin);
    EXPECT_LE(p.y, 2 + 1e-9);
    mean_y += p.y / 100;
  }
  EXPECT_GT(mean_y, 1.5);
}

TEST(Scatter, NoPointsNoChildren) {
  ShapeTree tree;
  const ShapeId l = lot(tree, kL);
  const OpResult r = scatter_args(tree, l, {{"", std::string("surface")}, {"", 0.0}});
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_TRUE(r.children.empty());
  // A fraction of a point is dropped (CityEngine takes a float).
  const OpResult f = scatter_args(tree, l, {{"", std::string("surface")}, {"", 2.9}});
  EXPECT_EQ(f.children.size(), 2U);
}

TEST(Scatter, BadInputIsAnError) {
  ShapeTree tree;
  const ShapeId l = lot(tree, kL);
  const auto error = [&](ShapeId id, std::vector<ArgInput> args) {
    const std::size_t before = tree.size();
    const OpResult r = scatter_args(tree, id, std::move(args));
    EXPECT_EQ(tree.size(), before);
    return r.error;
  };
  EXPECT_EQ(error(l, {{"", std::string("surface")}, {"", -1.0}}),
            "scatter: parameter 'count' must be >= 0; got -1");
  EXPECT_EQ(error(l, {{"", std::string("surface")}, {"", 2e6}}),
            "scatter: parameter 'count' must be <= 1000000; got 2000000");
  EXPECT_EQ(
      error(l, {{"", std::string("surface")}, {"", std::numeric_limits<double>::quiet_NaN()}}),
      "scatter: parameter 'count' must be finite; got nan");
  EXPECT_FALSE(error(l, {{"", std::string("ground")}, {"", 3.0}}).empty());
  EXPECT_FALSE(
      error(l, {{"", std::string("surface")}, {"", 3.0}, {"", std::string("poisson")}}).empty());
  EXPECT_EQ(error(l, {{"", std::string("surface")},
                      {"", 3.0},
                      {"", std::string("gaussian")},
                      {"", std::string("center")},
                      {"", SizeSpec{1, SizeMode::kFloating}}}),
            "scatter: the standard deviation must be meters or relative ('), >= 0 and finite");
  Scope scope;
  scope.size = {1, 1, 1};
  const ShapeId bare = tree.add_root(scope);
  EXPECT_EQ(error(bare, {{"", std::string("surface")}, {"", 3.0}}),
            "scatter: the shape has no faces to scatter on");
  EXPECT_EQ(error(bare, {{"", std::string("volume")}, {"", 3.0}}),
            "scatter: the shape has no faces to scatter on");
  // The scope domain needs no faces.
  EXPECT_EQ(scatter_args(tree, bare, {{"", std::string("scope")}, {"", 3.0}}).children.size(), 3U);
  kernel::Mesh broken = *box_mesh({1, 1, 1}, mass_box_tags());
  broken.positions()[0].x = std::numeric_limits<double>::infinity();
  const ShapeId nonfinite = tree.add_root(scope, std::make_shared<kernel::Mesh>(broken));
  EXPECT_EQ(error(nonfinite, {{"", std::string("surface")}, {"", 3.0}}),
            "scatter: the geometry has non-finite coordinates");
  // The typed entry point checks the bound the registry declares.
  ScatterOptions many;
  many.count = kMaxScatterPoints + 1;
  EXPECT_EQ(scatter(tree, l, many).error, "at most 1000000 points; got 1000001");
}

TEST(MeshSurface, NearestPointAndWindingNumber) {
  const auto mesh = box_mesh({2, 2, 2}, mass_box_tags());
  const kernel::MeshSurface surface(*mesh);
  EXPECT_NEAR(surface.area(), 24, 1e-12);
  EXPECT_NEAR(surface.winding_number({1, 1, 1}), 1, 1e-9);
  EXPECT_NEAR(surface.winding_number({3, 1, 1}), 0, 1e-9);
  const kernel::SurfacePoint p = surface.nearest({1, 5, 1.5});
  expect_near(p.position, {1, 2, 1.5});
  expect_near(p.normal, {0, 1, 0});
}

}  // namespace
}  // namespace insula::shape
