// The S3DB roof shapes (gambrel, half-hipped, saltbox, round, dome, onion), roof height, direction
// and orientation, and roofs on posts (building=roof), checked by their geometry through
// build_mass (docs/kernel-roofs.md, "S3DB shapes").
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "footprints.h"
#include "kernel/mass.h"
#include "kernel/roof_solid.h"

namespace insula::kernel {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kEave = 6;

Polygon rectangle(double l, double w) {
  return {{{0, 0}, {l, 0}, {l, w}, {0, w}}, {}};
}
using testing_footprints::circle;
Polygon l_shape() {
  return {{{0, 0}, {14, 0}, {14, 6}, {6, 6}, {6, 12}, {0, 12}}, {}};
}
Polygon u_shape() {
  return {{{0, 0}, {18, 0}, {18, 14}, {12, 14}, {12, 6}, {6, 6}, {6, 14}, {0, 14}}, {}};
}

MassResult build(const Polygon& p, RoofType type, const MassSpec& base = {}) {
  MassSpec spec = base;
  spec.wall_height = kEave;
  spec.roof = type;
  return build_mass(p, spec);
}

void expect_closed(const MassResult& r) {
  ASSERT_NE(r.status, MassStatus::kFailed) << r.message;
  const MeshCheck c = check(r.mesh);
  EXPECT_TRUE(c.closed);
  EXPECT_TRUE(c.oriented);
  EXPECT_GT(volume(r.mesh), 0);
  for (std::size_t f = 0; f < r.mesh.face_count(); ++f) {
    const Vec3 n = face_normal(r.mesh, f);
    const Vec3 p0 = r.mesh.position(r.mesh.face(f)[0]);
    for (std::uint32_t v : r.mesh.face(f)) {
      ASSERT_NEAR(dot(r.mesh.position(v) - p0, n), 0, 1e-7) << "face " << f << " not planar";
    }
  }
}

// Vertices of roof faces.
std::vector<Vec3> roof_points(const Mesh& m) {
  std::set<std::uint32_t> ids;
  for (std::size_t f = 0; f < m.face_count(); ++f) {
    if (m.tag(f).semantic != SemanticClass::kRoofSurface) continue;
    for (std::uint32_t v : m.face(f)) ids.insert(v);
  }
  std::vector<Vec3> out;
  for (std::uint32_t v : ids) out.push_back(m.position(v));
  return out;
}

double top(const Mesh& m) {
  double z = -1e300;
  for (const Vec3& p : m.positions()) z = std::max(z, p.z);
  return z;
}

// The vertices within 1 mm of the top.
std::vector<Vec3> highest(const Mesh& m) {
  std::vector<Vec3> out;
  const double z = top(m);
  for (const Vec3& p : m.positions()) {
    if (p.z > z - 1e-3) out.push_back(p);
  }
  return out;
}

int count(const Mesh& m, SemanticClass semantic) {
  int n = 0;
  for (std::size_t f = 0; f < m.face_count(); ++f) n += m.tag(f).semantic == semantic;
  return n;
}

TEST(RoofShapes, NamesIncludeTheS3dbSpellings) {
  for (RoofType t : kRoofTypes) EXPECT_EQ(roof_type_from_name(roof_type_name(t)), t);
  const std::vector<std::pair<std::string, RoofType>> s3db = {
      {"flat", RoofType::kFlat},
      {"skillion", RoofType::kShed},
      {"gabled", RoofType::kGable},
      {"half-hipped", RoofType::kHalfHipped},
      {"hipped", RoofType::kHip},
      {"pyramidal", RoofType::kPyramid},
      {"gambrel", RoofType::kGambrel},
      {"mansard", RoofType::kMansard},
      {"dome", RoofType::kDome},
      {"onion", RoofType::kOnion},
      {"round", RoofType::kRound},
      {"saltbox", RoofType::kSaltbox},
      {"Half_Hipped", RoofType::kHalfHipped}};
  for (const auto& [name, type] : s3db) EXPECT_EQ(roof_type_from_name(name), type) << name;
  EXPECT_FALSE(roof_type_from_name("cone").has_value());
}

TEST(RoofShapes, GableHeightAndOrientation) {
  MassSpec spec;
  spec.height = 3;
  const MassResult along = build(rectangle(10, 6), RoofType::kGable, spec);
  expect_closed(along);
  EXPECT_NEAR(top(along.mesh), kEave + 3, 1e-9);
  for (const Vec3& p : highest(along.mesh)) EXPECT_NEAR(p.y, 3, 1e-9);  // ridge along x (10 m)
  EXPECT_EQ(highest(along.mesh).size(), 2U);

  spec.orientation = RidgeOrientation::kAcross;
  const MassResult across = build(rectangle(10, 6), RoofType::kGable, spec);
  expect_closed(across);
  EXPECT_NEAR(top(across.mesh), kEave + 3, 1e-9);
  for (const Vec3& p : highest(across.mesh)) EXPECT_NEAR(p.x, 5, 1e-9);  // ridge along y (6 m)

  // roof:direction 0 (north-facing slope): the ridge runs east-west whatever the orientation.
  spec.direction_deg = 0;
  const MassResult north = build(rectangle(6, 10), RoofType::kGable, spec);
  expect_closed(north);
  for (const Vec3& p : highest(north.mesh)) EXPECT_NEAR(p.y, 5, 1e-9);
}

// A rectangle barely longer than wide, with overhang: the overhanging eave polygon (gable ends
// flush) is wider than long, and its skeleton used to put the gables on the other edges, so the
// gable fell back to hip. Quadrilaterals now take the ridge from the footprint.
TEST(RoofShapes, OverhangDoesNotTurnOrLoseTheGable) {
  const double a = 0.4;
  const Polygon p{{{0, 0},
                   {6.5 * std::cos(a), 6.5 * std::sin(a)},
                   {6.5 * std::cos(a) - 6 * std::sin(a), 6.5 * std::sin(a) + 6 * std::cos(a)},
                   {-6 * std::sin(a), 6 * std::cos(a)}},
                  {}};
  MassSpec spec;
  spec.overhang = 0.5;
  const MassResult r = build(p, RoofType::kGable, spec);
  expect_closed(r);
  EXPECT_EQ(r.status, MassStatus::kOk) << r.message;
  EXPECT_EQ(r.roof, RoofType::kGable);
  // The ridge joins the midpoints of the 6 m ends (lifted), parallel to the 6.5 m sides.
  const std::vector<Vec3> ridge = highest(r.mesh);
  ASSERT_EQ(ridge.size(), 2U);
  EXPECT_NEAR(length(drop(ridge[0]) - drop(ridge[1])), 6.5, 1e-9);
}

TEST(RoofShapes, HeightOverridesThePitch) {
  for (RoofType t : {RoofType::kHip, RoofType::kPyramid, RoofType::kMansard, RoofType::kGambrel,
                     RoofType::kHalfHipped, RoofType::kSaltbox, RoofType::kRound, RoofType::kDome,
                     RoofType::kOnion, RoofType::kShed}) {
    MassSpec spec;
    spec.height = 4.5;
    const MassResult r = build(rectangle(12, 8), t, spec);
    SCOPED_TRACE(std::string(roof_type_name(t)));
    expect_closed(r);
    EXPECT_EQ(r.roof, t);
    EXPECT_NEAR(top(r.mesh), kEave + 4.5, 1e-9);
  }
}

TEST(RoofShapes, ShedFallsTowardItsDirection) {
  MassSpec spec;
  spec.direction_deg = 90;  // looks east: low edge east, high edge west
  spec.height = 2;
  const MassResult r = build(rectangle(10, 6), RoofType::kShed, spec);
  expect_closed(r);
  for (const Vec3& p : roof_points(r.mesh)) EXPECT_NEAR(p.z, kEave + 2 * (10 - p.x) / 10, 1e-9);
  // Any footprint: on the L, north-facing, the southern edge is the high one.
  spec.direction_deg = 0;
  const MassResult l = build(l_shape(), RoofType::kShed, spec);
  expect_closed(l);
  for (const Vec3& p : roof_points(l.mesh)) EXPECT_NEAR(p.z, kEave + 2 * (12 - p.y) / 12, 1e-9);
}

TEST(RoofShapes, GambrelHasTwoSlopesPerSideAndGableEnds) {
  const MassResult r = build(rectangle(12, 8), RoofType::kGambrel);
  expect_closed(r);
  EXPECT_EQ(r.status, MassStatus::kOk);
  EXPECT_EQ(count(r.mesh, SemanticClass::kRoofSurface), 4);
  EXPECT_EQ(count(r.mesh, SemanticClass::kWallSurface), 4);
  // Lower slope 70 degrees up to the 2.5 m break, upper 30 degrees to the ridge at y = 4.
  const double t = 2.5 / std::tan(70 * kPi / 180);
  const double ridge = kEave + 2.5 + (4 - t) * std::tan(30 * kPi / 180);
  std::set<long> levels;
  for (const Vec3& p : roof_points(r.mesh)) levels.insert(std::lround((p.z - kEave) * 1000));
  EXPECT_EQ(levels, (std::set<long>{0, 2500, std::lround((ridge - kEave) * 1000)}));
  for (const Vec3& p : highest(r.mesh)) EXPECT_NEAR(p.y, 4, 1e-9);
}

TEST(RoofShapes, HalfHippedClipsTheGableHalfwayUp) {
  const MassResult r = build(rectangle(12, 8), RoofType::kHalfHipped);
  expect_closed(r);
  EXPECT_EQ(count(r.mesh, SemanticClass::kRoofSurface), 4);  // 2 slopes, 2 small hips
  const double h = 4 * std::tan(30 * kPi / 180);
  EXPECT_NEAR(top(r.mesh), kEave + h, 1e-9);
  // The ridge is set back from each end by the hip's run (2 m at the same pitch).
  for (const Vec3& p : highest(r.mesh))
    EXPECT_TRUE(std::abs(p.x - 2) < 1e-9 || std::abs(p.x - 10) < 1e-9);
  // Each end wall is a pentagon up to half the roof height.
  for (std::size_t f = 0; f < r.mesh.face_count(); ++f) {
    if (r.mesh.tag(f).semantic != SemanticClass::kWallSurface || r.mesh.face(f).size() != 6) {
      continue;
    }
    double z = 0;
    for (std::uint32_t v : r.mesh.face(f)) z = std::max(z, r.mesh.position(v).z);
    EXPECT_NEAR(z, kEave + h / 2, 1e-9);
  }
}

TEST(RoofShapes, SaltboxHasItsRidgeAThirdAcross) {
  const MassResult r = build(rectangle(12, 9), RoofType::kSaltbox);
  expect_closed(r);
  EXPECT_EQ(count(r.mesh, SemanticClass::kRoofSurface), 2);
  // The long side (6 m) at the pitch; the short side (3 m) twice as steep.
  EXPECT_NEAR(top(r.mesh), kEave + 6 * std::tan(30 * kPi / 180), 1e-9);
  for (const Vec3& p : highest(r.mesh))
    EXPECT_TRUE(std::abs(p.y - 3) < 1e-9 || std::abs(p.y - 6) < 1e-9);
  // With a direction, the long side faces it: south-facing puts the ridge 3 m from the north.
  MassSpec spec;
  spec.direction_deg = 180;
  const MassResult south = build(rectangle(12, 9), RoofType::kSaltbox, spec);
  expect_closed(south);
  for (const Vec3& p : highest(south.mesh)) EXPECT_NEAR(p.y, 6, 1e-9);
}

TEST(RoofShapes, RoundIsAHalfCylinder) {
  const MassResult r = build(rectangle(12, 8), RoofType::kRound);
  expect_closed(r);
  EXPECT_GE(count(r.mesh, SemanticClass::kRoofSurface), 12);
  // Every roof vertex lies on the circle of radius 4 over the ridge line y = 4.
  for (const Vec3& p : roof_points(r.mesh)) {
    EXPECT_NEAR(std::hypot(p.y - 4, p.z - kEave), 4, 1e-9);
  }
  EXPECT_NEAR(top(r.mesh), kEave + 4, 1e-9);
}

TEST(RoofShapes, DomeOverACircleIsAHemisphere) {
  const MassResult r = build(circle(48, 5), RoofType::kDome);
  expect_closed(r);
  for (const Vec3& p : roof_points(r.mesh)) {
    const double radial = std::hypot(p.x, p.y);
    // The rings scale the 48-gon's corners (radius 5), the top is its inradius: within 0.6 %.
    EXPECT_NEAR(std::hypot(radial, p.z - kEave), 5, 0.03);
  }
  EXPECT_NEAR(top(r.mesh), kEave + 5 * std::cos(kPi / 48), 1e-6);
  // Cylinder plus hemisphere, both of the inscribed 48-gon; the 8 rings cost a few percent.
  const double rr = 5 * std::cos(kPi / 48);
  const double expected = kPi * rr * rr * kEave + 2.0 / 3 * kPi * rr * rr * rr;
  EXPECT_NEAR(volume(r.mesh), expected, 0.03 * expected);
}

TEST(RoofShapes, OnionBulgesBeyondTheWalls) {
  const MassResult r = build(circle(32, 4), RoofType::kOnion);
  expect_closed(r);
  double widest = 0;
  for (const Vec3& p : roof_points(r.mesh)) widest = std::max(widest, std::hypot(p.x, p.y));
  EXPECT_GT(widest, 4 * 1.2);
  EXPECT_NEAR(top(r.mesh), kEave + 2 * 4 * std::cos(kPi / 32), 1e-6);
}

TEST(RoofShapes, UndefinedFootprintsFallBackWithAMessage) {
  const MassResult gambrel = build(l_shape(), RoofType::kGambrel);
  expect_closed(gambrel);
  EXPECT_EQ(gambrel.status, MassStatus::kFallback);
  EXPECT_EQ(gambrel.roof, RoofType::kMansard);
  EXPECT_EQ(gambrel.message,
            "gambrel roof could not be built; mansard roof instead (roof faces: the footprint is "
            "not a quadrilateral with two opposite ends)");
  for (RoofType t : {RoofType::kRound, RoofType::kSaltbox, RoofType::kHalfHipped}) {
    const MassResult r = build(l_shape(), t);
    expect_closed(r);
    EXPECT_EQ(r.roof, RoofType::kGable);
    EXPECT_EQ(r.status, MassStatus::kFallback);
  }
  const MassResult dome = build(u_shape(), RoofType::kDome);
  expect_closed(dome);
  EXPECT_EQ(dome.roof, RoofType::kHip);
  EXPECT_NE(dome.message.find("not star-shaped"), std::string::npos) << dome.message;
}

TEST(RoofShapes, RoofOnPostsHasNoWalls) {
  for (RoofType t : kRoofTypes) {
    MassSpec spec;
    spec.walls = false;
    const MassResult r = build(rectangle(10, 6), t, spec);
    SCOPED_TRACE(std::string(roof_type_name(t)));
    ASSERT_NE(r.status, MassStatus::kFailed) << r.message;
    const MeshCheck c = check(r.mesh);
    EXPECT_TRUE(c.closed);
    EXPECT_TRUE(c.oriented);
    EXPECT_EQ(c.components, 5U);  // the roof and 4 posts
    EXPECT_EQ(count(r.mesh, SemanticClass::kWallSurface), 0);
    EXPECT_GT(volume(r.mesh), 0);
    // Every post stands on the ground and reaches the roof's underside.
    int on_ground = 0;
    for (std::size_t f = 0; f < r.mesh.face_count(); ++f) {
      if (r.mesh.tag(f).semantic != SemanticClass::kGroundSurface) continue;
      ++on_ground;
      for (std::uint32_t v : r.mesh.face(f)) EXPECT_NEAR(r.mesh.position(v).z, 0, 1e-12);
    }
    EXPECT_EQ(on_ground, 4);
  }
  // A gable on posts: the slab's underside at the eave, the posts 0.25 m square up to it.
  MassSpec spec;
  spec.walls = false;
  const MassResult gable = build(rectangle(10, 6), RoofType::kGable, spec);
  const double roof_volume = 10 * 6 * 3 * std::tan(30 * kPi / 180) / 2;
  EXPECT_NEAR(volume(gable.mesh), roof_volume + 4 * 0.25 * 0.25 * kEave, 1e-9);
}

// Lowest z of the faces of one semantic class.
double lowest(const Mesh& m, SemanticClass semantic) {
  double z = 1e300;
  for (std::size_t f = 0; f < m.face_count(); ++f) {
    if (m.tag(f).semantic != semantic) continue;
    for (std::uint32_t v : m.face(f)) z = std::min(z, m.position(v).z);
  }
  return z;
}

// A roof height scales the rise above the eave, not the overhang's drop below it: a 2 x 1.5 m
// hip with a 0.5 m overhang and 4.5 m of roof had its soffit (and wall tops) 3.4 m below the
// eave, as a 1 m² .bldg part with a 3.5 m roof had its soffit under the ground.
TEST(RoofShapes, HeightKeepsTheSoffitOnTheWallTop) {
  MassSpec spec;
  spec.overhang = 0.5;
  spec.height = 4.5;
  for (RoofType t : {RoofType::kHip, RoofType::kGable, RoofType::kPyramid, RoofType::kMansard}) {
    SCOPED_TRACE(std::string(roof_type_name(t)));
    const MassResult r = build(rectangle(2, 1.5), t, spec);
    expect_closed(r);
    EXPECT_EQ(r.status, MassStatus::kOk) << r.message;
    EXPECT_NEAR(lowest(r.mesh, SemanticClass::kOuterCeilingSurface), kEave, 1e-9);
    EXPECT_NEAR(top(r.mesh), kEave + 4.5, 1e-9);
    for (std::size_t f = 0; f < r.mesh.face_count(); ++f) {
      if (r.mesh.tag(f).semantic != SemanticClass::kRoofSurface) continue;
      for (std::uint32_t v : r.mesh.face(f)) EXPECT_GE(r.mesh.position(v).z, kEave - 1e-9);
    }
  }
  // The closed roof solid of the .bldg builder stands on the eave the same way.
  RoofSolidSpec solid;
  solid.roof.overhang = 0.5;
  solid.height = 3.5;
  const RoofSolid roof = build_roof_solid(rectangle(1, 1), solid, 3.3);
  ASSERT_EQ(roof.status, RoofStatus::kOk) << roof.message;
  EXPECT_NEAR(roof.mesh.bounds().min.z, 3.3, 1e-9);
  EXPECT_NEAR(roof.mesh.bounds().max.z, 3.3 + 3.5, 1e-9);
}

// A 4.47 x 2.23 m near-parallelogram (an OpenStreetMap outline, as OBJ wrote its corners): both
// ends as wide within micrometres, and the crest between them a sliver that OBJ wrote as a
// degenerate triangle. Within 1 % of the half width the strips meet at the ridge, without crest.
TEST(RoofShapes, RoundHasNoSliverCrest) {
  const Polygon p{
      {{-0.989625, -0.837672}, {0.694063, 3.331284}, {2.768222, 2.492093}, {1.084535, -1.676864}},
      {}};
  const MassResult r = build(p, RoofType::kRound);
  expect_closed(r);
  EXPECT_EQ(count(r.mesh, SemanticClass::kRoofSurface), 12);
  for (std::size_t f = 0; f < r.mesh.face_count(); ++f) {
    EXPECT_GT(face_area(r.mesh, f), 1e-3) << "face " << f;
  }
}

// A rectangle with one more vertex 4 cm from a corner where the outline turns by 1 degree, as
// OpenStreetMap outlines have them: on a long side (a slope of the quadrilateral shapes) or a short
// one (an end).
Polygon near_rectangle(bool long_side) {
  const double off = 0.04 * std::tan(kPi / 180);
  if (long_side) return {{{0, 0}, {12, 0}, {12, 8}, {0.04, 8}, {0, 8 + off}}, {}};
  return {{{0, 0}, {12, 0}, {12, 8}, {0, 8}, {-off, 7.96}}, {}};
}

// Pyramid and the quadrilateral-only shapes see its four corners and build over all five vertices
// (they fell back to hip and gable).
TEST(RoofShapes, NearlyStraightVerticesDoNotHideAQuadrilateral) {
  for (bool long_side : {true, false}) {
    for (RoofType t : {RoofType::kPyramid, RoofType::kGambrel, RoofType::kHalfHipped,
                       RoofType::kSaltbox, RoofType::kRound}) {
      SCOPED_TRACE(std::string(roof_type_name(t)) + (long_side ? " long side" : " short side"));
      const MassResult r = build(near_rectangle(long_side), t);
      expect_closed(r);
      EXPECT_EQ(r.status, MassStatus::kOk) << r.message;
      EXPECT_EQ(r.roof, t);
      // Five walls, each from the ground; the roof within a millimetre of the rectangle's.
      EXPECT_EQ(count(r.mesh, SemanticClass::kWallSurface), 5);
      const MassResult plain = build(rectangle(12, 8), t);
      EXPECT_NEAR(top(r.mesh), top(plain.mesh), 1e-3);
      EXPECT_EQ(count(r.mesh, SemanticClass::kRoofSurface),
                count(plain.mesh, SemanticClass::kRoofSurface) + (t == RoofType::kPyramid));
    }
  }
  // A real corner is still one: an L is no quadrilateral.
  EXPECT_EQ(build(l_shape(), RoofType::kGambrel).roof, RoofType::kMansard);
}

// The same outlines as roofs on posts, with and without overhang: a vertex inside an end has its
// wall top up the end's slope (0.59 m on a half-hip), and the underside passed through it, folded
// (1.37 m on a gambrel with overhang, whose corners' wall tops are at the soffit) and open. Now it
// is flat at the lowest wall top, closed by a wall face up to that vertex.
TEST(RoofShapes, RoofOnPostsHasAFlatUndersideOverEndVertices) {
  for (bool long_side : {true, false}) {
    for (RoofType t : {RoofType::kGable, RoofType::kGambrel, RoofType::kHalfHipped,
                       RoofType::kSaltbox, RoofType::kHip}) {
      for (double overhang : {0.0, 0.5}) {
        SCOPED_TRACE(std::string(roof_type_name(t)) + (long_side ? " long side" : " short side") +
                     " overhang " + std::to_string(overhang));
        MassSpec spec;
        spec.walls = false;
        spec.overhang = overhang;
        const MassResult r = build(near_rectangle(long_side), t, spec);
        expect_closed(r);
        EXPECT_EQ(check(r.mesh).components, 6U);  // the roof and 5 posts
        // Every face seen from below lies at the eave or below it (a soffit), none above.
        for (std::size_t f = 0; f < r.mesh.face_count(); ++f) {
          if (r.mesh.tag(f).semantic != SemanticClass::kOuterCeilingSurface) continue;
          for (std::uint32_t v : r.mesh.face(f)) {
            EXPECT_LE(r.mesh.position(v).z, kEave + 1e-9) << "face " << f;
          }
        }
      }
    }
  }
}

// building=roof whose overhang brings the underside to the ground: built without the overhang,
// like a walled building, and reported the same way (it was dropped).
TEST(RoofShapes, RoofOnPostsDropsAnOverhangThatReachesTheGround) {
  MassSpec spec;
  spec.walls = false;
  spec.overhang = 2.5;  // a 70-degree mansard drops 6.9 m below the 6 m eave
  const MassResult r = build(rectangle(10, 6), RoofType::kMansard, spec);
  ASSERT_EQ(r.status, MassStatus::kFallback) << r.message;
  EXPECT_EQ(r.roof, RoofType::kMansard);
  EXPECT_EQ(r.message,
            "posts: the roof's underside is not above the ground; built without overhang");
  const MeshCheck c = check(r.mesh);
  EXPECT_TRUE(c.closed);
  EXPECT_EQ(c.components, 5U);
  EXPECT_NEAR(r.mesh.bounds().min.x, 0, 1e-12);  // no eave beyond the footprint
}

// Overhang on the quadrilateral shapes (docs/kernel-roofs.md, "Overhang"): gambrel, half-hipped and
// saltbox get eaves on their two slope sides and flush end walls, the roof over the wall line as
// without overhang. They were built without overhang ("gambrel roofs are built without overhang").

// A skewed quadrilateral as surveyed (no two edges parallel, ends not square to the sides), at
// local coordinates away from the origin.
Polygon skewed_quad() {
  const Vec2 o{431.7, -212.4};
  return {{o + Vec2{0, 0}, o + Vec2{12.4, 1.1}, o + Vec2{12.0, 9.3}, o + Vec2{-0.6, 8.0}}, {}};
}

// Signed distance of p from the line of edge e of `ring` (counter-clockwise), positive inside.
double inside_distance(const Ring& ring, std::size_t e, Vec2 p) {
  const Vec2 a = ring[e];
  const Vec2 d = normalized(ring[(e + 1) % ring.size()] - a);
  return cross(d, p - a);
}

// The lowest tangent of the roof's eaves: the lower slope of a gambrel, else the pitch.
double eave_tan(RoofType t) {
  return std::tan((t == RoofType::kGambrel ? 70 : 30) * kPi / 180);
}

TEST(RoofShapes, QuadrilateralShapesOverhangTheirSlopeSides) {
  constexpr double kOverhang = 0.5;
  for (const Polygon& p : {rectangle(12, 8), skewed_quad()}) {
    for (RoofType t : {RoofType::kGambrel, RoofType::kHalfHipped, RoofType::kSaltbox}) {
      SCOPED_TRACE(std::string(roof_type_name(t)) + (p.outer[0].x == 0 ? " rectangle" : " skewed"));
      MassSpec spec;
      spec.overhang = kOverhang;
      const MassResult r = build(p, t, spec);
      const MassResult plain = build(p, t);
      expect_closed(r);
      const MeshCheck c = check(r.mesh);
      EXPECT_EQ(c.boundary_edges, 0U);
      EXPECT_EQ(c.non_manifold_edges, 0U);
      EXPECT_EQ(c.components, 1U);
      EXPECT_EQ(r.status, MassStatus::kOk) << r.message;
      EXPECT_EQ(r.roof, t);
      EXPECT_EQ(r.message.find("without overhang"), std::string::npos) << r.message;

      // Edges 0 and 2 are the slopes (the longer pair), 1 and 3 the ends. The saltbox's steep
      // side (edge 0, twice the slope) overhangs half as far, so both eaves drop alike.
      const double steep = t == RoofType::kSaltbox ? kOverhang / 2 : kOverhang;
      const std::array<double, 4> out = {steep, 0, kOverhang, 0};
      for (std::size_t e = 0; e < 4; ++e) {
        double reach = 1e300;
        for (const Vec3& v : r.mesh.positions()) {
          reach = std::min(reach, inside_distance(p.outer, e, drop(v)));
        }
        EXPECT_NEAR(-reach, out[e], 1e-9) << "edge " << e;
      }

      // Soffits: horizontal, facing down, all at one height (saltbox too), joining the wall tops
      // to the eaves of the two slope sides.
      const double soffit_z = kEave - kOverhang * eave_tan(t);
      double soffit_area = 0;
      int soffits = 0;
      for (std::size_t f = 0; f < r.mesh.face_count(); ++f) {
        if (r.mesh.tag(f).semantic != SemanticClass::kOuterCeilingSurface) continue;
        ++soffits;
        soffit_area += face_area(r.mesh, f);
        EXPECT_NEAR(face_normal(r.mesh, f).z, -1, 1e-12);
        for (std::uint32_t v : r.mesh.face(f)) EXPECT_NEAR(r.mesh.position(v).z, soffit_z, 1e-9);
      }
      EXPECT_EQ(soffits, 2);
      const double sides =
          length(p.outer[1] - p.outer[0]) * steep + length(p.outer[3] - p.outer[2]) * kOverhang;
      EXPECT_NEAR(soffit_area, sides, 0.02 * sides);
      EXPECT_NEAR(lowest(r.mesh, SemanticClass::kRoofSurface), soffit_z, 1e-9);

      // Over the wall line the roof is the one without overhang: same ridge, same break and hip
      // points, every roof vertex above the eave still there.
      EXPECT_NEAR(top(r.mesh), top(plain.mesh), 1e-9);
      for (const Vec3& q : roof_points(plain.mesh)) {
        if (q.z < kEave + 1e-6) continue;
        double nearest = 1e300;
        for (const Vec3& v : roof_points(r.mesh)) nearest = std::min(nearest, length(v - q));
        EXPECT_LT(nearest, 1e-9) << q.x << " " << q.y << " " << q.z;
      }
      EXPECT_GT(volume(r.mesh), volume(plain.mesh) + 0.5 * sides * kOverhang * eave_tan(t) * 0.5);
    }
  }
}

// A parallelogram whose ends meet its sides at 12 degrees: an eave all round would mitre its two
// acute corners out beyond the limit, so a hip is built without overhang; a gable and the
// quadrilateral shapes, whose ends are flush, keep theirs on the slope sides (they lost it to the
// all-round test that ran before any type was planned).
TEST(RoofShapes, SharplySkewedQuadrilateralsOverhangTheirSlopeSides) {
  const double a = 12 * kPi / 180;
  const Vec2 end{9 * std::cos(a), 9 * std::sin(a)};  // 9 m ends, 1.87 m apart across the sides
  const Polygon p{{{0, 0}, {30, 0}, Vec2{30, 0} + end, end}, {}};
  MassSpec spec;
  spec.overhang = 0.5;
  for (RoofType t :
       {RoofType::kGable, RoofType::kGambrel, RoofType::kHalfHipped, RoofType::kSaltbox}) {
    SCOPED_TRACE(std::string(roof_type_name(t)));
    const MassResult r = build(p, t, spec);
    expect_closed(r);
    EXPECT_EQ(r.roof, t);
    EXPECT_EQ(r.message.find("overhang"), std::string::npos) << r.message;
    // The slope sides (edges 0 and 2) overhang, the eave beyond the footprint's y range.
    EXPECT_LT(r.mesh.bounds().min.y, -0.2);
    EXPECT_GT(r.mesh.bounds().max.y, end.y + 0.2);
  }
  const MassResult hip = build(p, RoofType::kHip, spec);
  expect_closed(hip);
  EXPECT_EQ(hip.roof, RoofType::kHip);
  EXPECT_NE(hip.message.find("makes the eave polygon self-intersect or reach too far out"),
            std::string::npos)
      << hip.message;
  EXPECT_NEAR(hip.mesh.bounds().min.y, 0, 1e-9);
}

// The gambrel's break stays at its height, 2.5 m above the wall top, and place, its lower slope
// reaching down to the eave under the overhang; the end walls take in the eave corners.
TEST(RoofShapes, GambrelOverhangKeepsTheBreak) {
  MassSpec spec;
  spec.overhang = 0.5;
  const MassResult r = build(rectangle(12, 8), RoofType::kGambrel, spec);
  expect_closed(r);
  const double drop = 0.5 * std::tan(70 * kPi / 180);
  const double t = 2.5 / std::tan(70 * kPi / 180);
  const double ridge = 2.5 + (4 - t) * std::tan(30 * kPi / 180);
  std::set<long> levels;
  for (const Vec3& p : roof_points(r.mesh)) {
    levels.insert(std::lround((p.z - kEave) * 1000));
    if (std::abs(p.z - kEave - 2.5) < 1e-9) {
      EXPECT_TRUE(std::abs(p.y - t) < 1e-9 || std::abs(p.y - (8 - t)) < 1e-9) << p.y;
    }
  }
  EXPECT_EQ(levels, (std::set<long>{std::lround(-drop * 1000), 2500, std::lround(ridge * 1000)}));
  // Each end wall: its ground edge, the two wall tops, the two eave corners, the two break
  // points and the ridge point.
  int ends = 0;
  for (std::size_t f = 0; f < r.mesh.face_count(); ++f) {
    if (r.mesh.tag(f).semantic != SemanticClass::kWallSurface) continue;
    const Vec3 n = face_normal(r.mesh, f);
    if (std::abs(n.x) < 0.5) continue;
    ++ends;
    EXPECT_EQ(r.mesh.face(f).size(), 9U);
    double y_min = 1e300, y_max = -1e300;
    for (std::uint32_t v : r.mesh.face(f)) {
      y_min = std::min(y_min, r.mesh.position(v).y);
      y_max = std::max(y_max, r.mesh.position(v).y);
    }
    EXPECT_NEAR(y_min, -0.5, 1e-9);
    EXPECT_NEAR(y_max, 8.5, 1e-9);
  }
  EXPECT_EQ(ends, 2);
}

// A party wall on a slope side keeps that side flush (offset 0), as for gables; the other side
// overhangs.
TEST(RoofShapes, QuadrilateralShapesKeepPartyWallsFlush) {
  for (RoofType t : {RoofType::kGambrel, RoofType::kHalfHipped, RoofType::kSaltbox}) {
    SCOPED_TRACE(std::string(roof_type_name(t)));
    MassSpec spec;
    spec.overhang = 0.5;
    PartyWall wall;  // along the north slope edge (edge 2)
    wall.a = {0, 8};
    wall.b = {12, 8};
    spec.party_walls = {wall};
    const MassResult r = build(rectangle(12, 8), t, spec);
    expect_closed(r);
    EXPECT_EQ(r.roof, t);
    EXPECT_EQ(r.message.find("without overhang"), std::string::npos) << r.message;
    EXPECT_NEAR(r.mesh.bounds().max.y, 8, 1e-9);
    EXPECT_LT(r.mesh.bounds().min.y, -0.2);
    EXPECT_EQ(count(r.mesh, SemanticClass::kOuterCeilingSurface), 1);
  }
}

// A party wall on an end whose corner has a 4 cm edge nearly in line with the slope side (edge 3
// of near_rectangle(true), turning 1 degree from edge 2 and 89 from the end): the end stays
// flush, the slope side overhangs. The short edge was made flush beside the party wall and took
// the whole side with it.
TEST(RoofShapes, PartyWallOnAnEndKeepsTheSlopeSidesOverhang) {
  for (RoofType t :
       {RoofType::kGable, RoofType::kGambrel, RoofType::kHalfHipped, RoofType::kSaltbox}) {
    SCOPED_TRACE(std::string(roof_type_name(t)));
    MassSpec spec;
    spec.overhang = 0.5;
    PartyWall wall;  // along the west end (edge 4)
    wall.a = {0, 0};
    wall.b = {0, 8.1};
    spec.party_walls = {wall};
    const MassResult r = build(near_rectangle(true), t, spec);
    expect_closed(r);
    EXPECT_EQ(r.roof, t);
    EXPECT_EQ(r.message.find("without overhang"), std::string::npos) << r.message;
    EXPECT_NEAR(r.mesh.bounds().min.x, 0, 1e-9);  // the party wall's end flush
    EXPECT_GT(r.mesh.bounds().max.y, 8.3);        // the north slope side overhangs
    EXPECT_LT(r.mesh.bounds().min.y, -0.2);       // and the south one (half as far on a saltbox)
  }
}

// A vertex 4 cm from a corner where the outline turns by 1 degree, on a slope side or an end: the
// roof keeps its overhang, its eave straight along the side (the vertex's eave point lies on the
// side's eave line) and every face planar (expect_closed).
TEST(RoofShapes, NearlyStraightVerticesKeepTheOverhang) {
  for (bool long_side : {true, false}) {
    for (RoofType t : {RoofType::kGambrel, RoofType::kHalfHipped, RoofType::kSaltbox}) {
      SCOPED_TRACE(std::string(roof_type_name(t)) + (long_side ? " long side" : " short side"));
      MassSpec spec;
      spec.overhang = 0.5;
      const MassResult r = build(near_rectangle(long_side), t, spec);
      expect_closed(r);
      EXPECT_EQ(r.status, MassStatus::kOk) << r.message;
      EXPECT_EQ(r.roof, t);
      EXPECT_EQ(count(r.mesh, SemanticClass::kOuterCeilingSurface), long_side ? 3 : 2);
      const double soffit_z = kEave - 0.5 * eave_tan(t);
      EXPECT_NEAR(lowest(r.mesh, SemanticClass::kRoofSurface), soffit_z, 1e-9);
      EXPECT_NEAR(r.mesh.bounds().max.y, 8 + 0.5, 1e-3);
      const MassResult plain = build(near_rectangle(long_side), t);
      EXPECT_NEAR(top(r.mesh), top(plain.mesh), 1e-9);
    }
  }
}

// Round, dome and onion spring from the wall: still built without overhang, and said so; the
// other shapes no longer are.
TEST(RoofShapes, OnlyVaultsAndDomesAreBuiltWithoutOverhang) {
  MassSpec spec;
  spec.overhang = 0.5;
  for (RoofType t : {RoofType::kRound, RoofType::kDome, RoofType::kOnion}) {
    const MassResult r = build(rectangle(12, 8), t, spec);
    expect_closed(r);
    EXPECT_EQ(r.roof, t);
    EXPECT_EQ(r.status, MassStatus::kFallback);
    EXPECT_EQ(r.message, std::string(roof_type_name(t)) + " roofs are built without overhang");
    EXPECT_EQ(count(r.mesh, SemanticClass::kOuterCeilingSurface), 0);
  }
  for (RoofType t : {RoofType::kGambrel, RoofType::kHalfHipped, RoofType::kSaltbox}) {
    const MassResult r = build(rectangle(12, 8), t, spec);
    EXPECT_EQ(r.status, MassStatus::kOk) << r.message;
    EXPECT_EQ(r.message, "");
    EXPECT_EQ(count(r.mesh, SemanticClass::kOuterCeilingSurface), 2);
  }
}

}  // namespace
}  // namespace insula::kernel
