// AST dumps of every examples/plasm/*.psm (goldens in tests/data/plasm/<name>.ast) and of every
// tests/data/plasm/*.psm (goldens beside them), regenerated with INSULA_UPDATE_GOLDEN=1; every
// example also passes the checker.
#include <gtest/gtest.h>

#include "test_util.h"

namespace insula::lang::plasm {
namespace {

using testing::data_dir;
using testing::examples_dir;
using testing::files_in;
using testing::read_file;

void expect_dump(const std::filesystem::path& path, const std::filesystem::path& golden) {
  SCOPED_TRACE(path.string());
  const base::Source source(path.filename().string(), read_file(path));
  const auto result = parse(source);
  ASSERT_TRUE(result.ok()) << base::render(result.diagnostics().front(), &source);
  const CheckResult checked = check(result.value(), source);
  ASSERT_TRUE(checked.diagnostics.empty()) << base::render(checked.diagnostics.front(), &source);
  insula::test::expect_golden(golden, dump(result.value(), source));
}

TEST(PlasmGolden, EveryExampleParsesChecksAndMatchesItsDump) {
  const auto files = files_in(examples_dir(), ".psm");
  ASSERT_GE(files.size(), 8U);
  for (const auto& path : files) {
    expect_dump(path, data_dir() / path.filename().replace_extension(".ast"));
  }
}

TEST(PlasmGolden, EveryTestProgramParsesChecksAndMatchesItsDump) {
  const auto files = files_in(data_dir(), ".psm");
  ASSERT_GE(files.size(), 2U);
  for (const auto& path : files) {
    auto golden = path;
    expect_dump(path, golden.replace_extension(".ast"));
  }
}

// The counts the CLI summary reports, on the column of Listing 2.
TEST(PlasmGolden, ColumnHasOneFunctionWithSixLocals) {
  const base::Source source("column.psm", read_file(examples_dir() / "column.psm"));
  const auto result = parse(source);
  ASSERT_TRUE(result.ok());
  ASSERT_EQ(result->statements.size(), 2U);
  const Def& column = result->statements[0].def;
  EXPECT_EQ(column.name, "columna");
  ASSERT_EQ(column.groups.size(), 1U);
  ASSERT_EQ(column.groups[0].decls.size(), 1U);
  EXPECT_EQ(column.groups[0].decls[0].names.size(), 3U);
  EXPECT_EQ(column.locals.size(), 6U);
  const CheckResult checked = check(result.value(), source);
  EXPECT_EQ(checked.functions, 1U);
  EXPECT_EQ(checked.values, 0U);
  EXPECT_EQ(checked.expressions, 1U);
}

}  // namespace
}  // namespace insula::lang::plasm
