// CityEngine's arrays in the CGA front-end (issue 20; docs/cga-cityengine.md, "Arrays"):
// literals, 1-D and 2-D indexing, the array functions, the comp function on known footprints,
// setback with a depth per edge, exports, and the diagnostics of bad arrays. Rule texts are our
// own.
#include <gtest/gtest.h>

#include <map>

#include "derive_util.h"
#include "lang/cga/checker.h"
#include "lang/cga/printer.h"
#include "test_util.h"

namespace insula::lang::cga {
namespace {

using testing::check_text;
using testing::compile_text;
using testing::derive_all;
using testing::diagnostics_text;
using testing::rectangle_lot;

Lot l_lot() {
  Lot lot;
  lot.id = "L";
  lot.polygons.push_back({{{0, 0}, {12, 0}, {12, 4}, {4, 4}, {4, 10}, {0, 10}}, {}});
  return lot;
}

// The print() lines of deriving `text` on `lot`, without their "file:line: print: " head.
std::vector<std::string> prints(const std::string& text, const Lot& lot) {
  const auto program = compile_text(text);
  if (!program) return {};
  const std::vector<LotResult> r = derive_all(*program, {lot});
  EXPECT_TRUE(r[0].ok) << diagnostics_text(r[0]);
  std::vector<std::string> out;
  for (const std::string& line : r[0].prints) out.push_back(line.substr(line.find("print: ") + 7));
  return out;
}

TEST(CityEngineArrays, LiteralsIndexingAndFunctions) {
  const std::vector<std::string> p = prints(R"(version "2020.0"
const a = [4, 5, 6]
const b = [1, 2; 3, 4; 5, 6]
const s = ["x", "y"]
tenth(i) = a[i] / 10
Lot -->
	print(a) print(b) print(a[0]) print(a[2]) print(b[2, 1]) print(b[3])
	print(size(b)) print(nRows(b)) print(nColumns(b)) print(transpose(b))
	print(findFirst(a, 5)) print(findFirst(a, 7)) print(findFirst([1.02, 2], 1, 0.05))
	print(findLast([1, 2, 1], 1)) print(sortIndices([30, 10, 20])) print(s[1] + "!")
	print(floatArray(["1.5", "2"])) print(boolArray([1, 0])) print(stringArray([true]))
	print(["a", s]) print([a; 7, 8, 9]) print(tenth(1)) print(a == [4, 5, 6]) print(a != b)
	print([1, 2] < [1, 3]) print(listToArray("p;q;")) print(listFromArray(a))
	print(size(floatArray())) print("a = " + a)
)",
                                            rectangle_lot(10, 10));
  const std::vector<std::string> expected = {"(3)[4,5,6]",
                                             "(3x2)[1,2;3,4;5,6]",
                                             "4",
                                             "6",
                                             "6",
                                             "4",
                                             "6",
                                             "3",
                                             "2",
                                             "(2x3)[1,3,5;2,4,6]",
                                             "1",
                                             "-1",
                                             "0",
                                             "2",
                                             "(3)[1,2,0]",
                                             "y!",
                                             "(2)[1.5,2]",
                                             "(2)[true,false]",
                                             "(1)[true]",
                                             "(3)[a,x,y]",
                                             "(2x3)[4,5,6;7,8,9]",
                                             "0.5",
                                             "true",
                                             "true",
                                             "true",
                                             "(2)[p,q]",
                                             "4;5;6;",
                                             "0",
                                             "a = (3)[4,5,6]"};
  EXPECT_EQ(p, expected);
}

TEST(CityEngineArrays, ColonOperatorAndIndexArrays) {
  // The examples of CityEngine's reference pages func_colon and func_index.
  const std::vector<std::string> p = prints(R"(version "2023.0"
const a = [1, 2, 3, 4]
const m = [1, 2, 3; 4, 5, 6; 7, 8, 9]
Lot -->
	print([2:4]) print([0.5:3]) print([4:2]) print([1:0.5:3]) print([4:-1:2])
	print([0:2; 3, 3, 3]) print(a[[0, 2]]) print(a[3:-1:1]) print(a[[true, false, true]])
	print(m[1, [0, 2]]) print(m[[0, 0, 1], 2]) print(m[0:2, [0, 2]]) print(m[[0; 3; 6]])
	print(findFirst(m[0:2, 1], 8)) print(a[sortIndices([3, 1, 2, 0])])
)",
                                            rectangle_lot(10, 10));
  const std::vector<std::string> expected = {"(3)[2,3,4]",   "(3)[0.5,1.5,2.5]",
                                             "(0)[]",        "(5)[1,1.5,2,2.5,3]",
                                             "(3)[4,3,2]",   "(2x3)[0,1,2;3,3,3]",
                                             "(2)[1,3]",     "(3)[4,3,2]",
                                             "(2)[1,3]",     "(2)[4,6]",
                                             "(3x1)[3;3;6]", "(3x2)[1,3;4,6;7,9]",
                                             "(3x1)[1;4;7]", "2",
                                             "(4)[4,2,3,1]"};
  EXPECT_EQ(p, expected);
  // Logical indices past the end give the default, with the warning.
  const auto program = compile_text(
      "version \"2023.0\"\nconst a = [1, 2]\nLot --> print(a[[false, true, true]]) X.\n");
  ASSERT_TRUE(program);
  const std::vector<LotResult> r = derive_all(*program, {rectangle_lot(10, 10)});
  ASSERT_EQ(r[0].prints.size(), 1U);
  EXPECT_EQ(r[0].prints[0], "test.cga:3: print: (2)[2,0]");
  EXPECT_NE(diagnostics_text(r[0]).find("warning[CGA604]: index 2 is outside the array's 2"),
            std::string::npos);
}

