#include "kernel/contract_loop.h"

#include <gtest/gtest.h>

#include <vector>

namespace insula::kernel {
namespace {

using Pieces = std::vector<std::vector<std::uint32_t>>;

Pieces contract(const std::vector<std::uint32_t>& keys) {
  return contract_loop(keys);
}

TEST(ContractLoop, DistinctKeysGiveTheLoopItself) {
  EXPECT_EQ(contract({4, 7, 9, 2}), (Pieces{{0, 1, 2, 3}}));
}

TEST(ContractLoop, ConsecutiveRepeatsMergeAlsoAcrossTheEnd) {
  EXPECT_EQ(contract({1, 2, 2, 3, 1}), (Pieces{{0, 1, 3}}));
  EXPECT_EQ(contract({5, 5, 5}), Pieces{});  // a face whose corners all meet vanishes
}

TEST(ContractLoop, ARepeatedKeySplitsTheLoopAndSpikesVanish) {
  // a b c b' d: the spike b -> c -> b vanishes, a b d remains.
  EXPECT_EQ(contract({10, 11, 12, 11, 13}), (Pieces{{0, 1, 4}}));
  // a b c a' d e: two triangles meeting at a.
  EXPECT_EQ(contract({1, 2, 3, 1, 4, 5}), (Pieces{{0, 1, 2}, {0, 4, 5}}));
  // a b a' c: two spikes, nothing left.
  EXPECT_EQ(contract({1, 2, 1, 3}), Pieces{});
}

}  // namespace
}  // namespace insula::kernel
