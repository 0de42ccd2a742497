// CityEngine's dialect of CGA (issue 20): the second reader, its checks, its derivation and
// imports. Rule texts here are our own, written in the style of the real files the dialect page
// counts (docs/cityengine-dialect.md).
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "base/text_encoding.h"
#include "derive_util.h"
#include "lang/cga/annotations.h"
#include "lang/cga/ast_dump.h"
#include "lang/cga/checker.h"
#include "lang/cga/cityengine_names.h"
#include "lang/cga/imports.h"
#include "lang/cga/operations.h"
#include "lang/cga/printer.h"
#include "shape/geometry_queries.h"
#include "test_util.h"

namespace insula::lang::cga {
namespace {

using testing::check_text;
using testing::compile_text;
using testing::derive_all;
using testing::diagnostics_text;
using testing::rectangle_lot;
using testing::symbol_count;

constexpr const char* kHouse = R"(version "2019.0"
/** File: house.cga */
@Group("Mass", 1) @Order(1) @Range(min = 3, max = 30)
attr height = 12
@Enum("flat", "hip") @Description("roof form")
attr roofType = "hip"
const floorH = 3.5
tileW(n) = scope.sx / n

@StartRule
Lot -->
	extrude(world.up, height)
	comp(f) { top = Roof | side : Facade(split.index) | bottom : NIL }

Roof -->
	case roofType == "hip" : roofHip(30) RoofTiles.
	else : RoofFlat.

Facade(idx) -->
	split(y) { ~floorH : Floor(idx) }*

Floor(i) -->
	case scope.sx < 4 : Wall.
	else :
		split(x) { ~2 : 30% : Window else : Wall. | 1 : Wall. }*
Window --> color("#334455") Glass.
)";

Grammar parse_ok(const std::string& text, const std::string& name = "house.cga") {
  const base::Source source(name, text);
  base::Result<Grammar> g = parse(source);
  EXPECT_TRUE(g.ok()) << (g.diagnostics().empty() ? "" : base::render(g.diagnostics().front()));
  return g.ok() ? std::move(g.value()) : Grammar{};
}

TEST(CityEngineDialect, IsDetectedFromWhatSeed004Lacks) {
  EXPECT_EQ(parse_ok(kHouse).dialect, Dialect::kCityEngine);
  EXPECT_EQ(parse_ok("Lot --> extrude(3) A\n").dialect, Dialect::kSeed004);
  EXPECT_EQ(parse_ok("Lot --> extrude(3) A.\n").dialect, Dialect::kCityEngine);
  EXPECT_EQ(parse_ok("f(x) = x * 2\nLot --> extrude(f(2)) A\n").dialect, Dialect::kCityEngine);
  EXPECT_EQ(parse_ok("1: Lot ~> extrude(3) A\n").dialect, Dialect::kSeed004);
}

TEST(CityEngineDialect, KeepsEveryDeclarationAndAnnotation) {
  const base::Source source("house.cga", kHouse);
  const Grammar g = parse_ok(kHouse);
  EXPECT_EQ(g.version, "2019.0");
  ASSERT_EQ(g.attrs.size(), 2U);
  ASSERT_EQ(g.attrs[0].annotations.size(), 3U);
  EXPECT_EQ(g.attrs[0].annotations[2].name, "Range");
  EXPECT_EQ(g.attrs[0].annotations[2].keys, (std::vector<std::string>{"min", "max"}));
  ASSERT_EQ(g.functions.size(), 2U);
  EXPECT_TRUE(g.functions[0].is_const);
  EXPECT_EQ(g.functions[1].params, std::vector<std::string>{"n"});
  const std::string dump_text = dump(g, source);
  // The `=` branch, the parameters, the chains and the terminals.
  EXPECT_NE(dump_text.find("(merged-key top)"), std::string::npos) << dump_text;
  EXPECT_NE(dump_text.find("(rule _ @19:1 (pred Facade) (params idx)"), std::string::npos)
      << dump_text;
  EXPECT_NE(dump_text.find("(case @16:"), std::string::npos) << dump_text;
  EXPECT_NE(dump_text.find("(chance @25:"), std::string::npos) << dump_text;
  EXPECT_NE(dump_text.find("(sym RoofTiles. @16:"), std::string::npos) << dump_text;
  // extrude(world.up, h) is run as extrude(h) (docs/cityengine-dialect.md, Differences).
  EXPECT_NE(dump_text.find("(op extrude @12:2 (height))"), std::string::npos) << dump_text;
}

TEST(CityEngineDialect, PrintsBackToTheSameModel) {
  const base::Source source("house.cga", kHouse);
  const Grammar g = parse_ok(kHouse);
  const std::string printed = print(g);
  const base::Source again("printed.cga", printed);
  base::Result<Grammar> reparsed = parse(again);
  ASSERT_TRUE(reparsed.ok()) << printed << base::render(reparsed.diagnostics().front());
  // Same model apart from positions.
  const auto strip = [](std::string text) {
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
      if (text[i] == '@' && i + 1 < text.size() && std::isdigit(text[i + 1])) {
        while (i + 1 < text.size() && text[i + 1] != ' ' && text[i + 1] != ')') ++i;
        continue;
      }
      out += text[i];
    }
    return out;
  };
  const auto body = [&](const std::string& text) { return strip(text.substr(text.find('\n'))); };
  EXPECT_EQ(body(dump(reparsed.value(), again)), body(dump(g, source))) << printed;
}

TEST(CityEngineDialect, ChecksWhatTheDialectAdds) {
  EXPECT_EQ(check_text("Lot --> A(1, 2)\nA(x) --> B.\n"),
            "t.cga:1:9: error[CGA331]: rule 'A' takes 1 parameter, called with 2\n");
  EXPECT_EQ(check_text("Lot --> 60% : A. 50% : B. else : C.\n"),
            "t.cga:1:9: error[CGA332]: the percentages sum to 110, more than 100\n");
  EXPECT_EQ(check_text("Lot --> case scope.sx > 3 : A.\n"),
            "t.cga:2:1: error[CGA111]: expected 'else :' to end the 'case' chain, found end of "
            "file\n");
  EXPECT_EQ(check_text("Lot --> taper(5) A.\n"),
            "t.cga:1:9: error[CGA901]: CityEngine operation 'taper' is not supported\n");
  EXPECT_EQ(check_text("Lot --> envelope(world.up, 30, 12, 45) A.\n"), "");  // a registry op now
  EXPECT_EQ(check_text("attr y = readTextFile(\"a.txt\")\nLot --> print(y) A.\n"),
            "t.cga:1:10: error[CGA902]: CityEngine function 'readTextFile' is not supported\n");
  EXPECT_EQ(check_text("Lot --> softenNormals(30) A.\n"),
            "t.cga:1:9: warning[CGA903]: CityEngine operation 'softenNormals' is not supported "
            "yet; it is skipped (the model lacks only that detail)\n");
  EXPECT_EQ(check_text("Lot --> projectUV(0) A.\n"), "");  // a registry operation now
  EXPECT_EQ(check_text("@Colour\nattr c = \"#ff0000\"\nLot --> color(c) A.\n"),
            "t.cga:1:1: warning[CGA430]: unknown annotation '@Colour' (kept, no effect)\n");
  EXPECT_EQ(check_text("f(a) = a\nLot --> extrude(f) A.\n"),
            "t.cga:2:17: error[CGA312]: function 'f' takes 1 argument, found none\n");
}

