#include "kernel/extrude.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

namespace insula::kernel {
namespace {

Ring rect(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

Polygon l_shape() {
  return {{{0, 0}, {6, 0}, {6, 2}, {2, 2}, {2, 5}, {0, 5}}, {}};
}

Polygon u_shape() {
  return {{{0, 0}, {9, 0}, {9, 6}, {6, 6}, {6, 2}, {3, 2}, {3, 6}, {0, 6}}, {}};
}

Polygon courtyard() {
  Ring hole = rect(3, 3, 7, 7);
  std::reverse(hole.begin(), hole.end());
  return {rect(0, 0, 10, 10), {hole}};
}

void expect_near(Vec3 actual, Vec3 expected, double tolerance = 1e-12) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
  EXPECT_NEAR(actual.z, expected.z, tolerance);
}

// The solid a prism must be: closed on shared vertices, Euler characteristic 2 - 2 * genus, one
// component, outward (positive volume).
void expect_closed_solid(const Mesh& mesh, int euler, double expected_volume) {
  const MeshCheck c = check(mesh);
  EXPECT_TRUE(c.closed);
  EXPECT_EQ(c.boundary_edges, 0U);
  EXPECT_EQ(c.non_manifold_edges, 0U);
  EXPECT_EQ(c.euler_characteristic, euler);
  EXPECT_EQ(c.components, 1U);
  EXPECT_TRUE(is_watertight(mesh));
  EXPECT_NEAR(volume(mesh), expected_volume, 1e-9);
}

// Every face with the given face id must face along `normal`.
void expect_faces_point(const Mesh& mesh, std::uint32_t face_id, Vec3 normal) {
  int found = 0;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    if (mesh.tag(f).face_id != face_id) continue;
    ++found;
    expect_near(face_normal(mesh, f), normal, 1e-9);
  }
  EXPECT_GT(found, 0) << "face id " << face_id;
}

TEST(Extrude, BoxHasSixTaggedOutwardFaces) {
  const ExtrudeResult r = extrude({rect(0, 0, 2, 3), {}}, 1, 4);
  ASSERT_TRUE(r.ok()) << extrude_status_message(r.status);
  expect_closed_solid(r.mesh, 2, 24);
  EXPECT_NEAR(surface_area(r.mesh), 2 * (6 + 8 + 12), 1e-9);
  ASSERT_EQ(r.mesh.face_count(), 6U);
  EXPECT_EQ(r.mesh.vertex_count(), 8U);
  EXPECT_EQ(r.mesh.tag(0).semantic, SemanticClass::kGroundSurface);
  EXPECT_EQ(r.mesh.tag(1).semantic, SemanticClass::kRoofSurface);
  expect_faces_point(r.mesh, 0, {0, 0, -1});
  expect_faces_point(r.mesh, 1, {0, 0, 1});
  // Side ids follow the edges: 0->1 is the south edge, then east, north, west.
  expect_faces_point(r.mesh, 2, {0, -1, 0});
  expect_faces_point(r.mesh, 3, {1, 0, 0});
  expect_faces_point(r.mesh, 4, {0, 1, 0});
  expect_faces_point(r.mesh, 5, {-1, 0, 0});
  for (std::size_t f = 2; f < 6; ++f)
    EXPECT_EQ(r.mesh.tag(f).semantic, SemanticClass::kWallSurface);
  EXPECT_NEAR(r.mesh.bounds().min.z, 1.0, 0);
  EXPECT_NEAR(r.mesh.bounds().max.z, 5.0, 0);
}

TEST(Extrude, LAndUShapesAreWatertightWithNGonCaps) {
  for (const Polygon& p : {l_shape(), u_shape()}) {
    const ExtrudeResult r = extrude(p, 0, 3);
    ASSERT_TRUE(r.ok());
    expect_closed_solid(r.mesh, 2, area(p) * 3);
    EXPECT_EQ(r.mesh.face_count(), p.outer.size() + 2);
    EXPECT_EQ(r.mesh.face(0).size(), p.outer.size());  // one non-convex n-gon per cap
  }
}

TEST(Extrude, CourtyardIsGenusOneWithFourQuadsACap) {
  const ExtrudeResult r = extrude(courtyard(), 0, 2);
  ASSERT_TRUE(r.ok()) << extrude_status_message(r.status);
  expect_closed_solid(r.mesh, 0, (100 - 16) * 2);
  std::size_t bottom = 0;
  std::size_t top = 0;
  std::set<std::uint32_t> side_ids;
  for (std::size_t f = 0; f < r.mesh.face_count(); ++f) {
    const FaceTag& tag = r.mesh.tag(f);
    if (tag.semantic == SemanticClass::kGroundSurface) {
      ++bottom;
      EXPECT_EQ(tag.face_id, 0U);
      EXPECT_EQ(r.mesh.face(f).size(), 4U);
    } else if (tag.semantic == SemanticClass::kRoofSurface) {
      ++top;
      EXPECT_EQ(tag.face_id, 1U);
    } else {
      side_ids.insert(tag.face_id);
    }
  }
  // A square with a square hole, as a window's frame: the four quads between the rings.
  EXPECT_EQ(bottom, 4U);
  EXPECT_EQ(top, 4U);
  EXPECT_EQ(side_ids, (std::set<std::uint32_t>{2, 3, 4, 5, 6, 7, 8, 9}));
  expect_faces_point(r.mesh, 0, {0, 0, -1});
  expect_faces_point(r.mesh, 1, {0, 0, 1});
  // Hole edge 0 runs (3,7) -> (7,7) (the reversed rectangle): its wall faces into the courtyard.
  expect_faces_point(r.mesh, 6, {0, -1, 0});
}

// The region's faces as add_region_faces gives them: their areas sum to the region's, each runs
// counter-clockwise (or clockwise when reversed) and is convex.
void expect_region_cover(const Polygon& region, bool reverse, std::size_t faces) {
  Mesh mesh;
  std::vector<std::uint32_t> ids;
  for (Vec2 p : region.outer) ids.push_back(mesh.add_vertex({p.x, p.y, 0}));
  for (Vec2 p : region.holes[0]) ids.push_back(mesh.add_vertex({p.x, p.y, 0}));
  ASSERT_TRUE(add_region_faces(mesh, region, ids, reverse, {}));
  EXPECT_EQ(mesh.face_count(), faces);
  double total = 0;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const auto loop = mesh.face(f);
    for (std::size_t c = 0; c < loop.size(); ++c) {
      const Vec3 a = mesh.position(loop[c]);
      const Vec3 b = mesh.position(loop[(c + 1) % loop.size()]);
      const Vec3 d = mesh.position(loop[(c + 2) % loop.size()]);
      const double turn = cross(Vec2{b.x - a.x, b.y - a.y}, Vec2{d.x - b.x, d.y - b.y});
      EXPECT_GT(reverse ? -turn : turn, 0) << "face " << f << " corner " << c;
    }
    total += face_area(mesh, f);
  }
  EXPECT_NEAR(total, area(region), 1e-9);
}

