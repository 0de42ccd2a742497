// The derivation engine (seed 004 §II): rule selection by priority and condition, probabilities,
// ε, terminals, successor semantics, attributes, limits and diagnostics.
#include <gtest/gtest.h>

#include <algorithm>

#include "derive_util.h"
#include "lang/cga/derive.h"
#include "shape/collect.h"
#include "shape/ops.h"

namespace insula::lang::cga {
namespace {

using testing::compile_text;
using testing::derive_all;
using testing::diagnostics_text;
using testing::rectangle_lot;
using testing::symbol_count;

TEST(Derive, SplitsALotIntoTerminals) {
  auto p = compile_text(R"(
Lot --> split("x"){ 4: A | ~1: B | 4: A }
B --> split("y"){ 2: C | 3: ε }
)");
  ASSERT_TRUE(p);
  const auto r = derive_all(*p, {rectangle_lot(20, 5)});
  ASSERT_TRUE(r[0].ok) << diagnostics_text(r[0]);
  // Terminals in emission order; B's pieces after the A's because B waits for its own rule.
  EXPECT_EQ(dump_derivation(*p, r),
            "shapes 5\nterminals 3\nrule_applications 2\nsymbol A 2\nsymbol B 1\nsymbol C 1\n"
            "symbol Lot 1\nlot 0 shapes 5 terminals 3\n"
            "  A rect at 0 0 0 size 4 5 0\n"
            "  A rect at 16 0 0 size 4 5 0\n"
            "  C rect at 4 0 0 size 12 2 0\n");
}

TEST(Derive, PaperRelativeSizesShareTheRemainder) {
  // §II: Subdiv("X",2,1r,1r,2){ B | A | A | B } on a 10 m floor: 2 | 3 | 3 | 2.
  auto p = compile_text(R"(1: floor ~> Subdiv("X", 2, 1r, 1r, 2){ B | A | A | B })");
  ASSERT_TRUE(p);
  const auto r = derive_all(*p, {rectangle_lot(10, 4)});
  ASSERT_TRUE(r[0].ok);
  ASSERT_EQ(r[0].terminals_store.size(), 4U);
  const double widths[] = {2, 3, 3, 2};
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_DOUBLE_EQ(r[0].terminals_store[i].scope.size.x, widths[i]);
  }
  // CityEngine's ' is a fraction of the scope: '0.25 of 10 m.
  auto q = compile_text(R"(L --> split("x"){ '0.25: A | ~1: B })");
  const auto s = derive_all(*q, {rectangle_lot(10, 4)});
  EXPECT_DOUBLE_EQ(s[0].terminals_store[0].scope.size.x, 2.5);
  EXPECT_DOUBLE_EQ(s[0].terminals_store[1].scope.size.x, 7.5);
}

TEST(Derive, NestedRepeatPatternsFillTheRest) {
  // 1 + n * (~2.5 + 0.4) + 1 over 20 m: n = floor(18 / 2.9) = 6 tiles of (18 - 2.4) / 6 = 2.6.
  auto p = compile_text(R"(F --> split("x"){ 1: W | { ~2.5: T | 0.4: P }* | 1: W })");
  const auto r = derive_all(*p, {rectangle_lot(20, 3)});
  ASSERT_TRUE(r[0].ok);
  EXPECT_EQ(symbol_count(*p, r[0], "T"), 6U);
  EXPECT_EQ(symbol_count(*p, r[0], "P"), 6U);
  EXPECT_EQ(symbol_count(*p, r[0], "W"), 2U);
  for (std::size_t i = 0; i < r[0].terminals_store.size(); ++i) {
    const Terminal& t = r[0].terminals_store[i];
    if (p->symbol_name(t.symbol) == "T") {
      EXPECT_NEAR(t.scope.size.x, 2.6, 1e-12);
    }
  }
}

TEST(Derive, PrioritiesConditionsAndTerminals) {
  // Level 1 rules of B have false conditions, so B falls to level 2; C has no rule: terminal.
  auto p = compile_text(R"(
PRIORITY 1:
1: Lot ~> split("x"){ 5: B | 5: C }
2: B : Scope.sx > 6 ~> X
PRIORITY 2:
3: B ~> Y
)");
  const auto r = derive_all(*p, {rectangle_lot(10, 10)});
  ASSERT_TRUE(r[0].ok);
  EXPECT_EQ(symbol_count(*p, r[0], "X"), 0U);
  EXPECT_EQ(symbol_count(*p, r[0], "Y"), 1U);
  EXPECT_EQ(r[0].terminals, 2U);  // C and Y
  EXPECT_EQ(r[0].rule_applications, 2U);
  EXPECT_EQ(p->symbol_name(p->start), "Lot");
}

TEST(Derive, EpsilonRemovesAndIsNoTerminal) {
  auto p = compile_text(R"(
Lot --> extrude(6) Mass
Mass --> comp("f"){ top: Roof | bottom: ε | side: Wall }
)");
  const auto r = derive_all(*p, {rectangle_lot(10, 8)});
  ASSERT_TRUE(r[0].ok) << diagnostics_text(r[0]);
  EXPECT_EQ(symbol_count(*p, r[0], "Wall"), 4U);
  EXPECT_EQ(symbol_count(*p, r[0], "Roof"), 1U);
  EXPECT_EQ(r[0].terminals, 5U);
  EXPECT_EQ(r[0].shapes, 7U);  // Lot, Mass, 4 walls, roof
}

TEST(Derive, ProbabilitiesFollowTheShapeSeed) {
  auto p = compile_text(R"(
Lot --> A : 0.5 ~> B : 0.5
)");
  std::vector<Lot> lots;
  for (int i = 0; i < 2000; ++i) lots.push_back(rectangle_lot(1, 1, std::to_string(i)));
  const auto r = derive_all(*p, lots);
  std::uint64_t a = 0;
  for (const LotResult& x : r) a += symbol_count(*p, x, "A");
  EXPECT_GT(a, 900U);
  EXPECT_LT(a, 1100U);
  // Same seed: same choices; another seed: other choices.
  const auto again = derive_all(*p, lots);
  EXPECT_EQ(dump_derivation(*p, r), dump_derivation(*p, again));
  DeriveOptions other;
  other.seed = 7;
  EXPECT_NE(dump_derivation(*p, r), dump_derivation(*p, derive_all(*p, lots, other)));
}

TEST(Derive, LotsAreIndependentOfDerivationOrder) {
  auto p = compile_text(R"(
Lot --> split("x"){ { ~rand(1, 3): T }* }
T --> color(rand(0, 1), 0.5, 0.5) W : 0.3 ~> V : 0.7
)");
  std::vector<Lot> lots;
  for (int i = 0; i < 8; ++i) lots.push_back(rectangle_lot(10 + i, 5, std::to_string(i)));
  const DeriveOptions options;
  std::vector<LotResult> forward = derive_all(*p, lots, options);
  std::vector<LotResult> backward(lots.size());
  for (std::size_t i = lots.size(); i-- > 0;) backward[i] = derive_lot(*p, lots[i], i, options);
  EXPECT_EQ(dump_derivation(*p, forward), dump_derivation(*p, backward));
}

TEST(Derive, AttributesDefaultsLotPropertiesAndSets) {
  auto p = compile_text(R"(
attr height = 5
attr style = "plain"
Lot --> extrude(height) Mass
fancy: Mass : style == "fancy" ~> set(height, 1) Fancy
Mass --> Plain
)");
  Lot lot = rectangle_lot(4, 4);
  auto r = derive_all(*p, {lot});
  ASSERT_TRUE(r[0].ok);
  EXPECT_DOUBLE_EQ(r[0].terminals_store[0].scope.size.y, 5);
  EXPECT_EQ(symbol_count(*p, r[0], "Plain"), 1U);
  lot.properties["height"] = 7.0;
  lot.properties["style"] = std::string("fancy");
  r = derive_all(*p, {lot});
  EXPECT_DOUBLE_EQ(r[0].terminals_store[0].scope.size.y, 7);
  EXPECT_EQ(symbol_count(*p, r[0], "Fancy"), 1U);
  EXPECT_EQ(std::get<double>(r[0].attributes.at("height")), 7.0);
  DeriveOptions options;
  options.sets = {{"height", 9.0}};  // --set wins over the lot property
  r = derive_all(*p, {lot}, options);
  EXPECT_DOUBLE_EQ(r[0].terminals_store[0].scope.size.y, 9);
}

// OpenStreetMap tags are not identifiers: attr building_levels reads `building:levels` (as Esri's
// OSM layers name it); a property of the attr's own name wins, and a null value counts as absent.
TEST(Derive, LotPropertiesMatchAttrsWrittenAsIdentifiers) {
  auto p = compile_text(R"(
attr building_levels = 1
attr roof_shape = "flat"
Lot --> extrude(building_levels * 3) Mass
gabled: Mass : roof_shape == "gabled" ~> Gabled
Mass --> Flat
)");
  Lot lot = rectangle_lot(4, 4);
  lot.properties["building:levels"] = 4.0;
  lot.properties["roof:shape"] = std::string("gabled");
  auto r = derive_all(*p, {lot});
  ASSERT_TRUE(r[0].ok) << diagnostics_text(r[0]);
  EXPECT_DOUBLE_EQ(r[0].terminals_store[0].scope.size.y, 12);
  EXPECT_EQ(symbol_count(*p, r[0], "Gabled"), 1U);
  lot.properties["building_levels"] = 2.0;  // the exact name wins
  r = derive_all(*p, {lot});
  EXPECT_DOUBLE_EQ(r[0].terminals_store[0].scope.size.y, 6);
  lot.properties["building_levels"] = shape::Value{};  // null: absent, and no other spelling
  r = derive_all(*p, {lot});
  EXPECT_DOUBLE_EQ(r[0].terminals_store[0].scope.size.y, 3);
}

// OpenStreetMap heights come with units ("66'", "12 m") or none that parse ("approx. 10"): a
// length is metres; other text keeps the number attr's default with a warning, and the lot is
// still built (one odd tag must not stop a city).
TEST(Derive, NumberAttrsReadLengthsAndWarnOnOtherText) {
  auto p = compile_text("attr height = 5\nLot --> extrude(height) Mass\n");
  Lot lot = rectangle_lot(4, 4);
  lot.properties["height"] = std::string("66'");
  auto r = derive_all(*p, {lot});
  ASSERT_TRUE(r[0].ok) << diagnostics_text(r[0]);
  EXPECT_NEAR(r[0].terminals_store[0].scope.size.y, 66 * 0.3048, 1e-12);
  lot.properties["height"] = std::string("12,5 m");
  r = derive_all(*p, {lot});
  EXPECT_NEAR(r[0].terminals_store[0].scope.size.y, 12.5, 1e-12);
  lot.properties["height"] = std::string("approx. 10");
  r = derive_all(*p, {lot});
  ASSERT_TRUE(r[0].ok) << diagnostics_text(r[0]);
  EXPECT_DOUBLE_EQ(r[0].terminals_store[0].scope.size.y, 5);
  EXPECT_EQ(diagnostics_text(r[0]),
            "test.cga:1:15: warning[CGA604]: lot property 'height' = \"approx. 10\" is not a "
            "number; the default 5 is used\nnote: in lot 'lot'\n");
}

TEST(Derive, PushPopAndInsertionBuildThePaperMassModel) {
  // §II Figure 2: three primitives placed with scope rules and a push/pop pair.
  auto p = compile_text(R"(
1: A ~> [ T(0, 0, 6) S(8, 10, 18) I("cube") ] T(6, 0, 0) S(7, 13, 18) I("cube")
        T(0, 0, 16) S(8, 15, 8) I("cube")
)");
  const auto r = derive_all(*p, {rectangle_lot(20, 30)});
  ASSERT_TRUE(r[0].ok) << diagnostics_text(r[0]);
  ASSERT_EQ(r[0].terminals, 3U);
  const auto& t = r[0].terminals_store;
  EXPECT_EQ(t[0].scope.size, (kernel::Vec3{8, 10, 18}));
  EXPECT_EQ(t[1].scope.size, (kernel::Vec3{7, 13, 18}));
  EXPECT_EQ(t[2].scope.size, (kernel::Vec3{8, 15, 8}));
  // The second cube starts 6 m along x; the third 16 m further along z (world -Y... of the lot
  // frame: scope z of a footprint is world up).
  EXPECT_NEAR(t[1].scope.origin.x, 6, 1e-12);
  EXPECT_NEAR(t[2].scope.origin.z, 16, 1e-12);
  const shape::Scene scene = to_scene(*p, {rectangle_lot(20, 30)}, r);
  ASSERT_EQ(scene.buildings.size(), 1U);
  EXPECT_EQ(scene.buildings[0].parts.size(), 3U);
  EXPECT_EQ(scene.buildings[0].parts[0].mesh.face_count(), 6U);
}

TEST(Derive, AConsumingSceneIsTheSameSceneAndFreesTheRecords) {
  auto p = compile_text(R"(
attr height = 9
Lot --> extrude(height) comp(f) { front: Facade | side: Wall | top: Roof }
Facade --> split(x) { ~3: Window | ~3: Window | ~3: Window }
)");
  const std::vector<Lot> lots{rectangle_lot(20, 12), rectangle_lot(9, 7)};
  std::vector<LotResult> r = derive_all(*p, lots);
  ASSERT_TRUE(r[0].ok && r[1].ok);
  const shape::Scene kept = to_scene(*p, lots, r);
  const shape::Scene consumed = to_scene(*p, lots, std::move(r));
  EXPECT_TRUE(r.empty());  // NOLINT(bugprone-use-after-move): the overload leaves it empty
  ASSERT_EQ(consumed.buildings.size(), kept.buildings.size());
  for (std::size_t b = 0; b < kept.buildings.size(); ++b) {
    const auto& a = kept.buildings[b].parts;
    const auto& c = consumed.buildings[b].parts;
    ASSERT_EQ(c.size(), a.size());
    EXPECT_GT(a.size(), 3U);
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_EQ(c[i].name, a[i].name);
      EXPECT_EQ(c[i].attributes, a[i].attributes);
      EXPECT_EQ(c[i].mesh.positions(), a[i].mesh.positions());
    }
  }
}