TEST(CityEngineDialect, UnsupportedTablesNameNoOperationInsulaHas) {
  // A name the registry (or CGA) runs must not be reported as unsupported or skipped.
  for (std::string_view name : kUnsupportedOperations) {
    EXPECT_EQ(find_operation(name), nullptr) << name;
  }
  for (std::string_view name : kDetailOperations) EXPECT_EQ(find_operation(name), nullptr) << name;
  for (std::string_view name : kUnsupportedFunctions) {
    EXPECT_EQ(find_function(name), nullptr) << name;
    if (name.starts_with("geometry.")) {
      EXPECT_EQ(shape::find_geometry_query(name.substr(9)), nullptr) << name;
    }
  }
}

TEST(CityEngineDialect, StartsFromTheMarkedStartRule) {
  const base::Source source("t.cga", "Helper --> A.\n@StartRule\nBuilding --> Helper\n");
  base::Result<Grammar> g = parse(source);
  ASSERT_TRUE(g.ok());
  EXPECT_EQ(check(g.value(), source).start_symbol, "Building");
  // Without @StartRule or Lot: the first rule no other rule calls.
  const base::Source roots("t.cga", "version \"2019.0\"\nWall --> X.\nHouse --> extrude(3) Wall\n");
  base::Result<Grammar> h = parse(roots);
  ASSERT_TRUE(h.ok());
  EXPECT_EQ(check(h.value(), roots).start_symbol, "House");
  // A file of constants only is a library others import, as in CityEngine: a warning, no start.
  EXPECT_EQ(check_text("version \"2023.1\"\nconst floorH = 3.2\n"),
            "t.cga: warning[CGA433]: the file has no rules: none can start a derivation\n");
}

TEST(CityEngineDialect, DerivesCasesParametersFunctionsAndTerminals) {
  CompileOptions lot_start;
  lot_start.start = "Lot";
  auto p = compile_text(kHouse, lot_start);
  ASSERT_TRUE(p);
  DeriveOptions options;
  const auto r = derive_all(*p, {rectangle_lot(12, 10)}, options);
  ASSERT_TRUE(r[0].ok) << diagnostics_text(r[0]);
  // extrude 12, floors of about 3.5 m: 3 per facade, 4 facades; a hip roof.
  EXPECT_EQ(symbol_count(*p, r[0], "Floor/1"), 12U);  // Floor(i): one parameter
  EXPECT_EQ(symbol_count(*p, r[0], "RoofTiles"), 1U);
  EXPECT_EQ(symbol_count(*p, r[0], "RoofFlat"), 0U);
  // Each tile is a Window (30%) or a Wall; every Window ends in Glass.
  const std::uint64_t windows = symbol_count(*p, r[0], "Window");
  EXPECT_EQ(symbol_count(*p, r[0], "Glass"), windows);
  EXPECT_GT(windows, 0U);
  EXPECT_GT(symbol_count(*p, r[0], "Wall"), windows);
}

TEST(CityEngineDialect, PercentagesFollowTheirWeights) {
  auto p = compile_text("Lot --> split(x) { 1 : Tile }*\nTile --> 30% : A. 20% : B. else : C.\n");
  ASSERT_TRUE(p);
  const auto r = derive_all(*p, {rectangle_lot(2000, 1)});
  ASSERT_TRUE(r[0].ok) << diagnostics_text(r[0]);
  const double a = static_cast<double>(symbol_count(*p, r[0], "A"));
  const double b = static_cast<double>(symbol_count(*p, r[0], "B"));
  const double c = static_cast<double>(symbol_count(*p, r[0], "C"));
  EXPECT_EQ(a + b + c, 2000);
  EXPECT_NEAR(a / 2000, 0.3, 0.04);
  EXPECT_NEAR(b / 2000, 0.2, 0.04);
  EXPECT_NEAR(c / 2000, 0.5, 0.04);
}

TEST(CityEngineDialect, RuleArgumentsReachTheRule) {
  // Each piece gets its own index; the rule reads it to choose a height.
  auto p = compile_text(R"(Lot --> split(x) { 2 : Part(split.index) }*
Part(i) --> extrude(h(i)) Mass.
h(i) = case i == 0 : 3 else : 3 + i * 2
)");
  ASSERT_TRUE(p);
  const auto r = derive_all(*p, {rectangle_lot(6, 2)}, [] {
    DeriveOptions o;
    o.keep_terminals = true;
    return o;
  }());
  ASSERT_TRUE(r[0].ok) << diagnostics_text(r[0]);
  std::vector<double> heights;
  for (std::size_t i = 0; i < r[0].terminals_store.size(); ++i) {
    heights.push_back(r[0].terminals_store[i].scope.size.y);  // y along the extrusion
  }
  ASSERT_EQ(heights.size(), 3U);
  EXPECT_NEAR(heights[0], 3, 1e-9);
  EXPECT_NEAR(heights[1], 5, 1e-9);
  EXPECT_NEAR(heights[2], 7, 1e-9);
}

TEST(CityEngineDialect, EndlessRecursionInAFunctionIsAnError) {
  auto p = compile_text("f(x) = f(x + 1)\nLot --> extrude(f(0)) A.\n");
  ASSERT_TRUE(p);
  const auto r = derive_all(*p, {rectangle_lot(4, 4)});
  EXPECT_FALSE(r[0].ok);
  EXPECT_NE(diagnostics_text(r[0]).find("error[CGA603]: function 'f' nested 200 calls deep"),
            std::string::npos)
      << diagnostics_text(r[0]);
}

TEST(CityEngineDialect, StringAndListFunctions) {
  auto p = compile_text(R"(attr l = "oak;elm;fir;"
Lot --> print(listSize(l), listItem(l, 1), listIndex(l, "fir"), listRange(l, 1, 3),
              find("a.b.c", ".", 1), substring("window", 1, 4), count("abab", "ab"),
              replace("a-b-c", "-", "+"), getPrefix("door.obj", "."),
              getSuffix("a/b/door.obj", "/")) A.
)");
  ASSERT_TRUE(p);
  const auto r = derive_all(*p, {rectangle_lot(4, 4)});
  ASSERT_TRUE(r[0].ok) << diagnostics_text(r[0]);
  ASSERT_EQ(r[0].prints.size(), 1U);
  EXPECT_EQ(r[0].prints[0], "test.cga:2: print: 3 elm 2 elm;fir; 3 ind 2 a+b+c door door.obj");
}

TEST(CityEngineDialect, AnnotationsBoundAttributeValues) {
  const Grammar g = parse_ok(kHouse);
  const AttrDecl& height = g.attrs[0];  // @Range(min = 3, max = 30)
  const AttrDecl& roof = g.attrs[1];    // @Enum("flat", "hip")
  EXPECT_FALSE(annotation_violation(height, shape::Value{12.0}));
  EXPECT_EQ(annotation_violation(height, shape::Value{31.0}).value_or(""),
            "outside @Range 3 .. 30");
  EXPECT_FALSE(annotation_violation(roof, shape::Value{std::string("flat")}));
  EXPECT_EQ(annotation_violation(roof, shape::Value{std::string("dome")}).value_or(""),
            "not one of @Enum \"flat\", \"hip\"");
  const Grammar loose = parse_ok("@Range(min = 0, max = 1, restricted = false)\nattr a = 0.5\n");
  EXPECT_FALSE(annotation_violation(loose.attrs[0], shape::Value{7.0}));
}

TEST(CityEngineDialect, CompSelIsTheSelectorThatTookTheShape) {
  auto p = compile_text(
      "Lot --> extrude(6) comp(f) { front : F | side : F | top : F. | bottom : NIL }\n"
      "F --> print(comp.sel) X.\n");
  ASSERT_TRUE(p);
  const auto r = derive_all(*p, {rectangle_lot(10, 8)});
  ASSERT_TRUE(r[0].ok) << diagnostics_text(r[0]);
  std::map<std::string, int> seen;
  for (const std::string& line : r[0].prints) ++seen[line.substr(line.rfind(' ') + 1)];
  EXPECT_EQ(seen, (std::map<std::string, int>{{"front", 1}, {"side", 3}}));
}

