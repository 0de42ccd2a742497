#include "base/diagnostic.h"

#include <gtest/gtest.h>

namespace insula::base {
namespace {

TEST(Source, LocatesOffsetsAsOneBasedLineAndColumn) {
  const Source source("a.bldg", "ab\ncde\n\nf");
  EXPECT_EQ(source.locate(0), std::make_pair(1U, 1U));
  EXPECT_EQ(source.locate(4), std::make_pair(2U, 2U));
  EXPECT_EQ(source.locate(8), std::make_pair(4U, 1U));
  EXPECT_EQ(source.locate(1000), std::make_pair(4U, 2U));
  EXPECT_EQ(source.line(2), "cde");
  EXPECT_EQ(source.line(3), "");
  EXPECT_EQ(source.line(9), "");
}

TEST(Diagnostic, RendersFileLineColumnCodeAndCaret) {
  const Source source("house.cga", "Lot --> extrude(10)\nFacade --> splt(y)\n");
  Diagnostic d =
      Diagnostic::error("CGA012", "unknown operation 'splt'", Span::at("house.cga", 2, 12, 4));
  d.notes.push_back("did you mean 'split'?");
  EXPECT_EQ(render(d, &source),
            "house.cga:2:12: error[CGA012]: unknown operation 'splt'\n"
            "Facade --> splt(y)\n"
            "           ^~~~\n"
            "note: did you mean 'split'?");
}

TEST(Diagnostic, RendersWithoutPositionOrSource) {
  const Diagnostic d = Diagnostic::warning("", "feature 3: no height", Span::whole("a.geojson"));
  EXPECT_EQ(render(d), "a.geojson: warning: feature 3: no height");
  EXPECT_EQ(render(Diagnostic::error("X1", "m", Span::at("f", 3, 7))), "f:3:7: error[X1]: m");
}

TEST(Diagnostic, HasErrorsIgnoresWarnings) {
  std::vector<Diagnostic> list{Diagnostic::warning("W", "w", {})};
  EXPECT_FALSE(has_errors(list));
  list.push_back(Diagnostic::error("E", "e", {}));
  EXPECT_TRUE(has_errors(list));
}

TEST(Result, CarriesValueOrDiagnostics) {
  Result<int> ok(42);
  EXPECT_TRUE(ok.ok());
  EXPECT_EQ(ok.value(), 42);
  auto failed = Result<int>::failure({Diagnostic::error("E", "bad", {})});
  EXPECT_FALSE(failed.ok());
  EXPECT_EQ(failed.diagnostics().size(), 1U);
}

}  // namespace
}  // namespace insula::base

namespace insula::base {
namespace {

TEST(Diagnostic, ClipsVeryLongLinesAroundTheColumn) {
  const std::string line = std::string(500, '[') + "x" + std::string(500, ']');
  const Source source("deep.json", line);
  const std::string shown =
      render(Diagnostic::error("E", "too deep", Span::at("deep.json", 1, 501)), &source);
  const std::string expected_line = "..." + std::string(60, '[') + "x" + std::string(99, ']');
  EXPECT_EQ(shown, "deep.json:1:501: error[E]: too deep\n" + expected_line + "\n" +
                       std::string(63, ' ') + "^");
}

}  // namespace
}  // namespace insula::base
