// One declaration per operation (issue 11): a parameter added to a registered operation, and a
// new operation, are usable and checked in CGA and Lua with no edit to either front-end. This
// binary amends the registry before it is built (shape::extend_registry): roof gains a parameter
// `test_cap` and `test_plinth` is registered; both front-ends then reach them by name.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "../cga/derive_util.h"
#include "../lua/run_util.h"
#include "lang/cga/checker.h"
#include "lang/cga/operations.h"
#include "shape/operation.h"

namespace insula {
namespace {

using shape::ParamType;

// Every test_cap value roof received, in call order.
std::vector<double>& caps_seen() {
  static std::vector<double> seen;
  return seen;
}

void amend(std::vector<shape::Operation>& ops) {
  for (shape::Operation& op : ops) {
    if (op.name != "roof") continue;
    op.params.push_back({"test_cap", ParamType::kNumber, "test only", 0.0, {}, 0.0, 1.0});
    op.execute = [inner = op.execute](shape::ShapeTree& tree, shape::ShapeId id,
                                      const shape::Arguments& args, const shape::Context& context) {
      caps_seen().push_back(args.number("test_cap"));
      return inner(tree, id, args, context);
    };
  }
  shape::Operation plinth;
  plinth.name = "test_plinth";
  plinth.doc = "test only: extrude by a bounded height";
  plinth.params = {
      {"height", ParamType::kNumber, "meters", {}, {}, 0.1, 3.0},
      {"side", ParamType::kEnum, "test only", std::string("out"), {"in", "out"}, {}, {}}};
  plinth.execute = [](shape::ShapeTree& tree, shape::ShapeId id, const shape::Arguments& args,
                      const shape::Context& context) {
    shape::Arguments extrude;
    extrude.set("height", args.number("height"));
    return shape::registry().find("extrude")->execute(tree, id, extrude, context);
  };
  ops.push_back(std::move(plinth));
}

const bool kAmended = shape::extend_registry(amend);

// The checker's diagnostics of `text`, rendered one per line without source lines.
std::string cga_check(const std::string& text) {
  const base::Source source("t.cga", text);
  auto grammar = lang::cga::parse(source);
  if (!grammar.ok()) return base::render(grammar.diagnostics().front());
  const lang::cga::CheckResult result = lang::cga::check(grammar.value(), source);
  std::string out;
  for (const base::Diagnostic& d : result.diagnostics) out += base::render(d) + "\n";
  return out;
}

double terminal_volume(const lang::cga::Program& program, const lang::cga::LotResult& r) {
  double volume = 0;
  for (std::size_t i = 0; i < r.terminals_store.size(); ++i) {
    const lang::cga::Terminal& t = r.terminals_store[i];
    const lang::cga::Geometry& g = r.geometry[t.geometry];
    if (g.mesh) volume += kernel::volume(*g.mesh);
  }
  (void)program;
  return volume;
}

TEST(RegistryFrontEnds, AmendmentWasAppliedBeforeTheTableWasBuilt) {
  ASSERT_TRUE(kAmended);
  shape::registry();
  EXPECT_FALSE(shape::extend_registry(amend));  // the table is built now: too late
  ASSERT_NE(shape::registry().find("test_plinth"), nullptr);
  ASSERT_NE(shape::registry().find("roof")->param("test_cap"), nullptr);
}

TEST(RegistryFrontEnds, NewParameterIsAnArgumentOfEveryCgaRoofSpelling) {
  const auto* hip = lang::cga::find_operation("roofHip");
  ASSERT_NE(hip, nullptr);
  // After roof's own height, closed and thickness.
  EXPECT_EQ(hip->signature, "n|nn|nnn|nnnb|nnnbn|nnnbnn");
  EXPECT_EQ(hip->max_args, 6);
  EXPECT_EQ(cga_check("Lot --> roofHip(30, 0, 0, false, 0, 0.5) Roof\n"), "");
  EXPECT_EQ(cga_check("Lot --> roofHip(30, 0, 0, false, 0, 2) Roof\n"),
            "t.cga:1:37: error[CGA319]: argument 6 of 'roofHip' (test_cap) is 2, must be in "
            "[0, 1]\n");
  EXPECT_EQ(cga_check("Lot --> roofMansard(60, 70, 2, 0, 0, false, 0, 0.5, 1) Roof\n"),
            "t.cga:1:9: error[CGA312]: 'roofMansard' expects 1 to 8 arguments, found 9\n");
}

TEST(RegistryFrontEnds, NewParameterReachesTheOperationFromCga) {
  caps_seen().clear();
  auto program =
      lang::cga::testing::compile_text("Lot --> roofGable(40, 0, 0, false, 0, 0.25) Roof\n");
  ASSERT_NE(program, nullptr);
  const auto results =
      lang::cga::testing::derive_all(*program, {lang::cga::testing::rectangle_lot(10, 8)});
  ASSERT_TRUE(results[0].ok) << lang::cga::testing::diagnostics_text(results[0]);
  EXPECT_EQ(caps_seen(), std::vector<double>{0.25});
}

TEST(RegistryFrontEnds, NewParameterReachesTheOperationFromLua) {
  caps_seen().clear();
  const auto r = lua::testing::run(R"lua(
    local lot = component{polygon={{0, 0}, {10, 0}, {10, 8}, {0, 8}}}
    roof(lot, "hip", 30, {test_cap=0.75})
    roof(component{polygon={{0, 0}, {10, 0}, {10, 8}, {0, 8}}}, "hip", 30, 0, 70, 2.5, 0, false, 0, 0.5)
  )lua");
  ASSERT_TRUE(r.ok()) << r.error();
  EXPECT_EQ(caps_seen(), (std::vector<double>{0.75, 0.5}));
  const auto bad = lua::testing::run(R"lua(
    roof(component{polygon={{0, 0}, {10, 0}, {10, 8}, {0, 8}}}, "hip", 30, {test_cap=3})
  )lua");
  EXPECT_EQ(bad.error(),
            "test.lua:2:5: error[LUA003]: in roof: parameter 'test_cap' must be <= 1; got 3");
}

TEST(RegistryFrontEnds, NewOperationIsCheckedAndRunByCga) {
  EXPECT_EQ(cga_check("Lot --> test_plinth(2, in) Plinth\n"), "");
  EXPECT_EQ(cga_check("Lot --> test_plinth(5) Plinth\n"),
            "t.cga:1:21: error[CGA319]: argument 1 of 'test_plinth' (height) is 5, must be in "
            "[0.1, 3]\n");
  EXPECT_EQ(cga_check("Lot --> test_plinth(1, \"up\") Plinth\n"),
            "t.cga:1:24: error[CGA319]: argument 2 of 'test_plinth' (side) is \"up\", must be one "
            "of in, out\n");
  EXPECT_EQ(cga_check("Lot --> test_plinth() Plinth\n"),
            "t.cga:1:9: error[CGA312]: 'test_plinth' expects 1 to 2 arguments, found 0\n");
  auto program = lang::cga::testing::compile_text("Lot --> test_plinth(2) Plinth\n");
  ASSERT_NE(program, nullptr);
  const auto results =
      lang::cga::testing::derive_all(*program, {lang::cga::testing::rectangle_lot(10, 8)});
  ASSERT_TRUE(results[0].ok) << lang::cga::testing::diagnostics_text(results[0]);
  EXPECT_EQ(lang::cga::testing::symbol_count(*program, results[0], "Plinth"), 1U);
  EXPECT_NEAR(terminal_volume(*program, results[0]), 160.0, 1e-9);
}

TEST(RegistryFrontEnds, NewOperationIsCheckedAndRunByLua) {
  const auto r = lua::testing::run(R"lua(
    local lot = component{polygon={{0, 0}, {10, 0}, {10, 8}, {0, 8}}}
    print(test_plinth(lot, 2, "in")[1].volume)
  )lua");
  ASSERT_TRUE(r.ok()) << r.error();
  EXPECT_EQ(r.printed, std::vector<std::string>{"160.0"});
  const auto bad = lua::testing::run(R"lua(
    test_plinth(component{polygon={{0, 0}, {10, 0}, {10, 8}, {0, 8}}}, 5)
  )lua");
  EXPECT_EQ(bad.error(),
            "test.lua:2:5: error[LUA003]: in test_plinth: parameter 'height' must be <= 3; got 5");
}

}  // namespace
}  // namespace insula
