// The checker's API behaviour beyond the catalog: start symbol selection (issue 4), reachability,
// terminals, options (known attributes, --start), constant folding, normalisation helpers, and
// that the front-end corpus checks clean where it should.
#include <gtest/gtest.h>

#include "lang/cga/checker.h"
#include "lang/cga/checker_internal.h"
#include "test_util.h"

namespace insula::lang::cga {
namespace {

using testing::data_dir;
using testing::read_file;

struct Checked {
  base::Source source;
  Grammar grammar;
  CheckResult result;
};

// Parses (must succeed) and checks `text`; the grammar lives in the returned object so the
// result's rule pointers stay valid.
std::unique_ptr<Checked> run(const std::string& text, const CheckOptions& options = {}) {
  auto out = std::make_unique<Checked>(Checked{base::Source("t.cga", text), {}, {}});
  auto parsed = parse(out->source);
  EXPECT_TRUE(parsed.ok()) << (parsed.ok() ? "" : base::render(parsed.diagnostics().front()));
  if (!parsed.ok()) return out;
  out->grammar = std::move(parsed.value());
  out->result = check(out->grammar, out->source, options);
  return out;
}

std::vector<std::string> rendered(const CheckResult& result) {
  std::vector<std::string> out;
  for (const base::Diagnostic& d : result.diagnostics) out.push_back(base::render(d));
  return out;
}

std::vector<std::string> reachable_ids(const CheckResult& result) {
  std::vector<std::string> out;
  for (const Rule* rule : result.reachable_rules()) out.push_back(rule->id);
  return out;
}

TEST(CgaChecker, StartIsFirstRuleOfLowestPrioritySet) {
  // Set 2 is written first; the start comes from set 1 wherever it is in the file.
  const auto c =
      run("PRIORITY 2:\n"
          "2: Mass ~> Comp(\"faces\"){ top: Roof | side: Wall }\n"
          "PRIORITY 1:\n"
          "1: Lot ~> extrude(10) Mass\n"
          "3: Other ~> X\n");
  EXPECT_EQ(c->result.start_symbol, "Lot");
  EXPECT_TRUE(c->result.ok);
  EXPECT_EQ(reachable_ids(c->result), (std::vector<std::string>{"2", "1"}));
  EXPECT_EQ(rendered(c->result),
            (std::vector<std::string>{"t.cga:5:1: warning[CGA402]: rule '3' is unreachable: "
                                      "'Other' is not derived from the start symbol 'Lot'"}));
  EXPECT_EQ(c->result.terminals, (std::vector<std::string>{"Roof", "Wall", "X"}));
}

TEST(CgaChecker, StartOptionOverridesTheDefault) {
  CheckOptions options;
  options.start = "Mass";
  const auto c =
      run("1: Lot ~> extrude(10) Mass\n"
          "2: Mass ~> Comp(\"faces\"){ top: Roof | side: Wall }\n",
          options);
  EXPECT_EQ(c->result.start_symbol, "Mass");
  EXPECT_EQ(reachable_ids(c->result), (std::vector<std::string>{"2"}));
  EXPECT_TRUE(c->result.ok);
}

TEST(CgaChecker, StartOptionMustNameAPredecessor) {
  CheckOptions options;
  options.start = "Roof";
  const auto c = run("1: Lot ~> extrude(10) Mass\n", options);
  EXPECT_FALSE(c->result.ok);
  EXPECT_TRUE(c->result.start_symbol.empty());
  EXPECT_EQ(rendered(c->result),
            (std::vector<std::string>{
                "t.cga: error[CGA314]: the start symbol 'Roof' is the predecessor of no rule"}));
}

TEST(CgaChecker, RecursiveGrammarIsReachableWithoutLooping) {
  const auto c =
      run("1: Facade : Shape.sy > 3 ~> BS(\"Y\", 3, 1r){ Floor | Facade }\n"
          "2: Facade ~> Floor\n"
          "3: Floor ~> RR(\"X\", 2){ Floor2 }\n"
          "4: Floor2 ~> Facade\n");
  EXPECT_TRUE(c->result.ok);
  EXPECT_EQ(reachable_ids(c->result), (std::vector<std::string>{"1", "2", "3", "4"}));
  EXPECT_TRUE(c->result.terminals.empty());
  EXPECT_TRUE(c->result.diagnostics.empty());
}

TEST(CgaChecker, KnownAttributesAreDefined) {
  const std::string text = "Lot --> extrude(height * 2) Mass\n";
  EXPECT_FALSE(run(text)->result.ok);
  CheckOptions options;
  options.known_attributes = {"height"};
  const auto c = run(text, options);
  EXPECT_TRUE(c->result.ok);
  EXPECT_TRUE(c->result.diagnostics.empty());
}

TEST(CgaChecker, LotSizeAttributesCountAsUsed) {
  // The derivation reads lotWidth and lotDepth for its default lot; 'spare' is unused.
  const auto c =
      run("attr lotWidth = 30\nattr lotDepth = 18\nattr spare = 1\nLot --> extrude(3) Mass\n");
  EXPECT_EQ(rendered(c->result),
            (std::vector<std::string>{"t.cga:3:6: warning[CGA403]: attribute 'spare' is never "
                                      "used"}));
}

TEST(CgaChecker, ProbabilitiesOfAttributesAreLeftToTheDerivation) {
  // Not constant: neither the range nor the sum can be known before the run.
  const auto c =
      run("attr p = 0.7\n"
          "1: A ~> B : (p) ~> C : (1 - p)\n"
          "2: B ~> D : 0.25 ~> E : 0.75\n"
          "3: C ~> F ~> G\n");  // no probabilities at all: equally likely
  EXPECT_TRUE(c->result.ok) << ::testing::PrintToString(rendered(c->result));
  EXPECT_TRUE(c->result.diagnostics.empty());
}

TEST(CgaChecker, ProbabilitySumToleranceIsOneBillionth) {
  EXPECT_TRUE(run("1: A ~> B : 0.1 ~> C : 0.2 ~> D : 0.7\n")->result.ok);  // 0.1+0.2 != 0.3
  EXPECT_FALSE(run("1: A ~> B : 0.3333 ~> C : 0.3333 ~> D : 0.3333\n")->result.ok);
  EXPECT_TRUE(run("1: A ~> B : (1/3) ~> C : (1/3) ~> D : (1/3)\n")->result.ok);
}

TEST(CgaChecker, AngleBoundsAreInclusive) {
  EXPECT_TRUE(run("1: A ~> Rx(0) Ry(360) Rz(180) I(\"cube\")\n")->result.ok);
  EXPECT_FALSE(run("1: A ~> Rx(360.5) I(\"cube\")\n")->result.ok);
  // CityEngine's r() is not the paper's RotationRule: any angle.
  EXPECT_TRUE(run("A --> r(-90, 0, 720) B\n")->result.ok);
}

TEST(CgaChecker, EmptyShapeAloneOrInABlockIsFine) {
  const auto c =
      run("1: A ~> ε : 0.5 ~> B : 0.5\n"
          "2: B ~> T(0,0,1) C\n"
          "3: C ~> Comp(\"faces\"){ top: ε | side: T(0, 0, 1) W }\n"
          "4: D ~> [ T(1,0,0) E ] nil()\n"
          "5: E ~> [ ε ] S(1, 1, 1) F\n"
          "6: F ~> [ T(1,0,0) G ] S(1, 1, 1) nil()\n");
  EXPECT_EQ(rendered(c->result),
            (std::vector<std::string>{
                "t.cga:4:1: warning[CGA402]: rule '4' is unreachable: 'D' is not derived from "
                "the start symbol 'A'",
                "t.cga:4:24: warning[CGA406]: the empty shape next to other successors has no "
                "effect",
                "t.cga:5:1: warning[CGA402]: rule '5' is unreachable: 'E' is not derived from "
                "the start symbol 'A'",
                "t.cga:5:11: warning[CGA406]: the empty shape next to other successors has no "
                "effect",
                "t.cga:6:1: warning[CGA402]: rule '6' is unreachable: 'F' is not derived from "
                "the start symbol 'A'",
                "t.cga:6:35: error[CGA303]: the empty shape has no scope, but the scope rule 'S' "
                "is in the same successor (seed 004 §IV.B, constraint 3)"}));
}

TEST(CgaChecker, DiagnosticsAreSortedByPosition) {
  const auto c =
      run("1: A ~> B : 2 ~> C : 0.5\n"
          "1: A ~> Rx(-1) D\n");
  const auto lines = rendered(c->result);
  ASSERT_EQ(lines.size(), 4U);
  EXPECT_EQ(lines[0],
            "t.cga:1:13: error[CGA301]: probability 2 is not in (0, 1] (seed 004 §IV.B, "
            "constraint 1)");
  EXPECT_EQ(lines[1],
            "t.cga:1:22: error[CGA305]: the probabilities of the 2 parts of the rule "
            "sum to 2.5, not 1 (seed 004 §IV.B, constraint 5)");
  EXPECT_EQ(lines[2],
            "t.cga:2:1: error[CGA307]: duplicate rule id '1' in priority set 1 (first "
            "at line 1)");
  EXPECT_EQ(lines[3],
            "t.cga:2:12: error[CGA302]: rotation angle -1 is not in [0, 360] (seed 004 "
            "§IV.B, constraint 2)");
}

TEST(CgaChecker, ComponentSplitForms) {
  // Constraint 4: index list and successors match; no list and one successor; selector keys.
  EXPECT_TRUE(run("1: a ~> CS(\"faces\", 0, 2, 4){ A | B | C }\n")->result.ok);
  EXPECT_TRUE(run("1: a ~> CS(\"edges\"){ A }\n")->result.ok);
  EXPECT_TRUE(run("1: a ~> comp(f){ front: A | 3: B | all: C }\n")->result.ok);
  EXPECT_TRUE(run("1: a ~> comp(\"v\"){ 0: A | 7: B }\n")->result.ok);
  EXPECT_TRUE(run("1: a ~> comp(\"f\"){ \"top\": A | \"side\": B }\n")->result.ok);
  EXPECT_FALSE(run("1: a ~> CS(\"faces\", 0){ front: A }\n")->result.ok);
  EXPECT_FALSE(run("1: a ~> comp(\"f\"){ front: A | B }\n")->result.ok);
}

TEST(CgaChecker, AxesOfThePaperAndOfCityEngine) {
  EXPECT_TRUE(run("1: a ~> RR(\"XY\", 3){ cell }\n")->result.ok);  // §VI
  EXPECT_TRUE(run("1: a ~> RR(\"xyz\", 1){ c }\n")->result.ok);
  // §VI: BasicSplitRule takes <axis> "like RepeatRule"; the paper's own example, as written.
  EXPECT_TRUE(run("1: front ~> BS( \"XY\", 3, 5, 7){ balcony| floor| door}\n")->result.ok);
  EXPECT_TRUE(run("1: a ~> Subdiv(\"xyz\", 1r, 2){ b | c }\n")->result.ok);
  EXPECT_FALSE(run("1: a ~> BS(\"YX\", 3, 5, 7){ b | f | d }\n")->result.ok);
  EXPECT_FALSE(run("A --> split(\"xy\"){ 1: B | ~1: C }\n")->result.ok);  // CityEngine's: one
  EXPECT_TRUE(run("A --> split(y){ 1: B | ~1: C }\n")->result.ok);        // bare word
  EXPECT_FALSE(run("A --> split(w){ 1: B }\n")->result.ok);
  EXPECT_FALSE(run("1: a ~> RR(\"YX\", 3){ cell }\n")->result.ok);
  // The axis is a word, never a value (as the compiler reads it): an attribute cannot be one.
  EXPECT_FALSE(run("attr dir = \"x\"\nA --> split(dir){ 1: B }\n")->result.ok);
  EXPECT_FALSE(run("A --> split(Shape.sx){ 1: B }\n")->result.ok);
}

TEST(CgaChecker, SplitPatternsAndSizes) {
  EXPECT_TRUE(run("F --> split(\"x\"){ 1: W | { ~2.5: T | 0.4: P }* | 1: W }\n")->result.ok);
  EXPECT_TRUE(run("F --> split(\"x\"){ '0.5: A | 2r: B | ~1: C }\n")->result.ok);
  EXPECT_FALSE(run("F --> split(\"x\"){ 1: W | { ~2.5: T | P }* }\n")->result.ok);
  EXPECT_FALSE(run("F --> split(\"x\"){ -1: W }\n")->result.ok);
  EXPECT_FALSE(run("F --> split(\"x\"){ \"a\": W }\n")->result.ok);
}

TEST(CgaChecker, FoldsOnlyLiteralArithmetic) {
  const auto value = [](const std::string& text) {
    const auto c = run("1: A : " + text + " ~> B\n");
    return detail::fold(*c->grammar.sets[0].rules[0].condition);
  };
  EXPECT_DOUBLE_EQ(value("(1 - 0.25) * 2")->value, 1.5);
  EXPECT_DOUBLE_EQ(value("-(3 % 2)")->value, -1.0);
  EXPECT_FALSE(value("1 / 0").has_value());
  EXPECT_FALSE(value("1 < 2").has_value());
  EXPECT_FALSE(value("Shape.sx").has_value());
  EXPECT_TRUE(value("~2")->floating);
}

TEST(CgaChecker, NormalisationHelpers) {
  EXPECT_EQ(canonical_axis("XZ"), "xz");
  EXPECT_EQ(canonical_axis("y"), "y");
  EXPECT_FALSE(canonical_axis("zx").has_value());
  EXPECT_FALSE(canonical_axis("").has_value());
  ASSERT_TRUE(comp_type_of("verticles").has_value());
  EXPECT_EQ(comp_type_of("verticles")->type, CompType::kVertices);
  EXPECT_TRUE(comp_type_of("verticles")->nonstandard);
  EXPECT_EQ(comp_type_of("side faces")->type, CompType::kSideFaces);
  EXPECT_FALSE(comp_type_of("f")->nonstandard);
  EXPECT_FALSE(comp_type_of("Faces").has_value());
  EXPECT_EQ(comp_type_name(CompType::kEdges), "edges");
}

TEST(CgaChecker, CorpusGrammarsOfRealBuildingsCheckClean) {
  for (const char* name : {"apartment_block.cga", "paper_example1.cga", "paper_fig13.cga"}) {
    SCOPED_TRACE(name);
    const auto c = run(read_file(data_dir() / name));
    EXPECT_TRUE(c->result.ok) << ::testing::PrintToString(rendered(c->result));
  }
}

TEST(CgaChecker, DeepAndLargeGrammarsStayFast) {
  // 2,000 chained rules (depth 2,000 in reachability) plus nesting at the parser's limit.
  std::string text;
  for (int i = 0; i < 2000; ++i) {
    text += std::to_string(i) + ": S" + std::to_string(i) + " ~> BS(\"X\", 1r, 1){ S" +
            std::to_string(i + 1) + " | W } : 0.5 ~> S" + std::to_string(i + 1) + " : 0.5\n";
  }
  std::string nested = "A";
  for (int i = 0; i < 90; ++i) nested = "RR(\"X\", 1){ " + nested + " }";
  text += "x: S2000 ~> " + nested + "\n";
  const auto c = run(text);
  EXPECT_TRUE(c->result.ok);
  EXPECT_EQ(c->result.reachable_rules().size(), 2001U);
  EXPECT_EQ(c->result.terminals, (std::vector<std::string>{"A", "W"}));
}

}  // namespace
}  // namespace insula::lang::cga
