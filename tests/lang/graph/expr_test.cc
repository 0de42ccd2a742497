// The expression language of §5: precedence, positions, types.
#include <gtest/gtest.h>

#include "lang/graph/eval.h"
#include "lang/graph/expr.h"

namespace insula::lang::graph {
namespace {

ExprScope scope() {
  ExprScope s;
  s.attribute = [](const std::string& name) -> std::optional<ValueType> {
    if (name == "floors") return ValueType::kInteger;
    if (name == "kind") return ValueType::kString;
    if (name == "tags") return ValueType::kList;
    return std::nullopt;
  };
  s.parameter = [](const std::string& name) -> std::optional<ValueType> {
    if (name == "floor_height") return ValueType::kNumber;
    return std::nullopt;
  };
  s.input_port = [](const std::string& port) { return port == "in" || port == "from"; };
  s.attributes = {"floors", "kind", "tags"};
  s.parameters = {"floor_height"};
  return s;
}

std::string typed(const std::string& text) {
  ExprError err;
  const std::optional<Expr> e = parse_expression(text, err);
  if (!e) return err.code + "@" + std::to_string(err.at) + ": " + err.message;
  const std::optional<ValueType> t = check_expression(*e, text, scope(), err);
  if (!t) return err.code + "@" + std::to_string(err.at) + ": " + err.message;
  return std::string(value_type_name(*t));
}

TEST(GraphExpr, TypesFollowTheFormat) {
  EXPECT_EQ(typed("@floors * 3"), "integer");
  EXPECT_EQ(typed("@floors * floor_height"), "number");
  EXPECT_EQ(typed("@floors / 2"), "number");  // real division
  EXPECT_EQ(typed("'a' + @kind"), "string");
  EXPECT_EQ(typed("not (area() > 10 and @kind == 'x') or false"), "bool");
  EXPECT_EQ(typed("vec(1, 2, 3).y + pos().x"), "number");
  EXPECT_EQ(typed("if(@floors > 2, 1, 2.5)"), "number");
  EXPECT_EQ(typed("@tags[0]"), "any");
  EXPECT_EQ(typed("from@floors + 1"), "integer");
  EXPECT_EQ(typed("-2 - -3 % 2"), "integer");
  EXPECT_EQ(typed("randint(1, 6) == 3.0"), "bool");  // integer with number compares
}

TEST(GraphExpr, ErrorsPointAtTheirCharacter) {
  EXPECT_EQ(typed("1 +"), "G023@3: expected a value at the end of the expression");
  EXPECT_EQ(typed("max(1, 2"), "G023@8: expected ')' after the arguments of 'max'");
  EXPECT_EQ(typed("(1 + 2"), "G023@6: expected ')'");
  EXPECT_EQ(typed("1 2"), "G023@2: unexpected '2' after the expression");
  EXPECT_EQ(typed("pos().w"), "G023@6: expected x, y or z after '.'");
  EXPECT_EQ(typed("'open"), "G023@0: unterminated string");
  EXPECT_EQ(typed("sqr(2)"), "G023@0: unknown function 'sqr' (did you mean 'sqrt'?)");
  EXPECT_EQ(typed("atan2(1)"), "G023@0: 'atan2' takes 2 arguments, found 1");
  EXPECT_EQ(typed("1 + @kind"), "G024@4: '@kind' is a string; '+' needs numbers");
  EXPECT_EQ(typed("@kind == 1"),
            "G024@6: '@kind' is a string and '1' is an integer; '==' compares values of one type");
  EXPECT_EQ(typed("if(1, 2, 3)"), "G024@3: '1' is an integer; 'if' needs a bool");
  EXPECT_EQ(typed("if(true, 'a', 3)"),
            "G024@0: 'if' gives a string or an integer; both branches must have one type");
  EXPECT_EQ(typed("@florrs"), "G020@0: unknown attribute 'florrs' (did you mean 'floors'?)");
  EXPECT_EQ(typed("floor_heigt"),
            "G021@0: unknown graph parameter 'floor_heigt' (did you mean 'floor_height'?)");
  EXPECT_EQ(typed("side@floors"), "G012@0: no input port 'side' to read 'side@floors' from");
  EXPECT_EQ(typed(std::string(150, '(') + "1" + std::string(150, ')')).substr(0, 7), "G023@10");
}

TEST(GraphExpr, EntityReadsAreRefusedWhereThereIsNoEntity) {
  ExprScope s = scope();
  s.entity_readable = false;
  s.not_readable_because =
      "parameter 'k' of 'c' (query.kmeans) is evaluated once per execution and";
  ExprError err;
  const std::optional<Expr> e = parse_expression("2 * area()", err);
  ASSERT_TRUE(e);
  EXPECT_FALSE(check_expression(*e, "2 * area()", s, err));
  EXPECT_EQ(err.code, "G022");
  EXPECT_EQ(err.at, 4U);
  EXPECT_EQ(err.message,
            "parameter 'k' of 'c' (query.kmeans) is evaluated once per execution and cannot read "
            "'area()'");
}

// Operator chains build trees as deep as they are long: past 20,000 operators the parser stops
// with G023 at the first operator too many, before the checker, the evaluator or the destructor
// walk a tree deep enough to exhaust the stack. At the bound every walk still succeeds.
TEST(GraphExpr, LongOperatorChainsAreBounded) {
  const auto chain = [](const std::string& first, const std::string& link, std::size_t n) {
    std::string text = first;
    for (std::size_t i = 0; i < n; ++i) text += link;
    return text;
  };
  EXPECT_EQ(typed(chain("0", "+1", 99999)),
            "G023@40001: expression too long (more than 20000 operators)");
  EXPECT_EQ(typed(chain("true", " or true", 30000)),
            "G023@160005: expression too long (more than 20000 operators)");
  EXPECT_EQ(typed(chain("[1]", "[0]", 100000)).substr(0, 10), "G023@60003");
  EXPECT_EQ(typed(chain("1", "*1", 20000)), "integer");

  class Env : public EvalEnv {
   public:
    Value parameter(const std::string&) override { return Value(std::int64_t{0}); }
    std::optional<Value> attribute(const std::string&, const std::string&) override {
      return std::nullopt;
    }
    std::optional<Value> property(const std::string&, std::string&) override {
      return std::nullopt;
    }
    shape::Rng& rng() override { return rng_; }

   private:
    shape::Rng rng_{1};
  };
  const std::string text = chain("0", "+1", 20000);
  ExprError err;
  const std::optional<Expr> e = parse_expression(text, err);
  ASSERT_TRUE(e) << err.message;
  Env env;
  EvalError eval_error;
  const std::optional<Value> v = evaluate(*e, env, eval_error);
  ASSERT_TRUE(v) << eval_error.message;
  EXPECT_EQ(v->integer(), 20000);
}

}  // namespace
}  // namespace insula::lang::graph