TEST(Extrude, FrameRegionIsFourQuadsWhereTheyAreConvex) {
  Ring hole = rect(0.07, 0.07, 1.23, 1.53);
  std::reverse(hole.begin(), hole.end());
  expect_region_cover({rect(0, 0, 1.3, 1.6), {hole}}, false, 4);
  expect_region_cover({rect(0, 0, 1.3, 1.6), {hole}}, true, 4);
  // The hole's ring starting elsewhere: its corners still meet their nearest outer corners.
  std::rotate(hole.begin(), hole.begin() + 1, hole.end());
  expect_region_cover({rect(0, 0, 1.3, 1.6), {hole}}, false, 4);
  // An arrowhead (a reflex corner at (6, 4)) round a small square: still four convex quads.
  Ring small = rect(7, 1, 8, 2);
  std::reverse(small.begin(), small.end());
  expect_region_cover({{{0, 0}, {10, 0}, {10, 10}, {6, 4}}, {small}}, false, 4);
  // A diamond in a square: the quad from a square's edge to the diamond's is not convex, so the
  // region is triangulated (8 triangles for 8 vertices and 2 rings).
  const Ring diamond{{5, 1}, {1, 5}, {5, 9}, {9, 5}};  // clockwise
  expect_region_cover({rect(0, 0, 10, 10), {diamond}}, false, 8);
  expect_region_cover({rect(0, 0, 10, 10), {diamond}}, true, 8);
}

