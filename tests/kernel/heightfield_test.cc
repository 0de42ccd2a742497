#include "kernel/heightfield.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace insula::kernel {
namespace {

Heightfield field(double width, double depth, double cell, Vec2 origin = {}) {
  std::string error;
  std::optional<Heightfield> f = make_heightfield(origin, width, depth, cell, 0, error);
  EXPECT_TRUE(f.has_value()) << error;
  return *f;
}

// z = a + b x + c y at every sample.
void set_plane(Heightfield& f, double a, double b, double c) {
  for (int j = 0; j < f.ny; ++j) {
    for (int i = 0; i < f.nx; ++i) {
      const Vec2 p = f.point(i, j);
      f.at(i, j) = a + b * p.x + c * p.y;
    }
  }
}

double variance(const Heightfield& f) {
  double mean = 0;
  for (double z : f.z) mean += z;
  mean /= static_cast<double>(f.z.size());
  double v = 0;
  for (double z : f.z) v += (z - mean) * (z - mean);
  return v / static_cast<double>(f.z.size());
}

Polygon square(double x0, double y0, double size) {
  return {{{x0, y0}, {x0 + size, y0}, {x0 + size, y0 + size}, {x0, y0 + size}}, {}};
}

TEST(Heightfield, GridCoversTheExactExtent) {
  const Heightfield f = field(100, 45, 2, {10, -5});
  EXPECT_EQ(f.nx, 51);
  EXPECT_EQ(f.ny, 24);  // 45 / 2 rounded up to 23 cells
  EXPECT_DOUBLE_EQ(f.width(), 100);
  EXPECT_DOUBLE_EQ(f.depth(), 45);
  EXPECT_EQ(f.cells(), 50U * 23U);
  std::string error;
  EXPECT_FALSE(make_heightfield({}, 10, 10, 0, 0, error).has_value());
  EXPECT_EQ(error, "a terrain's cell size must be finite and positive");
  EXPECT_FALSE(make_heightfield({}, -1, 10, 1, 0, error).has_value());
  EXPECT_EQ(error, "a terrain needs a finite, positive width and depth");
  EXPECT_FALSE(make_heightfield({}, 1e5, 1e5, 1, 0, error).has_value());
  EXPECT_EQ(error, "a terrain of 100001 x 100001 samples is more than 16777216; use a larger cell");
}

TEST(Heightfield, LookupIsExactOnPlanesAndClampsOutside) {
  Heightfield f = field(40, 30, 3, {-5, 7});
  set_plane(f, 2, 0.25, -0.5);
  for (double x = -5; x <= 35; x += 1.37) {
    for (double y = 7; y <= 37; y += 0.91) {
      EXPECT_NEAR(height_at(f, x, y), 2 + 0.25 * x - 0.5 * y, 1e-9) << x << " " << y;
    }
  }
  EXPECT_NEAR(height_at(f, -100, 7), 2 + 0.25 * -5 - 0.5 * 7, 1e-9);
  EXPECT_NEAR(height_at(f, 1000, 1000), 2 + 0.25 * 35 - 0.5 * 37, 1e-9);
}

TEST(Heightfield, NoiseIsDeterministicPerSeedAndWithinAmplitude) {
  NoiseParams p{3.5, 40, 5, 7};
  Heightfield a = field(200, 200, 2);
  Heightfield b = field(200, 200, 2);
  add_noise(a, p);
  add_noise(b, p);
  EXPECT_EQ(a.z, b.z);
  double low = 0;
  double high = 0;
  for (double z : a.z) {
    EXPECT_LE(std::abs(z), 3.5);
    low = std::min(low, z);
    high = std::max(high, z);
  }
  EXPECT_GT(high - low, 2.0);  // it is hilly, not flat
  Heightfield c = field(200, 200, 2);
  p.seed = 8;
  add_noise(c, p);
  std::size_t differing = 0;
  for (std::size_t k = 0; k < a.z.size(); ++k) differing += a.z[k] != c.z[k] ? 1 : 0;
  EXPECT_GT(differing, a.z.size() * 9 / 10);
  EXPECT_EQ(fbm({1, 10, 0, 0}, 3, 4), 0.0);  // no octaves, no noise
}

TEST(Heightfield, SmoothingReducesVarianceAndKeepsPlanesInside) {
  Heightfield f = field(100, 100, 1);
  add_noise(f, {5, 8, 3, 1});
  const double before = variance(f);
  smooth(f, 1);
  const double once = variance(f);
  smooth(f, 4);
  EXPECT_LT(once, before);
  EXPECT_LT(variance(f), once);
  Heightfield plane = field(20, 20, 1);
  set_plane(plane, 1, 0.5, 0.25);
  smooth(plane, 3);
  EXPECT_NEAR(plane.at(10, 10), 1 + 5 + 2.5, 1e-12);  // linear in, linear out, off the border
}

TEST(Heightfield, LevellingFlattensUnderASquareAndBlendsMonotonically) {
  Heightfield f = field(100, 100, 2);
  set_plane(f, 0, 0.2, 0);
  const Polygon lot = square(40, 40, 20);
  const std::vector<Polygon> lots{lot};
  const std::vector<double> plateau = level(f, {lots, {}, 10});
  ASSERT_EQ(plateau.size(), 1U);
  EXPECT_NEAR(plateau[0], 10, 1e-9);  // the mean of a plane over samples symmetric about x = 50
  for (double x = 40; x <= 60; x += 0.5) {
    for (double y = 40; y <= 60; y += 0.5) EXPECT_EQ(height_at(f, x, y), plateau[0]);
  }
  // Outwards along +x and -x the surface leaves the plateau steadily and meets the plane.
  double last = 0;
  for (double x = 60; x <= 100; x += 0.5) {
    const double off = height_at(f, x, 50) - plateau[0];
    EXPECT_GE(off, last - 1e-12) << x;
    last = off;
  }
  last = 0;
  for (double x = 40; x >= 0; x -= 0.5) {
    const double off = plateau[0] - height_at(f, x, 50);
    EXPECT_GE(off, last - 1e-12) << x;
    last = off;
  }
  // Beyond the margin (10) plus one cell diagonal the plane is untouched.
  EXPECT_NEAR(height_at(f, 75, 50), 15, 1e-12);
  EXPECT_NEAR(height_at(f, 25, 50), 5, 1e-12);
  EXPECT_NEAR(height_at(f, 50, 80), 10, 1e-12);
}

TEST(Heightfield, AdjoiningFootprintsShareOnePlateau) {
  Heightfield f = field(100, 100, 2);
  set_plane(f, 0, 0.2, 0.1);
  const std::vector<Polygon> lots{square(20, 40, 10), square(30, 40, 10), square(70, 40, 10)};
  const std::vector<double> plateau = level(f, {lots, {}, 4});
  EXPECT_EQ(plateau[0], plateau[1]);
  EXPECT_NE(plateau[1], plateau[2]);
  for (std::size_t p = 0; p < lots.size(); ++p) {
    for (const Vec2& v : lots[p].outer) EXPECT_EQ(height_at(f, v.x, v.y), plateau[p]);
  }
}

TEST(Heightfield, RoadsAreLevelledAcrossAndFollowTheTerrainAlong) {
  Heightfield f = field(200, 60, 2);
  set_plane(f, 0, 0.1, 0);  // along x the road climbs 0.1 per metre
  for (int j = 0; j < f.ny; ++j) {
    for (int i = 0; i < f.nx; ++i) f.at(i, j) += (j % 2 == 0 ? 1 : -1);  // ridges across
  }
  const std::vector<Polygon> roads{{{{0, 25}, {200, 25}, {200, 35}, {0, 35}}, {}}};
  level(f, {{}, roads, 5});
  // Across the road (y 25..35) at one x the heights agree closely; along it they climb.
  for (double x = 20; x <= 180; x += 10) {
    EXPECT_NEAR(height_at(f, x, 26), height_at(f, x, 34), 0.2) << x;
    EXPECT_NEAR(height_at(f, x, 30), 0.1 * x, 0.3) << x;
  }
  // Cells whose centre is inside the road (y 27..33; 25 and 35 are on its edge: four rows of
  // 100) are drawn as road.
  ASSERT_EQ(f.road.size(), f.cells());
  EXPECT_EQ(std::count(f.road.begin(), f.road.end(), 1), 400);
  const Mesh mesh = heightfield_mesh(f, 1, 2);
  std::size_t road_faces = 0;
  for (std::size_t k = 0; k < mesh.face_count(); ++k)
    road_faces += mesh.tag(k).material == 2 ? 1 : 0;
  EXPECT_EQ(road_faces, 800U);
  EXPECT_EQ(mesh.tag(0).material, 1);
}

TEST(Heightfield, MeshHasTwoTrianglesPerCellFacingUp) {
  Heightfield f = field(30, 20, 2.5, {3, 4});
  const Mesh mesh = heightfield_mesh(f);
  EXPECT_EQ(mesh.face_count(), 2 * f.cells());
  EXPECT_EQ(mesh.vertex_count(), f.z.size());
  EXPECT_NEAR(surface_area(mesh), 600, 1e-9);
  for (std::size_t k = 0; k < mesh.face_count(); ++k) {
    EXPECT_EQ(mesh.face(k).size(), 3U);
    EXPECT_NEAR(face_normal(mesh, k).z, 1, 1e-12);
    EXPECT_EQ(mesh.tag(k).semantic, SemanticClass::kGroundSurface);
  }
  const Bounds3 b = mesh.bounds();
  EXPECT_DOUBLE_EQ(b.min.x, 3);
  EXPECT_DOUBLE_EQ(b.max.y, 24);
  set_plane(f, 0, 0, 0.75);  // a slope of 3:4 stretches the surface by 5/4
  EXPECT_NEAR(surface_area(heightfield_mesh(f)), 750, 1e-9);
}

}  // namespace
}  // namespace insula::kernel
