#include "kernel/party_walls.h"

#include <gtest/gtest.h>

#include <vector>

namespace insula::kernel {
namespace {

Polygon box(double x0, double y0, double x1, double y1) {
  return {{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, {}};
}

// Two terraced houses share the wall x = 8 from y = 2 to y = 10; a third stands 1 m away.
TEST(PartyWalls, SharedStretchesBothWaysOnly) {
  const std::vector<std::vector<Polygon>> regions{
      {box(0, 0, 8, 10)}, {box(8, 2, 16, 12)}, {box(17, 0, 20, 10)}};
  const std::vector<PartyWall> walls = find_party_walls(regions);
  ASSERT_EQ(walls.size(), 2U);
  EXPECT_EQ(walls[0].footprint, 0U);
  EXPECT_EQ(walls[0].neighbour, 1U);
  EXPECT_EQ(walls[1].footprint, 1U);
  EXPECT_EQ(walls[1].neighbour, 0U);
  for (const PartyWall& wall : walls) {
    EXPECT_NEAR(wall.a.x, 8, 1e-12);
    EXPECT_NEAR(wall.b.x, 8, 1e-12);
    EXPECT_NEAR(std::abs(wall.b.y - wall.a.y), 8, 1e-12);  // y 2 to 10
  }
}

// Mapped neighbours outside OpenStreetMap rarely share their nodes: a 15 cm gap and a 1 degree
// skew still make a party wall; 30 cm, 5 degrees or a 40 cm overlap do not.
TEST(PartyWalls, ToleranceOfGapAngleAndLength) {
  EXPECT_TRUE(shared_stretch({8, 0}, {8, 10}, {8.15, 10}, {8.15, 0}));
  EXPECT_TRUE(shared_stretch({8, 0}, {8, 10}, {8.1, 10}, {8.1 - 0.17, 0.3}));
  EXPECT_FALSE(shared_stretch({8, 0}, {8, 10}, {8.3, 10}, {8.3, 0}));
  EXPECT_FALSE(shared_stretch({8, 0}, {8, 10}, {8 + 0.87, 10}, {8, 0}));
  EXPECT_FALSE(shared_stretch({8, 0}, {8, 10}, {8, 10.4}, {8, 9.6}));
  const auto stretch = shared_stretch({8, 0}, {8, 10}, {8, 12}, {8, 4});
  ASSERT_TRUE(stretch);
  EXPECT_NEAR(stretch->first, 4, 1e-12);
  EXPECT_NEAR(stretch->second, 10, 1e-12);
  // Corners that touch are not walls.
  EXPECT_TRUE(find_party_walls({{box(0, 0, 8, 10)}, {box(8, 10, 16, 20)}}).empty());
}

}  // namespace
}  // namespace insula::kernel
