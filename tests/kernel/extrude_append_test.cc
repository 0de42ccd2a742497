// kernel::extrude_between_append must add exactly what mesh.append(extrude_between(...).mesh)
// adds: same vertices, same faces in the same order, same tags (the 3D builder's goldens rely on
// it), and nothing on failure.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "kernel/extrude.h"

namespace insula::kernel {
namespace {

void expect_same(const Mesh& a, const Mesh& b) {
  ASSERT_EQ(a.vertex_count(), b.vertex_count());
  ASSERT_EQ(a.face_count(), b.face_count());
  for (std::size_t v = 0; v < a.vertex_count(); ++v) {
    EXPECT_EQ(a.positions()[v], b.positions()[v]) << "vertex " << v;
  }
  for (std::size_t f = 0; f < a.face_count(); ++f) {
    const auto fa = a.face(f);
    const auto fb = b.face(f);
    EXPECT_EQ(std::vector<std::uint32_t>(fa.begin(), fa.end()),
              std::vector<std::uint32_t>(fb.begin(), fb.end()))
        << "face " << f;
    EXPECT_EQ(a.tag(f).semantic, b.tag(f).semantic);
    EXPECT_EQ(a.tag(f).material, b.tag(f).material);
    EXPECT_EQ(a.tag(f).face_id, b.tag(f).face_id);
  }
}

Mesh seed() {
  Mesh mesh;  // something already in the storey mesh, so indices must be shifted
  const std::vector<Vec3> tri{{0, 0, 9}, {1, 0, 9}, {0, 1, 9}};
  mesh.add_polygon(tri, {SemanticClass::kWallSurface, 4, 7});
  return mesh;
}

void check_polygon(const Polygon& footprint, double z0, double z1) {
  ExtrudeOptions options;
  options.side.face_id = 5;
  options.tolerance = 1e-6;
  Mesh expected = seed();
  const ExtrudeResult prism = extrude_between(footprint, z0, z1, options);
  if (prism.ok()) expected.append(prism.mesh);
  Mesh actual = seed();
  EXPECT_EQ(extrude_between_append(actual, footprint, z0, z1, options), prism.status);
  expect_same(actual, expected);
}

TEST(ExtrudeAppend, CounterClockwiseSquare) {
  check_polygon({{{0, 0}, {4, 0}, {4, 3}, {0, 3}}, {}}, 0.5, 0.7);
}

TEST(ExtrudeAppend, ClockwiseConcaveRingWithDuplicates) {
  check_polygon({{{0, 0}, {0, 3}, {0, 3}, {2, 3}, {2, 1}, {4, 1}, {4, 0}, {4, 0}}, {}}, 2, 2.25);
}

TEST(ExtrudeAppend, DuplicateAtTheWrapAround) {
  check_polygon({{{0, 0}, {5, 0}, {5, 5}, {0, 0}}, {}}, 0, 1);
}

TEST(ExtrudeAppend, PolygonWithHoleIsTriangulated) {
  check_polygon({{{0, 0}, {6, 0}, {6, 6}, {0, 6}}, {{{2, 2}, {2, 4}, {4, 4}, {4, 2}}}}, 1, 2);
}

TEST(ExtrudeAppend, FailuresAddNothing) {
  check_polygon({{{0, 0}, {4, 0}, {4, 3}}, {}}, 1, 1);             // zero height
  check_polygon({{{0, 0}, {4, 0}, {8, 0}}, {}}, 0, 1);             // zero area
  check_polygon({{{0, 0}, {4, 0}, {4, 3}}, {}}, 0, std::nan(""));  // NaN top
  check_polygon({{{0, 0}, {1e-9, 0}}, {}}, 0, 1);                  // too few vertices
  const Mesh before = seed();
  Mesh mesh = seed();
  EXPECT_EQ(extrude_between_append(mesh, {{{0, 0}, {4, 0}, {4, 3}}, {}}, 2, 1),
            ExtrudeStatus::kInvalidHeight);
  expect_same(mesh, before);
}

}  // namespace
}  // namespace insula::kernel