TEST(CityEngineArrays, ElementwiseOperators) {
  // Complete Street's asset filter: the rows whose column 1 is a category, by a bool[] index.
  const std::vector<std::string> p = prints(R"(version "2023.0"
const t = ["a", "tree"; "b", "lamp"; "c", "tree"]
const n = [1, 2; 3, 4]
Lot -->
	print(t[t[0:2, 1] .== "tree", 0]) print(n .+ 1) print(2 .* n) print(n .- n)
	print(n ./ [2, 2; 2, 2]) print(n .> 2) print(n .<= 2 .|| n .== 4) print("x" .+ ["a", "b"])
	print(listRemove("a;b;a;c;", "a"))
)",
                                            rectangle_lot(10, 10));
  const std::vector<std::string> expected = {"(2x1)[a;c]",
                                             "(2x2)[2,3;4,5]",
                                             "(2x2)[2,4;6,8]",
                                             "(2x2)[0,0;0,0]",
                                             "(2x2)[0.5,1;1.5,2]",
                                             "(2x2)[false,false;true,true]",
                                             "(2x2)[true,true;false,true]",
                                             "(2)[xa,xb]",
                                             "b;c;"};
  EXPECT_EQ(p, expected);
}

TEST(CityEngineArrays, CompFunctionGivesOneValuePerFaceEdgeOfAnLLot) {
  // The L's edges in order: 12 (facing -y: front), 4 (+x: right), 8 (+y: back), 6 (+x: right),
  // 4 (+y: back), 10 (-x: left).
  const std::vector<std::string> p = prints(R"(version "2023.0"
const lengths = comp(fe) { all : scope.sx }
Lot -->
	print(lengths)
	print(comp(fe) { front : 1 | back = 2 | side : 3 })
	print(comp(fe) { street.front : "street" | object.left : "west" })
	print(comp(fe) { 2 : comp.index | right : 9 })
	print(comp(f) { all : geometry.area() })
	print(size(comp(v) { all : 1 }))
)",
                                            l_lot());
  const std::vector<std::string> expected = {
      "(6)[12,4,8,6,4,10]", "(6)[1,3,2,3,2,3]", "(6)[street,,,,,west]",
      "(6)[0,9,2,9,0,0]",   "(1)[72]",          "6"};
  EXPECT_EQ(p, expected);
}

