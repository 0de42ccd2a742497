#include "base/numbered_names.h"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

namespace insula::base {
namespace {

// The names a plain search from 2 upward gives: the first `base`, `base-2`, ... not in `taken`.
std::string first_free(const std::string& base, const std::set<std::string>& taken) {
  if (!taken.contains(base)) return base;
  for (int n = 2;; ++n) {
    const std::string name = base + "-" + std::to_string(n);
    if (!taken.contains(name)) return name;
  }
}

TEST(NumberedNames, GivesTheBaseThenNumbersFromTwo) {
  std::set<std::string> taken;
  NumberedNames names("-");
  const auto take = [&taken](const std::string& name) { return taken.insert(name).second; };
  EXPECT_EQ(names.next("Wall", take), "Wall");
  EXPECT_EQ(names.next("Wall", take), "Wall-2");
  EXPECT_EQ(names.next("Roof", take), "Roof");
  EXPECT_EQ(names.next("Wall", take), "Wall-3");
}

// Names taken elsewhere (an input feature called `Wall-3`, a part named `Wall-2` outright) are
// skipped, and every name is the one a search from 2 would give.
TEST(NumberedNames, SkipsNamesTakenElsewhereAsAFullSearchWould) {
  std::set<std::string> taken{"Wall-3"};
  NumberedNames names("-");
  const auto take = [&taken](const std::string& name) { return taken.insert(name).second; };
  const std::vector<std::string> bases{"Wall", "Wall", "Wall-2", "Wall", "Wall", "Wall-2"};
  const std::vector<std::string> expected{"Wall",   "Wall-2", "Wall-2-2",
                                          "Wall-4", "Wall-5", "Wall-2-3"};
  for (std::size_t i = 0; i < bases.size(); ++i) {
    std::set<std::string> before = taken;
    const std::string name = names.next(bases[i], take);
    EXPECT_EQ(name, first_free(bases[i], before)) << i;
    EXPECT_EQ(name, expected[i]) << i;
  }
}

TEST(NumberedNames, ASeparatorOfItsOwn) {
  std::set<std::string> taken{"a"};
  NumberedNames names("_");
  EXPECT_EQ(names.next("a", [&taken](const std::string& n) { return taken.insert(n).second; }),
            "a_2");
}

// n names of one base ask about each candidate once, the base itself twice (it is remembered only
// once refused): 10,000 parts called `Plaster` cost 10,001 questions, where a search from 2 each
// time asked 50 million.
TEST(NumberedNames, ManyNamesOfOneBaseAskAboutEachCandidateOnce) {
  std::set<std::string> taken;
  NumberedNames names("-");
  std::size_t asked = 0;
  const auto take = [&](const std::string& name) {
    ++asked;
    return taken.insert(name).second;
  };
  for (int i = 0; i < 10000; ++i) names.next("Plaster", take);
  EXPECT_EQ(taken.size(), 10000U);
  EXPECT_TRUE(taken.contains("Plaster-10000"));
  EXPECT_EQ(asked, 10001U);
}

}  // namespace
}  // namespace insula::base