TEST(Derive, PrintReportAndColor) {
  auto p = compile_text(R"(
Lot --> print("lot", Scope.sx) split("x"){ 2: A | 3: B }
A --> report("area", Shape.area) color("#FF0000") X
B --> report("area", Shape.area) color(0, 0, 1) Y
)");
  const auto r = derive_all(*p, {rectangle_lot(5, 4)});
  ASSERT_TRUE(r[0].ok) << diagnostics_text(r[0]);
  ASSERT_EQ(r[0].prints.size(), 1U);
  EXPECT_EQ(r[0].prints[0], "test.cga:2: print: lot 5");
  EXPECT_DOUBLE_EQ(r[0].reports.at("area").sum, 20);
  EXPECT_EQ(r[0].reports.at("area").count, 2U);
  const shape::Scene scene = to_scene(*p, {rectangle_lot(5, 4)}, r);
  ASSERT_EQ(scene.buildings[0].parts.size(), 2U);
  const auto& x = scene.buildings[0].parts[0];
  EXPECT_EQ(std::get<std::string>(x.attributes.at("color")), "#ff0000");
  EXPECT_EQ(scene.material_for(x.mesh.tag(0)).rgba[0], 1.0F);
  const auto& y = scene.buildings[0].parts[1];
  EXPECT_EQ(std::get<std::string>(y.attributes.at("color")), "#0000ff");
}