TEST(CityEngineArrays, CompOperationSplitsFaceEdges) {
  const auto program = compile_text(R"(version "2023.0"
Lot --> comp(fe) { front : F | back = B | side : S }
F --> report("F", scope.sx)
B --> report("B", scope.sx)
S --> report("S", scope.sx)
)");
  ASSERT_TRUE(program);
  const std::vector<LotResult> r = derive_all(*program, {l_lot()});
  ASSERT_TRUE(r[0].ok) << diagnostics_text(r[0]);
  EXPECT_EQ(r[0].reports.at("F").count, 1U);
  EXPECT_NEAR(r[0].reports.at("F").sum, 12, 1e-9);
  EXPECT_EQ(r[0].reports.at("B").count, 2U);
  EXPECT_NEAR(r[0].reports.at("B").sum, 8 + 4, 1e-9);
  EXPECT_EQ(r[0].reports.at("S").count, 3U);
  EXPECT_NEAR(r[0].reports.at("S").sum, 4 + 6 + 10, 1e-9);
}

// Strip and remainder areas of a setback on the 20 x 15 m rectangle (edges 20, 15, 20, 15).
std::map<std::string, double> setback_areas(const std::string& setback) {
  const auto program = compile_text("version \"2023.0\"\nLot --> " + setback +
                                    "\nS --> report(\"S\", geometry.area())\n"
                                    "R --> report(\"R\", geometry.area())\n");
  std::map<std::string, double> out;
  if (!program) return out;
  const std::vector<LotResult> r = derive_all(*program, {rectangle_lot(20, 15)});
  EXPECT_TRUE(r[0].ok) << diagnostics_text(r[0]);
  for (const auto& [name, e] : r[0].reports) out[name] = e.sum;
  return out;
}

TEST(CityEngineArrays, SetbackTakesADepthPerEdge) {
  std::map<std::string, double> a =
      setback_areas("setback([2, 0, 3, 0]) { all = S | remainder : R }");
  EXPECT_NEAR(a["S"], 20 * 2 + 20 * 3, 1e-6);
  EXPECT_NEAR(a["R"], 20 * 10, 1e-6);
  a = setback_areas("setback([2, 1, 3, 1]) { front : S | remainder : R }");
  EXPECT_NEAR(a["S"], 20 * 2, 1e-6);  // only the front edge's strip
  EXPECT_NEAR(a["R"], 300 - 40, 1e-6);
  // The corpus' form: depths from the comp function by street side (no street widths: the
  // object's sides). Strips of 4 (front), 1 (back) and 2 (sides) overlap at the corners.
  a = setback_areas(
      "setback(comp(fe){ street.front : 4 | street.back = 1 | street.side = 2 }) "
      "{ all = S | remainder : R }");
  EXPECT_NEAR(a["S"], 300 - 16 * 10, 1e-6);
  EXPECT_NEAR(a["R"], 16 * 10, 1e-6);
  // Missing entries mean no strip; extra ones are ignored (as CityEngine).
  a = setback_areas("setback([0, 5]) { all = S | remainder : R }");
  EXPECT_NEAR(a["S"], 15 * 5, 1e-6);
  a = setback_areas("setback([1, 0, 0, 0, 7, 7]) { all = S | remainder : R }");
  EXPECT_NEAR(a["S"], 20, 1e-6);
}

TEST(CityEngineArrays, ArrayAttributesAreExportedAsTheirLiteralText) {
  const auto program = compile_text(R"(version "2019.1"
attr heights = [3, 4.5; 6, 7]
attr names = ["a", "b\"c"]
Lot --> set(names, ["z"]) extrude(heights[1, 0]) Mass.
)");
  ASSERT_TRUE(program);
  const std::vector<LotResult> r = derive_all(*program, {rectangle_lot(10, 10)});
  ASSERT_TRUE(r[0].ok) << diagnostics_text(r[0]);
  EXPECT_EQ(shape::to_string(r[0].attributes.at("heights")), "[3,4.5;6,7]");
  EXPECT_EQ(shape::to_string(r[0].attributes.at("names")), "[\"a\",\"b\\\"c\"]");
  const shape::Scene scene = to_scene(*program, {rectangle_lot(10, 10)}, r);
  ASSERT_EQ(scene.buildings.size(), 1U);
  EXPECT_EQ(shape::to_string(scene.buildings[0].parts[0].attributes.at("names")), "[\"z\"]");
}

