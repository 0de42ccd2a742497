// Parallel evaluation (docs/plasm-language.md, "Parallel evaluation"): sequences and AA run their
// elements as tasks, and values, step counts, errors and budget failures are the same for one
// thread and for many.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "lang/plasm/checker.h"
#include "lang/plasm/eval.h"
#include "lang/plasm/parser.h"
#include "test_util.h"

namespace insula::lang::plasm {
namespace {

struct Run {
  std::string value;  // summary or first error
  std::uint64_t steps = 0;
};

Run run(const std::string& text, const std::string& name, std::size_t threads,
        Budgets budgets = {}) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  const base::Source source("t.psm", text);
  const auto program = parse(source);
  EXPECT_TRUE(program.ok());
  EXPECT_TRUE(check(program.value(), source).ok);
  Evaluator evaluator(program.value(), source, budgets);
  const auto value = evaluator.value_of(name);
  Run out;
  out.value = value.ok() ? summary(*value.value()) : base::render(value.diagnostics().front());
  out.steps = evaluator.steps_used();
  return out;
}

void expect_same_for_any_threads(const std::string& text, const std::string& name,
                                 const std::string& expected, Budgets budgets = {}) {
  const Run one = run(text, name, 1, budgets);
  EXPECT_EQ(one.value, expected);
  for (std::size_t threads : {2, 4, 8}) {
    const Run many = run(text, name, threads, budgets);
    EXPECT_EQ(many.value, one.value) << threads << " threads";
    EXPECT_EQ(many.steps, one.steps) << threads << " threads";
  }
}

// Tasks share a WHERE local of their parent: each computes it in its own memo, the parent adopts
// one after the join.
TEST(PlasmParallel, SharedLocalsGiveTheSameValues) {
  const std::string program =
      "DEF f (n::IsNat) = INSR:+:(1 .. n);\n"
      "DEF v = <f:base, f:(base + 1), LEN:(1 .. base), f:(2 * base)> WHERE base = f:20 END;\n";
  expect_same_for_any_threads(program, "v", "<22155, 22366, 210, 88410>");
}

TEST(PlasmParallel, AaOverAUserFunction) {
  const std::string program =
      "DEF sq (x::IsNum) = x * x;\nDEF v = AA:sq:(1 .. 6);\nDEF w = AA:(C:+:1):<1, 2>;\n";
  expect_same_for_any_threads(program, "v", "<1, 4, 9, 16, 25, 36>");
  expect_same_for_any_threads(program, "w", "<2, 3>");
}

// A binding its own tasks need is a cycle, found as in sequential evaluation (not a wait).
TEST(PlasmParallel, CyclesThroughTasksAreReported) {
  expect_same_for_any_threads(
      "DEF a = <f:1, f:2>;\nDEF f (x::IsNum) = LEN:a + x;\n", "a",
      "t.psm:2:24: error[PSM408]: the value of 'a' depends on itself (found while evaluating it)");
}

// The first failing element in sequence order is the error, whichever task fails first.
TEST(PlasmParallel, TheFirstFailingElementIsReported) {
  expect_same_for_any_threads("DEF f (x::IsNum) = 1 / x;\nDEF v = <f:1, f:0, SQRT:-1, f:0>;\n", "v",
                              "t.psm:1:20: error[PSM405]: division by zero");
  expect_same_for_any_threads("DEF f (x::IsNum) = 1 / x;\nDEF v = <f:1, -:<>, f:0, f:2>;\n", "v",
                              "t.psm:2:15: error[PSM407]: '-' of an empty sequence");
}

// Each task alone stays within the step budget; their sum, added at the join, does not: the
// sequence fails there, at its own position, for any number of threads.
TEST(PlasmParallel, BudgetsFailAlikeForAnyThreads) {
  Budgets small;
  small.steps = 3000;
  expect_same_for_any_threads(
      "DEF f (n::IsNat) = INSR:+:(AA:(C:+:1):(1 .. n));\nDEF v = <f:500, f:500, f:500>;\n", "v",
      "t.psm:2:9: error[PSM411]: evaluation takes more than 3000 steps (the step budget)", small);
}

// Polyhedra from tasks: a STRUCT of parts evaluated in parallel is the same complex (and a
// translation of fewer coordinates than the parts keeps their other coordinates).
TEST(PlasmParallel, GeometryFromTasks) {
  const std::string program =
      "DEF box (s::IsRealPos) = CUBOID:<s, s, s>;\n"
      "DEF v = STRUCT:<box:1, T:1:2, box:2, T:1:3, box:3>;\nDEF s = SIZE:<1, 2, 3>:v;\n";
  expect_same_for_any_threads(program, "v", "<polyhedron 3D, 3 cells>");
  expect_same_for_any_threads(program, "s", "<8, 3, 3>");
}

}  // namespace
}  // namespace insula::lang::plasm
