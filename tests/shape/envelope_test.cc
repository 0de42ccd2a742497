// CityEngine's envelope in the registry (docs/operations-cityengine.md, "envelope"): the prism up
// to the maximum height cut by a plane per edge that rises from the edge's base height.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <set>

#include "kernel/mesh.h"
#include "kernel/roof_solid.h"
#include "shape/ops.h"

namespace insula::shape {
namespace {

using kernel::Polygon;
using kernel::Vec3;

const Polygon kRect = {{{0, 0}, {20, 0}, {20, 10}, {0, 10}}, {}};
// An L: [0, 10] x [0, 5] and [0, 4] x [0, 10] (70 m²), concave at (4, 5).
const Polygon kL = {{{0, 0}, {10, 0}, {10, 5}, {4, 5}, {4, 10}, {0, 10}}, {}};

ShapeId lot(ShapeTree& tree, const Polygon& footprint) {
  const RootResult r = tree.create_root(footprint);
  EXPECT_TRUE(r.ok()) << r.error;
  return r.id;
}

OpResult run(ShapeTree& tree, ShapeId id, std::vector<ArgInput> args) {
  return registry().run(tree, id, "envelope", args);
}

std::vector<ArgInput> uniform(double max_height, double base, double angle) {
  return {{"", std::string("world.up")}, {"", max_height}, {"", base}, {"", angle}};
}

kernel::Mesh world_mesh(const ShapeTree& tree, const OpResult& r) {
  EXPECT_EQ(r.children.size(), 1U);
  const Shape& s = tree[r.children.front()];
  return mesh_to_world(*s.mesh, s.scope);
}

double degrees_from_horizontal(Vec3 n) {
  return std::acos(std::clamp(n.z, -1.0, 1.0)) * 180 / std::numbers::pi;
}

// 20 x 10, base 6, 45 degrees on all sides, max 10. A point d meters from the nearest edge is
// covered up to min(10, 6 + d); d reaches 5 on the long axis, so the planes are cut at d = 4 by the
// flat top, a 12 x 2 rectangle. V = 6 * 200 + integral over t in [0, 4] of the area where d >= t,
// (20 - 2t)(10 - 2t): 200 t - 30 t² + 4/3 t³ at 4 = 800 - 480 + 256/3. V = 1200 + 1216/3.
TEST(Envelope, RectangleVolumeTopAndSlopes) {
  ShapeTree tree;
  const ShapeId l = lot(tree, kRect);
  const OpResult r = run(tree, l, uniform(10, 6, 45));
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_FALSE(tree[l].active);
  const kernel::Mesh m = world_mesh(tree, r);
  EXPECT_TRUE(kernel::is_watertight(m));
  EXPECT_NEAR(kernel::volume(m), 1200 + 1216.0 / 3, 1e-4);
  double top_area = 0;
  std::set<std::uint32_t> slopes;  // face ids: the result of the booleans is triangles
  for (std::size_t f = 0; f < m.face_count(); ++f) {
    const Vec3 n = kernel::face_normal(m, f);
    const double tilt = degrees_from_horizontal(n);
    for (std::uint32_t v : m.face(f)) {
      const double z = m.position(v).z;
      if (tilt < 1e-6) {
        EXPECT_NEAR(z, 10, 1e-9);  // the flat top at max height
      } else if (tilt < 89.999) {
        EXPECT_GE(z, 6 - 1e-9);  // slopes start at the base height
      } else if (std::fabs(tilt - 90) < 1e-6) {
        EXPECT_LE(z, 6 + 1e-9);  // walls end there
      }
    }
    if (tilt < 1e-6) top_area += kernel::face_area(m, f);
    // Slivers as wide as the zones' overlap (1e-5 m) have normals only as good as their size.
    if (tilt > 1e-6 && tilt < 89.999 && kernel::face_area(m, f) > 1e-4) {
      EXPECT_NEAR(tilt, 45, 1e-6);
      EXPECT_EQ(m.tag(f).semantic, kernel::SemanticClass::kRoofSurface);
      slopes.insert(m.tag(f).face_id);
    }
  }
  EXPECT_NEAR(top_area, 12 * 2, 1e-4);
  EXPECT_EQ(slopes.size(), 4U);
  // The child stands like an extrusion: scope y up, sized to the envelope.
  const Shape& child = tree[r.children.front()];
  EXPECT_NEAR(child.scope.y.z, 1, 1e-12);
  EXPECT_NEAR(child.scope.size.y, 10, 1e-9);
}

// Only the back (the edge at y = 10, facing away from the lot's first edge) slopes: a cross
// section in y is min(10, 6 + (10 - y)), so V = 20 * (6 * 10 + 4 * 4 / 2 + 4 * 6) = 20 * 92.
TEST(Envelope, FrontBackAndSidesTakeTheirOwnValues) {
  ShapeTree tree;
  const ShapeId l = lot(tree, kRect);
  const OpResult r = run(tree, l,
                         {{"", std::string("normal")},
                          {"", 10.0},
                          {"", 0.0},
                          {"", 90.0},
                          {"", 6.0},
                          {"", 45.0},
                          {"", 0.0},
                          {"", 90.0}});
  ASSERT_TRUE(r.ok()) << r.error;
  const kernel::Mesh m = world_mesh(tree, r);
  EXPECT_TRUE(kernel::is_watertight(m));
  EXPECT_NEAR(kernel::volume(m), 20 * 92, 1e-4);
  for (std::size_t f = 0; f < m.face_count(); ++f) {
    const Vec3 n = kernel::face_normal(m, f);
    const double tilt = degrees_from_horizontal(n);
    if (tilt > 1e-6 && tilt < 89.999) {
      EXPECT_GT(n.y, 0);  // the slope faces the back
    }
  }
}

// Esri's Candler Building rules: envelope(world.up, 0.6, 0.45, 45, 0.45, 45, 0.45, 45), one form
// with front, back and side pairs; the envelope is lower than the base heights' prism's top.
TEST(Envelope, CandlerFormWithSidePairs) {
  ShapeTree tree;
  const ShapeId l = lot(tree, kRect);
  const OpResult r = run(tree, l,
                         {{"", std::string("world.up")},
                          {"", 0.6},
                          {"", 0.45},
                          {"", 45.0},
                          {"", 0.45},
                          {"", 45.0},
                          {"", 0.45},
                          {"", 45.0}});
  ASSERT_TRUE(r.ok()) << r.error;
  const kernel::Mesh m = world_mesh(tree, r);
  EXPECT_TRUE(kernel::is_watertight(m));
  // min(0.6, 0.45 + d): the top is cut at d = 0.15, an inner 19.7 x 9.7 rectangle;
  // V = 0.45 * 200 + integral over [0, 0.15] of (20 - 2t)(10 - 2t).
  const double t = 0.15;
  EXPECT_NEAR(kernel::volume(m), 0.45 * 200 + 200 * t - 30 * t * t + 4 * t * t * t / 3, 1e-4);
}

// With one base height and angle and no maximum in reach, the envelope of an L is the hip roof
// (the kernel's straight skeleton roof) standing on the prism of the base height: each inner
// edge's plane governs only its side of the valley at the reflex corner (4, 5).
TEST(Envelope, ConcaveLIsTheHipRoofOnItsBase) {
  ShapeTree tree;
  const OpResult r = run(tree, lot(tree, kL), uniform(20, 3, 45));
  ASSERT_TRUE(r.ok()) << r.error;
  const kernel::Mesh m = world_mesh(tree, r);
  EXPECT_TRUE(kernel::is_watertight(m));
  kernel::RoofSolidSpec hip;
  hip.roof.type = kernel::RoofType::kHip;
  hip.roof.pitch_deg = 45;
  const kernel::RoofSolid roof = kernel::build_roof_solid(kL, hip, 0);
  ASSERT_FALSE(roof.mesh.empty());
  EXPECT_NEAR(kernel::volume(m), 70 * 3 + kernel::volume(roof.mesh), 1e-3);
  // Cut by a maximum: still closed, between the base prism and the full height.
  ShapeTree low;
  const OpResult c = run(low, lot(low, kL), uniform(4, 3, 60));
  ASSERT_TRUE(c.ok()) << c.error;
  const kernel::Mesh cm = world_mesh(low, c);
  EXPECT_TRUE(kernel::is_watertight(cm));
  EXPECT_GT(kernel::volume(cm), 70 * 3);
  EXPECT_LT(kernel::volume(cm), 70 * 4);
  // Vertical angles leave the prism.
  ShapeTree plain;
  const OpResult p = run(plain, lot(plain, kL), uniform(8, 3, 90));
  ASSERT_TRUE(p.ok()) << p.error;
  EXPECT_NEAR(kernel::volume(world_mesh(plain, p)), 70 * 8, 1e-9);
}

TEST(Envelope, BadInputFailsWithAReason) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto error_of = [](std::vector<ArgInput> args) {
    ShapeTree tree;
    const OpResult r = run(tree, lot(tree, kRect), std::move(args));
    EXPECT_FALSE(r.ok());
    EXPECT_TRUE(r.children.empty());
    return r.error;
  };
  EXPECT_NE(error_of(uniform(10, -1, 45)).find("front_base_height"), std::string::npos);
  EXPECT_NE(error_of(uniform(10, 6, 95)).find("front_angle"), std::string::npos);
  EXPECT_NE(error_of(uniform(10, 6, -5)).find("front_angle"), std::string::npos);
  EXPECT_NE(error_of(uniform(nan, 6, 45)).find("height"), std::string::npos);
  EXPECT_NE(error_of(uniform(10, nan, 45)).find("height"), std::string::npos);
  EXPECT_NE(error_of(uniform(10, 6, nan)).find("angle"), std::string::npos);
  EXPECT_NE(error_of(uniform(0, 6, 45)).find("height"), std::string::npos);
  // Not flat: the extruded mass.
  ShapeTree tree;
  const OpResult mass = extrude(tree, lot(tree, kRect), 5);
  ASSERT_TRUE(mass.ok());
  const OpResult r = run(tree, mass.children.front(), uniform(10, 6, 45));
  EXPECT_NE(r.error.find("flat"), std::string::npos);
  // The typed call checks too.
  EnvelopeSpec spec;
  spec.max_height = 10;
  spec.left.base_height = nan;
  ShapeTree direct;
  EXPECT_NE(envelope(direct, lot(direct, kRect), spec).error.find("base height"),
            std::string::npos);
  spec.left = {0, 120};
  EXPECT_NE(envelope(direct, lot(direct, kRect), spec).error.find("angle"), std::string::npos);
  // Angle 0 at base 0 cuts everything away.
  EXPECT_NE(error_of(uniform(10, 0, 0)).find("no volume"), std::string::npos);
}

}  // namespace
}  // namespace insula::shape
