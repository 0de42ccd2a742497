// The planar primitives every layer shares (kernel/planar.h): boxes, convexity, half-plane clips.
#include "kernel/planar.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace insula::kernel {
namespace {

const Ring kSquare{{0, 0}, {1, 0}, {1, 1}, {0, 1}};

TEST(Planar, BoundsAndTouches) {
  const Bounds2 b = bounds(Ring{{2, -1}, {-3, 4}, {0, 0}});
  EXPECT_EQ(b.min, (Vec2{-3, -1}));
  EXPECT_EQ(b.max, (Vec2{2, 4}));
  EXPECT_TRUE(bounds(Ring{}).empty());
  Bounds2 grown = bounds(kSquare);
  add(grown, Ring{{5, 0.5}});
  EXPECT_EQ(grown.max, (Vec2{5, 1}));
  const Bounds2 right = bounds(Ring{{1, 0}, {2, 1}});
  const Bounds2 apart = bounds(Ring{{1.5, 0}, {2, 1}});
  EXPECT_TRUE(touches(bounds(kSquare), right));  // sharing a side counts
  EXPECT_FALSE(touches(bounds(kSquare), apart));
  EXPECT_TRUE(touches(bounds(kSquare), apart, 0.5));
}

TEST(Planar, ConvexityWithStraightCornersAndTolerance) {
  EXPECT_TRUE(is_convex(kSquare));
  Ring clockwise(kSquare.rbegin(), kSquare.rend());
  EXPECT_FALSE(is_convex(clockwise));
  EXPECT_TRUE(is_convex(clockwise, Winding::kEither));
  EXPECT_TRUE(is_convex(Ring{{0, 0}, {0.5, 0}, {1, 0}, {1, 1}, {0, 1}}));  // a straight corner
  const Ring l_shape{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  EXPECT_FALSE(is_convex(l_shape));
  EXPECT_FALSE(is_convex(l_shape, Winding::kEither));
  // A corner bent inward by 1e-13 m^2 passes a 1e-12 tolerance only.
  const Ring dent{{0, 0}, {0.5, 1e-13}, {1, 0}, {1, 1}, {0, 1}};
  EXPECT_FALSE(is_convex(dent));
  EXPECT_TRUE(is_convex(dent, Winding::kCounterClockwise, 1e-12));
  EXPECT_TRUE(is_convex(Ring{{0, 0}, {1, 1}}));
}

TEST(Planar, ClipKeepsTheInsideAndAddsNoRepeatedVertex) {
  Ring out;
  clip(kSquare, {{0.25, 0}, {1, 0}}, out);  // x >= 0.25
  EXPECT_NEAR(signed_area(out), 0.75, 1e-15);
  EXPECT_EQ(out.size(), 4U);
  // The line through two corners: they stay, nothing is added twice.
  clip(kSquare, {{0, 0}, {-1, 1}}, out);  // y >= x
  EXPECT_EQ(out, (Ring{{0, 0}, {1, 1}, {0, 1}}));
  // An offset moves the line along the normal: x >= 0.25 + 0.5.
  clip(kSquare, {{0.25, 0}, {1, 0}, 0.5}, out);
  EXPECT_NEAR(signed_area(out), 0.25, 1e-15);
  clip(kSquare, {{2, 0}, {1, 0}}, out);
  EXPECT_TRUE(out.empty());
}

TEST(Planar, AxisParallelCutsLieExactlyOnTheLine) {
  // Interpolated crossings may miss the line by an ulp; the clip puts them on it.
  const Ring quad{{0.013, 0.7}, {1.37, 0.011}, {2.9, 1.3}, {0.31, 2.17}};
  Ring out;
  clip(quad, {{1.1, 0}, {-1, 0}}, out);  // x <= 1.1
  int on_line = 0;
  for (const Vec2 p : out) on_line += p.x == 1.1;
  EXPECT_EQ(on_line, 2);
  clip(quad, {{0, 0.9}, {0, 1}}, out);  // y >= 0.9
  on_line = 0;
  for (const Vec2 p : out) on_line += p.y == 0.9;
  EXPECT_EQ(on_line, 2);
}

}  // namespace
}  // namespace insula::kernel
