#include "kernel/boolean2d.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

namespace insula::kernel {
namespace {

Polygon square(double x0, double y0, double side) {
  return {{{x0, y0}, {x0 + side, y0}, {x0 + side, y0 + side}, {x0, y0 + side}}, {}};
}

double total_area(const std::vector<Polygon>& polygons) {
  double sum = 0;
  for (const Polygon& p : polygons) sum += area(p);
  return sum;
}

void expect_normalized(const std::vector<Polygon>& polygons) {
  for (const Polygon& p : polygons) {
    EXPECT_GT(signed_area(p.outer), 0);
    for (const Ring& h : p.holes) EXPECT_LT(signed_area(h), 0);
    EXPECT_TRUE(repair(p, 1e-9).ok);
  }
}

TEST(Boolean2d, UnionOfOverlappingSquares) {
  const BooleanResult r = unite({square(0, 0, 2)}, {square(1, 1, 2)});
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.polygons.size(), 1U);
  EXPECT_NEAR(area(r.polygons[0]), 7.0, 1e-9);
  EXPECT_EQ(r.polygons[0].outer.size(), 8U);
  expect_normalized(r.polygons);
}

TEST(Boolean2d, IntersectionDifferenceXor) {
  const std::vector<Polygon> a{square(0, 0, 2)}, b{square(1, 1, 2)};
  const BooleanResult i = intersect(a, b);
  ASSERT_EQ(i.polygons.size(), 1U);
  EXPECT_NEAR(area(i.polygons[0]), 1.0, 1e-9);
  const BooleanResult d = subtract(a, b);
  ASSERT_EQ(d.polygons.size(), 1U);
  EXPECT_NEAR(area(d.polygons[0]), 3.0, 1e-9);
  EXPECT_EQ(d.polygons[0].outer.size(), 6U);  // an L
  const BooleanResult x = exclusive_or(a, b);
  EXPECT_NEAR(total_area(x.polygons), 6.0, 1e-9);
  expect_normalized(i.polygons);
  expect_normalized(d.polygons);
  expect_normalized(x.polygons);
  EXPECT_TRUE(intersect(a, {square(5, 5, 1)}).polygons.empty());
}

TEST(Boolean2d, SubtractingAnInnerSquareMakesAHole) {
  const BooleanResult r = subtract({square(0, 0, 10)}, {square(2, 2, 3), square(6, 6, 2)});
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.polygons.size(), 1U);
  EXPECT_EQ(r.polygons[0].holes.size(), 2U);
  EXPECT_NEAR(area(r.polygons[0]), 100.0 - 9.0 - 4.0, 1e-9);
  expect_normalized(r.polygons);
}

TEST(Boolean2d, HolesAndIslandsArePreserved) {
  // A frame (square with a hole) with an island inside the hole: two polygons out.
  Polygon frame = square(0, 0, 10);
  frame.holes.push_back(square(2, 2, 6).outer);  // counter-clockwise on purpose
  const BooleanResult r = unite({frame}, {square(4, 4, 2)});
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.polygons.size(), 2U);
  EXPECT_NEAR(area(r.polygons[0]), 64.0, 1e-9);  // sorted by area
  EXPECT_EQ(r.polygons[0].holes.size(), 1U);
  EXPECT_NEAR(area(r.polygons[1]), 4.0, 1e-9);
  EXPECT_TRUE(r.polygons[1].holes.empty());
  expect_normalized(r.polygons);
}

TEST(Boolean2d, UnionAllMergesTouchingFootprints) {
  // Three row houses sharing walls, plus a detached one.
  const std::vector<Polygon> houses{square(0, 0, 5), square(5, 0, 5), square(10, 0, 5),
                                    square(30, 0, 5)};
  const std::vector<Polygon> blocks = union_all(houses);
  ASSERT_EQ(blocks.size(), 2U);
  EXPECT_NEAR(area(blocks[0]), 75.0, 1e-9);
  EXPECT_EQ(blocks[0].outer.size(), 4U);  // shared walls and their vertices vanish
  EXPECT_NEAR(area(blocks[1]), 25.0, 1e-9);
  EXPECT_TRUE(union_all({}).empty());
}

TEST(Boolean2d, MiterOffsetOfSquare) {
  const double s = 4;
  const BooleanResult grown = offset({square(0, 0, s)}, 1.0, JoinType::kMiter);
  ASSERT_EQ(grown.polygons.size(), 1U);
  EXPECT_NEAR(area(grown.polygons[0]), (s + 2) * (s + 2), 1e-9);
  const BooleanResult shrunk = offset({square(0, 0, s)}, -1.0, JoinType::kMiter);
  ASSERT_EQ(shrunk.polygons.size(), 1U);
  EXPECT_NEAR(area(shrunk.polygons[0]), (s - 2) * (s - 2), 1e-9);
  EXPECT_TRUE(offset({square(0, 0, s)}, -2.5).polygons.empty());  // vanishes
}

TEST(Boolean2d, RoundAndSquareOffsets) {
  const double s = 4, d = 1;
  const BooleanResult round = offset({square(0, 0, s)}, d, JoinType::kRound);
  ASSERT_EQ(round.polygons.size(), 1U);
  const double analytic = s * s + 4 * s * d + std::numbers::pi * d * d;
  // Polygonal arcs within 1 mm of the circle lose at most 2 * pi * d * 1e-3 of area.
  EXPECT_LT(area(round.polygons[0]), analytic);
  EXPECT_NEAR(area(round.polygons[0]), analytic, 2 * std::numbers::pi * d * 1e-3);
  const BooleanResult sq = offset({square(0, 0, s)}, d, JoinType::kSquare);
  ASSERT_EQ(sq.polygons.size(), 1U);
  // A square join cuts each miter corner at distance d from the vertex: between round and miter.
  EXPECT_GT(area(sq.polygons[0]), analytic);
  EXPECT_LT(area(sq.polygons[0]), (s + 2 * d) * (s + 2 * d));
}

