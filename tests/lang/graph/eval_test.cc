// Evaluating §5 expressions on run-time values: operators, functions, randomness, run-time
// errors with their positions, and the value helpers (to_string, value_from_json, convert).
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <span>

#include "lang/graph/eval.h"

namespace insula::lang::graph {
namespace {

// Graph parameters, the entities at the node's input ports ("" is the current entity), the
// current entity's properties and a seeded random stream.
class FakeEnv : public EvalEnv {
 public:
  explicit FakeEnv(std::uint64_t seed = 42) : rng_(seed) {}

  Value parameter(const std::string& name) override { return parameters.at(name); }
  std::optional<Value> attribute(const std::string& port, const std::string& name) override {
    const auto entity = entities.find(port);
    if (entity == entities.end()) return std::nullopt;
    return entity->second.at(name);
  }
  std::optional<Value> property(const std::string& name, std::string& error) override {
    ++property_reads;
    const auto p = properties.find(name);
    if (p != properties.end()) return p->second;
    error = name + "() needs a flat shape";
    return std::nullopt;
  }
  shape::Rng& rng() override { return rng_; }

  std::map<std::string, Value> parameters;
  std::map<std::string, std::map<std::string, Value>> entities;
  std::map<std::string, Value> properties;
  int property_reads = 0;