// The first diagnostic of deriving `text` on a 10 x 10 m lot.
std::string derive_message(const std::string& text) {
  const auto program = compile_text(text);
  if (!program) return "";
  const std::vector<LotResult> r = derive_all(*program, {rectangle_lot(10, 10)});
  if (r[0].diagnostics.empty()) return "";
  const std::string rendered = base::render(r[0].diagnostics.front());
  return rendered.substr(0, rendered.find('\n'));  // without the notes (rule, lot)
}

TEST(CityEngineArrays, BadArraysArePositionedDiagnostics) {
  // Out of range: CityEngine's default value and a warning at the index.
  EXPECT_EQ(derive_message("version \"2020.0\"\nconst a = [1, 2; 3, 4]\n"
                           "Lot --> print(a[5]) print(a[0, 2]) X.\n"),
            "test.cga:3:15: warning[CGA604]: index 5 is outside the array's 4 elements; the value "
            "is 0 (CityEngine's default)");
  EXPECT_EQ(derive_message("version \"2020.0\"\nLot --> print([\"a\"][-1, 0]) X.\n"),
            "test.cga:2:15: warning[CGA604]: index [-1, 0] is outside the array's 1 x 1 "
            "elements; the value is \"\" (CityEngine's default)");
  // Type errors end the lot's derivation at their position.
  EXPECT_EQ(derive_message("version \"2020.0\"\nf(x) = [1, x]\nLot --> print(f(\"a\")) X.\n"),
            "test.cga:2:8: error[CGA603]: array elements must all be of one type, found float "
            "and string");
  EXPECT_EQ(derive_message("version \"2020.0\"\nf(x) = size(x)\nLot --> print(f(3)) X.\n"),
            "test.cga:2:8: error[CGA603]: size() expects an array, got a number");
  EXPECT_EQ(derive_message("version \"2020.0\"\nconst a = [1, 2]\nLot --> extrude(a * 2) X.\n"),
            "test.cga:3:17: error[CGA603]: arithmetic on a float[] (CityEngine's element-wise "
            "operators are written .+ .- .* ./)");
  EXPECT_EQ(derive_message("version \"2020.0\"\nLot --> print([1, 2] .+ [1, 2, 3]) X.\n"),
            "test.cga:2:15: error[CGA603]: element-wise operands of 1 x 2 and 1 x 3 elements");
  EXPECT_EQ(derive_message("version \"2020.0\"\nf(x) = [1, 2; x]\nLot --> print(f(3)) X.\n"),
            "test.cga:2:8: error[CGA603]: array rows of 2 and 1 columns");
  EXPECT_EQ(derive_message("version \"2020.0\"\nLot --> setback([\"a\"]) { all : X. }\n"),
            "test.cga:2:17: error[CGA603]: setback() takes a distance or a float[], got a "
            "string[]");
  EXPECT_EQ(derive_message("version \"2020.0\"\nconst n = 2\nLot --> print(n[0]) X.\n"),
            "test.cga:3:15: error[CGA603]: cannot index a number");
}