TEST(Extrude, ClockwiseInputKeepsInputEdgeIds) {
  Ring cw = rect(0, 0, 2, 3);
  std::reverse(cw.begin(), cw.end());  // (0,3) (2,3) (2,0) (0,0)
  Ring ccw_hole = rect(0.5, 0.5, 1.5, 1.5);
  const ExtrudeResult r = extrude({cw, {ccw_hole}}, 0, 1);
  ASSERT_TRUE(r.ok()) << extrude_status_message(r.status);
  expect_closed_solid(r.mesh, 0, 6 - 1);
  expect_faces_point(r.mesh, 2, {0, 1, 0});  // (0,3)->(2,3): north
  expect_faces_point(r.mesh, 3, {1, 0, 0});  // (2,3)->(2,0): east
  expect_faces_point(r.mesh, 6, {0, 1, 0});  // hole (0.5,0.5)->(1.5,0.5): faces into the hole
}

TEST(Extrude, DuplicateAndClosingVerticesAreMergedAndTheirIdsSkipped) {
  const Polygon p{{{0, 0}, {4, 0}, {4, 0}, {4, 4}, {0, 4}, {0, 0}}, {}};
  const ExtrudeResult r = extrude(p, 0, 1);
  ASSERT_TRUE(r.ok());
  expect_closed_solid(r.mesh, 2, 16);
  std::set<std::uint32_t> ids;
  for (std::size_t f = 2; f < r.mesh.face_count(); ++f) ids.insert(r.mesh.tag(f).face_id);
  // Input edges 1 ((4,0)->(4,0)) and 5 ((0,0)->(0,0)) have no length.
  EXPECT_EQ(ids, (std::set<std::uint32_t>{2, 4, 5, 6}));
  expect_faces_point(r.mesh, 4, {1, 0, 0});
}

TEST(Extrude, BadInputGivesStatusAndEmptyMesh) {
  const Polygon square{rect(0, 0, 1, 1), {}};
  EXPECT_EQ(extrude(square, 0, 0).status, ExtrudeStatus::kInvalidHeight);
  EXPECT_EQ(extrude(square, 0, -2).status, ExtrudeStatus::kInvalidHeight);
  EXPECT_EQ(extrude(square, 0, NAN).status, ExtrudeStatus::kInvalidHeight);
  EXPECT_EQ(extrude(square, INFINITY, 1).status, ExtrudeStatus::kNonFinite);
  EXPECT_EQ(extrude({{{0, 0}, {1, 0}, {0, 0}}, {}}, 0, 1).status, ExtrudeStatus::kTooFewVertices);
  EXPECT_EQ(extrude({{{0, 0}, {1, 0}, {2, 0}}, {}}, 0, 1).status, ExtrudeStatus::kZeroArea);
  EXPECT_EQ(extrude({{{0, 0}, {1, NAN}, {2, 0}}, {}}, 0, 1).status, ExtrudeStatus::kNonFinite);
  EXPECT_EQ(extrude({{}, {}}, 0, 1).status, ExtrudeStatus::kTooFewVertices);
  EXPECT_EQ(extrude_between(square, 3, 3).status, ExtrudeStatus::kInvalidHeight);
  EXPECT_TRUE(extrude(square, 0, -2).mesh.empty());
  EXPECT_EQ(extrude_status_message(ExtrudeStatus::kZeroArea), "a ring encloses zero area");
}

TEST(Extrude, BetweenTwoHeights) {
  const ExtrudeResult r = extrude_between({rect(0, 0, 2, 2), {}}, 3, 5.5);
  ASSERT_TRUE(r.ok());
  expect_closed_solid(r.mesh, 2, 10);
  EXPECT_EQ(r.mesh.bounds().min.z, 3.0);
  EXPECT_EQ(r.mesh.bounds().max.z, 5.5);
}

