#include "base/scanner.h"

#include <gtest/gtest.h>

#include "base/format.h"

namespace insula::base {
namespace {

constexpr ScanCodes kCodes = {"T001", "T002", "T003", "T004", "T005"};

TEST(Scanner, SkipsCommentsAndMarksLineStarts) {
  const Source source("t", "  # one\n/* two\n */ a // three\nb");
  Scanner scan(source, kCodes);
  scan.skip_trivia();
  EXPECT_TRUE(scan.take_line_start());
  EXPECT_FALSE(scan.take_line_start());
  EXPECT_EQ(scan.scan_identifier(), "a");
  scan.skip_trivia();
  EXPECT_TRUE(scan.take_line_start());
  EXPECT_EQ(scan.scan_identifier(), "b");
  EXPECT_TRUE(scan.at_end());
  EXPECT_TRUE(scan.take_diagnostics().empty());
}

TEST(Scanner, ScansNumbersAndReportsGluedLetters) {
  const Source source("t", "2.5e3 7 1e999 3x");
  Scanner scan(source, kCodes);
  std::size_t end = scan.scan_digits();
  EXPECT_EQ(end, 5U);
  EXPECT_EQ(scan.finish_number(0, end), 2500.0);
  scan.skip_trivia();
  end = scan.scan_digits();
  EXPECT_EQ(scan.finish_number(6, end), 7.0);
  scan.skip_trivia();
  end = scan.scan_digits();
  EXPECT_EQ(scan.finish_number(8, end), 0.0);  // out of range
  scan.skip_trivia();
  end = scan.scan_digits();
  EXPECT_EQ(scan.finish_number(14, end), 3.0);
  EXPECT_TRUE(scan.at_end());
  const std::vector<Diagnostic> diagnostics = scan.take_diagnostics();
  ASSERT_EQ(diagnostics.size(), 2U);
  EXPECT_EQ(render(diagnostics[0]), "t:1:9: error[T004]: number '1e999' is out of range");
  EXPECT_EQ(render(diagnostics[1]), "t:1:15: error[T004]: malformed number '3x'");
}

TEST(Scanner, ResolvesEscapesAndReportsUnterminatedText) {
  const Source source("t", "\"a\\\"b\\n\\q\" \"open\n/* never closed");
  Scanner scan(source, kCodes);
  EXPECT_EQ(scan.scan_string(), "a\"b\nq");
  scan.skip_trivia();
  EXPECT_EQ(scan.scan_string(), "open");
  scan.skip_trivia();
  EXPECT_TRUE(scan.at_end());
  const std::vector<Diagnostic> diagnostics = scan.take_diagnostics();
  ASSERT_EQ(diagnostics.size(), 3U);
  EXPECT_EQ(render(diagnostics[0]), "t:1:8: error[T005]: unknown escape sequence in string");
  EXPECT_EQ(render(diagnostics[1]), "t:1:12: error[T002]: unterminated string");
  EXPECT_EQ(render(diagnostics[2]), "t:2:1: error[T003]: unterminated block comment");
}

TEST(Scanner, ReportsAWholeCodePointOrOneBadByte) {
  const Source source("t", "\xC3\xA9\x01");
  Scanner scan(source, kCodes);
  scan.bad_character();
  EXPECT_EQ(scan.pos(), 2U);
  scan.bad_character();
  EXPECT_TRUE(scan.at_end());
  const std::vector<Diagnostic> diagnostics = scan.take_diagnostics();
  ASSERT_EQ(diagnostics.size(), 2U);
  EXPECT_EQ(diagnostics[0].message, "unexpected character '\xC3\xA9'");
  EXPECT_EQ(diagnostics[1].message, "unexpected byte 0x01");
}

TEST(Format, ShortestNumberRoundTripsAndQuotedStringEscapes) {
  EXPECT_EQ(shortest_number(2.5), "2.5");
  EXPECT_EQ(shortest_number(0.1), "0.1");
  EXPECT_EQ(shortest_number(1e300), "1e+300");
  EXPECT_EQ(shortest_number(-0.0), "-0");
  EXPECT_EQ(quoted_string("a\"b\\c\nd\te"), "\"a\\\"b\\\\c\\nd\\te\"");
}

}  // namespace
}  // namespace insula::base