TEST(CityEngineArrays, CheckerKnowsCompFunctionSelectors) {
  EXPECT_EQ(check_text("version \"2020.0\"\nLot --> print(comp(fe){ top : 1 }) X.\n"),
            "t.cga:2:25: error[CGA315]: face edges (fe) take front, back, left, right, side, all "
            "or an index\n");
  EXPECT_EQ(check_text("version \"2020.0\"\nLot --> print(comp(q){ all : 1 }) X.\n"),
            "t.cga:2:20: error[CGA309]: unknown component type of comp() (expected f, e, v or "
            "fe)\n");
  EXPECT_EQ(check_text("version \"2020.0\"\nLot --> print(comp(f){ street.front : 1 }) X.\n"),
            "t.cga:2:24: error[CGA902]: comp selector 'street.front' is supported on face edges "
            "(fe) only, with front, back, left, right or side\n");
  EXPECT_EQ(check_text("version \"2020.0\"\nLot --> print(comp(fe){ all : 1 | all : 2 }) X.\n"),
            "t.cga:2:35: error[CGA315]: selector 'all' appears twice\n");
  EXPECT_EQ(check_text("version \"2020.0\"\nLot --> print(comp(fe){ all : nope }) X.\n"),
            "t.cga:2:31: error[CGA313]: undefined identifier 'nope' (not an attribute or a shape "
            "attribute)\n");
}

TEST(CityEngineArrays, PrinterWritesRowsIndicesAndCompFunctions) {
  const std::string text =
      "version \"2020.0\"\nconst a = [1, 2; 3, 4]\n"
      "Lot --> print(a[1, 0]) setback(comp(fe) { front : 1 | back = 2 }) { all : X. }\n";
  const base::Source source("t.cga", text);
  base::Result<Grammar> g = parse(source);
  ASSERT_TRUE(g.ok());
  const std::string printed = print(g.value());
  EXPECT_NE(printed.find("[1, 2; 3, 4]"), std::string::npos) << printed;
  EXPECT_NE(printed.find("a[1, 0]"), std::string::npos) << printed;
  EXPECT_NE(printed.find("comp(fe) { front : 1 | back = 2 }"), std::string::npos) << printed;
  // What the printer writes reads back to the same text.
  const base::Source again("t.cga", printed);
  base::Result<Grammar> g2 = parse(again);
  ASSERT_TRUE(g2.ok());
  EXPECT_EQ(print(g2.value()), printed);
}

class TableFiles final : public FileQueries {
 public:
  bool exists(const std::string&) const override { return false; }
  std::string search(const std::string&, std::string&) const override { return ""; }
  std::string random(const std::string&, double, std::string&) const override { return ""; }
  std::optional<double> asset_info(const std::string&, const std::string&,
                                   std::string&) const override {
    return std::nullopt;
  }
  std::optional<double> image_info(const std::string&, const std::string&,
                                   std::string&) const override {
    return std::nullopt;
  }
  std::optional<std::string> read_text(const std::string& path, std::string& error) const override {
    if (path == "floors.csv") return "Floor;Height;Use\r\n0;4.5;shop\r\n1;3;flat\r\n";
    error = "file '" + path + "' not found";
    return std::nullopt;
  }
};

TEST(CityEngineArrays, ReadTablesFromCsv) {
  const auto program = compile_text(R"(version "2020.0"
const table = readStringTable("floors.csv")
const numbers = readFloatTable("floors.csv")
Lot --> print(table) print(numbers[1, 1] + numbers[2, 1]) print(nRows(table)) X.
)");
  ASSERT_TRUE(program);
  TableFiles files;
  DeriveOptions options;
  options.files = &files;
  const std::vector<LotResult> r = derive_all(*program, {rectangle_lot(10, 10)}, options);
  ASSERT_TRUE(r[0].ok) << diagnostics_text(r[0]);
  ASSERT_EQ(r[0].prints.size(), 3U);
  EXPECT_EQ(r[0].prints[0], "test.cga:4: print: (3x3)[Floor,Height,Use;0,4.5,shop;1,3,flat]");
  EXPECT_EQ(r[0].prints[1], "test.cga:4: print: 7.5");
  EXPECT_EQ(r[0].prints[2], "test.cga:4: print: 3");
  EXPECT_EQ(derive_message("version \"2020.0\"\nLot --> print(readStringTable(\"x.csv\")) X.\n"),
            "test.cga:2:15: error[CGA603]: file functions need files (none given)");
}

}  // namespace
}  // namespace insula::lang::cga