TEST(CityEngineDialect, CompInsideAndBorderAfterAnOffset) {
  // The courtyard is inside, the ring's faces border; report() sums the ring's area.
  auto p = compile_text(
      "Lot --> offset(-3) comp(f) { inside : Court. | border : Wing }\n"
      "Wing --> report(\"ring\", geometry.area()) W.\n");
  ASSERT_TRUE(p);
  const auto r = derive_all(*p, {rectangle_lot(10, 10)});
  ASSERT_TRUE(r[0].ok) << diagnostics_text(r[0]);
  EXPECT_EQ(symbol_count(*p, r[0], "Court"), 1U);
  ASSERT_TRUE(r[0].reports.count("ring"));
  EXPECT_NEAR(r[0].reports.at("ring").sum, 100 - 16, 1e-6);
}

TEST(CityEngineDialect, NegativeExtrusionGoesBehindTheFace) {
  auto p = compile_text("version \"2019.0\"\nLot --> extrude(-2) Slab.\n");
  ASSERT_TRUE(p);
  DeriveOptions options;
  options.keep_terminals = true;
  const auto r = derive_all(*p, {rectangle_lot(6, 4)}, options);
  ASSERT_TRUE(r[0].ok) << diagnostics_text(r[0]);
  ASSERT_EQ(r[0].terminals_store.size(), 1U);
  const shape::Scope& scope = r[0].terminals_store[0].scope;
  EXPECT_NEAR(scope.size.y, 2, 1e-9);     // the extrusion axis
  EXPECT_NEAR(scope.origin.z, -2, 1e-9);  // from 2 m below the lot up to it
}

// An L of two 8 m wide arms, 20 by 16 m.
Lot l_lot() {
  Lot lot = rectangle_lot(20, 16, "l");
  lot.polygons.front().outer = {{0, 0}, {20, 0}, {20, 8}, {8, 8}, {8, 16}, {0, 16}};
  return lot;
}

TEST(CityEngineDialect, RoofEdgesByClass) {
  auto p = compile_text(
      "Lot --> extrude(6) comp(f) { top : Top | side : W. }\n"
      "Top --> roofHip(30) comp(e) { ridge : R | hip : H | eave : E | valley : V }\n"
      "R --> report(\"ridge\", scope.sx)\nH --> report(\"hip\", scope.sx)\n"
      "E --> report(\"eave\", scope.sx)\nV --> report(\"valley\", scope.sx)\n");
  ASSERT_TRUE(p);
  const auto r = derive_all(*p, {rectangle_lot(20, 10), l_lot()});
  ASSERT_TRUE(r[0].ok && r[1].ok) << diagnostics_text(r[0]) << diagnostics_text(r[1]);
  // 20 x 10 at 30 degrees: a 10 m ridge, four hips from 5 m in and 5 tan 30 up, the perimeter.
  const double hip = std::sqrt(50 + 25.0 / 3);
  const auto& rect = r[0].reports;
  EXPECT_EQ(rect.at("ridge").count, 1U);
  EXPECT_NEAR(rect.at("ridge").sum, 10, 1e-6);
  EXPECT_EQ(rect.at("hip").count, 4U);
  EXPECT_NEAR(rect.at("hip").sum, 4 * hip, 1e-6);
  EXPECT_NEAR(rect.at("eave").sum, 60, 1e-6);
  EXPECT_EQ(rect.count("valley"), 0U);
  // The L (arms 8 m wide): one valley at the inner corner, five hips, two ridges, six eaves.
  const auto& l = r[1].reports;
  EXPECT_EQ(l.at("valley").count, 1U);
  EXPECT_EQ(l.at("hip").count, 5U);
  EXPECT_EQ(l.at("ridge").count, 2U);
  EXPECT_EQ(l.at("eave").count, 6U);
  EXPECT_NEAR(l.at("eave").sum, 72, 1e-6);
  // The comp function takes the same classes: one value per edge of the hip roof.
  auto values = compile_text(
      "version \"2024.0\"\nLot --> extrude(6) comp(f) { top : Top }\n"
      "Top --> roofHip(30) print(comp(e) { ridge : 1 | hip : 2 | eave : 3 })\n");
  ASSERT_TRUE(values);
  const auto v = derive_all(*values, {rectangle_lot(20, 10)});
  ASSERT_TRUE(v[0].ok) << diagnostics_text(v[0]);
  ASSERT_EQ(v[0].prints.size(), 1U);
  EXPECT_NE(v[0].prints[0].find("(9)[3,3,2,3,2,3,2,2,1]"), std::string::npos) << v[0].prints[0];
}

TEST(CityEngineDialect, WorldAndObjectSelectors) {
  // A lot whose first edge runs north: its object front faces east, whatever the world says.
  auto p = compile_text(
      "version \"2024.0\"\n"
      "Lot --> extrude(6) [ comp(f) { world.up : U } ] [ comp(f) { world.west : W } ]\n"
      "  [ comp(f) { object.front : F } ] comp(f) { world.side : S }\n"
      "U --> report(\"up\", geometry.area())\nW --> report(\"west\", scope.tx)\n"
      "F --> report(\"object front\", scope.tx)\nS --> report(\"side\", 1)\n");
  ASSERT_TRUE(p);
  Lot lot;
  lot.id = "north";
  lot.polygons.push_back({{{0, 0}, {0, 10}, {-8, 10}, {-8, 0}}, {}});
  const auto r = derive_all(*p, {lot});
  ASSERT_TRUE(r[0].ok) << diagnostics_text(r[0]);
  const auto& reports = r[0].reports;
  EXPECT_EQ(reports.at("up").count, 1U);
  EXPECT_NEAR(reports.at("up").sum, 80, 1e-9);
  EXPECT_EQ(reports.at("west").count, 1U);
  // scope.tx is in the object's coordinates: x runs north from the lot's CityEngine origin,
  // and the west face starts at its north end.
  EXPECT_NEAR(reports.at("west").sum, 10, 1e-9);
  EXPECT_EQ(reports.at("object front").count, 1U);
  EXPECT_NEAR(reports.at("object front").sum, 0, 1e-9);
  EXPECT_EQ(reports.at("side").count, 4U);
}

TEST(CityEngineDialect, ALotHasItsNormalOnY) {
  // CityEngine's lot: scope y is the normal (sy = 0), z runs from the far side of Insula's y;
  // t, s and split name those axes; a façade from comp keeps y up its face.
  auto p = compile_text(
      "version \"2019.0\"\n"
      "Lot --> report(\"lot sy\", scope.sy) report(\"lot sz\", scope.sz)\n"
      "  split(z) { 4 : Front | ~1 : Back }\n"
      "Front --> report(\"front tz\", scope.tz) t(0, 2, 0) s('0.5, 0, '1) Raised\n"
      "Raised --> report(\"raised ty\", scope.ty) report(\"raised sx\", scope.sx)\n"
      "  extrude(3) comp(f) { front : Face }\n"
      "Face --> report(\"face sy\", scope.sy) split(y) { 1 : Band. | ~1 : Rest. }\n"
      "Back --> report(\"back tz\", scope.tz) report(\"back sz\", scope.sz)\n");
  ASSERT_TRUE(p);
  DeriveOptions options;
  options.keep_terminals = true;
  const auto r = derive_all(*p, {rectangle_lot(20, 10)}, options);
  ASSERT_TRUE(r[0].ok) << diagnostics_text(r[0]);
  const auto& reports = r[0].reports;
  EXPECT_EQ(reports.at("lot sy").sum, 0);
  EXPECT_EQ(reports.at("lot sz").sum, 10);
  EXPECT_EQ(reports.at("front tz").sum, 0);  // the first piece starts where z starts
  EXPECT_EQ(reports.at("back tz").sum, 4);
  EXPECT_EQ(reports.at("back sz").sum, 6);
  EXPECT_EQ(reports.at("raised ty").sum, 2);  // t's y is up
  EXPECT_EQ(reports.at("raised sx").sum, 10);
  EXPECT_EQ(reports.at("face sy").sum, 3);  // a façade's y runs up it
  std::size_t bands = 0;
  for (std::size_t i = 0; i < r[0].terminals_store.size(); ++i) {
    const Terminal& t = r[0].terminals_store[i];
    if (t.symbol != p->symbol_ids.at("Band")) continue;
    ++bands;
    // The front piece lies at Insula's far y (CityEngine's z = -y starts there) and was raised
    // by 2 m: the band is the lowest metre of its 3 m wall.
    EXPECT_NEAR(t.scope.origin.z, 2, 1e-9);
    EXPECT_NEAR(t.scope.size.y, 1, 1e-9);
  }
  EXPECT_EQ(bands, 1U);
}

