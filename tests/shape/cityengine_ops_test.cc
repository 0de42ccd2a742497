// CityEngine's scope and footprint operations in the registry (docs/operations-cityengine.md):
// alignScopeToAxes, alignScopeToGeometry, rotateScope, setPivot, mirror, translate/rotate in a
// frame, shapeL/U/O, innerRectangle.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "kernel/inner_rectangle.h"
#include "shape/ops.h"

namespace insula::shape {
namespace {

using kernel::Polygon;
using kernel::Vec2;
using kernel::Vec3;

void expect_near(Vec3 a, Vec3 b, double tolerance = 1e-9) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

// A footprint of `w` x `d` meters turned by `degrees` about world Z.
Polygon turned_rectangle(double w, double d, double degrees) {
  const double a = degrees * std::numbers::pi / 180;
  const auto p = [&](double x, double y) {
    return Vec2{x * std::cos(a) - y * std::sin(a), x * std::sin(a) + y * std::cos(a)};
  };
  return {{p(0, 0), p(w, 0), p(w, d), p(0, d)}, {}};
}

ShapeId lot(ShapeTree& tree, const Polygon& footprint) {
  const RootResult r = tree.create_root(footprint);
  EXPECT_TRUE(r.ok()) << r.error;
  return r.id;
}

ShapeId only_child(const OpResult& r) {
  EXPECT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(r.children.size(), 1U);
  return r.children.empty() ? kNoShape : r.children[0];
}

ShapeId run(ShapeTree& tree, ShapeId id, std::string_view op, std::vector<ArgInput> args = {}) {
  return only_child(registry().run(tree, id, op, args));
}

// The shape's geometry in world space, vertices sorted (to compare before and after).
std::vector<Vec3> world_points(const ShapeTree& tree, ShapeId id) {
  std::vector<Vec3> out;
  for (const Vec3& p : tree[id].mesh->positions()) {
    Vec3 w = tree[id].scope.to_world(p);
    w = {std::round(w.x * 1e6) / 1e6, std::round(w.y * 1e6) / 1e6, std::round(w.z * 1e6) / 1e6};
    out.push_back(w);
  }
  std::sort(out.begin(), out.end(),
            [](Vec3 a, Vec3 b) { return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z); });
  return out;
}

void expect_same_world_geometry(const ShapeTree& tree, ShapeId a, ShapeId b) {
  const auto pa = world_points(tree, a);
  const auto pb = world_points(tree, b);
  ASSERT_EQ(pa.size(), pb.size());
  for (std::size_t i = 0; i < pa.size(); ++i) expect_near(pa[i], pb[i], 2e-6);
}

// Geometry lies in [0, size] of its scope.
void expect_fits(const Shape& s) {
  const kernel::Bounds3 b = s.mesh->bounds();
  expect_near(b.min, {0, 0, 0}, 1e-9);
  expect_near(b.max, s.scope.size, 1e-9);
}

TEST(AlignScopeToAxes, TurnsAMassToTheWorldAndKeepsItsGeometry) {
  ShapeTree tree;
  const ShapeId mass = only_child(extrude(tree, lot(tree, turned_rectangle(10, 4, 30)), 6));
  const ShapeId a = run(tree, mass, "alignScopeToAxes");
  const Shape& s = tree[a];
  // CityEngine's world axes: x east, y up, z south.
  expect_near(s.scope.x, {1, 0, 0});
  expect_near(s.scope.y, {0, 0, 1});
  expect_near(s.scope.z, {0, -1, 0});
  const double c = std::cos(std::numbers::pi / 6);
  const double n = std::sin(std::numbers::pi / 6);
  expect_near(s.scope.size, {10 * c + 4 * n, 6, 10 * n + 4 * c}, 1e-9);
  expect_same_world_geometry(tree, mass, a);
  expect_fits(s);
  EXPECT_NEAR(kernel::volume(*s.mesh), 240, 1e-9);
  EXPECT_TRUE(kernel::is_watertight(*s.mesh));
}

TEST(AlignScopeToAxes, OneAxisKeepsTheOthersByProjection) {
  ShapeTree tree;
  const ShapeId mass = only_child(extrude(tree, lot(tree, turned_rectangle(10, 4, 30)), 6));
  const ShapeId tilted = only_child(rotate(tree, mass, {20, 0, 0}, Pivot::kOrigin));
  const Vec3 x_before = tree[tilted].scope.x;
  const ShapeId a = run(tree, tilted, "alignScopeToAxes", {{"", std::string("y")}});
  expect_near(tree[a].scope.y, {0, 0, 1});
  expect_near(tree[a].scope.x, x_before);  // the tilt was about x: x stays horizontal
  expect_same_world_geometry(tree, tilted, a);
  expect_fits(tree[a]);
}

TEST(AlignScopeToAxes, AFlatLotStaysFlatWithZUp) {
  ShapeTree tree;
  const ShapeId root = lot(tree, turned_rectangle(10, 4, 30));
  const ShapeId a = run(tree, root, "alignScopeToAxes", {{"", std::string("world.xyz")}});
  const Shape& s = tree[a];
  ASSERT_TRUE(s.is_flat());
  expect_near(s.scope.x, {1, 0, 0});
  expect_near(s.scope.z, {0, 0, 1});
  EXPECT_EQ(s.scope.size.z, 0);
  EXPECT_NEAR(kernel::area(*s.outline), 40, 1e-9);
  expect_same_world_geometry(tree, root, a);
  // The object frame is the root's: aligning to it gives the root's own axes back.
  const ShapeId o = run(tree, a, "alignScopeToAxes", {{"", std::string("object.xyz")}});
  expect_near(tree[o].scope.x, tree[root].scope.x);
  expect_near(tree[o].scope.size, {10, 4, 0}, 1e-9);
}

TEST(AlignScopeToGeometry, LongestEdgeOfAFlatShape) {
  ShapeTree tree;
  const ShapeId root = lot(tree, {{{0, 0}, {2, 0}, {2, 10}, {0, 10}}, {}});
  ASSERT_NEAR(tree[root].scope.size.x, 2, 1e-9);  // the root's x runs along the first edge
  const ShapeId a =
      run(tree, root, "alignScopeToGeometry",
          {{"", std::string("yup")}, {"", std::int64_t{0}}, {"", std::string("longest")}});
  const Shape& s = tree[a];
  ASSERT_TRUE(s.is_flat());
  EXPECT_NEAR(std::fabs(s.scope.x.y), 1, 1e-12);
  expect_near(s.scope.z, {0, 0, 1});
  expect_near(s.scope.size, {10, 2, 0}, 1e-9);
  EXPECT_NEAR(kernel::area(*s.outline), 20, 1e-9);
  expect_same_world_geometry(tree, root, a);
}

TEST(AlignScopeToGeometry, LargestFaceOfAMassTakesTheUpAxis) {
  ShapeTree tree;
  Scope scope;
  scope.size = {10, 3, 6};
  const ShapeId box = tree.add_root(scope, box_mesh(scope.size, mass_box_tags()));
  // Faces -x, +x, -y, +y, -z, +z: the -y face (10 x 6) is the first largest.
  const ShapeId a = run(tree, box, "alignScopeToGeometry", {{"face", std::string("largest")}});
  expect_near(tree[a].scope.y, {0, -1, 0});
  EXPECT_NEAR(kernel::volume(*tree[a].mesh), 180, 1e-9);
  expect_same_world_geometry(tree, box, a);
  expect_fits(tree[a]);
  // zUp puts the normal of face 1 (+x) on z.
  const ShapeId z = run(tree, box, "alignScopeToGeometry",
                        {{"up", std::string("zup")}, {"face", std::int64_t{1}}});
  expect_near(tree[z].scope.z, {1, 0, 0});
  expect_near(tree[z].scope.size, {tree[z].scope.size.x, tree[z].scope.size.y, 10}, 1e-9);
}

TEST(AlignScopeToGeometry, BadPicksAreErrors) {
  ShapeTree tree;
  Scope scope;
  scope.size = {1, 1, 1};
  const ShapeId box = tree.add_root(scope, box_mesh(scope.size, mass_box_tags()));
  EXPECT_EQ(registry().run(tree, box, "alignScopeToGeometry", {{"face", std::int64_t{9}}}).error,
            "alignScopeToGeometry: face index 9 is out of range (the shape has 6 faces)");
  EXPECT_EQ(registry().run(tree, box, "alignScopeToGeometry", {{"edge", 4.0}}).error,
            "alignScopeToGeometry: edge index 4 is out of range (face 0 has 4 edges)");
  EXPECT_EQ(
      registry().run(tree, box, "alignScopeToGeometry", {{"face", std::string("biggest")}}).error,
      "alignScopeToGeometry: parameter 'face' must be one of N, largest, any, world.lowest, auto; "
      "got 'biggest'");
  EXPECT_EQ(
      registry().run(tree, box, "alignScopeToGeometry", {{"face", -1.0}}).error,
      "alignScopeToGeometry: parameter 'face' expects one of N, largest, any, world.lowest, auto; "
      "got a number");
  EXPECT_EQ(
      registry().run(tree, box, "alignScopeToGeometry", {{"face", std::string("N")}}).error,
      "alignScopeToGeometry: parameter 'face' must be one of N, largest, any, world.lowest, auto; "
      "got 'N'");
  const ShapeId point = tree.add_root(scope);
  EXPECT_EQ(registry().run(tree, point, "alignScopeToGeometry", {}).error,
            "alignScopeToGeometry: the shape has no faces");
}

TEST(RotateScope, TurnsOnlyTheScopeAndRefitsIt) {
  ShapeTree tree;
  Scope scope;
  scope.size = {10, 2, 10};
  const ShapeId box = tree.add_root(scope, box_mesh(scope.size, mass_box_tags()));
  const ShapeId r = run(tree, box, "rotateScope", {{"", 0.0}, {"", 45.0}, {"", 0.0}});
  const double h = std::sqrt(0.5);
  expect_near(tree[r].scope.x, {h, 0, -h});
  expect_near(tree[r].scope.size, {10 * std::sqrt(2.0), 2, 10 * std::sqrt(2.0)}, 1e-9);
  expect_same_world_geometry(tree, box, r);
  expect_fits(tree[r]);
  EXPECT_NEAR(kernel::volume(*tree[r].mesh), 200, 1e-9);
}

TEST(SetPivot, CornerAndAxisMapKeepTheBox) {
  ShapeTree tree;
  Scope scope;
  scope.size = {2, 3, 4};
  const ShapeId box = tree.add_root(scope, box_mesh(scope.size, mass_box_tags()));
  // Corner 1 is far in x: x would point back (-x), so x and z swap to stay right-handed.
  const ShapeId p = run(tree, box, "setPivot", {{"", std::string("xyz")}, {"", std::int64_t{1}}});
  const Scope& s = tree[p].scope;
  expect_near(s.origin, {2, 0, 0});
  expect_near(s.x, {0, 0, 1});
  expect_near(s.y, {0, 1, 0});
  expect_near(s.z, {-1, 0, 0});
  expect_near(s.size, {4, 3, 2});
  expect_same_world_geometry(tree, box, p);
  expect_fits(tree[p]);
  const ShapeId q = run(tree, box, "setPivot", {{"", std::string("zxy")}, {"", std::int64_t{0}}});
  expect_near(tree[q].scope.x, {0, 1, 0});
  expect_near(tree[q].scope.y, {0, 0, 1});
  expect_near(tree[q].scope.size, {3, 4, 2});
  EXPECT_NEAR(kernel::volume(*tree[q].mesh), 24, 1e-9);
  EXPECT_EQ(registry().run(tree, box, "setPivot", {{"corner", std::int64_t{8}}}).error,
            "setPivot: parameter 'corner' must be <= 7; got 8");
}

TEST(Mirror, FlipsGeometryInsideTheScopeAndKeepsFacesOutward) {
  ShapeTree tree;
  const ShapeId root = lot(tree, {{{0, 0}, {4, 0}, {0, 2}}, {}});
  const ShapeId m = run(tree, root, "mirror", {{"", true}, {"", false}, {"", false}});
  const Shape& s = tree[m];
  ASSERT_TRUE(s.is_flat());
  EXPECT_NEAR(kernel::signed_area(s.outline->outer), 4, 1e-12);  // still counter-clockwise
  expect_near(s.scope.origin, tree[root].scope.origin);
  // The right angle moved from x = 0 to x = 4.
  const auto& outer = s.outline->outer;
  EXPECT_EQ(std::count_if(outer.begin(), outer.end(), [](Vec2 p) { return p.x == 4; }), 2);
  const ShapeId mass = only_child(extrude(tree, m, 3));
  const ShapeId mm = run(tree, mass, "mirror", {{"z", true}});
  EXPECT_NEAR(kernel::volume(*tree[mm].mesh), 12, 1e-9);
  EXPECT_TRUE(kernel::is_watertight(*tree[mm].mesh));
}

TEST(TranslateRotateInFrames, WorldObjectAndScope) {
  ShapeTree tree;
  const ShapeId root = lot(tree, turned_rectangle(10, 4, 30));
  const ShapeId mass = only_child(extrude(tree, root, 6));
  const Vec3 o = tree[mass].scope.origin;
  // rel world: 3 m up whatever the scope's turn.
  const ShapeId up =
      run(tree, mass, "translate",
          {{"y", 3.0}, {"mode", std::string("rel")}, {"frame", std::string("world")}});
  expect_near(tree[up].scope.origin, o + Vec3{0, 0, 3});
  // abs world: x east, y up, z south.
  const ShapeId at = run(tree, mass, "translate",
                         {{"x", 1.0},
                          {"y", 2.0},
                          {"z", 3.0},
                          {"mode", std::string("abs")},
                          {"frame", std::string("world")}});
  expect_near(tree[at].scope.origin, {1, -3, 2});
  // abs object: the lot's origin plus the lot's axes.
  const ShapeId obj =
      run(tree, mass, "translate",
          {{"x", 2.0}, {"mode", std::string("abs")}, {"frame", std::string("object")}});
  expect_near(tree[obj].scope.origin, tree[root].scope.origin + tree[root].scope.x * 2);
  // abs in the scope frame is read as rel, and says so.
  const OpResult s =
      registry().run(tree, mass, "translate", {{"x", 1.0}, {"mode", std::string("abs")}});
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(s.warning,
            "abs in the scope or pivot frame is read as rel (Insula keeps no pivot apart from the "
            "scope)");
  // rel world rotation about up by 90 degrees: x turns a quarter about world Z.
  const Vec3 x = tree[mass].scope.x;
  const ShapeId turned = run(tree, mass, "rotate", {{"y", 90.0}, {"frame", std::string("world")}});
  expect_near(tree[turned].scope.x, {-x.y, x.x, 0});
  expect_near(tree[turned].scope.y, {0, 0, 1});
  expect_near(tree[turned].scope.origin, o);
  // abs world rotation (0, 0, 0): the world's axes.
  const ShapeId reset =
      run(tree, mass, "rotate", {{"mode", std::string("abs")}, {"frame", std::string("world")}});
  expect_near(tree[reset].scope.x, {1, 0, 0});
  expect_near(tree[reset].scope.y, {0, 0, 1});
  EXPECT_EQ(registry()
                .run(tree, mass, "rotate",
                     {{"pivot", std::string("center")}, {"frame", std::string("world")}})
                .error,
            "rotate: pivot center needs mode rel in the scope frame");
}

double total_area(const ShapeTree& tree, const OpResult& r, std::uint32_t piece) {
  double a = 0;
  for (std::size_t i = 0; i < r.children.size(); ++i) {
    if (r.pieces[i] == piece) a += kernel::area(*tree[r.children[i]].outline);
  }
  return a;
}

std::size_t count(const OpResult& r, std::uint32_t piece) {
  return static_cast<std::size_t>(std::count(r.pieces.begin(), r.pieces.end(), piece));
}

TEST(ShapeLUO, BandsAlongTheNamedSides) {
  ShapeTree tree;
  const ShapeId l = lot(tree, {{{0, 0}, {10, 0}, {10, 8}, {0, 8}}, {}});
  const OpResult rl = registry().run(tree, l, "shapeL", {{"", 3.0}, {"", 2.0}});
  ASSERT_TRUE(rl.ok()) << rl.error;
  EXPECT_EQ(count(rl, 0), 1U);
  EXPECT_EQ(count(rl, 1), 1U);
  EXPECT_NEAR(total_area(tree, rl, 0), 30 + 2 * 5, 1e-9);
  EXPECT_NEAR(total_area(tree, rl, 1), 8 * 5, 1e-9);
  // The remainder lies right of the left wing and behind the front wing.
  const Shape& rest = tree[rl.children[1]];
  expect_near(rest.scope.origin, tree[l].scope.to_world({2, 3, 0}));

  const ShapeId u = lot(tree, {{{0, 0}, {10, 0}, {10, 8}, {0, 8}}, {}});
  const OpResult ru = registry().run(tree, u, "shapeU", {{"", 3.0}, {"", 1.0}, {"", 2.0}});
  ASSERT_TRUE(ru.ok()) << ru.error;
  EXPECT_NEAR(total_area(tree, ru, 0), 30 + 3 * 5, 1e-9);
  EXPECT_NEAR(total_area(tree, ru, 1), 7 * 5, 1e-9);

  const ShapeId o = lot(tree, {{{0, 0}, {10, 0}, {10, 8}, {0, 8}}, {}});
  const OpResult ro =
      registry().run(tree, o, "shapeO", {{"", 1.0}, {"", 1.0}, {"", 1.0}, {"", 1.0}});
  ASSERT_TRUE(ro.ok()) << ro.error;
  ASSERT_EQ(count(ro, 0), 1U);
  EXPECT_EQ(tree[ro.children[0]].outline->holes.size(), 1U);  // a ring around the court
  EXPECT_NEAR(total_area(tree, ro, 0), 80 - 48, 1e-9);
  EXPECT_NEAR(total_area(tree, ro, 1), 48, 1e-9);

  const ShapeId k = lot(tree, {{{0, 0}, {10, 0}, {10, 8}, {0, 8}}, {}});
  const OpResult only =
      registry().run(tree, k, "shapeL", {{"", 3.0}, {"", 2.0}, {"", std::string("remainder")}});
  ASSERT_EQ(only.children.size(), 1U);
  EXPECT_EQ(only.pieces[0], 1U);
  EXPECT_EQ(registry().run(tree, k, "shapeL", {{"", -1.0}, {"", 2.0}}).error,
            "shapeL: parameter 'frontWidth' must be >= 0; got -1");
  EXPECT_EQ(registry().run(tree, k, "shapeL", {{"", 1.0}}).error,
            "shapeL: missing required parameter 'leftWidth'");
}

TEST(InnerRectangle, LargestRectangleOfAnLAndOfATriangle) {
  ShapeTree tree;
  const ShapeId l = lot(tree, {{{0, 0}, {10, 0}, {10, 5}, {4, 5}, {4, 10}, {0, 10}}, {}});
  const OpResult r = registry().run(tree, l, "innerRectangle", {});
  ASSERT_TRUE(r.ok()) << r.error;
  ASSERT_EQ(count(r, 0), 1U);
  const Shape& rect = tree[r.children[0]];
  expect_near(rect.scope.size, {10, 5, 0}, 1e-9);
  EXPECT_NEAR(kernel::area(*rect.outline), 50, 1e-9);
  EXPECT_NEAR(total_area(tree, r, 1), 20, 1e-9);
  EXPECT_EQ(rect.mesh->face_count(), 1U);

  // The largest rectangle in a right triangle has half its area.
  const auto t = kernel::largest_inner_rectangle({{{0, 0}, {3, 0}, {0, 5}}, {}});
  ASSERT_TRUE(t);
  EXPECT_NEAR(t->area(), 3.75, 1e-6);
  // A slanted side (not on the grid): within a fraction of a percent of the exact 8 (2 x 4 at
  // x = 2 under y = 8 - 2x on [0, 4]... the best is x in [0, 2], height 4).
  const auto s = kernel::largest_inner_rectangle({{{0, 0}, {4, 0}, {0, 8}}, {}}, 7);
  ASSERT_TRUE(s);
  EXPECT_NEAR(s->area(), 8, 1e-3);
  // A circle (a 1000-gon of radius 20) holds the square of area 2 r^2 = 800.
  Polygon circle;
  for (int k = 0; k < 1000; ++k) {
    const double a = 2 * std::numbers::pi * k / 1000;
    circle.outer.push_back({20 * std::cos(a), 20 * std::sin(a)});
  }
  const auto c = kernel::largest_inner_rectangle(circle);
  ASSERT_TRUE(c);
  EXPECT_NEAR(c->area(), 800, 0.1);
  EXPECT_NEAR(c->max.x - c->min.x, c->max.y - c->min.y, 0.05);
  // A hole in the middle of a square: the best rectangle runs beside it.
  const auto h = kernel::largest_inner_rectangle(
      {{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{{4, 4}, {4, 6}, {6, 6}, {6, 4}}}});
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->area(), 40, 1e-9);
}

