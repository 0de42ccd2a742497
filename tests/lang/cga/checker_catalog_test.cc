// The semantic catalog tests/data/cga/semantic/*.cga: every file parses, and its `// expect:`
// lines at the top list every diagnostic of the checker, exactly and in order
// (`line:col: error[CODE]: message`; file-wide ones without line:col; `nothing` for a grammar
// that must check clean). Also the checked-model
// goldens of the front-end corpus (tests/data/cga/*.cga -> semantic/checked/*.checked).
// INSULA_UPDATE_GOLDEN=1 rewrites the expectations (review the diff).
#include <gtest/gtest.h>

#include <cstdlib>

#include "lang/cga/checker.h"
#include "test_util.h"

namespace insula::lang::cga {
namespace {

using testing::data_dir;
using testing::files_in;
using testing::read_file;

constexpr std::string_view kExpect = "// expect: ";

// `file:line:col: error[...]` -> `line:col: error[...]`; `file: error[...]` -> `error[...]`.
std::string without_file(const std::string& rendered, const std::string& file) {
  std::string out = rendered.substr(file.size() + 1);
  if (!out.empty() && out.front() == ' ') out.erase(0, 1);
  return out;
}

struct CatalogEntry {
  std::vector<std::string> expected;
  std::string body;  // the text after the expect lines
};

CatalogEntry split_expectations(const std::string& text) {
  CatalogEntry entry;
  std::size_t pos = 0;
  while (text.compare(pos, kExpect.size(), kExpect) == 0) {
    const std::size_t end = text.find('\n', pos);
    entry.expected.push_back(text.substr(pos + kExpect.size(), end - pos - kExpect.size()));
    pos = end + 1;
  }
  entry.body = text.substr(pos);
  return entry;
}

std::vector<std::string> diagnostics_of(const std::string& name, const std::string& text) {
  const base::Source source(name, text);
  const auto grammar = parse(source);
  if (!grammar.ok()) return {"parse error: " + base::render(grammar.diagnostics().front())};
  const CheckResult result = check(grammar.value(), source);
  std::vector<std::string> out;
  for (const base::Diagnostic& d : result.diagnostics) {
    out.push_back(without_file(base::render(d), name));
  }
  return out;
}

TEST(CgaCheckerCatalog, EveryFileGivesExactlyItsExpectedDiagnostics) {
  const auto files = files_in(data_dir() / "semantic", ".cga");
  const bool update = std::getenv("INSULA_UPDATE_GOLDEN") != nullptr;
  std::size_t error_files = 0;
  for (const auto& path : files) {
    SCOPED_TRACE(path.filename().string());
    const std::string name = path.filename().string();
    const std::string text = read_file(path);
    const CatalogEntry entry = split_expectations(text);
    ASSERT_FALSE(entry.expected.empty()) << "no '// expect:' line";
    // The expect lines stay in the checked text, so line numbers are those of the file.
    std::vector<std::string> actual = diagnostics_of(name, text);
    if (actual.empty()) actual.push_back("nothing");
    if (update) {
      // The expect lines are part of the checked text: rewrite until the line count settles.
      std::string current = text;
      for (int round = 0; round < 4; ++round) {
        std::vector<std::string> now = diagnostics_of(name, current);
        if (now.empty()) now.push_back("nothing");
        std::string updated;
        for (const std::string& line : now) updated += std::string(kExpect) + line + "\n";
        updated += split_expectations(current).body;
        if (updated == current) break;
        current = updated;
      }
      std::ofstream(path, std::ios::binary) << current;
      continue;
    }
    EXPECT_EQ(actual, entry.expected);
    if (!actual.empty() && actual.front().find(": error[CGA3") != std::string::npos) {
      ++error_files;
    }
  }
  if (!update) {
    EXPECT_GE(error_files, 20U);
  }
}

// The expect lines must not change what is checked: one line per diagnostic, so a file's
// expectation count is fixed before and after an update.
TEST(CgaCheckerCatalog, CatalogCoversEveryCode) {
  std::string all;
  for (const auto& path : files_in(data_dir() / "semantic", ".cga")) all += read_file(path);
  for (int code = 301; code <= 322; ++code) {
    EXPECT_NE(all.find("[CGA" + std::to_string(code) + "]"), std::string::npos) << code;
  }
  for (int code = 401; code <= 406; ++code) {
    EXPECT_NE(all.find("[CGA" + std::to_string(code) + "]"), std::string::npos) << code;
  }
}

TEST(CgaCheckerGolden, CorpusCheckedModels) {
  const auto grammars = files_in(data_dir(), ".cga");
  ASSERT_GE(grammars.size(), 5U);
  for (const auto& path : grammars) {
    SCOPED_TRACE(path.string());
    const base::Source source(path.filename().string(), read_file(path));
    const auto grammar = parse(source);
    ASSERT_TRUE(grammar.ok());
    auto golden = data_dir() / "semantic" / "checked" / path.filename();
    golden.replace_extension(".checked");
    insula::test::expect_golden(golden,
                                dump_checked(grammar.value(), check(grammar.value(), source)));
  }
}

}  // namespace
}  // namespace insula::lang::cga