TEST(CityEngineDialect, ChainInsideBrackets) {
  // `[ case ... ]`: the chain's branch runs on the pushed shape; after `]` the rule goes on.
  auto p = compile_text(
      "version \"2020.0\"\nattr on = true\n"
      "Lot --> extrude(3) [ case on : A. else : NIL ] [ case !on : B. else : NIL ] C.\n");
  ASSERT_TRUE(p);
  const auto r = derive_all(*p, {rectangle_lot(10, 8)});
  ASSERT_TRUE(r[0].ok) << diagnostics_text(r[0]);
  EXPECT_EQ(symbol_count(*p, r[0], "A"), 1U);
  EXPECT_EQ(symbol_count(*p, r[0], "B"), 0U);
  EXPECT_EQ(symbol_count(*p, r[0], "C"), 1U);
  EXPECT_EQ(r[0].terminals, 2U);
}

TEST(CityEngineDialect, SplitAlongTextureCoordinatesSaysWhatItDoes) {
  EXPECT_EQ(check_text("version \"2020.0\"\nLot --> split(v, unitSpace, 0) { 2 : A. | ~1 : B. }\n"),
            "t.cga:2:9: warning[CGA904]: split along texture coordinates: Insula's shapes carry "
            "none here, so this splits along the scope's y axis in meters\n");
  auto p =
      compile_text("version \"2020.0\"\nLot --> split(v, unitSpace, 0) { 2 : A. | ~1 : B. }\n");
  ASSERT_TRUE(p);
  DeriveOptions options;
  options.keep_terminals = true;
  const auto r = derive_all(*p, {rectangle_lot(10, 8)}, options);
  ASSERT_TRUE(r[0].ok) << diagnostics_text(r[0]);
  ASSERT_EQ(r[0].terminals_store.size(), 2U);
  EXPECT_NEAR(r[0].terminals_store[0].scope.size.y, 2, 1e-9);
  EXPECT_NEAR(r[0].terminals_store[1].scope.size.y, 6, 1e-9);
}

TEST(CityEngineDialect, MinimumDistanceToLabelledShapes) {
  // A 4 m hall at x 0..4 labelled "hall"; boxes of 1 m at x = 6 and 8 (2 and 4 m from it);
  // no "shed" anywhere: +inf.
  auto p = compile_text(
      "version \"2024.0\"\n"
      "Lot --> split(x) { 4 : extrude(5) label(\"hall\") Hall. | 2 : NIL | 1 : Box | 1 : NIL "
      "| 1 : Box | ~1 : NIL }\n"
      "Box --> extrude(1) report(\"d\", minimumDistance(intra, \"hall\"))\n"
      "  report(\"none\", isinf(minimumDistance(all, \"shed\")))\n"
      "  report(\"sel\", minimumDistance(sel(target), \"hall\"))\n"
      "  report(\"quoted\", minimumDistance(\"intra\", \"hall\")) B.\n"
      "attr target = \"intra\"\n");
  ASSERT_TRUE(p);
  const auto r = derive_all(*p, {rectangle_lot(12, 8)});
  ASSERT_TRUE(r[0].ok) << diagnostics_text(r[0]);
  EXPECT_EQ(r[0].reports.at("d").count, 2U);
  EXPECT_NEAR(r[0].reports.at("d").sum, 2 + 4, 1e-9);
  EXPECT_EQ(r[0].reports.at("none").sum, 2);
  EXPECT_NEAR(r[0].reports.at("sel").sum, 2 + 4, 1e-9);     // sel(attr): the target computed
  EXPECT_NEAR(r[0].reports.at("quoted").sum, 2 + 4, 1e-9);  // the word in quotes
}

TEST(CityEngineDialect, OcclusionQueriesWithLabels) {
  // Two labelled blocks side by side: of each block's four walls the one against the other block
  // touches it (its own block is its ancestor and does not count); the tower inside the front
  // block's box is inside a "block"; nothing is "inter" (one lot).
  auto p = compile_text(
      "version \"2024.0\"\n"
      "Lot --> split(x) { 5 : Mass(\"a\") | 5 : Mass(\"b\") }\n"
      "Mass(n) --> extrude(6) label(\"block\") comp(f) { side : Wall }\n"
      "Wall --> case touches(intra, \"block\") : Inner.\n"
      "  case touches(inter, \"block\") : Neighbour.\n"
      "  else : Outer.\n");
  ASSERT_TRUE(p);
  const auto r = derive_all(*p, {rectangle_lot(10, 8)});
  ASSERT_TRUE(r[0].ok) << diagnostics_text(r[0]);
  EXPECT_EQ(symbol_count(*p, r[0], "Inner"), 2U);
  EXPECT_EQ(symbol_count(*p, r[0], "Outer"), 6U);
  EXPECT_EQ(symbol_count(*p, r[0], "Neighbour"), 0U);
  auto inside = compile_text(
      "version \"2024.0\"\n"
      "Lot --> split(x) { 6 : extrude(9) label(\"hall\") Hall. | ~1 : Yard }\n"
      "Yard --> extrude(3) split(x) { ~1 : Probe | ~1 : Probe }\n"
      "Probe --> t(-2, 0, 0) s(1, 1, 1) Box\n"
      "Box --> case inside(all, \"hall\") : In. case overlaps(all, \"hall\") : Part.\n"
      "  else : Out.\n");
  ASSERT_TRUE(inside);
  const auto q = derive_all(*inside, {rectangle_lot(10, 8)});
  ASSERT_TRUE(q[0].ok) << diagnostics_text(q[0]);
  // The yard runs from x = 6 to 10; its probes start at 6 and 8, moved 2 m back: 4..5 lies in
  // the hall, 6..7 outside it.
  EXPECT_EQ(symbol_count(*inside, q[0], "In"), 1U);
  EXPECT_EQ(symbol_count(*inside, q[0], "Out"), 1U);
  EXPECT_EQ(check_text("version \"2024.0\"\nA --> case touches(near) : B. else : C.\n"),
            "t.cga:2:20: error[CGA315]: the target of 'touches' is intra, inter or all, found "
            "'near'\n");
}

