// The evaluator (docs/plasm-language.md, "Evaluation"): exact values of small programs, the value
// goldens tests/data/plasm/eval/*.values, runtime diagnostics and budgets.
#include <gtest/gtest.h>

#include "lang/plasm/builtins.h"
#include "lang/plasm/eval_context.h"
#include "test_util.h"

namespace insula::lang::plasm {
namespace {

using testing::first_run_error;
using testing::value_of;

std::string eval_expr(const std::string& expr) {
  return value_of("DEF v = " + expr + ";", "v");
}

TEST(PlasmEval, NumbersAndArithmetic) {
  EXPECT_EQ(eval_expr("1 + 2 * 3"), "7");
  EXPECT_EQ(eval_expr("2 ** 3 ** 2"), "64");
  EXPECT_EQ(eval_expr("7 / 2"), "3.5");
  EXPECT_EQ(eval_expr("10 - 4 - 3"), "3");
  EXPECT_EQ(eval_expr("-:5"), "-5");
  EXPECT_EQ(eval_expr("PI"), "3.141592653589793");
}

TEST(PlasmEval, ApplicationCompositionConstruction) {
  EXPECT_EQ(eval_expr("(LEN ~ CAT):<<1, 2>, <3>>"), "3");
  EXPECT_EQ(eval_expr("[S2, S1, LEN]:<5, 6>"), "<6, 5, 2>");
  EXPECT_EQ(eval_expr("CONS:<ID, REVERSE>:<1, 2>"), "<<1, 2>, <2, 1>>");
  EXPECT_EQ(eval_expr("IF:<IsNum, K:\"n\", K:\"s\">:<1>"), "\"s\"");
}

TEST(PlasmEval, LiftedArithmeticOnFunctions) {
  EXPECT_EQ(eval_expr("(SIN * SIN + COS * COS):0.3"), "1");
  EXPECT_EQ(eval_expr("(ID * ID - K:1):4"), "15");
  EXPECT_EQ(eval_expr("(S1 / S2):<3, 4>"), "0.75");
  EXPECT_EQ(eval_expr("(ID + 1):1"), "2");
  EXPECT_EQ(eval_expr("SIN + COS"), "<function +>");
}

TEST(PlasmEval, OperatorsAsValuesAndRepeat) {
  EXPECT_EQ(eval_expr("AA:-:<1, -2>"), "<-1, 2>");
  EXPECT_EQ(eval_expr("C:*:(PI/6):3"), "1.5707963267948966");
  EXPECT_EQ(eval_expr("INSR:+:(1 .. 100)"), "5050");
  EXPECT_EQ(eval_expr("INSR:-:<10, 4, 3>"), "9");
  EXPECT_EQ(eval_expr("INSL:-:<10, 4, 3>"), "3");
  EXPECT_EQ(eval_expr("#:3:<0>"), "<<0>, <0>, <0>>");
  EXPECT_EQ(eval_expr("##:2:<1, -2>"), "<1, -2, 1, -2>");
  EXPECT_EQ(eval_expr("2 .. 4"), "<2, 3, 4>");
  EXPECT_EQ(eval_expr("3 .. 1"), "<>");
  EXPECT_EQ(eval_expr("<1, 2> AR 3"), "<1, 2, 3>");
}

TEST(PlasmEval, FlToolbox) {
  EXPECT_EQ(eval_expr("DISTL:<0, <1, 2>>"), "<<0, 1>, <0, 2>>");
  EXPECT_EQ(eval_expr("DISTR:<<1, 2>, 0>"), "<<1, 0>, <2, 0>>");
  EXPECT_EQ(eval_expr("TRANS:<<1, 2>, <3, 4>, <5, 6>>"), "<<1, 3, 5>, <2, 4, 6>>");
  EXPECT_EQ(eval_expr("SEL:3:(INTSTO:5)"), "3");
  EXPECT_EQ(eval_expr("S9:(1 .. 9)"), "9");
  EXPECT_EQ(eval_expr("<FIRST, LAST, TAIL, BUTLAST>"),
            "<<function FIRST>, <function LAST>, <function TAIL>, <function BUTLAST>>");
  EXPECT_EQ(eval_expr("EQ:<<1, <2>>, <1, <2>>>"), "TRUE");
  EXPECT_EQ(eval_expr("<LT:3:2, GT:3:2, AND:<TRUE, FALSE>, OR:<FALSE, TRUE>, NOT:TRUE>"),
            "<TRUE, FALSE, FALSE, TRUE, FALSE>");
  EXPECT_EQ(eval_expr("AA:(IsSeqOf:IsIntPos):<<1, 2>, <1, 0>, 3>"), "<TRUE, FALSE, FALSE>");
}

// Partial applications count the arguments received; what makes a function (the f and g of
// f ~ g) is not one.
TEST(PlasmEval, FunctionSummaries) {
  EXPECT_EQ(eval_expr("AA:SIN"), "<function AA, 1 of 2 arguments>");
  EXPECT_EQ(eval_expr("C:+:1"), "<function C, 2 of 3 arguments>");
  EXPECT_EQ(eval_expr("SIN ~ COS"), "<function ~>");
  EXPECT_EQ(eval_expr("[ID, ID]"), "<function [2]>");
  EXPECT_EQ(eval_expr("#:2"), "<function #>");
  EXPECT_EQ(eval_expr("CUBOID"), "<function CUBOID>");
}

TEST(PlasmEval, CurriedGroupsAndPartialApplication) {
  const std::string program =
      "DEF f (a, b::IsNum)(c::IsSeq) = a * b + LEN:c;\n"
      "DEF p = f:<2, 3>;\n"
      "DEF r = p:<1, 1>;\n";
  EXPECT_EQ(value_of(program, "p"), "<function f, 1 of 2 arguments>");
  EXPECT_EQ(value_of(program, "r"), "8");
  EXPECT_EQ(value_of(program, "f"), "<function f>");
}

TEST(PlasmEval, RecursionAndOrderFreeBindings) {
  const std::string program =
      "DEF fact (n::IsNat) = IF:<C:EQ:0, K:1, ID * (fact ~ C:+:-1)>:n;\n"
      "DEF v = fact:10 + w;\n"
      "DEF w = a WHERE a = b + 1, b = 1 END;\n";
  EXPECT_EQ(value_of(program, "v"), "3628802");
}

// A predicate sees the earlier groups: (s::C:EQ:n ~ LEN) after (n::IsNat).
TEST(PlasmEval, PredicatesSeeEarlierGroups) {
  const std::string program =
      "DEF f (n::IsNat)(s::C:EQ:n ~ LEN) = s;\nDEF a = f:2:<7, 8>;\n"
      "DEF b = f:2:<7>;\n";
  EXPECT_EQ(value_of(program, "a"), "<7, 8>");
  EXPECT_EQ(value_of(program, "b"),
            "t.psm:3:9: error[PSM403]: 'f': parameter 's' must satisfy C:EQ:n ~ LEN, found <7>");
}

TEST(PlasmEval, RuntimeDiagnosticsArePositioned) {
  EXPECT_EQ(eval_expr("1 + 2 / (3 - 3)"), "t.psm:1:13: error[PSM405]: division by zero");
  EXPECT_EQ(eval_expr("3:4"),
            "t.psm:1:9: error[PSM401]: cannot apply a number 3: it is not a function");
  EXPECT_EQ(eval_expr("S3:<1, 2>"),
            "t.psm:1:9: error[PSM407]: 'S3' selects element 3 of a sequence of 2");
  EXPECT_EQ(eval_expr("SQRT:-1"), "t.psm:1:9: error[PSM406]: 'SQRT' gives no finite number here");
  EXPECT_EQ(eval_expr("<1> + 2"),
            "t.psm:1:9: error[PSM402]: '+' needs numbers or functions, found a sequence <1> and a "
            "number 2");
  EXPECT_EQ(eval_expr("CUBOID:<1, 1, 1> + 1"),
            "t.psm:1:9: error[PSM402]: '+' needs numbers or functions, found a polyhedron "
            "<polyhedron 3D, 1 cells> and a number 1");
  EXPECT_EQ(value_of("DEF a = f:1;\nDEF f (x) = a + x;", "a"),
            "t.psm:2:13: error[PSM408]: the value of 'a' depends on itself (found while "
            "evaluating it)");
}

// About six levels of the depth budget per recursive call (docs: "Budgets").
TEST(PlasmEval, DepthBudgetAllowsAFewHundredRecursiveCalls) {
  const std::string count =
      "DEF count (n::IsNat) = IF:<C:EQ:0, K:0, K:1 + (count ~ C:+:-1)>:n;\n"
      "DEF a = count:300;\nDEF b = count:400;\n";
  EXPECT_EQ(value_of(count, "a"), "300");
  EXPECT_EQ(value_of(count, "b").substr(0, 30), "t.psm:1:28: error[PSM412]: rec");
}

TEST(PlasmEval, BudgetsBoundRunawayPrograms) {
  const std::string loop = "DEF f (n) = f:(n + 1);\nDEF v = f:0;\n";
  EXPECT_EQ(value_of(loop, "v"),
            "t.psm:1:16: error[PSM412]: recursion deeper than 2000 levels (the depth budget)");
  Budgets small;
  small.steps = 1000;
  EXPECT_EQ(value_of("DEF v = AA:(C:+:1):(1 .. 10000);", "v", small),
            "t.psm:1:9: error[PSM411]: evaluation takes more than 1000 steps (the step budget)");
  EXPECT_EQ(value_of("DEF v = 1 .. 1e12;", "v"),
            "t.psm:1:9: error[PSM413]: evaluation needs more than 4000000 cells of memory (the "
            "memory budget)");
  EXPECT_EQ(value_of("DEF v = INSR:LIST:(1 .. 1000);", "v"),
            "t.psm:1:9: error[PSM413]: a value nests deeper than 500 levels (the nesting budget)");
  // The step budget is shared: a later value fails once an earlier one used it up.
  EXPECT_EQ(first_run_error("DEF f (n) = f:(n + 1);\nf:0;\n", "t.psm", small).substr(0, 21),
            "t.psm:1:13: error[PSM");
}

// The app's stop flag (SIGINT) is asked every 4096 steps and ends the evaluation with PSM419.
TEST(PlasmEval, StopFlagInterruptsEvaluation) {
  Budgets stopping;
  int asked = 0;
  stopping.stop = [&asked] { return ++asked >= 2; };
  EXPECT_EQ(value_of("DEF v = INSR:+:(AA:(C:+:1):(1 .. 10000));", "v", stopping),
            "t.psm:1:17: error[PSM419]: evaluation interrupted");
  EXPECT_EQ(asked, 2);
  Budgets never;
  never.stop = [] { return false; };
  EXPECT_EQ(value_of("DEF v = INSR:+:(AA:(C:+:1):(1 .. 10000));", "v", never), "50015000");
}

// Every builtin of the table is implemented: none is left unknown to the evaluator.
TEST(PlasmEval, EveryBuiltinIsImplemented) {
  std::string missing;
  for (const Builtin& b : builtins()) {
    if (find_native(b.name) == nullptr && find_constant(b.name) == nullptr)
      missing += std::string(b.name) + " ";
  }
  EXPECT_EQ(missing, "");
}

TEST(PlasmEval, ValueGoldens) {
  const auto files = testing::files_in(testing::data_dir() / "eval", ".psm");
  ASSERT_GE(files.size(), 5U);
  for (const auto& path : files) {
    SCOPED_TRACE(path.string());
    const base::Source source(path.filename().string(), testing::read_file(path));
    const auto parsed = parse(source);
    ASSERT_TRUE(parsed.ok()) << base::render(parsed.diagnostics().front(), &source);
    const CheckResult checked = check(parsed.value(), source);
    ASSERT_TRUE(checked.diagnostics.empty()) << base::render(checked.diagnostics.front(), &source);
    const auto values = value_summaries(parsed.value(), source);
    ASSERT_TRUE(values.ok()) << base::render(values.diagnostics().front(), &source);
    auto golden = path;
    insula::test::expect_golden(golden.replace_extension(".values"), values.value());
  }
}

}  // namespace
}  // namespace insula::lang::plasm