// OpenStreetMap's building:colour is a CSS name as often as a hex code: color() takes both; other
// text is still an error.
TEST(Derive, ColorTakesCssNames) {
  auto p = compile_text(R"(
attr building_colour = "#ffffff"
Lot --> split("x"){ 2: A | 3: B }
A --> color(building_colour) X
B --> color("Dark Slate Grey") Y
)");
  Lot lot = rectangle_lot(5, 4);
  lot.properties["building:colour"] = std::string("light grey");
  const auto r = derive_all(*p, {lot});
  ASSERT_TRUE(r[0].ok) << diagnostics_text(r[0]);
  const shape::Scene scene = to_scene(*p, {lot}, r);
  ASSERT_EQ(scene.buildings[0].parts.size(), 2U);
  EXPECT_EQ(std::get<std::string>(scene.buildings[0].parts[0].attributes.at("color")), "#d3d3d3");
  EXPECT_EQ(std::get<std::string>(scene.buildings[0].parts[1].attributes.at("color")), "#2f4f4f");
  lot.properties["building:colour"] = std::string("brick");
  const auto bad = derive_all(*p, {lot});
  EXPECT_FALSE(bad[0].ok);
  EXPECT_NE(diagnostics_text(bad[0]).find("or a CSS colour name, got \"brick\""), std::string::npos)
      << diagnostics_text(bad[0]);
}