TEST(CityEngineDialect, SetbackStreetSidesAreTheLotsSides) {
  // No street data: street.front is the lot's front edge (its first), street.back its back.
  auto p = compile_text(
      "version \"2020.0\"\nLot --> setback(3) { street.front : F | street.back : B | remainder "
      ": R }\nF --> report(\"front\", geometry.area())\nB --> report(\"back\", "
      "geometry.area())\nR --> report(\"rest\", geometry.area())\n");
  ASSERT_TRUE(p);
  const auto r = derive_all(*p, {rectangle_lot(20, 10)});
  ASSERT_TRUE(r[0].ok) << diagnostics_text(r[0]);
  EXPECT_NEAR(r[0].reports.at("front").sum, 60, 1e-6);
  EXPECT_NEAR(r[0].reports.at("back").sum, 60, 1e-6);
  EXPECT_NEAR(r[0].reports.at("rest").sum, 80, 1e-6);
  // CityEngine 2012's noStreetSide: every edge but the street's (the front): a U of depth 3.
  auto old = compile_text(
      "version \"2014.0\"\nLot --> setback(3) { noStreetSide : U | remainder : R }\n"
      "U --> report(\"u\", geometry.area())\nR --> report(\"rest\", geometry.area())\n");
  ASSERT_TRUE(old);
  const auto u = derive_all(*old, {rectangle_lot(20, 10)});
  ASSERT_TRUE(u[0].ok) << diagnostics_text(u[0]);
  EXPECT_NEAR(u[0].reports.at("rest").sum, 14 * 7, 1e-6);
  EXPECT_NEAR(u[0].reports.at("u").sum, 200 - 14 * 7, 1e-6);
}

TEST(CityEngineDialect, SetbackByUvSide) {
  // scope.xz on a lot: u along x, v along CityEngine's z (the lot's -y), so uv.top is the
  // front edge (y = 0) and uv.left the edge at x = 0.
  for (const auto& [side, area] : {std::pair{"uv.top", 40.0}, std::pair{"uv.left", 20.0}}) {
    auto p = compile_text(std::string("version \"2020.0\"\n") +
                          "Lot --> setupProjection(0, scope.xz, 1, 1) projectUV(0)\n"
                          "  setback(2) { " +
                          side +
                          " : S | remainder : R }\n"
                          "S --> report(\"s\", geometry.area()) report(\"x\", scope.tx)\n"
                          "R --> report(\"rest\", geometry.area())\n");
    ASSERT_TRUE(p);
    const auto r = derive_all(*p, {rectangle_lot(20, 10)});
    ASSERT_TRUE(r[0].ok) << diagnostics_text(r[0]);
    EXPECT_NEAR(r[0].reports.at("s").sum, area, 1e-6) << side;
    EXPECT_NEAR(r[0].reports.at("rest").sum, 200 - area, 1e-6) << side;
    EXPECT_NEAR(r[0].reports.at("x").sum, 0, 1e-6) << side;  // at x = 0, not x = 18
  }
}

TEST(CityEngineDialect, CompIndexComputedPerShape) {
  // `n + 1` is evaluated on the shape comp splits: face 3 (of the six) takes the door.
  auto p = compile_text(
      "version \"2020.0\"\nattr n = 2\nLot --> extrude(6) comp(f) { n + 1 : Door | all : Wall }\n"
      "Door --> report(\"door\", comp.index) D.\n");
  ASSERT_TRUE(p);
  const auto r = derive_all(*p, {rectangle_lot(10, 8)});
  ASSERT_TRUE(r[0].ok) << diagnostics_text(r[0]);
  EXPECT_EQ(symbol_count(*p, r[0], "Door"), 1U);
  EXPECT_EQ(symbol_count(*p, r[0], "Wall"), 5U);
  EXPECT_EQ(r[0].reports.at("door").sum, 3);
}

TEST(CityEngineDialect, ColourFunctions) {
  auto p = compile_text(
      "version \"2024.0\"\nLot --> print(colorRGBToHex(1, 0.5, 0)) print(colorHSVToHex(120, 1, "
      "0.5)) print(colorHexToH(\"#00ff00\")) print(colorHexToS(\"#808080\")) "
      "print(colorHexToV(\"#ff8000\")) print(colorHexToB(\"#00f\")) X.\n");
  ASSERT_TRUE(p);
  const auto r = derive_all(*p, {rectangle_lot(10, 8)});
  ASSERT_TRUE(r[0].ok) << diagnostics_text(r[0]);
  ASSERT_EQ(r[0].prints.size(), 6U);
  const std::vector<std::string> expected = {"#ff8000", "#008000", "120", "0", "1", "1"};
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const std::string& line = r[0].prints[i];
    EXPECT_EQ(line.substr(line.rfind(' ') + 1), expected[i]) << line;
  }
}

TEST(CityEngineDialect, UtilityFunctionsAndShapeValues) {
  // The utility library's getRange, colorRamp and file path parts; material.color.r of a shape
  // (white unset); initialShape.origin and scope.elevation; float() of a non-number is NaN.
  auto p = compile_text(
      "version \"2019.0\"\n"
      "Lot --> print(getRange(\"building_f4_t3_a.jpg\", \"f\", \"_t\")) "
      "print(getRange(\"x\", \"y\", \"z\")) print(colorRamp(\"whiteToBlack\", 0)) "
      "print(colorRamp(\"yellowToRed\", 1)) print(fileName(\"a/b/win.obj\")) "
      "print(fileBasename(\"a/b/win.obj\")) print(fileDirectory(\"a/b/win.obj\")) "
      "print(fileExtension(\"a/b/win.obj\")) print(material.color.r) color(0.5, 0, 0) "
      "print(material.color.r) print(initialShape.origin.px) t(0, 2, 0) "
      "print(scope.elevation) print(isnan(float(\"\")))  X.\n");
  ASSERT_TRUE(p);
  Lot lot = rectangle_lot(10, 8);
  for (auto& v : lot.polygons[0].outer) v.x += 100;
  const auto r = derive_all(*p, {lot});
  ASSERT_TRUE(r[0].ok) << diagnostics_text(r[0]);
  const std::vector<std::string> expected = {
      "4",   "",  "#ffffff", "#cc0000", "win.obj", "win", "a/b/", ".obj", "1", "0.5019607843137255",
      "100", "2", "true"};
  ASSERT_EQ(r[0].prints.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const std::string& line = r[0].prints[i];
    const std::size_t colon = line.find("print:");
    const std::string value = line.size() > colon + 7 ? line.substr(colon + 7) : std::string();
    EXPECT_EQ(value, expected[i]) << line;
  }
  EXPECT_EQ(check_text("version \"2019.0\"\nLot --> color(colorRamp(\"rainbow\", 0.5)) X.\n"),
            "");  // an unknown ramp is known only when derived
}

TEST(CityEngineDialect, OlderFormsAndUvExtents) {
  // CityEngine 2011's forms (rand without parentheses, alignScopeToGeometry(yUp, auto)), an
  // enum argument held in a constant, initialShape.startRule, listTerminate, and
  // geometry.du/dv/uMin/vMax on a projected uv set (2 m per repeat on a 10 x 4 m facade).
  auto p = compile_text(
      "version \"2011.1\"\nconst up = \"zUp\"\n"
      "@StartRule\nLot --> report(\"r\", rand < 1) print(initialShape.startRule) "
      "print(listTerminate(\"a;b\")) alignScopeToGeometry(yUp, auto) extrude(4)\n"
      "  comp(f) { front : Facade }\n"
      "Facade --> alignScopeToGeometry(up, 0, 0) setupProjection(0, scope.xy, 2, 1) projectUV(0)\n"
      "  report(\"du\", geometry.du(0, uvSpace)) report(\"du m\", geometry.du(0, unitSpace))\n"
      "  report(\"vmax\", geometry.vMax) report(\"none\", geometry.dv(1, uvSpace)) F.\n");
  ASSERT_TRUE(p);
  const auto r = derive_all(*p, {rectangle_lot(10, 6)});
  ASSERT_TRUE(r[0].ok) << diagnostics_text(r[0]);
  EXPECT_EQ(r[0].reports.at("r").sum, 1);
  ASSERT_EQ(r[0].prints.size(), 2U);
  EXPECT_EQ(r[0].prints[0], "test.cga:4: print: Lot");
  EXPECT_EQ(r[0].prints[1], "test.cga:4: print: a;b;");
  EXPECT_NEAR(r[0].reports.at("du").sum, 5, 1e-9);
  EXPECT_NEAR(r[0].reports.at("du m").sum, 10, 1e-9);
  EXPECT_NEAR(r[0].reports.at("vmax").sum, 4, 1e-9);
  EXPECT_EQ(r[0].reports.at("none").sum, 0);  // no uv set 1
  // A uv set out of 0..9 (here NaN) is an error at its place, never an undefined conversion.
  auto bad = compile_text(
      "version \"2019.0\"\nLot --> report(\"d\", geometry.du(0 / scope.sy, uvSpace)) X.\n");
  ASSERT_TRUE(bad);
  const auto e = derive_all(*bad, {rectangle_lot(10, 6)});
  EXPECT_FALSE(e[0].ok);
  EXPECT_NE(diagnostics_text(e[0]).find("error[CGA603]: a uv set is a whole number 0..9, got NaN"),
            std::string::npos)
      << diagnostics_text(e[0]);
}