TEST(Extrude, CustomTagsAndIds) {
  ExtrudeOptions options;
  options.bottom = {SemanticClass::kFloorSurface, 3, 10};
  options.top = {SemanticClass::kCeilingSurface, 4, 11};
  options.side = {SemanticClass::kInteriorWallSurface, 5, 20};
  const ExtrudeResult r = extrude({rect(0, 0, 1, 1), {}}, 0, 1, options);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.mesh.tag(0).semantic, SemanticClass::kFloorSurface);
  EXPECT_EQ(r.mesh.tag(0).material, 3);
  EXPECT_EQ(r.mesh.tag(1).face_id, 11U);
  EXPECT_EQ(r.mesh.tag(5).face_id, 23U);
  EXPECT_EQ(r.mesh.tag(5).material, 5);
  EXPECT_EQ(r.mesh.tag(5).semantic, SemanticClass::kInteriorWallSurface);
}

// The top face of a unit box extruded upward: a box on top with its bottom at z = 1.
TEST(Extrude, FaceOfAMeshGrowsAlongItsNormal) {
  const Mesh box = extrude({rect(0, 0, 1, 1), {}}, 0, 1).mesh;
  const ExtrudeResult up = extrude_face(box, 1, 2);
  ASSERT_TRUE(up.ok());
  expect_closed_solid(up.mesh, 2, 2);
  EXPECT_NEAR(up.mesh.bounds().min.z, 1, 1e-12);
  EXPECT_NEAR(up.mesh.bounds().max.z, 3, 1e-12);
  expect_faces_point(up.mesh, 0, {0, 0, -1});
  // A side face (normal +x) extruded inward by -0.25: a slab inside the box, the bottom-tagged
  // cap still lies in the face's plane.
  const ExtrudeResult in = extrude_face(box, 3, -0.25);
  ASSERT_TRUE(in.ok());
  expect_closed_solid(in.mesh, 2, 0.25);
  expect_faces_point(in.mesh, 0, {1, 0, 0});
  expect_faces_point(in.mesh, 1, {-1, 0, 0});
  EXPECT_NEAR(in.mesh.bounds().min.x, 0.75, 1e-12);
  EXPECT_EQ(extrude_face(box, 99, 1).status, ExtrudeStatus::kDegenerateFace);
}

TEST(Extrude, LoopInATiltedPlane) {
  // A 2 x 1 rectangle in the plane x + z = 1, extruded by 3 along its normal.
  const double s = std::sqrt(0.5);
  const std::vector<Vec3> loop{{0, 0, 1}, {s * 2, 0, 1 - s * 2}, {s * 2, 1, 1 - s * 2}, {0, 1, 1}};
  const ExtrudeResult r = extrude_loop(loop, 3);
  ASSERT_TRUE(r.ok());
  expect_closed_solid(r.mesh, 2, 6);
  expect_faces_point(r.mesh, 1, {s, 0, s});
  const std::vector<Vec3> line{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  EXPECT_EQ(extrude_loop(line, 1).status, ExtrudeStatus::kDegenerateFace);
}

TEST(Extrude, PlanarFrameMayMirror) {
  const Polygon l = l_shape();
  const Transform mirror = frame({0, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, 0, 1});
  const ExtrudeResult r = extrude_planar(l, mirror, 2);
  ASSERT_TRUE(r.ok());
  expect_closed_solid(r.mesh, 2, area(l) * 2);
  const Transform wall = frame({5, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 0});
  const ExtrudeResult w = extrude_planar(courtyard(), wall, 0.3);
  ASSERT_TRUE(w.ok());
  expect_closed_solid(w.mesh, 0, 84 * 0.3);
  EXPECT_EQ(extrude_planar(l, scaling({1, 0, 1}), 1).status, ExtrudeStatus::kDegenerateFace);
}

}  // namespace
}  // namespace insula::kernel
