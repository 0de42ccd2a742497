// The general wavefront straight skeleton (skeleton_wavefront.h) against CGAL's builder on the
// outlines it is for: real footprints' shapes (L, T, U, H, Z, plus, combs) turned to any angle,
// with survey noise, far from the origin, with nearly collinear extra vertices; random star
// polygons; regular polygons and stars (simultaneous events); courtyards (holes). Whenever the
// wavefront answers, its skeleton must be valid and CGAL's face by face. It may decline (CGAL then
// takes over), but only rarely on footprint shapes: each group counts its declines.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "kernel/polygon.h"
#include "kernel/skeleton.h"
#include "kernel/skeleton_wavefront.h"
#include "skeleton_checks.h"

namespace insula::kernel {
namespace {

using testing_skeleton::expect_matches;
using testing_skeleton::expect_valid;

struct Tally {
  int compared = 0;
  int declined = 0;
  int skipped = 0;  // not simple, or CGAL failed: nothing to compare with
  void print(const char* what) const {
    std::printf("[ tally    ] %s: %d compared, %d declined, %d without reference\n", what, compared,
                declined, skipped);
  }
};

void check(const Polygon& polygon, const std::string& what, Tally& tally) {
  SCOPED_TRACE(what);
  if (!is_simple_polygon(polygon)) {
    ++tally.skipped;
    return;
  }
  const auto reference = general_straight_skeleton(polygon);
  const auto ours = wavefront_straight_skeleton(polygon);
  if (!reference) {
    ++tally.skipped;
    if (ours) expect_valid(polygon, *ours, what);
    return;
  }
  if (!ours) {
    ++tally.declined;
    return;
  }
  expect_valid(polygon, *ours, what);
  expect_matches(polygon, *ours, *reference, what);
  ++tally.compared;
}

Ring counter_clockwise(Ring ring) {
  if (signed_area(ring) < 0) std::reverse(ring.begin(), ring.end());
  return ring;
}

Ring clockwise(Ring ring) {
  if (signed_area(ring) > 0) std::reverse(ring.begin(), ring.end());
  return ring;
}

// `ring` turned by `angle`, scaled, moved, each vertex moved by up to `noise` on each axis.
Ring placed(const Ring& ring, double angle, double scale, Vec2 offset, double noise,
            std::mt19937& random) {
  std::uniform_real_distribution<double> jitter(-noise, noise);
  const double c = std::cos(angle), s = std::sin(angle);
  Ring out;
  for (Vec2 p : ring) {
    out.push_back(Vec2{(p.x * c - p.y * s) * scale + offset.x + jitter(random),
                       (p.x * s + p.y * c) * scale + offset.y + jitter(random)});
  }
  return out;
}

const std::vector<std::pair<std::string, Ring>>& footprint_shapes() {
  static const std::vector<std::pair<std::string, Ring>> shapes = {
      {"L", {{0, 0}, {16, 0}, {16, 6}, {6, 6}, {6, 14}, {0, 14}}},
      {"T", {{0, 0}, {6, 0}, {6, 8}, {12, 8}, {12, 12}, {-6, 12}, {-6, 8}, {0, 8}}},
      {"U", {{0, 0}, {14, 0}, {14, 10}, {10, 10}, {10, 4}, {4, 4}, {4, 10}, {0, 10}}},
      {"H",
       {{0, 0},
        {4, 0},
        {4, 4},
        {8, 4},
        {8, 0},
        {12, 0},
        {12, 12},
        {8, 12},
        {8, 8},
        {4, 8},
        {4, 12},
        {0, 12}}},
      {"Z", {{0, 0}, {10, 0}, {10, 5}, {15, 5}, {15, 10}, {5, 10}, {5, 5}, {0, 5}}},
      {"plus",
       {{4, 0},
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
        {4, 4}}},
      {"comb",
       {{0, 0},
        {20, 0},
        {20, 8},
        {18, 8},
        {18, 3},
        {16, 3},
        {16, 8},
        {14, 8},
        {14, 3},
        {12, 3},
        {12, 8},
        {10, 8},
        {10, 3},
        {8, 3},
        {8, 8},
        {0, 8}}},
      {"trapezoid wing", {{0, 0}, {18, 0}, {18, 5}, {9, 7}, {7, 15}, {0, 13}}},
  };
  return shapes;
}

TEST(WavefrontSkeleton, FootprintShapesAtAnyAngleMatchCgal) {
  std::mt19937 random(17);
  std::uniform_real_distribution<double> angle(0, std::numbers::pi);
  std::uniform_real_distribution<double> scale(0.4, 3);
  std::uniform_real_distribution<double> far(-6e5, 6e5);
  const double noises[] = {0, 0.001, 0.01, 0.05, 0.2};
  for (const auto& [name, shape] : footprint_shapes()) {
    Tally tally;
    for (int k = 0; k < 40; ++k) {
      const Vec2 offset = k % 3 == 0 ? Vec2{far(random), far(random)} : Vec2{0, 0};
      const double noise = noises[k % 5];
      const Polygon polygon{
          counter_clockwise(placed(shape, angle(random), scale(random), offset, noise, random)),
          {}};
      check(polygon, name + " #" + std::to_string(k), tally);
    }
    tally.print(name.c_str());
    // Declines are CGAL's work. The exact shapes (no noise: 8 of the 40) have split events at the
    // time of other events, which the wavefront leaves to CGAL; 26 to 40 answered when this was
    // written.
    EXPECT_GE(tally.compared, 24) << name;
  }
}

// Surveyed outlines carry extra vertices a few centimetres off a straight wall.
TEST(WavefrontSkeleton, NearlyCollinearVerticesMatchCgal) {
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(0, 1);
  std::uniform_real_distribution<double> off(-0.03, 0.03);
  const Ring rectangle{{0, 0}, {10, 0}, {10, 6}, {0, 6}};
  const Ring& l_shape = footprint_shapes()[0].second;
  Tally tally;
  for (int k = 0; k < 120; ++k) {
    const Ring& base = k % 2 == 0 ? rectangle : l_shape;
    Ring ring;
    for (std::size_t i = 0; i < base.size(); ++i) {
      const Vec2 p = base[i], q = base[(i + 1) % base.size()];
      ring.push_back(p);
      if (unit(random) < 0.6) {
        const double t = 0.2 + 0.6 * unit(random);
        ring.push_back(p + (q - p) * t + Vec2{off(random), off(random)});
      }
    }
    const Polygon polygon{counter_clockwise(placed(ring, 3.1 * unit(random), 1, {}, 0, random)),
                          {}};
    check(polygon, "collinear #" + std::to_string(k), tally);
  }
  tally.print("nearly collinear");
  EXPECT_GE(tally.compared, 100);  // 113 of 120 when this was written
}

TEST(WavefrontSkeleton, RandomStarPolygonsMatchCgal) {
  std::mt19937 random(11);
  std::uniform_int_distribution<int> count(5, 40);
  std::uniform_real_distribution<double> turn(0, 2 * std::numbers::pi);
  std::uniform_real_distribution<double> radius(3, 10);
  Tally tally;
  for (int k = 0; k < 300; ++k) {
    std::vector<double> angles(static_cast<std::size_t>(count(random)));
    for (double& a : angles) a = turn(random);
    std::sort(angles.begin(), angles.end());
    Ring ring;
    for (double a : angles) {
      const double r = radius(random);
      ring.push_back({r * std::cos(a), r * std::sin(a)});
    }
    check(Polygon{counter_clockwise(ring), {}}, "star #" + std::to_string(k), tally);
  }
  tally.print("random stars");
  EXPECT_GE(tally.compared, 250);  // all 300 when this was written
}

// Symmetric outlines have many events at one time and place; declining them is allowed.
TEST(WavefrontSkeleton, RegularPolygonsAndStarsAreValidWhenAnswered) {
  Tally tally;
  for (int n = 5; n < 25; ++n) {
    Ring regular, star;
    for (int i = 0; i < n; ++i) {
      const double a = 2 * std::numbers::pi * i / n;
      regular.push_back({5 * std::cos(a), 5 * std::sin(a)});
    }
    for (int i = 0; i < 2 * n; ++i) {
      const double a = std::numbers::pi * i / n;
      const double r = i % 2 == 0 ? 5 : 2;
      star.push_back({r * std::cos(a), r * std::sin(a)});
    }
    for (const Ring& ring : {regular, star}) {
      const Polygon polygon{ring, {}};
      if (const auto ours = wavefront_straight_skeleton(polygon)) {
        expect_valid(polygon, *ours, std::to_string(n));
        ++tally.compared;
      } else {
        ++tally.declined;
      }
    }
  }
  tally.print("regular polygons and stars");
}

TEST(WavefrontSkeleton, CourtyardsMatchCgal) {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> unit(0, 1);
  Tally tally;
  for (int k = 0; k < 80; ++k) {
    const double angle = 3.1 * unit(random);
    const double noise = 0.01 * (k % 3);
    const double x = 3 + 6 * unit(random), y = 3 + 4 * unit(random), w = 1 + 3 * unit(random);
    Polygon polygon{counter_clockwise(
                        placed({{0, 0}, {20, 0}, {20, 14}, {0, 14}}, angle, 1, {}, noise, random)),
                    {}};
    polygon.holes.push_back(
        clockwise(placed({{x, y}, {x + w, y}, {x + w, y + 0.8 * w}, {x, y + 0.8 * w}}, angle, 1, {},
                         noise, random)));
    if (k % 2 == 1) {
      polygon.holes.push_back(
          clockwise(placed({{14, 4}, {17, 4}, {17, 9}, {14, 9}}, angle, 1, {}, noise, random)));
    }
    check(polygon, "courtyard #" + std::to_string(k), tally);
  }
  tally.print("courtyards");
  EXPECT_GE(tally.compared, 45);  // 53 of 80 when this was written
}

// A union of grid cells turned to an angle: many events at one time, split events among them.
// Taken in the order rounding gave, they left a skeleton that passed every check of the builder
// and yet was not CGAL's: the faces of two parallel edges traded 5 m2 of a 257 m2 outline. Such
// ties go to CGAL.
TEST(WavefrontSkeleton, SimultaneousSplitEventsMatchCgalOrDecline) {
  const Polygon polygon{{{-11.584045299, -11.102025137},
                         {-18.245260381, -4.151597958},
                         {-20.562069441, -6.372002985},
                         {-22.782474469, -4.055193925},
                         {-15.832047289, 2.606021157},
                         {-22.493262371, 9.556448337},
                         {-34.077307671, -1.545576800},
                         {-27.416092588, -8.496003980},
                         {-25.099283529, -6.275598953},
                         {-22.878878501, -8.592408012},
                         {-25.195687561, -10.812813040},
                         {-18.534472479, -17.763240219}},
                        {}};
  const auto reference = general_straight_skeleton(polygon);
  ASSERT_TRUE(reference);
  if (const auto ours = wavefront_straight_skeleton(polygon)) {
    expect_matches(polygon, *ours, *reference, "turned grid union");
  }
  const auto chosen = interior_straight_skeleton(polygon);
  ASSERT_TRUE(chosen);
  expect_matches(polygon, *chosen, *reference, "turned grid union, any builder");
}

// interior_straight_skeleton answers concave outlines at any angle (through the wavefront, or
// CGAL when it declines) with CGAL's skeleton.
TEST(WavefrontSkeleton, InteriorSkeletonOfARotatedLIsCgals) {
  std::mt19937 random(1);
  const Polygon polygon{
      counter_clockwise(placed(footprint_shapes()[0].second, 0.3, 1, {455000, 5428000}, 0, random)),
      {}};
  const auto chosen = interior_straight_skeleton(polygon);
  const auto reference = general_straight_skeleton(polygon);
  ASSERT_TRUE(chosen && reference);
  expect_matches(polygon, *chosen, *reference, "rotated L");
}

TEST(WavefrontSkeleton, DeclinesOutlinesPastItsSize) {
  Ring ring;
  for (int i = 0; i < 400; ++i) {
    const double a = 2 * std::numbers::pi * i / 400;
    const double r = i % 2 == 0 ? 10 : 9;
    ring.push_back({r * std::cos(a), r * std::sin(a)});
  }
  EXPECT_FALSE(wavefront_straight_skeleton(Polygon{ring, {}}));
  EXPECT_TRUE(interior_straight_skeleton(Polygon{ring, {}}));
}

}  // namespace
}  // namespace insula::kernel