TEST(CityEngineDialect, ConvertBetweenFrames) {
  // A 10 x 8 lot moved 3 m up: the scope origin in world coordinates (x east, y up, z south;
  // the volume's z points south, so its origin is on the lot's north edge, z = -8), a point 2 m
  // along the scope's x, the whole triple as a float[3], and a bad system.
  auto p = compile_text(
      "version \"2024.0\"\nLot --> extrude(6) t(0, 3, 0) print(convert(x, scope, world, pos, "
      "2, 0, 0)) print(convert(y, scope, world, pos, 0, 0, 0)) print(convert(scope, world, pos, "
      "[0, 0, 0])) print(convert(y, scope, object, orient, 0, 0, 0)) X.\n");
  ASSERT_TRUE(p);
  const auto r = derive_all(*p, {rectangle_lot(10, 8)});
  ASSERT_TRUE(r[0].ok) << diagnostics_text(r[0]);
  ASSERT_EQ(r[0].prints.size(), 4U);
  EXPECT_NE(r[0].prints[0].find(": 2"), std::string::npos) << r[0].prints[0];
  EXPECT_NE(r[0].prints[1].find(": 3"), std::string::npos) << r[0].prints[1];
  EXPECT_NE(r[0].prints[2].find("(3)[0,3,-8]"), std::string::npos) << r[0].prints[2];
  EXPECT_NE(r[0].prints[3].find(": 0"), std::string::npos) << r[0].prints[3];
  EXPECT_EQ(
      check_text("version \"2024.0\"\nLot --> print(convert(x, scope, earth, pos, 0, 0, 0)) X.\n"),
      "t.cga:2:33: error[CGA315]: the system to convert to of 'convert' is one of scope, pivot, "
      "object, world\n");
}

TEST(CityEngineDialect, GeometryFunctions) {
  auto p = compile_text(
      "version \"2024.0\"\n"
      "Lot --> report(\"rect\", geometry.isRectangular(5)) report(\"concave\", "
      "geometry.isConcave()) extrude(6) Mass\n"
      "Mass --> report(\"h\", geometry.height()) report(\"top\", geometry.area(top))\n"
      "  report(\"side\", geometry.area(side)) report(\"edges\", geometry.nEdges())\n"
      "  report(\"closed\", geometry.isClosedSurface()) report(\"top area\", "
      "geometry.area(world.up)) comp(f) { top : Top }\n"
      "Top --> roofGable(45) comp(f) { aslant : Plane }\n"
      "Plane --> report(\"slope\", geometry.angle(maxSlope)) report(\"azimuth\", "
      "geometry.angle(azimuth)) report(\"planar\", geometry.isPlanar(1))\n"
      "  report(\"up\", geometry.isOriented(world.up)) report(\"south\", "
      "geometry.isOriented(world.south))\n");
  ASSERT_TRUE(p);
  const auto r = derive_all(*p, {rectangle_lot(20, 10), l_lot()});
  ASSERT_TRUE(r[0].ok && r[1].ok) << diagnostics_text(r[0]) << diagnostics_text(r[1]);
  const auto& rect = r[0].reports;
  EXPECT_EQ(rect.at("rect").sum, 1);
  EXPECT_EQ(rect.at("concave").sum, 0);
  EXPECT_NEAR(rect.at("h").sum, 6, 1e-9);
  EXPECT_NEAR(rect.at("top").sum, 200, 1e-9);
  EXPECT_NEAR(rect.at("side").sum, 6 * 60, 1e-9);
  EXPECT_EQ(rect.at("edges").sum, 12);
  EXPECT_EQ(rect.at("closed").sum, 1);
  EXPECT_NEAR(rect.at("top area").sum, 200, 1e-9);
  // A gable on 20 x 10: two planes at 45 degrees, one falling south (180), one north (0).
  EXPECT_EQ(rect.at("slope").count, 2U);
  EXPECT_NEAR(rect.at("slope").sum, 90, 1e-6);
  EXPECT_NEAR(rect.at("azimuth").sum, 180, 1e-6);
  EXPECT_EQ(rect.at("planar").sum, 2);
  // At 45 degrees a plane's normal is as much up as south: comp's tie rule makes it face up.
  EXPECT_EQ(rect.at("up").sum, 2);
  EXPECT_EQ(rect.at("south").sum, 0);
  EXPECT_EQ(r[1].reports.at("rect").sum, 0);
  EXPECT_EQ(r[1].reports.at("concave").sum, 1);
  EXPECT_EQ(check_text("version \"2024.0\"\nLot --> report(\"a\", geometry.area(ridge)) X.\n"),
            "t.cga:2:35: error[CGA315]: unknown selector 'ridge' for 'geometry.area'\n");
  EXPECT_EQ(check_text("version \"2024.0\"\nLot --> report(\"a\", geometry.angle(up)) X.\n"),
            "t.cga:2:36: error[CGA315]: unknown angle type 'up' for 'geometry.angle' (maxSlope, "
            "azimuth or zenith)\n");
  EXPECT_EQ(check_text("version \"2024.0\"\nLot --> report(\"a\", geometry.isPlanar()) X.\n"),
            "t.cga:2:21: error[CGA312]: 'geometry.isPlanar' expects 1 argument, found 0\n");
}

TEST(CityEngineDialect, HolesPrintAsAFunctionAndIndexConstants) {
  // geometry.nHoles counts a courtyard; print() in an expression prints and returns its value;
  // a comp key that names a constant is that index (comp(f) { bottomFace = ... }).
  auto p = compile_text(
      "version \"2019.0\"\nconst bottomFace = 0\n"
      "Lot --> report(\"holes\", print(geometry.nHoles)) extrude(3)\n"
      "  comp(f) { bottomFace = Bottom | 1.2 : One | all = Other }\n");
  ASSERT_TRUE(p);
  Lot court;
  court.id = "court";
  court.polygons.push_back(
      {{{0, 0}, {20, 0}, {20, 20}, {0, 20}}, {{{5, 5}, {5, 15}, {15, 15}, {15, 5}}}});
  const auto r = derive_all(*p, {court, rectangle_lot(10, 8)});
  ASSERT_TRUE(r[0].ok && r[1].ok) << diagnostics_text(r[0]) << diagnostics_text(r[1]);
  EXPECT_EQ(r[0].reports.at("holes").sum, 1);
  EXPECT_EQ(r[1].reports.at("holes").sum, 0);
  ASSERT_EQ(r[0].prints.size(), 1U);
  EXPECT_EQ(r[0].prints[0], "test.cga:3: print: 1");
  EXPECT_EQ(symbol_count(*p, r[1], "Bottom"), 1U);
  EXPECT_EQ(symbol_count(*p, r[1], "One"), 1U);
  EXPECT_EQ(symbol_count(*p, r[1], "Other"), 4U);
  EXPECT_EQ(check_text("version \"2019.0\"\nLot --> extrude(3) comp(f) { 1.2 : A. }\n"),
            "t.cga:2:30: warning[CGA323]: component index 1.2 is not a whole number: read as 1\n");
  EXPECT_EQ(check_text("version \"2019.0\"\nLot --> report(\"n\", geometry.nHole) X.\n"),
            "t.cga:2:21: error[CGA321]: unknown function 'geometry.nHole'\n");
}