TEST(InnerRectangle, EdgeAlignmentFollowsTheLongestEdge) {
  ShapeTree tree;
  Scope scope;  // x east: the rectangle is turned 30 degrees against the scope
  const Polygon outline = turned_rectangle(4, 3, 30);
  const kernel::Bounds2 b = kernel::bounds(outline);
  Polygon moved = outline;
  for (Vec2& p : moved.outer) p -= b.min;
  scope.size = {b.max.x - b.min.x, b.max.y - b.min.y, 0};
  auto shape = std::make_shared<Polygon>(moved);
  const ShapeId root = tree.add_root(scope, flat_mesh(moved, {}), shape);
  const OpResult by_scope = registry().run(tree, root, "innerRectangle", {}, {});
  ASSERT_TRUE(by_scope.ok());
  EXPECT_LT(kernel::area(*tree[by_scope.children[0]].outline), 8);
  const OpResult by_edge =
      registry().run(tree, root, "innerRectangle", {{"", std::string("edge")}});
  ASSERT_TRUE(by_edge.ok()) << by_edge.error;
  const Shape& rect = tree[by_edge.children[0]];
  EXPECT_NEAR(kernel::area(*rect.outline), 12, 1e-6);
  expect_near(rect.scope.x, {std::cos(std::numbers::pi / 6), 0.5, 0}, 1e-9);
  EXPECT_EQ(count(by_edge, 1), 0U);  // nothing left over
}

