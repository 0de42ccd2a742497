// AST dumps of every tests/data/cga/*.cga against its .ast golden (regenerated with
// INSULA_UPDATE_GOLDEN=1).
#include <gtest/gtest.h>

#include "lang/cga/ast_dump.h"
#include "test_util.h"

namespace insula::lang::cga {
namespace {

using testing::data_dir;
using testing::files_in;
using testing::read_file;

TEST(CgaGolden, EveryGrammarParsesToItsGoldenDump) {
  const auto grammars = files_in(data_dir(), ".cga");
  ASSERT_GE(grammars.size(), 5U);
  for (const auto& path : grammars) {
    SCOPED_TRACE(path.string());
    const base::Source source(path.filename().string(), read_file(path));
    const auto result = parse(source);
    ASSERT_TRUE(result.ok()) << base::render(result.diagnostics().front(), &source);
    auto golden = path;
    golden.replace_extension(".ast");
    insula::test::expect_golden(golden, dump(result.value(), source));
  }
}

TEST(CgaGolden, ApartmentBlockHasThirtyPlusRulesInFourSets) {
  const auto path = data_dir() / "apartment_block.cga";
  const base::Source source("apartment_block.cga", read_file(path));
  const auto result = parse(source);
  ASSERT_TRUE(result.ok());
  std::size_t rules = 0;
  for (const PrioritySet& set : result->sets) rules += set.rules.size();
  EXPECT_EQ(result->sets.size(), 4U);
  EXPECT_EQ(rules, 40U);
  EXPECT_EQ(result->attrs.size(), 9U);
}

}  // namespace
}  // namespace insula::lang::cga