// ---- imports

std::map<std::string, std::string> files() {
  return {
      {"lib/windows.cga",
       "attr height = 2\nattr depth = 0.3\nconst frame = 0.1\n"
       "Window --> s('1, height, depth) Glass.\n"},
      {"lib/loop.cga", "import again : \"loop.cga\"\nX --> Y.\n"},
      {"lib/zoning.cga", "attr floors = 3\nMass --> extrude(floors) M.\n"},
      {"lib/lshape.cga",
       "attr shape = \"l\"\nLot --> shapeL(4, 3) { shape : Wing | remainder : Yard. }\n"
       "Wing --> extrude(2) W.\n"},
      {"lib/roofed.cga",
       "version \"2022.0\"\nstart Init(h) --> extrude(h) comp(f) { top : Roof(22) | side : Wall. "
       "}\n"
       "extension Roof(angle) --> roofHip(angle) Hip.\n"},
      {"lib/volume.cga",
       "version \"2019.0\"\nMass --> extrude(3) comp(f) { top : Slab | side : Wall. }\n"
       "Slab --> NIL.\n"},
  };
}

base::Result<Grammar> load(base::Source& source) {
  base::Result<Grammar> g = parse(source);
  if (!g.ok()) return g;
  Grammar grammar = std::move(g.value());
  const std::map<std::string, std::string> on_disk = files();
  const ImportLoader loader = [&](const std::string& path, const std::string& /*from*/,
                                  std::string& error) -> std::optional<ImportedFile> {
    const std::string name = "lib/" + path;
    auto it = on_disk.find(name);
    if (it == on_disk.end()) {
      error = "no such file";
      return std::nullopt;
    }
    return ImportedFile{name, it->second};
  };
  std::vector<base::Diagnostic> diags = resolve_imports(grammar, source, loader);
  if (base::has_errors(diags)) return base::Result<Grammar>::failure(std::move(diags));
  return base::Result<Grammar>(std::move(grammar), std::move(diags));
}

TEST(CityEngineImports, NamesComeUnderTheAliasAndAttributesPropagate) {
  base::Source source("main.cga",
                      "import win : \"windows.cga\" (depth = 0.5)\nattr height = 3\n"
                      "Lot --> extrude(win.frame * 100) split(x) { 2 : win.Window }*\n");
  base::Result<Grammar> g = load(source);
  ASSERT_TRUE(g.ok()) << base::render(g.diagnostics().front());
  // The importing file's model keeps its override (printing or dumping it stays possible).
  ASSERT_EQ(g.value().imports.size(), 1U);
  ASSERT_TRUE(g.value().imports[0].overrides.at(0).second);
  const CheckResult checked = check(g.value(), source);
  ASSERT_TRUE(checked.ok) << base::render(checked.diagnostics.front());
  auto program = compile(g.value(), source, {});
  ASSERT_TRUE(program.ok()) << base::render(program.diagnostics().front());
  DeriveOptions options;
  options.keep_terminals = true;
  const LotResult r = derive_lot(*program.value(), rectangle_lot(6, 4), 0, options);
  ASSERT_TRUE(r.ok) << testing::diagnostics_text(r);
  // The importer's height (3, not the library's 2) and the override's depth (0.5).
  ASSERT_EQ(r.terminals_store.size(), 3U);
  EXPECT_NEAR(r.terminals_store[0].scope.size.y, 3, 1e-9);
  EXPECT_NEAR(r.terminals_store[0].scope.size.z, 0.5, 1e-9);
  EXPECT_EQ(program.value()->symbol_name(r.terminals_store[0].symbol), "Glass");
}

TEST(CityEngineImports, ErrorsPointIntoTheRightFile) {
  base::Source missing("main.cga", "import w : \"nowhere.cga\"\nLot --> A.\n");
  base::Result<Grammar> g = load(missing);
  ASSERT_FALSE(g.ok());
  EXPECT_EQ(base::render(g.diagnostics().front()),
            "main.cga:1:12: error[CGA340]: cannot import \"nowhere.cga\": no such file");
  base::Source cycle("main.cga", "import l : \"loop.cga\"\nLot --> l.X\n");
  g = load(cycle);
  ASSERT_FALSE(g.ok());
  EXPECT_EQ(base::render(g.diagnostics().front()),
            "lib/loop.cga:1:16: error[CGA341]: \"loop.cga\" imports itself (through "
            "lib/loop.cga)");
}

TEST(CityEngineImports, TheImporterGivesAnImportedFilesRule) {
  // `volume.Slab -->` in the importing file takes the place of volume.cga's own Slab (Esri's
  // envelope2002 gives its facade rules to the volume file so); `NIL.` is NIL.
  base::Source source("main.cga",
                      "version \"2019.0\"\nimport volume : \"volume.cga\"\n"
                      "Lot --> volume.Mass\n"
                      "volume.Slab -->\n  case seedian >= 0 : Roof.\n  else : NIL.\n");
  base::Result<Grammar> g = load(source);
  ASSERT_TRUE(g.ok()) << base::render(g.diagnostics().front());
  const CheckResult checked = check(g.value(), source);
  ASSERT_TRUE(checked.ok) << base::render(checked.diagnostics.front());
  auto program = compile(g.value(), source, {});
  ASSERT_TRUE(program.ok()) << base::render(program.diagnostics().front());
  const LotResult r = derive_lot(*program.value(), rectangle_lot(6, 4), 0, {});
  ASSERT_TRUE(r.ok) << testing::diagnostics_text(r);
  EXPECT_EQ(symbol_count(*program.value(), r, "Roof"), 1U);
  EXPECT_EQ(symbol_count(*program.value(), r, "Wall"), 4U);  // a terminal keeps its bare name
}

TEST(CityEngineImports, AnAttributeReadingTheImportedOneIsNoCycle) {
  // Esri's `attr Floor_Count_Min = Zoning.Floor_Count_Min`: the imported attribute keeps its
  // own default instead of taking the importer's (which would read itself).
  base::Source source("main.cga",
                      "version \"2015.0\"\nimport z : \"zoning.cga\"\nattr floors = z.floors + 1\n"
                      "Lot --> print(floors) z.Mass\n");
  base::Result<Grammar> g = load(source);
  ASSERT_TRUE(g.ok()) << base::render(g.diagnostics().front());
  auto program = compile(g.value(), source, {});
  ASSERT_TRUE(program.ok()) << base::render(program.diagnostics().front());
  DeriveOptions options;
  options.keep_terminals = true;
  const LotResult r = derive_lot(*program.value(), rectangle_lot(6, 4), 0, options);
  ASSERT_TRUE(r.ok) << testing::diagnostics_text(r);
  ASSERT_EQ(r.prints.size(), 1U);
  EXPECT_NE(r.prints[0].find("print: 4"), std::string::npos) << r.prints[0];
  ASSERT_EQ(r.terminals_store.size(), 1U);
  EXPECT_NEAR(r.terminals_store[0].scope.size.y, 3, 1e-9);
}