TEST(Boolean2d, OffsetShrinksHolesAndUnitesFirst) {
  Polygon frame = square(0, 0, 10);
  frame.holes.push_back(square(3, 3, 4).outer);
  const BooleanResult r = offset({frame}, 1.0);
  ASSERT_EQ(r.polygons.size(), 1U);
  ASSERT_EQ(r.polygons[0].holes.size(), 1U);
  EXPECT_NEAR(area(r.polygons[0]), 144.0 - 4.0, 1e-9);
  // Two overlapping squares shrunk: the union's inset, not the union of insets.
  const BooleanResult inset = offset({square(0, 0, 4), square(2, 0, 4)}, -1.0);
  ASSERT_EQ(inset.polygons.size(), 1U);
  EXPECT_NEAR(area(inset.polygons[0]), 4.0 * 2.0, 1e-9);
}

TEST(Boolean2d, UtmCoordinatesKeepMicrometrePrecision) {
  const double x = 500000.123456, y = 5000000.654321;
  const BooleanResult r = unite({square(x, y, 10)}, {square(x + 10, y, 10)});
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.polygons.size(), 1U);
  EXPECT_NEAR(area(r.polygons[0]), 200.0, 1e-4);
  const Bounds2 b = bounds(r.polygons[0]);
  EXPECT_NEAR(b.min.x, x, 1e-6);
  EXPECT_NEAR(b.min.y, y, 1e-6);
  EXPECT_NEAR(b.max.x, x + 20, 1e-6);
  EXPECT_NEAR(b.max.y, y + 10, 1e-6);
  // A 3 micrometre sliver survives.
  const BooleanResult sliver = subtract({square(x, y, 10)}, {square(x + 3e-6, y - 1, 12)});
  ASSERT_EQ(sliver.polygons.size(), 1U);
  EXPECT_NEAR(bounds(sliver.polygons[0]).max.x - x, 3e-6, 1e-6);
}

TEST(Boolean2d, BadInputGivesStatus) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Polygon bad = square(0, 0, 1);
  bad.outer[2].x = nan;
  EXPECT_EQ(unite({bad}, {}).status, BooleanStatus::kNonFinite);
  EXPECT_EQ(offset({square(0, 0, 1)}, nan).status, BooleanStatus::kNonFinite);
  const BooleanResult huge = unite({square(0, 0, 1), square(2e12, 0, 1)}, {});
  EXPECT_EQ(huge.status, BooleanStatus::kRangeTooLarge);
  EXPECT_TRUE(huge.polygons.empty());
  EXPECT_EQ(offset({square(0, 0, 1)}, 1e13).status, BooleanStatus::kRangeTooLarge);
  EXPECT_EQ(to_string(BooleanStatus::kRangeTooLarge).substr(0, 16), "the input spans ");
  // Degenerate rings are ignored, not fatal.
  const BooleanResult flat = unite({Polygon{{{0, 0}, {1, 1}, {2, 2}}, {}}}, {square(0, 0, 1)});
  ASSERT_TRUE(flat.ok());
  EXPECT_NEAR(total_area(flat.polygons), 1.0, 1e-12);
}

// A window a split left 1 micrometre wide (a real OpenStreetMap footprint through building.cga)
// is one grid unit wide: Clipper's union of it reported failure. Inset by 8 cm it vanishes.
TEST(Boolean2d, OffsetOfAGridUnitWideRectangle) {
  const Polygon thin{{{0, 0}, {9.9999999747524271e-07, 0}, {9.9999999747524271e-07, 1.6}, {0, 1.6}},
                     {}};
  const BooleanResult inside = offset({thin}, -0.08);
  ASSERT_TRUE(inside.ok()) << to_string(inside.status);
  EXPECT_TRUE(inside.polygons.empty());
  const BooleanResult united = unite({thin}, {});
  ASSERT_TRUE(united.ok()) << to_string(united.status);
}

// Strips along both edges of a bend that turns away from the region meet at a point of its
// outline. Clipper's strictly simple pass gave the difference as the whole chevron with each strip
// a hole running along the outline (right area, invalid region); it is one ring.
TEST(Boolean2d, DifferenceOfStripsMeetingAtABendIsOneRing) {
  const Polygon chevron{{{35, 0}, {25, 25}, {0, 35}, {0, 20}, {14, 14}, {20, 0}}, {}};
  std::vector<Polygon> strips;
  for (std::size_t i : {3U, 4U}) {
    const Vec2 a = chevron.outer[i];
    const Vec2 b = chevron.outer[i + 1];
    const Vec2 inward = perp(normalized(b - a));
    strips.push_back({{a, b, b + inward * 4.0, a + inward * 4.0}, {}});
  }
  const BooleanResult rest = subtract({chevron}, strips);
  const BooleanResult band = intersect({chevron}, strips);
  ASSERT_TRUE(rest.ok() && band.ok());
  ASSERT_EQ(rest.polygons.size(), 1U);
  EXPECT_TRUE(rest.polygons[0].holes.empty());
  EXPECT_TRUE(validate(rest.polygons[0]).empty());
  EXPECT_NEAR(total_area(rest.polygons) + total_area(band.polygons), area(chevron), 1e-4);
  expect_normalized(rest.polygons);
}

}  // namespace
}  // namespace insula::kernel