// Two unit cubes side by side as separate meshes: 12 faces, 16 vertices, a double wall between.
kernel::Mesh two_cubes(double jitter) {
  kernel::Mesh m = *box_mesh({1, 1, 1}, mass_box_tags());
  kernel::Mesh second = *box_mesh({1, 1, 1}, mass_box_tags());
  for (Vec3& p : second.positions()) p = p + Vec3{1 + jitter, 0, 0};
  m.append(second);
  return m;
}

TEST(CleanupGeometry, MergesTwoCubesIntoOneClosedBox) {
  ShapeTree tree;
  Scope scope;
  scope.size = {2, 1, 1};
  const ShapeId id = tree.add_root(scope, std::make_shared<kernel::Mesh>(two_cubes(0.004)));
  ASSERT_EQ(kernel::check(*tree[id].mesh).components, 2U);
  const ShapeId c = run(tree, id, "cleanupGeometry", {{"", std::string("all")}, {"", 0.01}});
  const kernel::Mesh& m = *tree[c].mesh;
  // Vertices merged, the double wall dropped, the split sides merged, the mid vertices dropped.
  EXPECT_EQ(m.face_count(), 6U);
  EXPECT_EQ(m.vertex_count(), 8U);
  EXPECT_TRUE(kernel::is_watertight(m));
  EXPECT_NEAR(kernel::volume(m), 2, 0.01);
  // Faces only: merged vertices and no double wall, the sides still split in two (10 faces).
  const ShapeId f = run(tree, id, "cleanupGeometry", {{"", std::string("faces")}, {"", 0.01}});
  EXPECT_EQ(tree[f].mesh->face_count(), 10U);
  EXPECT_TRUE(kernel::is_watertight(*tree[f].mesh));
  // Exact matching (tolerance 0) leaves the 4 mm gap alone: nothing merges across it.
  const ShapeId e = run(tree, id, "cleanupGeometry", {{"", std::string("all")}, {"", 0.0}});
  EXPECT_EQ(tree[e].mesh->face_count(), 12U);
  EXPECT_EQ(registry().run(tree, id, "cleanupGeometry", {{"tolerance", 2.0}}).error,
            "cleanupGeometry: parameter 'tolerance' must be <= 1; got 2");
}