TEST(CityEngineImports, SelectorKeysStaySelectorsUnderAnAttributeOfTheirName) {
  // Esri's massmodeling_01 has `attr shape` and `shapeL(...) { shape : ... }`; imported, the key
  // is still shapeL's selector, not the attribute `ls.shape`.
  base::Source source("main.cga",
                      "version \"2011.1\"\nimport ls : \"lshape.cga\"\nLot --> ls.Lot\n");
  base::Result<Grammar> g = load(source);
  ASSERT_TRUE(g.ok()) << base::render(g.diagnostics().front());
  const CheckResult checked = check(g.value(), source);
  ASSERT_TRUE(checked.ok) << base::render(checked.diagnostics.front());
  auto program = compile(g.value(), source, {});
  ASSERT_TRUE(program.ok()) << base::render(program.diagnostics().front());
  const LotResult r = derive_lot(*program.value(), rectangle_lot(10, 8), 0, {});
  ASSERT_TRUE(r.ok) << testing::diagnostics_text(r);
  EXPECT_EQ(symbol_count(*program.value(), r, "W"), 1U);
  EXPECT_EQ(symbol_count(*program.value(), r, "Yard"), 1U);
}

TEST(CityEngineImports, StartAndExtensionRules) {
  // CityEngine 2022.0: `start Init` is also `start` (here `roof.start(6)`), and the import
  // redefines the extension rule Roof in the importing file's names (`Flat` is main.cga's).
  base::Source source("main.cga",
                      "version \"2022.0\"\n"
                      "import roof : \"roofed.cga\" (Roof(a) --> Flat(a))\n"
                      "Lot --> roof.start(6)\nFlat(a) --> print(a) Top.\n");
  base::Result<Grammar> g = load(source);
  ASSERT_TRUE(g.ok()) << base::render(g.diagnostics().front());
  const CheckResult checked = check(g.value(), source);
  ASSERT_TRUE(checked.ok) << base::render(checked.diagnostics.front());
  auto program = compile(g.value(), source, {});
  ASSERT_TRUE(program.ok()) << base::render(program.diagnostics().front());
  DeriveOptions options;
  options.keep_terminals = true;
  const LotResult r = derive_lot(*program.value(), rectangle_lot(6, 4), 0, options);
  ASSERT_TRUE(r.ok) << testing::diagnostics_text(r);
  EXPECT_EQ(symbol_count(*program.value(), r, "Top"), 1U);
  EXPECT_EQ(symbol_count(*program.value(), r, "Hip"), 0U);
  EXPECT_EQ(symbol_count(*program.value(), r, "Wall"), 4U);
  ASSERT_EQ(r.prints.size(), 1U);
  EXPECT_NE(r.prints[0].find("print: 22"), std::string::npos) << r.prints[0];
  // In its own file, `start` is the start rule, callable as `start`.
  const auto own =
      compile_text("version \"2022.0\"\nLot --> start(2)\nstart Mass(h) --> extrude(h) M.\n");
  ASSERT_TRUE(own);
  const std::vector<LotResult> built = derive_all(*own, {rectangle_lot(6, 4)});
  ASSERT_TRUE(built[0].ok) << diagnostics_text(built[0]);
  EXPECT_EQ(symbol_count(*own, built[0], "M"), 1U);
  // Redefining a rule the imported file does not have is an error at the redefinition.
  base::Source wrong("main.cga",
                     "version \"2022.0\"\nimport roof : \"roofed.cga\" (Gable --> X.)\n"
                     "Lot --> roof.start(6)\n");
  g = load(wrong);
  ASSERT_FALSE(g.ok());
  EXPECT_EQ(base::render(g.diagnostics().front()),
            "main.cga:2:29: error[CGA343]: \"roofed.cga\" has no rule 'Gable' to redefine");
}

TEST(CityEngineDialect, TutorialForms) {
  // Esri's tutorials: a split branch without a size takes what is left (~1); a rule named `i`
  // beside i("...") calls of the operation; material.colormap reads the texture ("" unset).
  auto p = compile_text(
      "version \"2011.1\"\n"
      "Lot --> split(x) { 2 : A | split(z) { 1 : B | ~1 : C } | 3 : i }\n"
      "i --> i(\"builtin:cube\") I.\n"
      "A --> texture(\"w.png\") report(\"a\", fileName(material.colormap) == \"w.png\") X.\n"
      "B --> report(\"b\", scope.sx) report(\"none\", material.colormap == \"\") X.\n"
      "C --> X.\n");
  ASSERT_TRUE(p);
  const auto r = derive_all(*p, {rectangle_lot(10, 4)});
  ASSERT_TRUE(r[0].ok) << diagnostics_text(r[0]);
  EXPECT_NEAR(r[0].reports.at("b").sum, 5, 1e-9);  // 10 - 2 - 3
  EXPECT_EQ(r[0].reports.at("a").sum, 1);
  EXPECT_EQ(r[0].reports.at("none").sum, 1);
  EXPECT_EQ(symbol_count(*p, r[0], "I"), 1U);
}

TEST(CityEngineDialect, AnnotationPatternsAndBraceLists) {
  // Complete Street's handles: `shape=Name^4` and `translate={.1,0,0}` kept as their text.
  base::Source source("t.cga",
                      "version \"2023.0\"\n"
                      "@Handle(shape=Side^4, axis=x, translate={.1, 0, 0}, color=\"#FF11FF\")\n"
                      "attr w = 3\nLot --> extrude(w) A.\n");
  base::Result<Grammar> g = parse(source);
  ASSERT_TRUE(g.ok()) << base::render(g.diagnostics().front());
  const Annotation& a = g.value().attrs.at(0).annotations.at(0);
  ASSERT_EQ(a.args.size(), 4U);
  EXPECT_EQ(a.args[0]->text, "Side^4");
  EXPECT_EQ(a.args[2]->text, "{0.1, 0, 0}");
  // A terminal right before a comment is no element-wise `./`.
  EXPECT_EQ(check_text("version \"2023.0\"\nLot --> X Wall.// note\nX --> Y./* n */\n"), "");
  EXPECT_EQ(check_text("version \"2023.0\"\nLot --> roofHip(30, 1, true) R.\n"),
            "t.cga:2:9: warning[CGA905]: 'roofHip': the arguments after the overhang (even) are "
            "not supported; the roof is built without them\n");
  EXPECT_EQ(check_text("version \"2023.0\"\n@Handle(translate={1, 2\nattr w = 3\n"),
            "t.cga:3:1: error[CGA101]: expected '}' to close the annotation's list\n");
}

// ---- files as they are found

TEST(CityEngineFiles, WindowsEncodingAndByteOrderMark) {
  bool converted = false;
  // "Geländer" in Windows-1252, and a euro sign (0x80).
  EXPECT_EQ(base::utf8_text("Gel\xE4nder \x80", converted), "Gel\xC3\xA4nder \xE2\x82\xAC");
  EXPECT_TRUE(converted);
  EXPECT_EQ(base::utf8_text("\xEF\xBB\xBFLot --> A.", converted), "Lot --> A.");
  EXPECT_FALSE(converted);
  EXPECT_TRUE(base::is_utf8("Gel\xC3\xA4nder"));
  EXPECT_FALSE(base::is_utf8("\xC3"));          // truncated
  EXPECT_FALSE(base::is_utf8("\xC0\xAF"));      // overlong
  EXPECT_FALSE(base::is_utf8("\xED\xA0\x80"));  // a surrogate
  // CRLF line endings read as LF ones.
  const Grammar g = parse_ok("version \"2015.2\"\r\nLot -->\r\n\textrude(3)\r\n\tA.\r\n");
  EXPECT_EQ(g.sets.front().rules.front().alternatives.front().items.size(), 2U);
}

}  // namespace
}  // namespace insula::lang::cga
