#include "kernel/skeleton_rectilinear.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <string>

#include "kernel/boolean2d.h"
#include "kernel/skeleton.h"
#include "skeleton_checks.h"

namespace insula::kernel {
namespace {

using testing_skeleton::expect_valid;
using testing_skeleton::face_ring;

// The same roof as CGAL's builder: every face has the same area and the ridge the same height.
void expect_same_as_cgal(const Polygon& polygon, const std::string& what) {
  const auto ours = rectilinear_straight_skeleton(polygon);
  const auto reference = general_straight_skeleton(polygon);
  ASSERT_TRUE(reference.has_value()) << what;
  ASSERT_TRUE(ours.has_value()) << what;
  expect_valid(polygon, *ours, what);
  EXPECT_NEAR(ours->max_time(), reference->max_time(), 1e-9 * (1 + reference->max_time())) << what;
  for (std::uint32_t e = 0; e < ours->contour_count; ++e) {
    EXPECT_NEAR(signed_area(face_ring(*ours, e)), signed_area(face_ring(*reference, e)),
                1e-7 * area(polygon))
        << what << " face " << e;
  }
}

TEST(RectilinearSkeleton, RectangleHasARidgeAtHalfWidth) {
  const Polygon p{{{0, 0}, {10, 0}, {10, 6}, {0, 6}}, {}};
  const auto s = rectilinear_straight_skeleton(p);
  ASSERT_TRUE(s.has_value());
  ASSERT_EQ(s->vertices.size(), 6U);
  for (std::size_t v = 4; v < 6; ++v) EXPECT_DOUBLE_EQ(s->vertices[v].time, 3.0);
  EXPECT_EQ(s->face(0).size(), 4U);  // the long edges sweep trapezoids
  EXPECT_EQ(s->face(1).size(), 3U);  // the short ones triangles
  expect_same_as_cgal(p, "rectangle");
}

TEST(RectilinearSkeleton, SquareMeetsInOnePoint) {
  const Polygon p{{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {}};
  const auto s = rectilinear_straight_skeleton(p);
  ASSERT_TRUE(s.has_value());
  ASSERT_EQ(s->vertices.size(), 5U);
  EXPECT_EQ(s->vertices[4].position, (Vec2{2, 2}));
  expect_same_as_cgal(p, "square");
}

TEST(RectilinearSkeleton, BuildingOutlinesMatchCgal) {
  expect_same_as_cgal({{{0, 0}, {12, 0}, {12, 5}, {5, 5}, {5, 12}, {0, 12}}, {}}, "L");
  expect_same_as_cgal(
      {{{0, 0}, {14, 0}, {14, 10}, {10, 10}, {10, 4}, {4, 4}, {4, 10}, {0, 10}}, {}}, "U");
  expect_same_as_cgal({{{4, 0}, {8, 0}, {8, 6}, {12, 6}, {12, 10}, {0, 10}, {0, 6}, {4, 6}}, {}},
                      "T");
  expect_same_as_cgal({{{63.5, 44.3},
                        {57.371146, 44.3},
                        {57.371146, 29.684259},
                        {5.187385, 29.684259},
                        {5.187385, 44.3},
                        {-0.3, 44.3},
                        {-0.3, -0.3},
                        {5.187385, -0.3},
                        {5.187385, 14.315741},
                        {57.371146, 14.315741},
                        {57.371146, -0.3},
                        {63.5, -0.3}},
                       {}},
                      "H of Table 2's heaviest building");
  // A plus: four reflex vertices whose valleys meet the arms' ridges (vertex events).
  expect_same_as_cgal({{{4, 0},
                        {8, 0},
                        {8, 4},
                        {12, 4},
                        {12, 8},
                        {8, 8},
                        {8, 12},
                        {4, 12},
                        {4, 8},
                        {0, 8},
                        {0, 4},
                        {4, 4}},
                       {}},
                      "plus");
  // A staircase and an outline with collinear vertices (straight wavefront vertices).
  expect_same_as_cgal({{{0, 0}, {9, 0}, {9, 3}, {6, 3}, {6, 6}, {3, 6}, {3, 9}, {0, 9}}, {}},
                      "staircase");
  expect_same_as_cgal({{{0, 0}, {14, 0}, {14, 6}, {10, 6}, {6, 6}, {6, 12}, {3, 12}, {0, 12}}, {}},
                      "L with collinear vertices");
}

TEST(RectilinearSkeleton, CourtyardHoleMatchesCgal) {
  Polygon p{{{0, 0}, {20, 0}, {20, 14}, {0, 14}}, {{{6, 4}, {6, 9}, {15, 9}, {15, 4}}}};
  expect_same_as_cgal(p, "courtyard");
  Polygon centred{{{0, 0}, {12, 0}, {12, 12}, {0, 12}}, {{{4, 4}, {4, 8}, {8, 8}, {8, 4}}}};
  expect_same_as_cgal(centred, "centred square courtyard");
}

// An island joined to the rest by a neck 2 m wide inside a C-shaped courtyard: at t = 1 the neck
// is gone and the island is a region of its own inside the other region's hole.
TEST(RectilinearSkeleton, IslandCutOffInsideACourtyardMatchesCgal) {
  Ring c_shape{{24, 16}, {24, 24}, {6, 24},  {6, 6},   {24, 6},  {24, 14},
               {20, 14}, {20, 10}, {10, 10}, {10, 20}, {20, 20}, {20, 16}};
  std::reverse(c_shape.begin(), c_shape.end());  // holes run clockwise
  expect_same_as_cgal({{{0, 0}, {30, 0}, {30, 30}, {0, 30}}, {c_shape}}, "island");
}

TEST(RectilinearSkeleton, FarFromTheOriginStaysExact) {
  Polygon p{{{0, 0}, {12, 0}, {12, 5}, {5, 5}, {5, 12}, {0, 12}}, {}};
  for (Vec2& v : p.outer) v = v + Vec2{512345.25, 4812345.5};
  expect_same_as_cgal(p, "L at UTM coordinates");
}

Polygon comb(int teeth) {
  Polygon p;
  for (int i = 0; i < teeth; ++i) {
    p.outer.push_back({4.0 * i, 0});
    p.outer.push_back({4.0 * i + 2, 0});
    p.outer.push_back({4.0 * i + 2, -3 - 0.25 * (i % 3)});
    p.outer.push_back({4.0 * i + 4, -3 - 0.25 * (i % 3)});
  }
  p.outer.push_back({4.0 * teeth, 5});
  p.outer.push_back({0, 5});
  return p;
}

TEST(RectilinearSkeleton, LongCombMatchesCgal) {
  expect_same_as_cgal(comb(60), "comb");
}

TEST(RectilinearSkeleton, DeclinesWhatIsNotRectilinearOrTooLarge) {
  EXPECT_FALSE(rectilinear_straight_skeleton({{{0, 0}, {4, 0}, {5, 3}, {0, 3}}, {}}).has_value());
  EXPECT_FALSE(is_rectilinear({{{0, 0}, {4, 0}, {4, 3}}, {}}));
  const Polygon large = comb(300);  // 1,202 vertices: left to CGAL
  EXPECT_TRUE(is_rectilinear(large));
  EXPECT_FALSE(rectilinear_straight_skeleton(large).has_value());
}

// Unions of random rectangles on an integer grid are full of simultaneous events (equal widths,
// aligned reflex vertices, touching corners); on real coordinates they are generic. Each polygon
// of the union (with its holes) must give CGAL's roof.
std::vector<Polygon> random_outlines(std::uint32_t seed, bool on_grid) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> count(2, 8);
  std::uniform_int_distribution<int> cell(0, 10);
  std::uniform_real_distribution<double> real(0, 10);
  std::vector<Polygon> rectangles;
  const int n = count(rng);
  for (int i = 0; i < n; ++i) {
    double x0 = on_grid ? cell(rng) : real(rng), x1 = on_grid ? cell(rng) : real(rng);
    double y0 = on_grid ? cell(rng) : real(rng), y1 = on_grid ? cell(rng) : real(rng);
    if (x0 > x1) std::swap(x0, x1);
    if (y0 > y1) std::swap(y0, y1);
    if (x1 - x0 < 1 || y1 - y0 < 1) continue;
    rectangles.push_back({{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, {}});
  }
  return union_all(rectangles);
}

TEST(RectilinearSkeleton, RandomRectangleUnionsMatchCgal) {
  int compared = 0;
  for (std::uint32_t seed = 1; seed <= 400; ++seed) {
    for (const Polygon& p : random_outlines(seed, seed % 2 == 0)) {
      if (!is_simple_polygon(p) || !is_rectilinear(p)) continue;
      if (!general_straight_skeleton(p).has_value()) continue;
      expect_same_as_cgal(p, "seed " + std::to_string(seed));
      ++compared;
    }
  }
  EXPECT_GT(compared, 300);
}

}  // namespace
}  // namespace insula::kernel