TEST(CleanupGeometry, KeepsAClosedMeshClosedAndDropsDegenerateFacesOfAnOpenOne) {
  ShapeTree tree;
  Scope scope;
  scope.size = {3, 3, 3};
  const ShapeId box = tree.add_root(scope, box_mesh(scope.size, mass_box_tags()));
  // Every face (9 m²) is far above 1 m²: a cube is left as it is.
  const ShapeId c = run(tree, box, "cleanupGeometry", {{"", std::string("faces")}, {"", 1.0}});
  EXPECT_EQ(tree[c].mesh->face_count(), 6U);
  EXPECT_TRUE(kernel::is_watertight(*tree[c].mesh));
  // An open mesh: a square and a sliver triangle of 0.05 m² beside it.
  kernel::Mesh open;
  open.add_polygon(std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {});
  open.add_polygon(std::vector<Vec3>{{1, 0, 0}, {2, 0, 0}, {1, 0.1, 0}}, {});
  Scope flat;
  flat.size = {2, 1, 0};
  const ShapeId o = tree.add_root(flat, std::make_shared<kernel::Mesh>(open));
  const ShapeId k = run(tree, o, "cleanupGeometry", {{"", std::string("faces")}, {"", 0.1}});
  EXPECT_EQ(tree[k].mesh->face_count(), 1U);
  EXPECT_NEAR(kernel::surface_area(*tree[k].mesh), 1, 1e-12);
}