 private:
  shape::Rng rng_;
};

FakeEnv building_env() {
  FakeEnv env;
  env.parameters = {{"floors", Value(std::int64_t{4})}, {"floor_height", Value(3.5)}};
  env.entities[""] = {{"height", Value(12.0)}, {"name", Value("tower")}};
  env.entities["other"] = {{"height", Value(std::int64_t{7})}};
  env.properties = {
      {"area", Value(20.0)}, {"pos", Value(kernel::Vec3{1, 2, 3})}, {"type", Value("shape")}};
  return env;
}

// A scope that knows every name, typed as the environment's values (kAny when it has none), so
// run-time type errors are reached through checked expressions with list elements.
ExprScope permissive(FakeEnv& env) {
  ExprScope s;
  s.attribute = [&env](const std::string& name) -> std::optional<ValueType> {
    for (const auto& [port, attributes] : env.entities) {
      const auto a = attributes.find(name);
      if (a != attributes.end()) return a->second.type();
    }
    return ValueType::kAny;
  };
  s.parameter = [&env](const std::string& name) -> std::optional<ValueType> {
    const auto p = env.parameters.find(name);
    return p == env.parameters.end() ? std::nullopt : std::optional(p->second.type());
  };
  s.input_port = [](const std::string&) { return true; };
  return s;
}

// "integer 12", "number 2.5", "string tower" or "error@<at>: <message>".
std::string run(const std::string& text, FakeEnv& env) {
  ExprError err;
  const std::optional<Expr> e = parse_expression(text, err);
  if (!e) return "parse " + err.code + ": " + err.message;
  if (!check_expression(*e, text, permissive(env), err))
    return "check " + err.code + ": " + err.message;
  EvalError error;
  const std::optional<Value> v = evaluate(*e, env, error);
  if (!v) return "error@" + std::to_string(error.at) + ": " + error.message;
  EXPECT_TRUE(error.message.empty()) << text;
  return std::string(value_type_name(v->type())) + " " + to_string(*v);
}

std::string run(const std::string& text) {
  FakeEnv env = building_env();
  return run(text, env);
}

TEST(GraphEval, IntegersStayIntegersExceptDivision) {
  EXPECT_EQ(run("7 + 3"), "integer 10");
  EXPECT_EQ(run("7 - 10"), "integer -3");
  EXPECT_EQ(run("6 * 7"), "integer 42");
  EXPECT_EQ(run("7 / 2"), "number 3.5");
  EXPECT_EQ(run("6 / 3"), "number 2");
  EXPECT_EQ(run("10 - 2 - 3"), "integer 5");  // left to right
  EXPECT_EQ(run("2 - -3"), "integer 5");
  EXPECT_EQ(run("1 + 2 * 3"), "integer 7");
  EXPECT_EQ(run("(1 + 2) * 3"), "integer 9");
  EXPECT_EQ(run("floors * 3"), "integer 12");
  EXPECT_EQ(run("floors * floor_height"), "number 14");
  EXPECT_EQ(run("1 + 2.0"), "number 3");
  EXPECT_EQ(run("2 * 1.25"), "number 2.5");
  EXPECT_EQ(run("-floors"), "integer -4");
  EXPECT_EQ(run("-floor_height"), "number -3.5");
}

TEST(GraphEval, RemainderFollowsTheLeftOperand) {
  EXPECT_EQ(run("7 % 3"), "integer 1");
  EXPECT_EQ(run("-7 % 3"), "integer -1");
  EXPECT_EQ(run("7 % -3"), "integer 1");
  EXPECT_EQ(run("-7 % -3"), "integer -1");
  EXPECT_EQ(run("7.5 % 2"), "number 1.5");
  EXPECT_EQ(run("-7.5 % 2"), "number -1.5");
  EXPECT_EQ(run("(-9223372036854775807 - 1) % -1"), "integer 0");
}

TEST(GraphEval, StringsVectorsAndLists) {
  EXPECT_EQ(run("'ab' + \"cd\""), "string abcd");
  EXPECT_EQ(run("@name + '-' + str(floors)"), "string tower-4");
  EXPECT_EQ(run("vec(1, 2, 3) + vec(1, 1, 1)"), "vec3 [2, 3, 4]");
  EXPECT_EQ(run("vec(1, 2, 3) - vec(1, 1, 1)"), "vec3 [0, 1, 2]");
  EXPECT_EQ(run("vec(1, 2, 3) * 2"), "vec3 [2, 4, 6]");
  EXPECT_EQ(run("2 * vec(1, 2, 3)"), "vec3 [2, 4, 6]");
  EXPECT_EQ(run("vec(1, 2, 3) / 2"), "vec3 [0.5, 1, 1.5]");
  EXPECT_EQ(run("-vec(1, 0, 3)"), "vec3 [-1, 0, -3]");
  EXPECT_EQ(run("pos().x + pos().y * 10 + pos().z * 100"), "number 321");
  EXPECT_EQ(run("vec(4, 5, 6)[2]"), "number 6");
  EXPECT_EQ(run("[1, 'a', true]"), "list [1, a, true]");
  EXPECT_EQ(run("[]"), "list []");
  EXPECT_EQ(run("[[1, 2], [3]][0][1]"), "integer 2");
  EXPECT_EQ(run("[10, 20][[1.0][0]]"), "integer 20");  // an integral number indexes
}

TEST(GraphEval, Comparisons) {
  EXPECT_EQ(run("1 < 2"), "bool true");
  EXPECT_EQ(run("2 <= 2"), "bool true");
  EXPECT_EQ(run("2 > 2.5"), "bool false");
  EXPECT_EQ(run("2 >= 2.0"), "bool true");
  EXPECT_EQ(run("1 == 1.0"), "bool true");
  EXPECT_EQ(run("1 != 1.5"), "bool true");
  EXPECT_EQ(run("'a' == 'a'"), "bool true");
  EXPECT_EQ(run("'a' != 'b'"), "bool true");
  EXPECT_EQ(run("true == false"), "bool false");
  EXPECT_EQ(run("vec(1, 2, 3) == vec(1, 2, 3)"), "bool true");
  EXPECT_EQ(run("vec(1, 2, 3) != vec(1, 2, 4)"), "bool true");
  EXPECT_EQ(run("[1, [2, 'x']] == [1.0, [2, 'x']]"), "bool true");
  EXPECT_EQ(run("[1, 2] == [1, 2, 3]"), "bool false");
  EXPECT_EQ(run("[1, 'a'] == [1, 2]"), "bool false");  // elements of other types differ
  // 2^53 + 1 is not the double 2^53: integers and numbers compare exactly.
  EXPECT_EQ(run("9007199254740993 == 9007199254740992.0"), "bool false");
  EXPECT_EQ(run("9007199254740993 > 9007199254740992.0"), "bool true");
}

TEST(GraphEval, LogicShortCircuits) {
  EXPECT_EQ(run("true and false"), "bool false");
  EXPECT_EQ(run("true or false"), "bool true");
  EXPECT_EQ(run("not true"), "bool false");
  EXPECT_EQ(run("not not true"), "bool true");
  EXPECT_EQ(run("true or 1 % 0 == 0"), "bool true");
  EXPECT_EQ(run("false and 1 % 0 == 0"), "bool false");
  EXPECT_EQ(run("false or 1 % 0 == 0"), "error@11: modulo by zero");
  EXPECT_EQ(run("true and 1 % 0 == 0"), "error@11: modulo by zero");
  EXPECT_EQ(run("if(true, 1, 1 % 0)"), "integer 1");
  EXPECT_EQ(run("if(false, 1 % 0, 2)"), "integer 2");
  EXPECT_EQ(run("if(false, 1, 1 % 0)"), "error@15: modulo by zero");
  EXPECT_EQ(run("if(@height > 10, 'tall', 'short')"), "string tall");
  FakeEnv env = building_env();
  EXPECT_EQ(run("if(true, 1, area())", env), "integer 1");
  EXPECT_EQ(env.property_reads, 0);
}

TEST(GraphEval, MathFunctions) {
  EXPECT_EQ(run("abs(-3)"), "integer 3");
  EXPECT_EQ(run("abs(-2.5)"), "number 2.5");
  EXPECT_EQ(run("min(3, 1, 2)"), "integer 1");
  EXPECT_EQ(run("min(3, 1.5)"), "number 1.5");
  EXPECT_EQ(run("max(4, 9)"), "integer 9");
  EXPECT_EQ(run("max(1, 2.5, 2)"), "number 2.5");
  EXPECT_EQ(run("max(3, 2.5)"), "number 3");  // a number as soon as one argument is
  EXPECT_EQ(run("floor(2.7)"), "number 2");
  EXPECT_EQ(run("floor(-2.5)"), "number -3");
  EXPECT_EQ(run("floor(5)"), "number 5");
  EXPECT_EQ(run("ceil(2.1)"), "number 3");
  EXPECT_EQ(run("round(2.5)"), "number 3");
  EXPECT_EQ(run("round(-2.5)"), "number -3");  // halves away from zero
  EXPECT_EQ(run("round(2.49)"), "number 2");
  EXPECT_EQ(run("sqrt(16)"), "number 4");
  EXPECT_EQ(run("sqrt(2.25)"), "number 1.5");
  EXPECT_EQ(run("pow(2, 10)"), "number 1024");
  EXPECT_EQ(run("pow(4, 0.5)"), "number 2");
  EXPECT_EQ(run("clamp(5, 0, 3)"), "integer 3");
  EXPECT_EQ(run("clamp(-1.5, 0, 3)"), "number 0");
  EXPECT_EQ(run("clamp(2.5, 0, 3)"), "number 2.5");
  EXPECT_EQ(run("clamp(1, 1, 1)"), "integer 1");
}

TEST(GraphEval, TrigonometryIsInDegreesAndExactAtTableAngles) {
  EXPECT_EQ(run("sin(30)"), "number 0.5");
  EXPECT_EQ(run("sin(90)"), "number 1");
  EXPECT_EQ(run("sin(180)"), "number 0");
  EXPECT_EQ(run("sin(-90)"), "number -1");
  EXPECT_EQ(run("sin(750)"), "number 0.5");
  EXPECT_EQ(run("cos(0)"), "number 1");
  EXPECT_EQ(run("cos(60)"), "number 0.5");
  EXPECT_EQ(run("cos(90)"), "number 0");
  EXPECT_EQ(run("cos(180)"), "number -1");
  EXPECT_EQ(run("cos(-120)"), "number -0.5");
  EXPECT_EQ(run("tan(0)"), "number 0");
  EXPECT_EQ(run("tan(45)"), "number 1");
  EXPECT_EQ(run("tan(135)"), "number -1");
  EXPECT_EQ(run("tan(225)"), "number 1");
  EXPECT_EQ(run("atan2(1, 1)"), "number 45");
  EXPECT_EQ(run("atan2(0, -1)"), "number 180");
  EXPECT_EQ(run("atan2(-1, 0)"), "number -90");
  FakeEnv env;
  EvalError error;
  ExprError err;
  for (double degrees : {10.0, 45.0, 60.0, 100.0, -33.0, 1000.5}) {
    const double radians = degrees * 3.14159265358979323846 / 180;
    const std::string arg = '(' + to_string(Value(degrees)).append(")");
    for (const auto& [f, expected] : {std::pair{"sin", std::sin(radians)},
                                      {"cos", std::cos(radians)},
                                      {"tan", std::tan(radians)}}) {
      const std::optional<Expr> e = parse_expression(f + arg, err);
      ASSERT_TRUE(e);
      const std::optional<Value> v = evaluate(*e, env, error);
      ASSERT_TRUE(v) << f << arg;
      EXPECT_NEAR(v->number(), expected, 1e-12) << f << arg;
    }
  }
}

TEST(GraphEval, VectorStringAndListFunctions) {
  EXPECT_EQ(run("vec(1, 2.5, floors)"), "vec3 [1, 2.5, 4]");
  EXPECT_EQ(run("dist(vec(1, 1, 1), vec(4, 5, 1))"), "number 5");
  EXPECT_EQ(run("length(vec(0, 3, 4))"), "number 5");
  EXPECT_EQ(run("str(3) + str(2.5) + str(true) + str('x')"), "string 32.5truex");
  EXPECT_EQ(run("str(vec(1, 2.5, 3))"), "string [1, 2.5, 3]");
  EXPECT_EQ(run("str([1, ['a'], false])"), "string [1, [a], false]");
  EXPECT_EQ(run("len('h\xC3\xA9llo')"), "integer 6");  // bytes
  EXPECT_EQ(run("len([1, 2, 3])"), "integer 3");
  EXPECT_EQ(run("len('')"), "integer 0");
  EXPECT_EQ(run("size([1, [2, 3]])"), "integer 2");
  EXPECT_EQ(run("size(vec(1, 2, 3))"), "integer 3");
}

TEST(GraphEval, EntityReads) {
  EXPECT_EQ(run("@height * 2"), "number 24");
  EXPECT_EQ(run("other@height + 1"), "integer 8");
  EXPECT_EQ(run("area() / 4"), "number 5");
  EXPECT_EQ(run("type()"), "string shape");
  EXPECT_EQ(run("normal()"), "error@0: normal() needs a flat shape");
  EXPECT_EQ(run("1 + b@height"), "error@5: no entity at port 'b' this round");
  FakeEnv empty;
  EXPECT_EQ(run("2 * @height", empty), "error@4: no current entity to read '@height' from");
}

TEST(GraphEval, RandomDrawsAreReproducibleAndInRange) {
  FakeEnv a(7);
  FakeEnv b(7);
  shape::Rng reference(7);
  for (int i = 0; i < 5; ++i) {
    const std::string drawn = run("rand()", a);
    EXPECT_EQ(drawn, run("rand()", b));
    EXPECT_EQ(drawn, "number " + to_string(Value(reference.unit())));
  }
  FakeEnv other(8);
  EXPECT_NE(run("rand()", other), run("rand()", a));
  EXPECT_EQ(run("rand() == rand()", a), "bool false");  // each call draws

  FakeEnv env(1);
  ExprError err;
  EvalError error;
  const std::optional<Expr> uniform = parse_expression("rand(2, 5)", err);
  const std::optional<Expr> die = parse_expression("randint(1, 6)", err);
  const std::optional<Expr> reversed = parse_expression("randint(3, -1)", err);
  ASSERT_TRUE(uniform && die && reversed);
  std::set<std::int64_t> faces;
  std::set<std::int64_t> reversed_faces;
  for (int i = 0; i < 2000; ++i) {
    const double u = evaluate(*uniform, env, error)->number();
    EXPECT_GE(u, 2.0);
    EXPECT_LT(u, 5.0);
    faces.insert(evaluate(*die, env, error)->integer());
    reversed_faces.insert(evaluate(*reversed, env, error)->integer());
  }
  EXPECT_EQ(faces, (std::set<std::int64_t>{1, 2, 3, 4, 5, 6}));  // both ends, nothing outside
  EXPECT_EQ(reversed_faces, (std::set<std::int64_t>{-1, 0, 1, 2, 3}));
  EXPECT_EQ(run("randint(3, 3)", env), "integer 3");
  EXPECT_EQ(run("rand(2.5, 2.5)", env), "number 2.5");
}

struct Failure {
  const char* text;
  const char* message;
  std::size_t at;
};

void expect_failures(std::span<const Failure> cases) {
  for (const Failure& f : cases) {
    EXPECT_EQ(run(f.text), "error@" + std::to_string(f.at) + ": " + f.message) << f.text;
  }
}

TEST(GraphEval, ArithmeticErrorsPointAtTheOperation) {
  const Failure cases[] = {
      {"9223372036854775807 + 1", "integer overflow in '+'", 20},
      {"-9223372036854775807 - 2", "integer overflow in '-'", 21},
      {"4611686018427387904 * 2", "integer overflow in '*'", 20},
      {"-(-9223372036854775807 - 1)", "integer overflow in '-'", 0},
      {"abs(-9223372036854775807 - 1)", "integer overflow in 'abs'", 0},
      {"5 % 0", "modulo by zero", 2},
      {"5.5 % 0", "modulo by zero", 4},
      {"1 / 0", "division by zero", 2},
      {"1.5 / (2 - 2.0)", "division by zero", 4},
      {"vec(1, 2, 3) / 0", "division by zero", 13},
      {"1 + (2 * (3 % 0))", "modulo by zero", 12},
      {"1e308 * 10", "number overflow in '*'", 6},
      {"-1e308 - 1e308", "number overflow in '-'", 7},
      {"vec(1e308, 0, 0) * 10", "number overflow in '*'", 17},
      {"vec(1e308, 0, 0) + vec(1e308, 0, 0)", "number overflow in '+'", 17},
      {"vec(1e308, 0, 0) / 0.5", "number overflow in '/'", 17},
      {"vec(0, 0, 0) / 0", "division by zero", 13},
      {"length(vec(1.5e308, 1.5e308, 0))", "number overflow in 'length'", 0},
      {"rand(-1e308, 1e308)", "number overflow in 'rand'", 0},
      {"sqrt(-1)", "sqrt(-1) is not a real number", 0},
      {"1 + sqrt(-0.5)", "sqrt(-0.5) is not a real number", 4},
      {"pow(10, 400)", "pow(10, 400) is not finite", 0},
      {"pow(0, -1)", "pow(0, -1) is not finite", 0},
      {"pow(-8, 1 / 3)", "pow(-8, 0.3333333333333333) is not a real number", 0},
      {"tan(90)", "tan(90) is not finite", 0},
      {"tan(-270)", "tan(-270) is not finite", 0},
      {"clamp(1, 5, 2)", "clamp's lower bound 5 is above its upper bound 2", 0},
      {"[1, 2][2]", "index 2 is outside the list of 2", 6},
      {"[1, 2][-1]", "index -1 is outside the list of 2", 6},
      {"[][0]", "index 0 is outside the list of 0", 2},
      {"vec(1, 2, 3)[3]", "index 3 is outside the vec3", 12},
      {"[1, 2][[0.5][0]]", "index 0.5 is not an integer", 6},
  };
  expect_failures(cases);
}

// List elements are typed kAny by the checker, so their types are checked again at run time.
TEST(GraphEval, RunTimeTypeErrors) {
  const Failure cases[] = {
      {"[1, 'a'][1] + 1", "'+' cannot take a string and an integer", 12},
      {"vec(1, 2, 3) * [vec(1, 2, 3)][0]", "'*' cannot take a vec3 and a vec3", 13},
      {"[true][0] < 1", "'<' needs numbers, found a bool", 10},
      {"2 >= ['x'][0]", "'>=' needs numbers, found a string", 2},
      {"[1][0] == 'a'", "'==' compares values of one type, found an integer and a string", 7},
      {"[1][0] and true", "'and' needs bools, found an integer", 7},
      {"false or [1][0]", "'or' needs bools, found an integer", 6},
      {"not [1][0]", "'not' needs a bool, found an integer", 0},
      {"-[1, 'a'][1]", "'-' needs a number or a vec3, found a string", 0},
      {"[1][0].x", "'.x' needs a vec3, found an integer", 6},
      {"[1][0][0]", "'[]' needs a list or a vec3, found an integer", 6},
      {"[1][['a'][0]]", "'[]' needs an integer index, found a string", 3},
      {"sqrt(['a'][0])", "'sqrt' needs numbers, found a string", 0},
      {"length([1][0])", "'length' needs vec3s, found an integer", 0},
      {"randint(1, [2.5][0])", "'randint' needs integers, found 2.5", 0},
      {"randint(1, [[2]][0])", "'randint' needs integers, found a list", 0},
      {"if([1][0], 1, 2)", "'if' needs a bool, found an integer", 0},
      {"len([vec(1, 2, 3)][0])", "'len' needs a string or a list, found a vec3", 0},
      {"size(['a'][0])", "'size' needs a list or a vec3, found a string", 0},
  };
  expect_failures(cases);
}

// evaluate() is meant for checked expressions, but an unchecked one fails cleanly too.
TEST(GraphEval, UncheckedCallsFailCleanly) {
  FakeEnv env;
  for (const auto& [text, message] : {std::pair{"1 + pow(2)", "wrong number of arguments to 'pow'"},
                                      {"1 + if(true, 1)", "wrong number of arguments to 'if'"},
                                      {"1 + rand(1)", "wrong number of arguments to 'rand'"},
                                      {"1 + nosuch(1)", "unknown function 'nosuch'"}}) {
    ExprError err;
    const std::optional<Expr> e = parse_expression(text, err);
    ASSERT_TRUE(e) << text;
    EvalError error;
    EXPECT_FALSE(evaluate(*e, env, error)) << text;
    EXPECT_EQ(error.message, message);
    EXPECT_EQ(error.at, 4U) << text;
  }
}

// Left-nested chains are as deep as they are long, beyond the parser's 100 levels.
TEST(GraphEval, LongChainsDoNotRecurse) {
  std::string sum = "0";
  std::string index = "[[0]]";
  for (int i = 0; i < 20000; ++i) sum += " + 1";
  for (int i = 0; i < 20000; ++i) index += "[0]";
  FakeEnv env;
  ExprError err;
  EvalError error;
  const std::optional<Expr> e = parse_expression(sum, err);
  ASSERT_TRUE(e);
  const std::optional<Value> v = evaluate(*e, env, error);
  ASSERT_TRUE(v);
  EXPECT_EQ(v->integer(), 20000);
  const std::optional<Expr> i = parse_expression(index, err);
  ASSERT_TRUE(i);
  EXPECT_FALSE(evaluate(*i, env, error));
  EXPECT_EQ(error.message, "'[]' needs a list or a vec3, found an integer");
  EXPECT_EQ(error.at, 11U);
}

TEST(GraphValue, TypesAndText) {
  EXPECT_EQ(Value(2.0).type(), ValueType::kNumber);
  EXPECT_EQ(Value(std::int64_t{2}).type(), ValueType::kInteger);
  EXPECT_EQ(Value(true).type(), ValueType::kBool);
  EXPECT_EQ(Value("a").type(), ValueType::kString);
  EXPECT_EQ(Value(kernel::Vec3{}).type(), ValueType::kVec3);
  EXPECT_EQ(Value(ValueList{}).type(), ValueType::kList);
  EXPECT_EQ(Value(std::int64_t{-3}).number(), -3.0);
  EXPECT_EQ(Value("3").number(), 0.0);

  EXPECT_EQ(to_string(Value(3.0)), "3");
  EXPECT_EQ(to_string(Value(2.5)), "2.5");
  EXPECT_EQ(to_string(Value(0.1)), "0.1");
  EXPECT_EQ(to_string(Value(-0.0)), "0");
  EXPECT_EQ(to_string(Value(1e21)), "1e+21");
  EXPECT_EQ(to_string(Value(1e20)), "100000000000000000000");
  EXPECT_EQ(to_string(Value(100000.0)), "100000");
  EXPECT_EQ(to_string(Value(-0.000001)), "-0.000001");
  EXPECT_EQ(to_string(Value(1.5e-8)), "1.5e-08");
  EXPECT_EQ(to_string(Value(1.0 / 3)), "0.3333333333333333");
  EXPECT_EQ(to_string(Value(INT64_MIN)), "-9223372036854775808");
  EXPECT_EQ(to_string(Value(false)), "false");
  EXPECT_EQ(to_string(Value("it's")), "it's");
  EXPECT_EQ(to_string(Value(kernel::Vec3{1, -2.5, 0})), "[1, -2.5, 0]");
  EXPECT_EQ(to_string(Value(ValueList{std::int64_t{1}, ValueList{"a", true}, ValueList{}})),
            "[1, [a, true], []]");
}

TEST(GraphValue, EqualityIsByValue) {
  EXPECT_EQ(Value(std::int64_t{3}), Value(3.0));
  EXPECT_NE(Value(std::int64_t{3}), Value(3.5));
  EXPECT_NE(Value(std::int64_t{9007199254740993}), Value(9007199254740992.0));
  EXPECT_NE(Value("1"), Value(std::int64_t{1}));
  EXPECT_NE(Value(true), Value(std::int64_t{1}));
  EXPECT_EQ(Value(kernel::Vec3{1, 2, 3}), Value(kernel::Vec3{1, 2, 3}));
  EXPECT_NE(Value(kernel::Vec3{1, 2, 3}), Value(ValueList{1.0, 2.0, 3.0}));
  EXPECT_EQ(Value(ValueList{std::int64_t{1}, "a"}), Value(ValueList{1.0, "a"}));
  EXPECT_NE(Value(ValueList{std::int64_t{1}}), Value(ValueList{std::int64_t{1}, "a"}));
}

std::optional<Value> from_json(const std::string& text, ValueType want = ValueType::kAny) {
  const base::Source source("t.json", text);
  const base::Result<JsonValue> json = parse_json(source);
  EXPECT_TRUE(json.ok()) << text;
  return value_from_json(json.value(), want);
}

std::string described(const std::optional<Value>& v) {
  return v ? std::string(value_type_name(v->type())) + " " + to_string(*v) : "none";
}

TEST(GraphValue, FromJson) {
  EXPECT_EQ(described(from_json("3")), "integer 3");
  EXPECT_EQ(described(from_json("3", ValueType::kNumber)), "integer 3");  // convert() does that
  EXPECT_EQ(described(from_json("3.0")), "number 3");
  EXPECT_EQ(described(from_json("-2.5e1")), "number -25");
  EXPECT_EQ(described(from_json("18446744073709551615")), "number 18446744073709551616");
  EXPECT_EQ(described(from_json("\"=x\"")), "string =x");
  EXPECT_EQ(described(from_json("true")), "bool true");
  EXPECT_EQ(described(from_json("[1, 2.5, 3]", ValueType::kVec3)), "vec3 [1, 2.5, 3]");
  EXPECT_EQ(described(from_json("[1, 2.5, 3]")), "list [1, 2.5, 3]");
  EXPECT_EQ(described(from_json("[1, \"a\", 3]", ValueType::kVec3)), "list [1, a, 3]");
  EXPECT_EQ(described(from_json("[1, 2]", ValueType::kVec3)), "list [1, 2]");
  EXPECT_EQ(described(from_json("[[1, 2, 3], []]", ValueType::kVec3)), "list [[1, 2, 3], []]");
  EXPECT_EQ(described(from_json("null")), "none");
  EXPECT_EQ(described(from_json("{\"a\": 1}")), "none");
  EXPECT_EQ(described(from_json("[1, null]")), "none");
  EXPECT_EQ(described(from_json("[[{}]]")), "none");
}

TEST(GraphValue, Convert) {
  const Value three(std::int64_t{3});
  EXPECT_EQ(described(convert(three, ValueType::kNumber)), "number 3");
  EXPECT_EQ(described(convert(three, ValueType::kAny)), "integer 3");
  EXPECT_EQ(described(convert(Value(3.0), ValueType::kInteger)), "integer 3");
  EXPECT_EQ(described(convert(Value(-0.0), ValueType::kInteger)), "integer 0");
  EXPECT_EQ(described(convert(Value(3.5), ValueType::kInteger)), "none");
  EXPECT_EQ(described(convert(Value(1e19), ValueType::kInteger)), "none");
  EXPECT_EQ(described(convert(Value(-9223372036854775808.0), ValueType::kInteger)),
            "integer -9223372036854775808");
  EXPECT_EQ(described(convert(Value(9223372036854775808.0), ValueType::kInteger)), "none");
  EXPECT_EQ(described(convert(Value(ValueList{three, 2.5, 1.0}), ValueType::kVec3)),
            "vec3 [3, 2.5, 1]");
  EXPECT_EQ(described(convert(Value(ValueList{three, 2.5}), ValueType::kVec3)), "none");
  EXPECT_EQ(described(convert(Value(ValueList{three, "a", 1.0}), ValueType::kVec3)), "none");
  EXPECT_EQ(described(convert(Value(kernel::Vec3{1, 2, 3}), ValueType::kVec3)), "vec3 [1, 2, 3]");
  EXPECT_EQ(described(convert(Value(kernel::Vec3{1, 2, 3}), ValueType::kList)), "none");
  EXPECT_EQ(described(convert(Value("flat"), ValueType::kEnum)), "string flat");
  EXPECT_EQ(described(convert(three, ValueType::kEnum)), "none");
  EXPECT_EQ(described(convert(Value(true), ValueType::kNumber)), "none");
  EXPECT_EQ(described(convert(Value("3"), ValueType::kInteger)), "none");
  EXPECT_EQ(described(convert(three, ValueType::kString)), "none");
}

}  // namespace
}  // namespace insula::lang::graph
