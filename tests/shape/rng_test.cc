#include "shape/rng.h"

#include <gtest/gtest.h>

#include <array>
#include <set>
#include <vector>

namespace insula::shape {
namespace {

TEST(Rng, SameSeedGivesSameStream) {
  Rng a(42);
  Rng b(42);
  for (int i = 0; i < 100; ++i) EXPECT_EQ(a.next(), b.next());
  Rng c(43);
  EXPECT_NE(Rng(42).next(), c.next());
}

TEST(Rng, ChildSeedsDependOnParentAndIndexOnly) {
  EXPECT_EQ(child_seed(7, 3), child_seed(7, 3));
  std::set<std::uint64_t> seen;
  for (std::uint64_t parent = 0; parent < 20; ++parent) {
    for (std::uint32_t i = 0; i < 20; ++i) seen.insert(child_seed(parent, i));
  }
  EXPECT_EQ(seen.size(), 400U);  // no collisions among neighbouring (parent, index) pairs
}

TEST(Rng, UniformStaysInRange) {
  Rng r(1);
  double sum = 0;
  for (int i = 0; i < 10000; ++i) {
    const double v = r.uniform(2, 5);
    ASSERT_GE(v, 2);
    ASSERT_LT(v, 5);
    sum += v;
  }
  EXPECT_NEAR(sum / 10000, 3.5, 0.05);
  EXPECT_EQ(r.uniform(4, 4), 4);
}

TEST(Rng, IntegerCoversInclusiveRange) {
  Rng r(2);
  std::array<int, 4> counts{};
  for (int i = 0; i < 4000; ++i) {
    const auto v = r.integer(-1, 2);
    ASSERT_GE(v, -1);
    ASSERT_LE(v, 2);
    ++counts[static_cast<std::size_t>(v + 1)];
  }
  for (int c : counts) EXPECT_NEAR(c, 1000, 120);
  EXPECT_EQ(r.integer(5, 5), 5);
}

TEST(Rng, ChoiceFollowsWeights) {
  Rng r(3);
  const std::vector<double> weights = {1, 0, 3};
  std::array<int, 3> counts{};
  for (int i = 0; i < 8000; ++i) ++counts[r.choice(weights)];
  EXPECT_EQ(counts[1], 0);
  EXPECT_NEAR(counts[0], 2000, 200);
  EXPECT_NEAR(counts[2], 6000, 200);
  EXPECT_EQ(r.choice(std::vector<double>{0, -1}), 2U);
  EXPECT_EQ(r.choice(std::vector<double>{}), 0U);
}

}  // namespace
}  // namespace insula::shape
