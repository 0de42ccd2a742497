#include "base/union_find.h"

#include <gtest/gtest.h>

namespace insula::base {
namespace {

TEST(UnionFind, StartsWithSingletons) {
  UnionFind sets(4);
  EXPECT_EQ(sets.size(), 4U);
  for (std::uint32_t i = 0; i < 4; ++i) EXPECT_EQ(sets.find(i), i);
}

TEST(UnionFind, UniteJoinsTransitivelyAndKeepsTheSecondRepresentative) {
  UnionFind sets(6);
  EXPECT_TRUE(sets.unite(0, 1));
  EXPECT_EQ(sets.find(0), 1U);
  EXPECT_TRUE(sets.unite(2, 3));
  EXPECT_TRUE(sets.unite(1, 3));
  EXPECT_FALSE(sets.unite(0, 2));  // already one set through 1 and 3
  for (std::uint32_t i : {0U, 1U, 2U}) EXPECT_EQ(sets.find(i), sets.find(3));
  EXPECT_NE(sets.find(4), sets.find(0));
  EXPECT_EQ(sets.find(5), 5U);
}

TEST(UnionFind, AddedElementsStartAlone) {
  UnionFind sets(2);
  const std::uint32_t e = sets.add();
  EXPECT_EQ(e, 2U);
  EXPECT_EQ(sets.size(), 3U);
  EXPECT_EQ(sets.find(e), e);
  EXPECT_TRUE(sets.unite(e, 0));
  EXPECT_EQ(sets.find(e), sets.find(0));
}

TEST(UnionFind, LongChainsFlatten) {
  constexpr std::uint32_t kN = 100000;
  UnionFind sets(kN);
  for (std::uint32_t i = 0; i + 1 < kN; ++i) sets.unite(i, i + 1);
  for (std::uint32_t i = 0; i < kN; i += 997) EXPECT_EQ(sets.find(i), kN - 1);
}

}  // namespace
}  // namespace insula::base
