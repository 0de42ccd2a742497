// One query language for every front-end (shape/query_expr.h): label expressions, attribute tests,
// Lua's shape and face queries share one lexer and parser, so one text means one thing in each.
#include "shape/query_expr.h"

#include <gtest/gtest.h>

#include <string>

#include "shape/query.h"

namespace insula::shape {
namespace {

std::string error_of(const base::Result<QueryExpr>& r) {
  return r.ok() ? std::string("ok") : r.diagnostics().front().message;
}

TEST(QueryExpr, LabelExpressionsParseAlikeInEveryGrammar) {
  const char* text = "a or b and not (c or 'd e')";
  const auto labels = LabelExpr::parse(text);
  const auto shapes = QueryExpr::parse(text);
  const auto faces = QueryExpr::parse_faces(text);
  ASSERT_TRUE(labels.ok());
  ASSERT_TRUE(shapes.ok());
  ASSERT_TRUE(faces.ok());
  EXPECT_EQ(labels->to_string(), "(a or (b and (not (c or \"d e\"))))");
  EXPECT_EQ(shapes->to_string(), labels->to_string());
  EXPECT_EQ(faces->to_string(), labels->to_string());
}

TEST(QueryExpr, LabelGrammarLeavesOutTreeCriteria) {
  EXPECT_TRUE(QueryExpr::parse("parent(room) and level >= 1").ok());
  const auto bad = LabelExpr::parse("parent(room)", "q");
  ASSERT_FALSE(bad.ok());
  const base::Diagnostic& d = bad.diagnostics().front();
  EXPECT_EQ(d.code, "Q001");
  EXPECT_EQ(d.message, "expected 'and', 'or' or end of query, found '('");
  EXPECT_EQ(d.span.column, 7U);
}

TEST(QueryExpr, KeywordsAreNotLabels) {
  EXPECT_EQ(error_of(QueryExpr::parse("room and and")), "expected a label or '(', found 'and'");
  EXPECT_EQ(error_of(QueryExpr::parse("or")), "expected a label or '(', found 'or'");
}

TEST(QueryExpr, BadCharactersAreReportedWhereTheyStand) {
  const auto r = QueryExpr::parse("room $");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.diagnostics().front().message, "expected 'and', 'or' or end of query, found '$'");
  EXPECT_EQ(r.diagnostics().front().span.column, 6U);
  EXPECT_EQ(error_of(QueryExpr::parse("room and 'open")), "expected a label or '(', found ''open'");
}

TEST(QueryExpr, NumbersWithExponentsInEveryGrammar) {
  const auto test = AttributeTest::parse("height >= 1e-5");
  ASSERT_TRUE(test.ok()) << test.diagnostics().front().message;
  EXPECT_EQ(test->op, Compare::kGreaterEqual);
  EXPECT_EQ(std::get<double>(test->value), 1e-5);
  const auto shapes = QueryExpr::parse("wall and height >= 1e-5");
  ASSERT_TRUE(shapes.ok()) << error_of(shapes);
  EXPECT_EQ(std::get<double>(shapes->nodes()[1].value), 1e-5);
}

TEST(QueryExpr, AttributeTestIsOneComparison) {
  const auto bad = AttributeTest::parse("level == 1 and wall");
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.diagnostics().front().code, "Q002");
  EXPECT_EQ(bad.diagnostics().front().message, "expected end of query, found 'and'");
  const auto quoted = AttributeTest::parse("'roof type' == 'hip'");
  ASSERT_TRUE(quoted.ok());
  EXPECT_EQ(quoted->name, "roof type");
  EXPECT_EQ(std::get<std::string>(quoted->value), "hip");
}

}  // namespace
}  // namespace insula::shape
