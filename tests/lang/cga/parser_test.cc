// Behaviour of the CGA parser beyond the goldens: rule boundaries, sizes, keys, recovery.
#include <gtest/gtest.h>

#include "lang/cga/ast_dump.h"
#include "lang/cga/lexer.h"
#include "test_util.h"

namespace insula::lang::cga {
namespace {

Grammar parse_ok(const std::string& text) {
  const base::Source source("t.cga", text);
  auto result = parse(source);
  EXPECT_TRUE(result.ok()) << (result.ok() ? "" : base::render(result.diagnostics().front()));
  return result.ok() ? std::move(result.value()) : Grammar{};
}

std::vector<std::string> all_errors(const std::string& text) {
  const base::Source source("t.cga", text);
  const auto result = parse(source);
  std::vector<std::string> out;
  for (const auto& d : result.diagnostics()) out.push_back(base::render(d));
  return out;
}

std::string rule_with_parentheses(const std::string& name, int levels) {
  return name + " --> extrude(" + std::string(static_cast<std::size_t>(levels), '(') + "1" +
         std::string(static_cast<std::size_t>(levels), ')') + ") X\n";
}

// A rule nested too deeply is one error, and the rules after it may nest as deeply as any other
// (the guard that throws gave its level back only from its destructor, which a constructor that
// throws never runs: each too-deep rule lowered the limit of the rest by one).
TEST(CgaParser, TooDeepRuleDoesNotLowerTheLimitOfTheNext) {
  int deepest = 0;
  while (all_errors(rule_with_parentheses("A", deepest + 1)).empty()) ++deepest;
  ASSERT_GT(deepest, 40);  // two levels per parenthesis (operand, parenthesised expression)
  std::string text;
  for (int i = 0; i < 5; ++i) text += rule_with_parentheses("Bad" + std::to_string(i), deepest + 9);
  text += rule_with_parentheses("Good", deepest);
  const std::vector<std::string> errors = all_errors(text);
  ASSERT_EQ(errors.size(), 5U);
  for (const std::string& e : errors) EXPECT_NE(e.find("error[CGA105]"), std::string::npos) << e;
}

TEST(CgaParser, RulesEndWhereTheNextIdColonBegins) {
  const Grammar g = parse_ok("PRIORITY 1:\n1: A ~> B C\n2: C ~> D : 0.5 ~> E F : 0.5\nr3: F ~> G");
  ASSERT_EQ(g.sets.size(), 1U);
  const auto& rules = g.sets[0].rules;
  ASSERT_EQ(rules.size(), 3U);
  EXPECT_EQ(rules[0].alternatives[0].items.size(), 2U);
  ASSERT_EQ(rules[1].alternatives.size(), 2U);
  EXPECT_EQ(rules[1].alternatives[1].items.size(), 2U);
  EXPECT_EQ(dump(*rules[1].alternatives[1].probability), "0.5");
  EXPECT_EQ(rules[2].id, "r3");
  EXPECT_EQ(rules[2].predecessor, "F");
}

TEST(CgaParser, UnnamedRulesStartAtAnArrowAfterAnIdentifier) {
  const Grammar g = parse_ok("Lot --> extrude(10) Mass\nMass -> comp(\"f\"){ top: Roof }");
  ASSERT_EQ(g.sets.size(), 1U);
  EXPECT_TRUE(g.sets[0].implicit);
  ASSERT_EQ(g.sets[0].rules.size(), 2U);
  EXPECT_EQ(g.sets[0].rules[0].id, "");
  EXPECT_EQ(g.sets[0].rules[0].alternatives[0].items[1].name, "Mass");
  EXPECT_EQ(g.sets[0].rules[1].predecessor, "Mass");
}

TEST(CgaParser, SizesAreRelativeFloatingOrAbsolute) {
  const Grammar g = parse_ok("1: A ~> BS(\"X\", 2, 1r, ~1.5, '0.3){ B | C | D | E }");
  const Item& split = g.sets[0].rules[0].alternatives[0].items[0];
  EXPECT_EQ(split.op, OpKind::kSplit);
  ASSERT_EQ(split.args.size(), 5U);
  EXPECT_EQ(dump(*split.args[1]), "2");
  EXPECT_EQ(dump(*split.args[2]), "(rel 1)");
  EXPECT_EQ(dump(*split.args[3]), "(float 1.5)");
  EXPECT_EQ(dump(*split.args[4]), "(rel 0.3)");
  EXPECT_EQ(split.branches.size(), 4U);
}

TEST(CgaParser, OperatorPrecedenceFollowsJava) {
  const Grammar g = parse_ok("1: A : a + b * 2 > 3 and not c or d <> 1 ~> B");
  EXPECT_EQ(dump(*g.sets[0].rules[0].condition), "(or (and (> (+ a (* b 2)) 3) (not c)) (!= d 1))");
}

TEST(CgaParser, SpansPointAtTheSource) {
  const base::Source source("t.cga", "PRIORITY 2:\n  7: Facade ~> Rz(90) I(box)\n");
  const auto result = parse(source);
  ASSERT_TRUE(result.ok());
  const Rule& rule = result->sets[0].rules[0];
  EXPECT_EQ(result->sets[0].priority, 2U);
  const base::Span id = span_of(source, rule.id_range);
  EXPECT_EQ(std::make_pair(id.line, id.column), std::make_pair(2U, 3U));
  const Item& rotate = rule.alternatives[0].items[0];
  EXPECT_EQ(rotate.axis, 'z');
  const base::Span span = span_of(source, rotate.range);
  EXPECT_EQ(span.column, 16U);
  EXPECT_EQ(span.end_column, 22U);  // `Rz(90)` is 6 bytes
}

TEST(CgaParser, RecoversAndReportsEveryBadRule) {
  const auto errors = all_errors("1: A ~> B\n2: C ~>\n3: D ~> T(1,2)\n4: E ~> F $\n5: G ~> H");
  ASSERT_EQ(errors.size(), 3U);
  EXPECT_EQ(errors[0],
            "t.cga:3:1: error[CGA103]: expected a successor (a shape, an operation, 'ε', '[' or "
            "']'), found number 3");
  EXPECT_EQ(errors[1], "t.cga:3:9: error[CGA201]: 'T' expects 3 arguments, found 2");
  EXPECT_EQ(errors[2], "t.cga:4:11: error[CGA001]: unexpected character '$'");
}

TEST(CgaParser, StopsAfterTooManyErrors) {
  std::string text;
  for (int i = 0; i < 80; ++i) text += "1: A ~>\n";
  const auto errors = all_errors(text);
  ASSERT_EQ(errors.size(), static_cast<std::size_t>(kMaxErrors) + 1);
  EXPECT_NE(errors.back().find("error[CGA108]: too many errors; giving up"), std::string::npos);
}

TEST(CgaParser, EpsilonHasThreeSpellings) {
  const Grammar g = parse_ok("1: A ~> ε : 0.5 ~> epsilon : 0.25 ~> NIL : 0.25");
  for (const Alternative& alt : g.sets[0].rules[0].alternatives) {
    ASSERT_EQ(alt.items.size(), 1U);
    EXPECT_EQ(alt.items[0].kind, ItemKind::kEmpty);
  }
}

TEST(CgaLexer, TokensCarryKindsTextAndRelativeFlag) {
  const base::Source source("t.cga", "-->->~>~<><= 2r 3.5e2 \"a\\\"b\" # comment\nx");
  const LexOutput out = lex(source);
  ASSERT_TRUE(out.diagnostics.empty());
  std::vector<Tok> kinds;
  for (const Token& t : out.tokens) kinds.push_back(t.kind);
  EXPECT_EQ(kinds, (std::vector<Tok>{Tok::kLongArrow, Tok::kArrow, Tok::kTildeArrow, Tok::kTilde,
                                     Tok::kNe, Tok::kLe, Tok::kNumber, Tok::kNumber, Tok::kString,
                                     Tok::kIdent, Tok::kEnd}));
  EXPECT_TRUE(out.tokens[6].relative);
  EXPECT_EQ(out.tokens[6].number, 2.0);
  EXPECT_EQ(out.tokens[7].number, 350.0);
  EXPECT_EQ(out.tokens[8].text, "a\"b");
  EXPECT_TRUE(out.tokens[9].line_start);
}

TEST(CgaLexer, OutOfRangeNumberIsAnError) {
  EXPECT_EQ(testing::first_error("1: A ~> T(1e999, 0, 0)"),
            "t.cga:1:11: error[CGA004]: number '1e999' is out of range");
}

}  // namespace
}  // namespace insula::lang::cga