TEST(Primitives, FillTheScopeOrStandInItsCentre) {
  ShapeTree tree;
  // On a flat 4 x 2 lot the cube's height is the mean of the lot's sides and runs up.
  const ShapeId lot_id = lot(tree, {{{0, 0}, {4, 0}, {4, 2}, {0, 2}}, {}});
  const ShapeId cube = run(tree, lot_id, "primitiveCube");
  expect_near(tree[cube].scope.size, {4, 3, 2}, 1e-9);
  expect_near(tree[cube].scope.y, {0, 0, 1});
  EXPECT_NEAR(kernel::volume(*tree[cube].mesh), 24, 1e-9);
  EXPECT_TRUE(kernel::is_watertight(*tree[cube].mesh));
  expect_fits(tree[cube]);
  // Sized: in the xz centre of a 10 m box, on its floor.
  Scope scope;
  scope.size = {10, 10, 10};
  const ShapeId box = tree.add_root(scope, box_mesh(scope.size, mass_box_tags()));
  const ShapeId small = run(tree, box, "primitiveCube", {{"", 1.0}, {"", 2.0}, {"", 3.0}});
  expect_near(tree[small].scope.origin, {4.5, 0, 3.5});
  expect_near(tree[small].scope.size, {1, 2, 3});
  // An octagonal prism of radius 1 and height 2.
  const ShapeId cyl =
      run(tree, box, "primitiveCylinder", {{"", std::int64_t{8}}, {"", 1.0}, {"", 2.0}});
  const kernel::Mesh& m = *tree[cyl].mesh;
  EXPECT_EQ(m.face_count(), 10U);
  EXPECT_NEAR(kernel::volume(m), 8 * std::sin(std::numbers::pi / 4), 1e-9);
  EXPECT_TRUE(kernel::is_watertight(m));
  expect_near(tree[cyl].scope.size, {2, 2, 2}, 1e-9);
  expect_near(tree[cyl].scope.origin, {4, 0, 4}, 1e-9);
  // On a lot the cylinder stands up.
  const ShapeId upright =
      run(tree, lot(tree, {{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {}}), "primitiveCylinder");
  expect_near(tree[upright].scope.size, {4, 4, 4}, 1e-9);
  expect_near(tree[upright].scope.y, {0, 0, 1});
  EXPECT_EQ(tree[upright].mesh->face_count(), 18U);
  // A quad on a box's floor is a flat shape facing the box's up axis.
  Scope b;
  b.size = {4, 3, 2};
  const ShapeId low = tree.add_root(b, box_mesh(b.size, mass_box_tags()));
  const ShapeId quad = run(tree, low, "primitiveQuad");
  ASSERT_TRUE(tree[quad].is_flat());
  expect_near(tree[quad].scope.z, {0, 1, 0});
  expect_near(tree[quad].scope.size, {4, 2, 0});
  EXPECT_NEAR(kernel::area(*tree[quad].outline), 8, 1e-12);
  expect_near(tree[quad].scope.to_world({0, 2, 0}), {0, 0, 0});
  EXPECT_EQ(registry().run(tree, box, "primitiveCube", {{"", 1.0}, {"", 0.0}, {"", 2.0}}).error,
            "primitiveCube: sizes must all be > 0 (or none given)");
  EXPECT_EQ(registry().run(tree, box, "primitiveCylinder", {{"sides", std::int64_t{2}}}).error,
            "primitiveCylinder: parameter 'sides' must be >= 3; got 2");
}

TEST(Primitives, SphereConeAndDisk) {
  ShapeTree tree;
  Scope scope;
  scope.size = {10, 10, 10};
  const ShapeId box = tree.add_root(scope, box_mesh(scope.size, mass_box_tags()));
  // A sphere of 8 segments and 4 bands, radius 1, standing on the box's floor in its xz centre.
  const ShapeId ball =
      run(tree, box, "primitiveSphere", {{"", std::int64_t{8}}, {"", std::int64_t{4}}, {"", 1.0}});
  const kernel::Mesh& sphere = *tree[ball].mesh;
  EXPECT_EQ(sphere.face_count(), 8U * 4U);  // two fans of triangles, two bands of quads
  EXPECT_TRUE(kernel::is_watertight(sphere));
  expect_near(tree[ball].scope.size, {2, 2, 2}, 1e-9);
  expect_near(tree[ball].scope.origin, {4, 0, 4}, 1e-9);
  // Inscribed in the unit sphere: below 4/3 pi, and near it with many faces.
  EXPECT_LT(kernel::volume(sphere), 4.0 / 3 * std::numbers::pi);
  const ShapeId fine = run(tree, box, "primitiveSphere",
                           {{"", std::int64_t{64}}, {"", std::int64_t{64}}, {"", 1.0}});
  EXPECT_NEAR(kernel::volume(*tree[fine].mesh), 4.0 / 3 * std::numbers::pi, 0.01);
  // A square cone (4 sides) of radius 1 and height 3: a pyramid over a 2 m² square.
  const ShapeId cone =
      run(tree, box, "primitiveCone", {{"", std::int64_t{4}}, {"", 1.0}, {"", 3.0}});
  EXPECT_EQ(tree[cone].mesh->face_count(), 5U);
  EXPECT_TRUE(kernel::is_watertight(*tree[cone].mesh));
  EXPECT_NEAR(kernel::volume(*tree[cone].mesh), 2.0 * 3 / 3, 1e-9);
  // On a lot the cone and the sphere fill the scope and stand up.
  const ShapeId tall =
      run(tree, lot(tree, {{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {}}), "primitiveCone");
  expect_near(tree[tall].scope.y, {0, 0, 1});
  expect_near(tree[tall].scope.size, {4, 4, 4}, 1e-9);
  // A disk of 6 corners, radius 2, on the box's floor: a flat hexagon facing up.
  const ShapeId disk = run(tree, box, "primitiveDisk", {{"", std::int64_t{6}}, {"", 2.0}});
  ASSERT_TRUE(tree[disk].is_flat());
  expect_near(tree[disk].scope.z, {0, 1, 0});
  EXPECT_EQ(tree[disk].outline->outer.size(), 6U);
  EXPECT_NEAR(kernel::area(*tree[disk].outline), 1.5 * std::sqrt(3.0) * 4, 1e-9);
  EXPECT_GT(kernel::signed_area(tree[disk].outline->outer), 0);
  EXPECT_EQ(registry().run(tree, box, "primitiveSphere", {{"divisions", std::int64_t{2}}}).error,
            "primitiveSphere: parameter 'divisions' must be >= 3; got 2");
}

// A unit quad at `at` facing `n` (unit), as one face of `mesh`.
void add_quad(kernel::Mesh& mesh, Vec3 at, Vec3 n) {
  Vec3 u =
      kernel::normalized(kernel::cross(std::fabs(n.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0}, n));
  const Vec3 v = kernel::cross(n, u);
  mesh.add_polygon(std::vector<Vec3>{at, at + u, at + u + v, at + v}, {});
}

TEST(CompSelectors, SlopeClassesByAngleToTheScopeXzPlane) {
  kernel::Mesh m;
  const double r = std::sqrt(0.5);
  add_quad(m, {0, 5, 0}, {0, 1, 0});                          // 0: up, horizontal
  add_quad(m, {2, 5, 2}, {0, r, r});                          // 1: 45 degrees up, aslant
  add_quad(m, {4, 5, 4}, {1, 0, 0});                          // 2: vertical
  add_quad(m, {6, 5, 6}, {0, -r, r});                         // 3: 45 degrees down, nutant
  add_quad(m, {8, 5, 8}, {0, -1, 0});                         // 4: down, horizontal
  add_quad(m, {9, 5, 9}, {0, std::sin(0.1), std::cos(0.1)});  // 5: 5.7 degrees up, vertical
  const auto pieces = [&](const char* selector) {
    ShapeTree tree;
    Scope scope;
    scope.size = {10, 10, 10};
    const ShapeId id = tree.add_root(scope, std::make_shared<kernel::Mesh>(m));
    const OpResult result = registry().run(tree, id, "comp", {{"select", std::string(selector)}});
    EXPECT_TRUE(result.ok()) << result.error;
    return result.pieces;
  };
  using V = std::vector<std::uint32_t>;
  EXPECT_EQ(pieces("horizontal"), (V{0, 4}));
  EXPECT_EQ(pieces("aslant"), (V{1}));
  EXPECT_EQ(pieces("vertical"), (V{2, 5}));
  EXPECT_EQ(pieces("nutant"), (V{3}));
}

TEST(CompFaceEdges, OneLineScopePerEdgeOfEveryFace) {
  ShapeTree tree;
  Scope scope;
  scope.size = {2, 3, 4};
  const ShapeId box = tree.add_root(scope, box_mesh(scope.size, mass_box_tags()));
  const OpResult r = registry().run(tree, box, "comp", {{"type", std::string("faceedges")}});
  ASSERT_TRUE(r.ok()) << r.error;
  ASSERT_EQ(r.children.size(), 24U);  // 6 faces x 4 edges: shared edges once per face
  double total = 0;
  std::size_t up = 0;
  for (ShapeId c : r.children) {
    const Scope& e = tree[c].scope;
    total += e.size.x;
    EXPECT_NEAR(kernel::dot(kernel::cross(e.x, e.y), e.z), 1, 1e-12);
    if (e.y.y < 0.5) continue;
    // An edge of the top face: z points away from the face's centre, in its plane.
    ++up;
    const Vec3 mid = e.origin + e.x * (e.size.x / 2);
    EXPECT_NEAR(e.z.y, 0, 1e-12);
    EXPECT_GT(kernel::dot(e.z, mid - Vec3{1, 3, 2}), 0);
  }
  EXPECT_NEAR(total, 72, 1e-9);  // the faces' perimeters
  EXPECT_EQ(up, 4U);
}

TEST(ObjectFrame, TheContextNamesTheInitialShape) {
  ShapeTree tree;
  Scope scope;
  scope.size = {2, 2, 2};
  const ShapeId id = tree.add_root(scope, box_mesh(scope.size, mass_box_tags()));
  // A footprint scope turned 90 degrees: x north, normal up.
  Scope object;
  object.origin = {5, 5, 0};
  object.x = {0, 1, 0};
  object.y = {-1, 0, 0};
  object.z = {0, 0, 1};
  object.size = {10, 10, 0};
  Context context;
  context.object = &object;
  const OpResult r = registry().run(
      tree, id, "translate",
      {{"x", 2.0}, {"y", 1.0}, {"mode", std::string("abs")}, {"frame", std::string("object")}},
      context);
  ASSERT_TRUE(r.ok()) << r.error;
  // Object x is north, object y is the footprint's normal (up).
  expect_near(tree[r.children[0]].scope.origin, {5, 7, 1});
  const OpResult a =
      registry().run(tree, id, "alignScopeToAxes", {{"", std::string("object.xyz")}}, context);
  ASSERT_TRUE(a.ok()) << a.error;
  expect_near(tree[a.children[0]].scope.x, {0, 1, 0});
  expect_near(tree[a.children[0]].scope.y, {0, 0, 1});
}

bool is_convex(const kernel::Ring& ring) {
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Vec2 a = ring[i];
    const Vec2 b = ring[(i + 1) % ring.size()];
    const Vec2 c = ring[(i + 2) % ring.size()];
    if (kernel::cross(b - a, c - b) < -1e-9) return false;
  }
  return true;
}

TEST(Convexify, ConvexPiecesTileTheShape) {
  ShapeTree tree;
  const ShapeId l = lot(tree, {{{0, 0}, {10, 0}, {10, 5}, {4, 5}, {4, 10}, {0, 10}}, {}});
  const OpResult r = registry().run(tree, l, "convexify", {});
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(r.children.size(), 2U);  // one reflex corner: two pieces
  double area = 0;
  for (ShapeId c : r.children) {
    EXPECT_TRUE(is_convex(tree[c].outline->outer));
    area += kernel::area(*tree[c].outline);
  }
  EXPECT_NEAR(area, 70, 1e-9);
  // A square with a square hole: convex pieces around the hole.
  const ShapeId h =
      lot(tree, {{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{{4, 4}, {4, 6}, {6, 6}, {6, 4}}}});
  const OpResult rh = registry().run(tree, h, "convexify", {});
  ASSERT_TRUE(rh.ok()) << rh.error;
  double ah = 0;
  for (ShapeId c : rh.children) {
    EXPECT_TRUE(is_convex(tree[c].outline->outer));
    ah += kernel::area(*tree[c].outline);
  }
  EXPECT_NEAR(ah, 96, 1e-9);
  EXPECT_GE(rh.children.size(), 4U);
  // maxLength 1: every cut line is longer, so the L stays whole.
  const ShapeId k = lot(tree, {{{0, 0}, {10, 0}, {10, 5}, {4, 5}, {4, 10}, {0, 10}}, {}});
  const OpResult rk = registry().run(tree, k, "convexify", {{"", 1.0}});
  ASSERT_EQ(rk.children.size(), 1U);
  EXPECT_NEAR(kernel::area(*tree[rk.children[0]].outline), 70, 1e-9);
  Scope scope;
  scope.size = {1, 1, 1};
  const ShapeId box = tree.add_root(scope, box_mesh(scope.size, mass_box_tags()));
  EXPECT_EQ(registry().run(tree, box, "convexify", {}).error,
            "convexify: needs a flat shape (a footprint or a face)");
}

TEST(SplitArea, PiecesHaveTheGivenAreas) {
  ShapeTree tree;
  const ShapeId rect = lot(tree, {{{0, 0}, {10, 0}, {10, 4}, {0, 4}}, {}});
  const OpResult r = registry().run(
      tree, rect, "splitArea",
      {{"", std::string("x")},
       {"", std::vector<SizeSpec>{{10, SizeMode::kAbsolute}, {1, SizeMode::kFloating}}}});
  ASSERT_TRUE(r.ok()) << r.error;
  ASSERT_EQ(r.children.size(), 2U);
  EXPECT_NEAR(kernel::area(*tree[r.children[0]].outline), 10, 1e-9);
  EXPECT_NEAR(tree[r.children[0]].scope.size.x, 2.5, 1e-9);
  EXPECT_NEAR(kernel::area(*tree[r.children[1]].outline), 30, 1e-9);
  EXPECT_EQ(r.pieces, (std::vector<std::uint32_t>{0, 1}));
  // A right triangle halved by area: the cut is at 4 - 2 sqrt(2), not at the middle.
  const ShapeId tri = lot(tree, {{{0, 0}, {4, 0}, {0, 4}}, {}});
  const OpResult t = registry().run(
      tree, tri, "splitArea",
      {{"", std::string("x")},
       {"", std::vector<SizeSpec>{{0.5, SizeMode::kRelative}, {1, SizeMode::kFloating}}}});
  ASSERT_TRUE(t.ok()) << t.error;
  ASSERT_EQ(t.children.size(), 2U);
  EXPECT_NEAR(kernel::area(*tree[t.children[0]].outline), 4, 1e-9);
  EXPECT_NEAR(kernel::area(*tree[t.children[1]].outline), 4, 1e-9);
  EXPECT_NEAR(tree[t.children[0]].scope.size.x, 4 - 2 * std::sqrt(2.0), 1e-9);
  Scope scope;
  scope.size = {1, 1, 1};
  const ShapeId box = tree.add_root(scope, box_mesh(scope.size, mass_box_tags()));
  EXPECT_EQ(registry().run(tree, box, "splitArea", {{"", std::string("x")}, {"", 1.0}}).error,
            "splitArea: needs a flat shape (a footprint or a face)");
}

TEST(Trim, IsAcceptedWithAWarning) {
  ShapeTree tree;
  Scope scope;
  scope.size = {1, 2, 3};
  const ShapeId box = tree.add_root(scope, box_mesh(scope.size, mass_box_tags()));
  const OpResult r = registry().run(tree, box, "trim", {});
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.warning, "trim planes are not made in Insula: trim() leaves the shape unchanged");
  EXPECT_EQ(tree[r.children[0]].mesh, tree[box].mesh);
  expect_near(tree[r.children[0]].scope.size, {1, 2, 3});
}

}  // namespace
}  // namespace insula::shape