TEST(Derive, DepthLimitNamesTheRule) {
  auto p = compile_text("Lot --> A\nA --> T(0, 0, 0) A\n");
  DeriveOptions options;
  options.limits.max_depth = 50;
  const auto r = derive_all(*p, {rectangle_lot(1, 1)}, options);
  EXPECT_FALSE(r[0].ok);
  EXPECT_EQ(diagnostics_text(r[0]),
            "test.cga:2:1: error[CGA601]: derivation depth limit of 50 reached in rule 'A -->' "
            "(line 2)\nnote: in lot 'lot'\n");
}

TEST(Derive, ShapeLimitNamesTheRule) {
  auto p = compile_text("Lot --> A\nr7: A ~> B B\nr8: B ~> A A\n");
  DeriveOptions options;
  options.limits.max_shapes = 1000;
  const auto r = derive_all(*p, {rectangle_lot(1, 1)}, options);
  EXPECT_FALSE(r[0].ok);
  const std::string text = diagnostics_text(r[0]);
  EXPECT_NE(text.find("error[CGA602]: shape limit of 1000 reached in rule 'r"), std::string::npos)
      << text;
}

TEST(Derive, EvaluationErrorsArePositioned) {
  auto p = compile_text("attr w = 20\nLot --> extrude(1 / (Scope.sx - w)) X\n");
  const auto r = derive_all(*p, {rectangle_lot(20, 5)});
  EXPECT_FALSE(r[0].ok);
  EXPECT_EQ(diagnostics_text(r[0]),
            "test.cga:2:17: error[CGA603]: division by zero\nnote: in rule 'Lot -->' (line 2)\n"
            "note: in lot 'lot'\n");
}

