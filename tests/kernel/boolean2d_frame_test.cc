// subtract(a, b, frame): the difference snapped in a given integer frame (boolean2d.h), which lets
// a caller leave out the clip polygons that only touch `a` and still get the same vertices.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "kernel/boolean2d.h"

namespace insula::kernel {
namespace {

Polygon rect(double x0, double y0, double x1, double y1) {
  return {{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, {}};
}

Bounds2 bounds_of(const std::vector<Polygon>& a, const std::vector<Polygon>& b) {
  Bounds2 box;
  for (const auto* set : {&a, &b}) {
    for (const Polygon& p : *set) {
      const Bounds2 pb = bounds(p);
      box.add(pb.min);
      box.add(pb.max);
    }
  }
  return box;
}

// The vertices of every result ring, sorted: equal when two results differ at most in where a
// ring starts.
std::vector<std::pair<double, double>> vertex_set(const std::vector<Polygon>& polygons) {
  std::vector<std::pair<double, double>> out;
  for (const Polygon& p : polygons) {
    for (Vec2 v : p.outer) out.emplace_back(v.x, v.y);
    for (const Ring& hole : p.holes) {
      for (Vec2 v : hole) out.emplace_back(v.x, v.y);
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

// A room cell with walls across its sides (the rooms stage's fallback), plus walls of the
// neighbouring cells that only touch its corner or side: the coordinates are not multiples of the
// micrometre grid, so the snapped result depends on the frame's centre.
TEST(Boolean2dFrame, TouchingClipPolygonsLeftOutGiveTheSameVertices) {
  const std::vector<Polygon> cell{rect(0.1234567, 0.7654321, 5.3333333, 4.1111111)};
  const std::vector<Polygon> crossing{rect(-0.1, 0.6654321, 5.4333333, 0.8654321),
                                      rect(5.2333333, 0.6654321, 5.4333333, 4.2111111),
                                      rect(2.0000001, 3.0000003, 2.2000001, 4.2111111)};
  std::vector<Polygon> all = crossing;
  all.push_back(rect(5.3333333, 2.0, 9.0, 2.2));          // touches the right side only
  all.push_back(rect(-3.0, -3.0, 0.1234567, 0.7654321));  // touches a corner only
  all.push_back(rect(0.5, 4.1111111, 0.7, 8.0));          // touches the top side only
  const BooleanResult reference = subtract(cell, all);
  const BooleanResult framed = subtract(cell, crossing, bounds_of(cell, all));
  const BooleanResult unframed = subtract(cell, crossing);
  ASSERT_TRUE(reference.ok());
  ASSERT_TRUE(framed.ok());
  ASSERT_TRUE(unframed.ok());
  ASSERT_EQ(reference.polygons.size(), 1U);
  ASSERT_EQ(framed.polygons.size(), 1U);
  EXPECT_EQ(reference.polygons[0].outer.size(), 8U);  // a notch cut by the third wall
  EXPECT_EQ(vertex_set(framed.polygons), vertex_set(reference.polygons));
  EXPECT_NEAR(area(framed.polygons[0]), area(reference.polygons[0]), 1e-12);
  // Without the frame the snapping grid moves with the operands' centre: other coordinates.
  EXPECT_NE(vertex_set(unframed.polygons), vertex_set(reference.polygons));
}

TEST(Boolean2dFrame, FrameInsideTheOperandsChangesNothing) {
  const std::vector<Polygon> a{rect(0.3, 0.3, 4.7, 3.9)};
  const std::vector<Polygon> b{rect(1.1, 1.1, 2.3, 5.0)};
  const BooleanResult plain = subtract(a, b);
  const BooleanResult framed = subtract(a, b, bounds(rect(1, 1, 2, 2)));
  ASSERT_TRUE(plain.ok());
  ASSERT_TRUE(framed.ok());
  ASSERT_EQ(plain.polygons.size(), framed.polygons.size());
  for (std::size_t i = 0; i < plain.polygons.size(); ++i) {
    EXPECT_EQ(plain.polygons[i].outer, framed.polygons[i].outer);
  }
}

TEST(Boolean2dFrame, OversizedOrNonFiniteFrameIsReported) {
  const std::vector<Polygon> a{rect(0, 0, 1, 1)};
  Bounds2 huge;
  huge.add({-1e13, 0});
  huge.add({1e13, 1});
  EXPECT_EQ(subtract(a, {}, huge).status, BooleanStatus::kRangeTooLarge);
  Bounds2 infinite;
  infinite.add({0, 0});
  infinite.add({1e308 * 10, 1});
  EXPECT_EQ(subtract(a, {}, infinite).status, BooleanStatus::kNonFinite);
}

}  // namespace
}  // namespace insula::kernel
