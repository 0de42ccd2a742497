// The PLaSM checker: name resolution through parameters, WHERE locals (order-free), top-level
// DEFs and builtins; suggestions; duplicates; cycles among value bindings only; builtin arity.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "lang/plasm/builtins.h"
#include "test_util.h"

namespace insula::lang::plasm {
namespace {

using testing::first_error;

TEST(PlasmChecker, BuiltinTableIsSortedAndUpperCase) {
  const auto table = builtins();
  ASSERT_GT(table.size(), 90U);
  for (std::size_t i = 0; i < table.size(); ++i) {
    EXPECT_EQ(name_key(table[i].name), table[i].name);
    if (i > 0) {
      EXPECT_LT(table[i - 1].name, table[i].name);
    }
    EXPECT_EQ(find_builtin(table[i].name), &table[i]);
  }
  EXPECT_EQ(find_builtin("Bezier"), nullptr);  // keys are case-folded by the caller
  EXPECT_NE(find_builtin(name_key("Bezier")), nullptr);
}

// docs/plasm-language.md lists the table's names in order, so the page follows the table.
TEST(PlasmChecker, LanguagePageListsEveryBuiltin) {
  std::string page =
      testing::read_file(std::filesystem::path(INSULA_SOURCE_DIR) / "docs" / "plasm-language.md");
  std::replace(page.begin(), page.end(), '\n', ' ');
  std::string names = "Its names:";
  for (const Builtin& b : builtins()) {
    names += ' ';
    names += b.name;
  }
  EXPECT_NE(page.find(names + "."), std::string::npos) << names;
}

TEST(PlasmChecker, NamesResolveCaseInsensitivelyAndInAnyOrder) {
  EXPECT_EQ(first_error("DEF a = B + b;\nDEF b = 1;"), "");
  EXPECT_EQ(first_error("DEF f (X::isreal) = y WHERE y = z * x, z = 2 END;"), "");
  EXPECT_EQ(first_error("DEF v = bezier:s1:<K:0, K:1>;"), "");
}

TEST(PlasmChecker, ParametersAreNotVisibleOutsideTheirDefinition) {
  EXPECT_EQ(first_error("DEF f (a::IsReal) = a;\nDEF g = a;"),
            "t.psm:2:9: error[PSM301]: unknown name 'a'; did you mean 'AA'?");
  EXPECT_EQ(first_error("DEF f (a::IsReal) = b WHERE b = 1 END;\nDEF g = b;"),
            "t.psm:2:9: error[PSM301]: unknown name 'b'; did you mean 'f'?");
}

TEST(PlasmChecker, PredicatesSeeEarlierGroupsOnly) {
  EXPECT_EQ(first_error("DEF f (n::IsNat)(s::C:EQ:n ~ LEN) = s;"), "");
  EXPECT_EQ(first_error("DEF f (s::C:EQ:n ~ LEN)(n::IsNat) = s;"),
            "t.psm:1:16: error[PSM301]: unknown name 'n'; did you mean 'f'?");
  EXPECT_EQ(first_error("DEF f (n::IsNat; s::C:EQ:n ~ LEN) = s;"),
            "t.psm:1:26: error[PSM301]: unknown name 'n'; did you mean 'f'?");
}

TEST(PlasmChecker, SuggestionsPreferTheSameInitialAndInnerScopes) {
  EXPECT_EQ(first_error("DEF c (dm, h::IsReal) = d;"),
            "t.psm:1:25: error[PSM301]: unknown name 'd'; did you mean 'dm'?");
  EXPECT_EQ(first_error("DEF a = Trunkone;"),
            "t.psm:1:9: error[PSM301]: unknown name 'Trunkone'; did you mean 'TRUNCONE'?");
  EXPECT_EQ(first_error("DEF a = zzzzzz;"), "t.psm:1:9: error[PSM301]: unknown name 'zzzzzz'");
}

TEST(PlasmChecker, OnlyValueBindingsFormCycles) {
  // Mutually recursive functions are fine: only calling them can loop.
  EXPECT_EQ(first_error("DEF f (n::IsInt) = g:n;\nDEF g (n::IsInt) = f:n;"), "");
  // A value that calls a function that uses the value is not followed statically.
  EXPECT_EQ(first_error("DEF x = f:1;\nDEF f (n::IsInt) = x;"), "");
  EXPECT_EQ(first_error("DEF x = x;"),
            "t.psm:1:5: error[PSM305]: the value of 'x' depends on itself: x -> x");
  EXPECT_EQ(first_error("DEF f (a::IsReal) = p WHERE p = <a, q>, q = r, r = AA:ID:p END;"),
            "t.psm:1:29: error[PSM305]: the value of 'p' depends on itself: p -> q -> r -> p");
  // A value binding with its own WHERE: the local is part of the cycle.
  EXPECT_EQ(first_error("DEF v = w WHERE w = v END;"),
            "t.psm:1:5: error[PSM305]: the value of 'v' depends on itself: v -> w -> v");
}

TEST(PlasmChecker, EachCycleIsReportedOnce) {
  const base::Source source("t.psm", "DEF a = b;\nDEF b = a;\nDEF c = a + d;\nDEF d = d;");
  const auto program = parse(source);
  ASSERT_TRUE(program.ok());
  const CheckResult checked = check(program.value(), source);
  ASSERT_EQ(checked.diagnostics.size(), 2U);
  EXPECT_EQ(base::render(checked.diagnostics[0]),
            "t.psm:1:5: error[PSM305]: the value of 'a' depends on itself: a -> b -> a");
  EXPECT_EQ(base::render(checked.diagnostics[1]),
            "t.psm:4:5: error[PSM305]: the value of 'd' depends on itself: d -> d");
}

TEST(PlasmChecker, ArityOfBuiltinsAppliedToLiteralSequences) {
  EXPECT_EQ(first_error("DEF a = TRUNCONE:<1, 2, 3>:24;"), "");
  EXPECT_EQ(first_error("DEF a = MKPOL:<<<0>>, <<1>>>;"),
            "t.psm:1:9: error[PSM306]: 'MKPOL' takes a sequence of 3 values, found 2");
  EXPECT_EQ(first_error("DEF a = 1 AL <2>;"), "");
  // A definition of the same name hides the builtin and its arity.
  EXPECT_EQ(first_error("DEF a = mkpol:<1>;\nDEF mkpol = ID;"), "");
  EXPECT_EQ(first_error("DEF a = 1 TRUNCONE 2;"),
            "t.psm:1:11: error[PSM306]: 'TRUNCONE' takes a sequence of 3 values, so it cannot "
            "be used as an infix (binary) function");
}

TEST(PlasmChecker, SummaryCounts) {
  const base::Source source("t.psm", "DEF f (a::IsReal) = a;\nDEF v = 1;\nDEF w = 2;\nf:v;");
  const auto program = parse(source);
  ASSERT_TRUE(program.ok());
  const CheckResult checked = check(program.value(), source);
  EXPECT_TRUE(checked.ok);
  EXPECT_EQ(checked.functions, 1U);
  EXPECT_EQ(checked.values, 2U);
  EXPECT_EQ(checked.expressions, 1U);
}

}  // namespace
}  // namespace insula::lang::plasm