namespace insula::shape {
namespace {

TEST(ConvertBetweenFrames, PositionsAndOrientations) {
  // A volume scope 5 m east, 2 m north, turned 90 degrees about the vertical: its x points north.
  Scope scope;
  scope.origin = {5, 2, 0};
  scope.x = {0, 1, 0};
  scope.y = {0, 0, 1};
  scope.z = {1, 0, 0};
  scope.size = {4, 3, 2};
  // Its origin in the world (x east, y up, z south).
  const kernel::Vec3 origin =
      convert_between_frames(Frame::kScope, Frame::kWorld, false, {0, 0, 0}, scope, nullptr);
  EXPECT_NEAR(origin.x, 5, 1e-12);
  EXPECT_NEAR(origin.y, 0, 1e-12);
  EXPECT_NEAR(origin.z, -2, 1e-12);
  // A point 1 m along its x is 1 m further north (world z - 1).
  const kernel::Vec3 ahead =
      convert_between_frames(Frame::kScope, Frame::kWorld, false, {1, 0, 0}, scope, nullptr);
  EXPECT_NEAR(ahead.z, -3, 1e-12);
  // And back.
  const kernel::Vec3 back =
      convert_between_frames(Frame::kWorld, Frame::kScope, false, ahead, scope, nullptr);
  EXPECT_NEAR(back.x, 1, 1e-12);
  EXPECT_NEAR(back.y, 0, 1e-12);
  EXPECT_NEAR(back.z, 0, 1e-12);
  // Its orientation against the world: a quarter turn about the vertical (y).
  const kernel::Vec3 turn =
      convert_between_frames(Frame::kScope, Frame::kWorld, true, {0, 0, 0}, scope, nullptr);
  EXPECT_NEAR(turn.x, 0, 1e-9);
  EXPECT_NEAR(std::fabs(turn.y), 90, 1e-9);
  EXPECT_NEAR(turn.z, 0, 1e-9);
  // Orientation round trip through the world.
  const kernel::Vec3 angles{-10, 70, 15};
  const kernel::Vec3 w =
      convert_between_frames(Frame::kScope, Frame::kWorld, true, angles, scope, nullptr);
  const kernel::Vec3 again =
      convert_between_frames(Frame::kWorld, Frame::kScope, true, w, scope, nullptr);
  EXPECT_NEAR(again.x, angles.x, 1e-9);
  EXPECT_NEAR(again.y, angles.y, 1e-9);
  EXPECT_NEAR(again.z, angles.z, 1e-9);
}

}  // namespace
}  // namespace insula::shape
