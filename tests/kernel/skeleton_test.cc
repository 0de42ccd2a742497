#include "kernel/skeleton.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace insula::kernel {
namespace {

Polygon rectangle(double w, double l) {
  return {{{0, 0}, {l, 0}, {l, w}, {0, w}}, {}};
}

double ridge_length(const Skeleton& s) {
  // Nodes at the maximal time of a rectangle lie on the ridge; their spread is its length.
  double lo = 1e300;
  double hi = -1e300;
  for (std::size_t v = s.contour_count; v < s.vertices.size(); ++v) {
    lo = std::min(lo, s.vertices[v].position.x);
    hi = std::max(hi, s.vertices[v].position.x);
  }
  return hi - lo;
}

TEST(Skeleton, RectangleRidgeIsLengthMinusWidthAtHalfWidth) {
  const auto s = interior_straight_skeleton(rectangle(6, 10));
  ASSERT_TRUE(s.has_value());
  EXPECT_EQ(s->contour_count, 4U);
  ASSERT_EQ(s->vertices.size(), 6U);
  for (std::size_t v = 4; v < 6; ++v) {
    EXPECT_NEAR(s->vertices[v].time, 3.0, 1e-9);
    EXPECT_NEAR(s->vertices[v].position.y, 3.0, 1e-9);
  }
  EXPECT_NEAR(ridge_length(*s), 4.0, 1e-9);
  EXPECT_NEAR(s->max_time(), 3.0, 1e-9);
  // Long edges sweep trapezoids, short edges triangles.
  ASSERT_EQ(s->face_count(), 4U);
  EXPECT_EQ(s->face(0).size(), 4U);
  EXPECT_EQ(s->face(1).size(), 3U);
  EXPECT_EQ(s->face(2).size(), 4U);
  EXPECT_EQ(s->face(3).size(), 3U);
}

TEST(Skeleton, FacesStartWithTheirEdgeAndRunCounterClockwise) {
  const Polygon l_shape{{{0, 0}, {12, 0}, {12, 5}, {5, 5}, {5, 12}, {0, 12}}, {}};
  const auto s = interior_straight_skeleton(l_shape);
  ASSERT_TRUE(s.has_value());
  for (std::uint32_t e = 0; e < s->contour_count; ++e) {
    const auto face = s->face(e);
    EXPECT_EQ(face[0], e);
    EXPECT_EQ(face[1], s->next_contour(e));
    Ring ring;
    for (std::uint32_t v : face) ring.push_back(s->vertices[v].position);
    EXPECT_GT(signed_area(ring), 0) << "face " << e;
  }
  // The faces tile the polygon.
  double total = 0;
  for (std::uint32_t e = 0; e < s->contour_count; ++e) {
    Ring ring;
    for (std::uint32_t v : s->face(e)) ring.push_back(s->vertices[v].position);
    total += signed_area(ring);
  }
  EXPECT_NEAR(total, area(l_shape), 1e-9);
}

TEST(Skeleton, TimesAreDistancesToTheFaceEdgeLine) {
  const Polygon irregular{{{0, 0}, {9, -1}, {14, 4}, {8, 6}, {9, 11}, {1, 9}, {3, 5}}, {}};
  const auto s = interior_straight_skeleton(irregular);
  ASSERT_TRUE(s.has_value());
  for (std::uint32_t e = 0; e < s->contour_count; ++e) {
    const Vec2 a = s->vertices[e].position;
    const Vec2 d = normalized(s->vertices[s->next_contour(e)].position - a);
    for (std::uint32_t v : s->face(e)) {
      EXPECT_NEAR(cross(d, s->vertices[v].position - a), s->vertices[v].time, 1e-7);
    }
  }
}

TEST(Skeleton, CourtyardHasFacesForHoleEdges) {
  Polygon courtyard = rectangle(20, 20);
  courtyard.holes.push_back({{6, 6}, {6, 14}, {14, 14}, {14, 6}});  // clockwise
  const auto s = interior_straight_skeleton(courtyard);
  ASSERT_TRUE(s.has_value());
  EXPECT_EQ(s->face_count(), 8U);
  EXPECT_EQ(s->ring_starts, (std::vector<std::uint32_t>{0, 4, 8}));
  EXPECT_EQ(s->next_contour(7), 4U);
  EXPECT_EQ(s->previous_contour(4), 7U);
  EXPECT_NEAR(s->max_time(), 3.0, 1e-9);  // the ring between hole and outer is 6 m wide
}

TEST(Skeleton, CollinearVerticesAreKept) {
  const Polygon p{{{0, 0}, {5, 0}, {10, 0}, {10, 4}, {0, 4}}, {}};
  const auto s = interior_straight_skeleton(p);
  ASSERT_TRUE(s.has_value());
  EXPECT_EQ(s->face_count(), 5U);
  EXPECT_NEAR(s->max_time(), 2.0, 1e-9);
}

TEST(Skeleton, ManyVerticesCircle) {
  Polygon circle;
  for (int i = 0; i < 256; ++i) {
    const double a = 2 * 3.14159265358979 * i / 256;
    circle.outer.push_back({10 * std::cos(a), 10 * std::sin(a)});
  }
  const auto s = interior_straight_skeleton(circle);
  ASSERT_TRUE(s.has_value());
  EXPECT_EQ(s->face_count(), 256U);
  EXPECT_NEAR(s->max_time(), 10 * std::cos(3.14159265358979 / 256), 1e-6);
}

// Large footprints stay practical: a 4,000-vertex convex ring takes the wavefront path, and the
// simplicity check of a 20,000-vertex comb (non-convex, so it reaches CGAL's input check) is a
// sweep, not all pairs of edges.
TEST(Skeleton, LargeConvexRingAndLargeCombAreHandled) {
  Polygon circle;
  for (int i = 0; i < 4000; ++i) {
    const double a = 2 * 3.14159265358979 * i / 4000;
    circle.outer.push_back({50 * std::cos(a), 50 * std::sin(a)});
  }
  const auto s = interior_straight_skeleton(circle);
  ASSERT_TRUE(s.has_value());
  EXPECT_EQ(s->face_count(), 4000U);
  EXPECT_NEAR(s->max_time(), 50 * std::cos(3.14159265358979 / 4000), 1e-6);

  Polygon strip;
  for (int i = 0; i < 5000; ++i) {
    strip.outer.push_back({2.0 * i, 0});
    strip.outer.push_back({2.0 * i + 1, 0});
  }
  strip.outer.push_back({10000, 5});
  strip.outer.push_back({0, 5});
  EXPECT_TRUE(is_simple_polygon(strip));
  strip.outer.push_back({5000, -1});  // the closing edges now cross the base
  EXPECT_FALSE(is_simple_polygon(strip));
}

// Coordinates whose squares overflow made CGAL's exact fallback trap (SIGFPE); they are declined.
TEST(Skeleton, HugeCoordinatesGiveNothingAndDoNotCrash) {
  for (double scale : {1e101, 1e154, 1e300}) {
    const Polygon l_shape{{{0, 0},
                           {12 * scale, 0},
                           {12 * scale, 5 * scale},
                           {5 * scale, 5 * scale},
                           {5 * scale, 12 * scale},
                           {0, 12 * scale}},
                          {}};
    EXPECT_FALSE(interior_straight_skeleton(l_shape).has_value()) << scale;
    EXPECT_FALSE(general_straight_skeleton(l_shape).has_value()) << scale;
  }
  const double big = 1e12;  // far beyond any footprint, still answered
  const Polygon large{{{0, 0},
                       {12 * big, 0},
                       {12 * big, 5 * big},
                       {5 * big, 5 * big},
                       {5 * big, 12 * big},
                       {0, 12 * big}},
                      {}};
  EXPECT_TRUE(interior_straight_skeleton(large).has_value());
}

TEST(Skeleton, InvalidInputGivesNothing) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(interior_straight_skeleton({{{0, 0}, {1, 0}}, {}}).has_value());
  EXPECT_FALSE(interior_straight_skeleton({{{0, 0}, {1, 0}, {nan, 1}}, {}}).has_value());
  // Bow tie.
  EXPECT_FALSE(interior_straight_skeleton({{{0, 0}, {4, 4}, {4, 0}, {0, 4}}, {}}).has_value());
  // Clockwise outer ring.
  EXPECT_FALSE(interior_straight_skeleton({{{0, 0}, {0, 4}, {4, 4}, {4, 0}}, {}}).has_value());
  // Repeated vertex.
  EXPECT_FALSE(
      interior_straight_skeleton({{{0, 0}, {4, 0}, {4, 0}, {4, 4}, {0, 4}}, {}}).has_value());
  // Hole outside the outer ring.
  Polygon outside = rectangle(4, 4);
  outside.holes.push_back({{10, 10}, {10, 11}, {11, 11}, {11, 10}});
  EXPECT_FALSE(interior_straight_skeleton(outside).has_value());
  // Hole crossing the outer ring.
  Polygon crossing = rectangle(4, 4);
  crossing.holes.push_back({{2, 2}, {2, 6}, {3, 6}, {3, 2}});
  EXPECT_FALSE(interior_straight_skeleton(crossing).has_value());
  EXPECT_FALSE(is_simple_polygon(crossing));
  EXPECT_TRUE(is_simple_polygon(rectangle(4, 4)));
}

}  // namespace
}  // namespace insula::kernel
