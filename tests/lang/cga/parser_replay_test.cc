// Replays truncations and byte mutations of every golden grammar through the parser (the fuzz
// corpus as a unit test): each input must either parse or fail with at least one positioned
// error diagnostic, never crash or hang.
#include <gtest/gtest.h>

#include <cstdint>

#include "test_util.h"

namespace insula::lang::cga {
namespace {

using testing::data_dir;
using testing::files_in;
using testing::read_file;

void expect_parse_or_error(const std::string& text) {
  const base::Source source("replay.cga", text);
  const auto result = parse(source);
  if (result.ok()) return;
  ASSERT_FALSE(result.diagnostics().empty());
  const base::Diagnostic& first = result.diagnostics().front();
  EXPECT_EQ(first.severity, base::Severity::kError);
  EXPECT_GE(first.span.line, 1U);
  EXPECT_EQ(first.code.rfind("CGA", 0), 0U) << first.code;
  EXPECT_LE(result.diagnostics().size(), static_cast<std::size_t>(kMaxErrors) + 1);
}

std::vector<std::string> corpus() {
  std::vector<std::string> out;
  for (const auto& path : files_in(data_dir(), ".cga")) out.push_back(read_file(path));
  for (const auto& path : files_in(data_dir() / "bad", ".cga")) out.push_back(read_file(path));
  return out;
}

TEST(CgaReplay, EveryTruncationParsesOrFails) {
  for (const std::string& text : corpus()) {
    for (std::size_t length = 0; length <= text.size(); ++length) {
      expect_parse_or_error(text.substr(0, length));
    }
  }
}

TEST(CgaReplay, ByteMutationsParseOrFail) {
  // Bytes that change the token structure the most: brackets, separators, quotes, arrows,
  // high bytes (broken UTF-8) and NUL.
  const std::string replacements = std::string("{}[]()|:;,\"~>-'*/#\xCE\xB5\xFF") + '\0';
  std::uint64_t state = 0x9E3779B97F4A7C15ULL;  // fixed seed: the test is deterministic
  for (const std::string& text : corpus()) {
    if (text.empty()) continue;
    for (int round = 0; round < 400; ++round) {
      std::string mutated = text;
      for (int k = 0; k < 3; ++k) {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        const std::size_t at = (state >> 33) % mutated.size();
        mutated[at] = replacements[(state >> 17) % replacements.size()];
      }
      expect_parse_or_error(mutated);
    }
  }
}

TEST(CgaReplay, PathologicalInputsStayBounded) {
  expect_parse_or_error(std::string(100000, '('));
  expect_parse_or_error("1: A : " + std::string(100000, '!') + "true ~> B");
  expect_parse_or_error("1: A : " + std::string(50000, '-') + "1 ~> B");
  std::string sum = "1: A : 1";
  for (int i = 0; i < 50000; ++i) sum += "+1";
  expect_parse_or_error(sum + " > 0 ~> B");
  std::string calls = "1: A : f";
  for (int i = 0; i < 50000; ++i) calls += "()";
  expect_parse_or_error(calls + " ~> B");
  expect_parse_or_error("1: A ~> " + std::string(100000, '['));
  expect_parse_or_error(std::string(100000, '{'));
  expect_parse_or_error(std::string(1000, '\xFF'));
}

}  // namespace
}  // namespace insula::lang::cga