TEST(Derive, FailedOperationsWarnAndKeepTheShape) {
  // extrude needs a flat shape: the second extrude fails, the mass stays as it is.
  auto p = compile_text("Lot --> extrude(3) extrude(2) X\n");
  const auto r = derive_all(*p, {rectangle_lot(4, 4)});
  ASSERT_TRUE(r[0].ok);
  EXPECT_EQ(r[0].terminals, 1U);
  EXPECT_DOUBLE_EQ(r[0].terminals_store[0].scope.size.y, 3);
  EXPECT_EQ(diagnostics_text(r[0]),
            "test.cga:1:20: warning[CGA604]: extrude: needs a flat shape (a footprint or a "
            "face)\nnote: in lot 'lot'\n");
}

TEST(Derive, OcclusionSeesTheOtherShapesOfTheLot) {
  auto p = compile_text(R"(
Lot --> extrude(10) [ S(1r, 1r, 1r) Block ] T(0, 0, 0) S('0.5, '0.5, '0.5) Probe
hidden: Probe : Shape.occ("all") == "full" ~> Hidden
Probe --> Visible
)");
  const auto r = derive_all(*p, {rectangle_lot(10, 10)});
  ASSERT_TRUE(r[0].ok) << diagnostics_text(r[0]);
  EXPECT_EQ(symbol_count(*p, r[0], "Hidden"), 1U);
  EXPECT_EQ(symbol_count(*p, r[0], "Visible"), 0U);
}

TEST(Derive, DefaultLotUsesLotWidthAndDepth) {
  auto p = compile_text("attr lotWidth = 12\nattr lotDepth = 30\nLot --> X\n");
  const Lot lot = default_lot(*p, {});
  ASSERT_EQ(lot.polygons.size(), 1U);
  EXPECT_DOUBLE_EQ(kernel::area(lot.polygons[0]), 360);
  auto q = compile_text("Lot --> X\n");
  EXPECT_DOUBLE_EQ(kernel::area(default_lot(*q, {}).polygons[0]), 400);
}

TEST(Derive, StartShapeFollowsTheInputsFirstEdge) {
  auto p = compile_text("Lot --> X\n");
  Lot lot = rectangle_lot(10, 4);
  auto r = derive_all(*p, {lot});
  EXPECT_EQ(r[0].terminals_store[0].scope.x, (kernel::Vec3{1, 0, 0}));
  // A file that listed the ring clockwise from (10, 4) to (10, 0): after normalisation that edge
  // is (10, 0) -> (10, 4), and the scope's x axis runs along it.
  lot.first_edges = {{kernel::Vec2{10, 4}, kernel::Vec2{10, 0}}};
  r = derive_all(*p, {lot});
  const shape::Scope& s = r[0].terminals_store[0].scope;
  EXPECT_NEAR(s.x.x, 0, 1e-12);
  EXPECT_NEAR(s.x.y, 1, 1e-12);
  EXPECT_NEAR(s.size.x, 4, 1e-12);
  EXPECT_NEAR(s.size.y, 10, 1e-12);
}

TEST(Derive, StartSymbolOption) {
  CompileOptions options;
  options.start = "B";
  auto p = compile_text("A --> X\nB --> Y\n", options);
  const auto r = derive_all(*p, {rectangle_lot(1, 1)});
  EXPECT_EQ(symbol_count(*p, r[0], "Y"), 1U);
  EXPECT_EQ(symbol_count(*p, r[0], "X"), 0U);
}

TEST(Derive, ReportOnlyRunKeepsNoTerminals) {
  auto p = compile_text("Lot --> split(\"x\"){ { ~1: T }* }\n");
  DeriveOptions options;
  options.keep_terminals = false;
  const auto r = derive_all(*p, {rectangle_lot(10, 1)}, options);
  EXPECT_EQ(r[0].terminals, 10U);
  EXPECT_EQ(r[0].terminals_store.size(), 0U);
}

TEST(Derive, PaperBasicSplitAlongTwoAxes) {
  // §VI's example exactly as written: BS along "XY" is a nested split, the sizes 3, 5, 7 divide
  // x, each piece is divided along y by the same sizes, and successor i gets every cell of the
  // i-th x piece (docs/cga-language.md, Decisions). On a 15 x 15 m lot: 9 cells.
  auto p = compile_text(R"(6: front ~> BS( "XY", 3, 5, 7){ balcony| floor| door})");
  ASSERT_TRUE(p);
  const auto r = derive_all(*p, {rectangle_lot(15, 15)});
  ASSERT_TRUE(r[0].ok) << diagnostics_text(r[0]);
  EXPECT_EQ(dump_derivation(*p, r),
            "shapes 10\nterminals 9\nrule_applications 1\nsymbol balcony 3\nsymbol door 3\n"
            "symbol floor 3\nsymbol front 1\nlot 0 shapes 10 terminals 9\n"
            "  balcony rect at 0 0 0 size 3 3 0\n"
            "  balcony rect at 0 3 0 size 3 5 0\n"
            "  balcony rect at 0 8 0 size 3 7 0\n"
            "  floor rect at 3 0 0 size 5 3 0\n"
            "  floor rect at 3 3 0 size 5 5 0\n"
            "  floor rect at 3 8 0 size 5 7 0\n"
            "  door rect at 8 0 0 size 7 3 0\n"
            "  door rect at 8 3 0 size 7 5 0\n"
            "  door rect at 8 8 0 size 7 7 0\n");
}

TEST(Derive, BasicSplitAlongThreeAxesResolvesSizesPerAxis) {
  // Relative sizes resolve against each axis' own extent. A mass's scope has y up (scope.h), so
  // the 10 x 6 lot extruded by 4 has scope 10 x 4 x 6: x 10 -> 7 | 3, y 4 -> 1 | 3,
  // z 6 -> 3 | 3. Successor A gets the 4 cells of the first x piece, B those of the second.
  auto p = compile_text("Lot --> extrude(4) M\nM --> BS(\"XYZ\", 1r, 3){ A | B }\n");
  ASSERT_TRUE(p);
  const auto r = derive_all(*p, {rectangle_lot(10, 6)});
  ASSERT_TRUE(r[0].ok) << diagnostics_text(r[0]);
  EXPECT_EQ(r[0].terminals, 8U);
  EXPECT_EQ(symbol_count(*p, r[0], "A"), 4U);
  EXPECT_EQ(symbol_count(*p, r[0], "B"), 4U);
  ASSERT_EQ(r[0].terminals_store.size(), 8U);
  double volume_a = 0;
  double volume_b = 0;
  for (std::size_t i = 0; i < 8; ++i) {
    const Terminal& t = r[0].terminals_store[i];
    const double v = t.scope.size.x * t.scope.size.y * t.scope.size.z;
    const bool a = p->symbol_name(t.symbol) == "A";
    EXPECT_DOUBLE_EQ(t.scope.size.x, a ? 7 : 3);
    EXPECT_TRUE(t.scope.size.y == 1 || t.scope.size.y == 3) << t.scope.size.y;
    EXPECT_DOUBLE_EQ(t.scope.size.z, 3);
    (a ? volume_a : volume_b) += v;
  }
  EXPECT_DOUBLE_EQ(volume_a, 7 * 6 * 4);
  EXPECT_DOUBLE_EQ(volume_b, 3 * 6 * 4);
}

TEST(Derive, ComputedProbabilityOutsideZeroOneIsAnError) {
  // Seed 004 §IV.B constraint 1 for values only known while deriving (CGA605), not a weight
  // silently clamped to 0.
  auto p = compile_text("attr p = -0.25\nr1: Lot ~> A : (p) ~> B : (1 - p)\n");
  ASSERT_TRUE(p);
  auto r = derive_all(*p, {rectangle_lot(1, 1)});
  EXPECT_FALSE(r[0].ok);
  EXPECT_EQ(diagnostics_text(r[0]),
            "test.cga:2:17: error[CGA605]: the probability of rule 'r1' (line 2) evaluates to "
            "-0.25, not a number in [0, 1] (seed 004 §IV.B, constraint 1)\nnote: in lot 'lot'\n");
  // Above 1 from a shape attribute (10 m / 4 = 2.5).
  p = compile_text("Lot --> A : (Scope.sx / 4) ~> B\n");
  r = derive_all(*p, {rectangle_lot(10, 1)});
  EXPECT_FALSE(r[0].ok);
  EXPECT_EQ(diagnostics_text(r[0]),
            "test.cga:1:14: error[CGA605]: the probability of rule 'Lot -->' (line 1) evaluates "
            "to 2.5, not a number in [0, 1] (seed 004 §IV.B, constraint 1)\nnote: in lot 'lot'\n");
  // Checked when the rule has a single part too.
  p = compile_text("attr q = 3\nLot --> A : (q)\n");
  r = derive_all(*p, {rectangle_lot(1, 1)});
  EXPECT_FALSE(r[0].ok);
  EXPECT_NE(diagnostics_text(r[0]).find("error[CGA605]"), std::string::npos);
  // 0 is a valid value: it switches an alternative off.
  p = compile_text("attr p = 0\nLot --> A : (p) ~> B : (1 - p)\n");
  std::vector<Lot> lots;
  for (int i = 0; i < 50; ++i) lots.push_back(rectangle_lot(1, 1, std::to_string(i)));
  r = derive_all(*p, lots);
  std::uint64_t b = 0;
  for (const LotResult& x : r) {
    EXPECT_TRUE(x.ok);
    b += symbol_count(*p, x, "B");
  }
  EXPECT_EQ(b, 50U);
}

}  // namespace
}  // namespace insula::lang::cga
