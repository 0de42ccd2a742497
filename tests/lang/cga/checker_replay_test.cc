// Replays truncations and byte mutations of every grammar of the corpus and of the semantic
// catalog through parser and checker: whatever parses must check without crashing, with
// diagnostics that are positioned (or file-wide CGA314), coded CGA3xx/CGA4xx, sorted, and an
// `ok` that agrees with them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <tuple>

#include "lang/cga/checker.h"
#include "test_util.h"

namespace insula::lang::cga {
namespace {

using testing::data_dir;
using testing::files_in;
using testing::read_file;

std::size_t checked_count = 0;

void expect_sound_check(const std::string& text) {
  const base::Source source("replay.cga", text);
  const auto grammar = parse(source);
  if (!grammar.ok()) return;
  ++checked_count;
  const CheckResult result = check(grammar.value(), source);
  EXPECT_EQ(result.ok, !base::has_errors(result.diagnostics));
  const auto lines = static_cast<std::uint32_t>(std::count(text.begin(), text.end(), '\n') + 1);
  for (const base::Diagnostic& d : result.diagnostics) {
    ASSERT_TRUE(d.code.rfind("CGA3", 0) == 0 || d.code.rfind("CGA4", 0) == 0) << d.code;
    EXPECT_EQ(d.severity == base::Severity::kError, d.code[3] == '3') << d.code;
    if (d.code == "CGA314" || d.code == "CGA433") {  // about the whole file
      EXPECT_EQ(d.span.line, 0U);
    } else {
      EXPECT_GE(d.span.line, 1U) << base::render(d);
      EXPECT_LE(d.span.line, lines) << base::render(d);
    }
  }
  EXPECT_TRUE(std::is_sorted(result.diagnostics.begin(), result.diagnostics.end(),
                             [](const base::Diagnostic& a, const base::Diagnostic& b) {
                               return std::tie(a.span.line, a.span.column) <
                                      std::tie(b.span.line, b.span.column);
                             }));
  std::size_t rules = 0;
  for (const PrioritySet& set : grammar->sets) rules += set.rules.size();
  EXPECT_EQ(result.rules.size(), rules);
  if (rules > 0) {
    EXPECT_FALSE(result.start_symbol.empty());
  }
}

std::vector<std::string> corpus() {
  std::vector<std::string> out;
  for (const auto& path : files_in(data_dir(), ".cga")) out.push_back(read_file(path));
  for (const auto& path : files_in(data_dir() / "semantic", ".cga")) {
    out.push_back(read_file(path));
  }
  return out;
}

TEST(CgaCheckerReplay, EveryTruncationChecksSoundly) {
  checked_count = 0;
  for (const std::string& text : corpus()) {
    for (std::size_t length = 0; length <= text.size(); ++length) {
      expect_sound_check(text.substr(0, length));
    }
  }
  EXPECT_GT(checked_count, 1000U);  // the replay reaches the checker, not only the parser
}

TEST(CgaCheckerReplay, TokenMutationsCheckSoundly) {
  // Replacements that keep the text parseable often but change its meaning: numbers, signs,
  // ε, brackets, names of operations, axes and selectors.
  const std::vector<std::string> words = {"0",    "-1",     "1.5",   "400", "ε",     "[",
                                          "]",    "\"XY\"", "\"q\"", "A",   "front", "split",
                                          "comp", "T",      "Rx",    ":",   "|",     "~>"};
  std::uint64_t state = 0x9E3779B97F4A7C15ULL;  // fixed seed: deterministic
  checked_count = 0;
  for (const std::string& text : corpus()) {
    if (text.empty()) continue;
    for (int round = 0; round < 300; ++round) {
      std::string mutated = text;
      for (int k = 0; k < 2; ++k) {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        const std::size_t at = (state >> 33) % mutated.size();
        const std::size_t end = std::min(mutated.size(), at + 1 + (state >> 7) % 3);
        mutated.replace(at, end - at, words[(state >> 17) % words.size()]);
      }
      expect_sound_check(mutated);
    }
  }
  EXPECT_GT(checked_count, 1000U);
}

}  // namespace
}  // namespace insula::lang::cga
