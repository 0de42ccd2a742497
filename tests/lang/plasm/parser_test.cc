// The PLaSM lexer and parser: tokens and positions, precedence and associativity (the paper's
// application, composition and infix rules), operators as values, negative literals by context,
// curried and typed parameter groups.
#include <gtest/gtest.h>

#include "lang/plasm/lexer.h"
#include "test_util.h"

namespace insula::lang::plasm {
namespace {

using testing::expr_dump;
using testing::first_error;

TEST(PlasmLexer, TokensKeepPositionsSpellingAndFoldedKeys) {
  const base::Source source("t.psm",
                            "def Foo = <1,2>;\n  % a comment\n spanning lines %x##y:: 2.5");
  const LexOutput out = lex(source);
  ASSERT_TRUE(out.diagnostics.empty());
  std::vector<std::string> texts;
  for (const Token& t : out.tokens) texts.push_back(t.text);
  EXPECT_EQ(texts, (std::vector<std::string>{"def", "Foo", "=", "<", "1", ",", "2", ">", ";", "x",
                                             "##", "y", "::", "2.5", ""}));
  EXPECT_EQ(out.tokens[0].kind, Tok::kDef);
  EXPECT_EQ(out.tokens[1].key, "FOO");
  EXPECT_EQ(out.tokens[4].number, 1.0);
  EXPECT_EQ(out.tokens[13].number, 2.5);
  const auto [line, column] = source.locate(out.tokens[9].range.begin);  // x after the comment
  EXPECT_EQ(line, 3U);
  EXPECT_EQ(column, 18U);
}

TEST(PlasmLexer, RangeDotsAreNotADecimalPoint) {
  const base::Source source("t.psm", "1..6 1.5..2");
  const LexOutput out = lex(source);
  ASSERT_EQ(out.tokens.size(), 7U);
  EXPECT_EQ(out.tokens[1].kind, Tok::kDotDot);
  EXPECT_EQ(out.tokens[3].number, 1.5);
  EXPECT_EQ(out.tokens[4].kind, Tok::kDotDot);
}

TEST(PlasmParser, ApplicationIsLeftAssociativeAndBindsTightest) {
  EXPECT_EQ(expr_dump("f:x:y"), "(: (: f x) y)");
  EXPECT_EQ(expr_dump("(f ~ g ~ h):x"), "(: (~ (~ f g) h) x)");
  EXPECT_EQ(expr_dump("f ~ g:x"), "(~ f (: g x))");
  EXPECT_EQ(expr_dump("K:r * COS ~ S1"), "(* (: K r) (~ COS S1))");
}

TEST(PlasmParser, ArithmeticLevelsFollowTheOriginalGrammar) {
  EXPECT_EQ(expr_dump("a + b * c"), "(+ a (* b c))");
  EXPECT_EQ(expr_dump("a - b - c"), "(- (- a b) c)");
  EXPECT_EQ(expr_dump("a * b ** c"), "(* a (** b c))");
  EXPECT_EQ(expr_dump("a ** b ** c"), "(** (** a b) c)");  // %left in the original grammar
  EXPECT_EQ(expr_dump("a ** f ~ g"), "(** a (~ f g))");
  EXPECT_EQ(expr_dump("1 .. n - 1"), "(.. 1 (- n 1))");
}

TEST(PlasmParser, InfixFunctionsAreLowestAndLeftAssociative) {
  EXPECT_EQ(expr_dump("a TOP b TOP c"), "(infix TOP (infix TOP a b) c)");
  EXPECT_EQ(expr_dump("K:0 AL ArchSurf2D"), "(infix AL (: K 0) ArchSurf2D)");
  EXPECT_EQ(expr_dump("a + b TOP c * d"), "(infix TOP (+ a b) (* c d))");
  EXPECT_EQ(expr_dump("+:<1, 3>"), "(: (op +) (seq 1 3))");
}

TEST(PlasmParser, OperatorsAsValues) {
  EXPECT_EQ(expr_dump("AA:-"), "(: AA (op -))");
  EXPECT_EQ(expr_dump("C:*:(PI/6)"), "(: (: C (op *)) (/ PI 6))");
  EXPECT_EQ(expr_dump("-:ceiling"), "(: (op -) ceiling)");
  EXPECT_EQ(expr_dump("K:r * - ~ SIN ~ S2"), "(* (: K r) (~ (~ (op -) SIN) S2))");
  EXPECT_EQ(expr_dump("STRUCT ~ AA:- ~ DISTR"), "(~ (~ STRUCT (: AA (op -))) DISTR)");
  EXPECT_EQ(expr_dump("INSR:~:<f, g>"), "(: (: INSR (op ~)) (seq f g))");
  EXPECT_EQ(expr_dump("##:3:<1, -2>"), "(: (: (op ##) 3) (seq 1 -2))");
  EXPECT_EQ(expr_dump("<+, **, />"), "(seq (op +) (op **) (op /))");
}

TEST(PlasmParser, NegativeLiteralsByContext) {
  EXPECT_EQ(expr_dump("S:1:-1"), "(: (: S 1) -1)");
  EXPECT_EQ(expr_dump("7*dm/-12"), "(/ (* 7 dm) -12)");
  EXPECT_EQ(expr_dump("<<-6,0>,<-3,2>>"), "(seq (seq -6 0) (seq -3 2))");
  EXPECT_EQ(expr_dump("a -1"), "(- a 1)");  // after an operand, '-' subtracts
  EXPECT_EQ(expr_dump("-2 ** 2"), "(** -2 2)");
  EXPECT_EQ(first_error("f:-x;"),
            "t.psm:1:3: error[PSM103]: PLaSM has no unary minus: write -:x to negate x (or a "
            "literal such as -1)");
}

TEST(PlasmParser, ConstructionSequenceRangeAndIf) {
  EXPECT_EQ(expr_dump("[f, g]:x"), "(: (cons f g) x)");
  EXPECT_EQ(expr_dump("< >"), "(seq)");
  EXPECT_EQ(expr_dump("aa:list:(1 .. 13)"), "(: (: aa list) (.. 1 13))");
  EXPECT_EQ(expr_dump("IF:<IsReal, K:1, ID>:x"), "(: (if IsReal (: K 1) ID) x)");
  EXPECT_EQ(expr_dump("\"a\\\"b\""), "\"a\\\"b\"");
}

TEST(PlasmParser, CurriedTypedGroupsAndWhere) {
  const base::Source source("t.psm",
                            "DEF f (a, b::IsReal; c)(d::IsSeqOf:IsReal) = g\n"
                            "WHERE g = h, h (x::IsReal) = x * k WHERE k = 2 END END;");
  const auto result = parse(source);
  ASSERT_TRUE(result.ok()) << base::render(result.diagnostics().front());
  const Def& f = result->statements.at(0).def;
  ASSERT_EQ(f.groups.size(), 2U);
  ASSERT_EQ(f.groups[0].decls.size(), 2U);
  EXPECT_EQ(f.groups[0].decls[0].names.size(), 2U);
  EXPECT_EQ(dump(*f.groups[0].decls[0].predicate), "IsReal");
  EXPECT_EQ(f.groups[0].decls[1].predicate, nullptr);
  EXPECT_EQ(dump(*f.groups[1].decls[0].predicate), "(: IsSeqOf IsReal)");
  ASSERT_EQ(f.locals.size(), 2U);
  EXPECT_FALSE(f.locals[0].is_function());
  EXPECT_TRUE(f.locals[1].is_function());
  EXPECT_EQ(f.locals[1].locals.size(), 1U);
  EXPECT_EQ(dump(result.value(), source),
            "(program \"t.psm\"\n"
            "  (def f @1:5 (a b :: IsReal; c) (d :: (: IsSeqOf IsReal))\n"
            "    g\n"
            "    (where\n"
            "      (def g @2:7\n"
            "        h)\n"
            "      (def h @2:14 (x :: IsReal)\n"
            "        (* x k)\n"
            "        (where\n"
            "          (def k @2:42\n"
            "            2))))))\n");
}

TEST(PlasmParser, KeywordsAreCaseInsensitive) {
  EXPECT_EQ(first_error("def a = 1 where b = 2 end;"), "");
  EXPECT_EQ(first_error("Def A = if:<tt, id, id>;"), "");
}

TEST(PlasmParser, ErrorsRecoverAtTheNextStatement) {
  const base::Source source("t.psm", "DEF a = ;\nDEF b = (1;\nDEF c = 1;");
  const auto result = parse(source);
  ASSERT_FALSE(result.ok());
  ASSERT_EQ(result.diagnostics().size(), 2U);
  EXPECT_EQ(base::render(result.diagnostics()[0]),
            "t.psm:1:9: error[PSM104]: expected an expression, found ';'");
  EXPECT_EQ(base::render(result.diagnostics()[1]),
            "t.psm:2:11: error[PSM101]: expected ')' to close '(', found ';'");
}

// Each statement that nests too deep is one error, and the next statement starts from level 0.
TEST(PlasmParser, TooDeepStatementsDoNotRaiseTheLevelOfTheNext) {
  std::string text;
  const auto nested = [](int depth) {
    return "DEF a = " + std::string(static_cast<std::size_t>(depth), '(') + "1" +
           std::string(static_cast<std::size_t>(depth), ')') + ";\n";
  };
  for (int i = 0; i < 49; ++i) text += nested(60);
  text += nested(30);  // 61 levels: fine on its own
  const auto result = parse(base::Source("t.psm", text));
  ASSERT_FALSE(result.ok());
  ASSERT_EQ(result.diagnostics().size(), 49U);
  EXPECT_EQ(result.diagnostics().back().span.line, 49U);
  EXPECT_EQ(result.diagnostics().back().code, "PSM105");
}

TEST(PlasmParser, TooManyErrorsStops) {
  std::string text;
  for (int i = 0; i < 60; ++i) text += "DEF = 1;\n";
  const auto result = parse(base::Source("t.psm", text));
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.diagnostics().size(), static_cast<std::size_t>(kMaxErrors) + 1);
  EXPECT_EQ(result.diagnostics().back().code, "PSM108");
}

}  // namespace
}  // namespace insula::lang::plasm
