// The model transformations of seed 004 (§IV, §VII): printer round trips, the JSON model, the
// derivation graph of §VII.B (Fig. 13), BuildingGen XML with the Fig. 15 checks (Fig. 16), and
// reading that XML back. Goldens in tests/data/cga/transform/ (INSULA_UPDATE_GOLDEN=1).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <pugixml.hpp>

#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "lang/cga/ast_dump.h"
#include "lang/cga/buildinggen_xml.h"
#include "lang/cga/checker.h"
#include "lang/cga/derivation_graph.h"
#include "lang/cga/model_json.h"
#include "lang/cga/model_xmi.h"
#include "lang/cga/printer.h"
#include "lang/cga/xml_reader.h"
#include "test_util.h"

namespace insula::lang::cga {
namespace {

using testing::data_dir;
using testing::files_in;
using testing::read_file;

std::filesystem::path transform_dir() {
  return data_dir() / "transform";
}

// A dump without ` @line:col`.
std::string strip_positions(const std::string& dump) {
  std::string out;
  for (std::size_t i = 0; i < dump.size(); ++i) {
    if (dump[i] == ' ' && i + 1 < dump.size() && dump[i + 1] == '@') {
      std::size_t j = i + 2;
      while (j < dump.size() &&
             (std::isdigit(static_cast<unsigned char>(dump[j])) || dump[j] == ':'))
        ++j;
      i = j - 1;
      continue;
    }
    out += dump[i];
  }
  return out;
}

struct Parsed {
  base::Source source;
  Grammar grammar;
};

Parsed parse_text(const std::string& text, const std::string& name = "t.cga") {
  base::Source source(name, text);
  base::Result<Grammar> result = parse(source);
  EXPECT_TRUE(result.ok()) << (result.diagnostics().empty()
                                   ? ""
                                   : base::render(result.diagnostics()[0]));
  if (!result.ok()) return {std::move(source), Grammar{}};
  return {std::move(source), std::move(result.value())};
}

Parsed parse_path(const std::filesystem::path& path) {
  return parse_text(read_file(path), path.filename().string());
}

std::string stripped_dump(const Parsed& p) {
  return strip_positions(dump(p.grammar, p.source));
}

// Compares `actual` with the golden file, or rewrites it under INSULA_UPDATE_GOLDEN.
void expect_golden(const std::string& actual, const std::filesystem::path& golden) {
  if (std::getenv("INSULA_UPDATE_GOLDEN")) {
    std::ofstream(golden, std::ios::binary) << actual;
    return;
  }
  ASSERT_TRUE(std::filesystem::exists(golden)) << golden;
  EXPECT_EQ(actual, read_file(golden)) << golden;
}

// The diagnostics a catalog file expects: one `// expect: LINE:COL: ...` (or
// `<!-- expect: ... -->`) line each, rendered with the file name in front.
std::vector<std::string> expected_diagnostics(const std::string& text, const std::string& file) {
  std::vector<std::string> out;
  for (std::size_t at = text.find("expect: "); at != std::string::npos;
       at = text.find("expect: ", at + 1)) {
    const std::size_t end = text.find('\n', at);
    std::string line = text.substr(at + 8, end - at - 8);
    if (line.size() > 4 && line.compare(line.size() - 4, 4, " -->") == 0) {
      line.resize(line.size() - 4);
    }
    out.push_back(file + ":" + line);
  }
  return out;
}

std::vector<std::string> rendered(const std::vector<base::Diagnostic>& diagnostics) {
  std::vector<std::string> out;
  for (const base::Diagnostic& d : diagnostics) out.push_back(base::render(d));
  return out;
}

std::vector<std::filesystem::path> grammar_files() {
  std::vector<std::filesystem::path> out = files_in(data_dir(), ".cga");
  for (const auto& p : files_in(transform_dir(), ".cga")) out.push_back(p);
  for (const auto& p : files_in(transform_dir() / "bad_buildinggen", ".cga")) out.push_back(p);
  return out;
}

// ---- printer ----

TEST(CgaPrinter, EveryGrammarFileRoundTrips) {
  for (const auto& path : grammar_files()) {
    const Parsed original = parse_path(path);
    const std::string printed = print(original.grammar);
    const Parsed again = parse_text(printed, path.filename().string());
    EXPECT_EQ(stripped_dump(again), stripped_dump(original)) << path << "\n" << printed;
    EXPECT_EQ(print(again.grammar), printed) << path;  // printing is a fixed point
  }
}

TEST(CgaPrinter, ParenthesesOnlyWherePrecedenceNeedsThem) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"1: A : (a + b) * c ~> B", "1: A : (a + b) * c ~> B\n"},
      {"1: A : a - (b - c) ~> B", "1: A : a - (b - c) ~> B\n"},
      {"1: A : (a - b) - c ~> B", "1: A : a - b - c ~> B\n"},
      {"1: A : not (x == 1) or y and z ~> B", "1: A : !(x == 1) || y && z ~> B\n"},
      {"1: A : (x or y) and z ~> B", "1: A : (x || y) && z ~> B\n"},
      {"1: A : - -x < -(2 * y) ~> B", "1: A : - -x < -(2 * y) ~> B\n"},
      {"1: A : (a < b) == true ~> B", "1: A : (a < b) == true ~> B\n"},
      {"1: A : Shape.occ(\"all\") <> \"no\\\"ne\" ~> B",
       "1: A : Shape.occ(\"all\") != \"no\\\"ne\" ~> B\n"},
      {"1: A : (2r).x > '(a) ~> B", "1: A : 2r.x > 'a ~> B\n"},
      {"A --> split(\"x\"){ '0.5: B | { ~1: C | 2: D }* }",
       "A --> split(\"x\"){ 0.5r: B | { ~1: C | 2: D }* }\n"},
      {"1: A ~> B : (p) ~> C : -0.5 ~> D : (1 - 0.25)",
       "1: A ~> B : (p)\n    ~> C : -0.5\n    ~> D : (1 - 0.25)\n"},
      {"attr h = 1e21\nattr s = \"a\tb\"", "attr h = 1e+21;\nattr s = \"a\\tb\";\n"},
  };
  for (const auto& [source, expected] : cases) {
    const Parsed p = parse_text(source);
    const std::string printed = print(p.grammar);
    EXPECT_EQ(printed, expected) << source;
    EXPECT_EQ(stripped_dump(parse_text(printed)), stripped_dump(p)) << source;
  }
}

TEST(CgaPrinter, DeepNestingAndLongChainsRoundTrip) {
  // Close to the parser's nesting limit (kMaxNesting): nested blocks, parentheses, unary chains.
  std::string blocks = "1: A ~> ";
  for (int i = 0; i < 60; ++i) blocks += "BS(\"X\", 1r){ ";
  blocks += "B";
  for (int i = 0; i < 60; ++i) blocks += " }";
  std::string parens = "2: B : ";
  for (int i = 0; i < 25; ++i) parens += "(x - ";
  parens += "1";
  for (int i = 0; i < 25; ++i) parens += ")";
  parens += " > 0 ~> C";
  std::string chain = "3: C : 1";
  for (int i = 0; i < 80; ++i) chain += " + 1";
  chain += " > - -~'x && !!!y ~> D";
  const Parsed p = parse_text(blocks + "\n" + parens + "\n" + chain + "\n");
  const Parsed again = parse_text(print(p.grammar));
  EXPECT_EQ(stripped_dump(again), stripped_dump(p));
  EXPECT_TRUE(nlohmann::json::accept(model_json(p.grammar, p.source)));
  pugi::xml_document doc;
  EXPECT_TRUE(doc.load_string(model_xmi(p.grammar, p.source).c_str()));
  const DerivationGraph g = derivation_graph(p.grammar, p.source);
  EXPECT_EQ(g.edges.size(), 3U);
  EXPECT_EQ(g.edges[0].targets.size(), 1U);
  EXPECT_EQ(g.edges[0].operations.size(), 60U);
}

// ---- JSON model ----

TEST(CgaModelJson, PaperFig13) {
  const Parsed p = parse_path(data_dir() / "paper_fig13.cga");
  const nlohmann::json j = nlohmann::json::parse(model_json(p.grammar, p.source));
  EXPECT_EQ(j["format"], "insula-cga-model");
  ASSERT_EQ(j["prioritySets"].size(), 1U);
  const auto& rules = j["prioritySets"][0]["rules"];
  ASSERT_EQ(rules.size(), 3U);
  EXPECT_EQ(rules[0]["id"], "0");
  EXPECT_EQ(rules[0]["predecessor"], "floor");
  const auto& split = rules[0]["ruleParts"][0]["successors"][0];
  EXPECT_EQ(split["operation"], "basicSplit");
  EXPECT_EQ(split["name"], "BS");
  EXPECT_EQ(split["arguments"][0]["value"], "X");
  EXPECT_EQ(split["arguments"][1]["kind"], "unary");
  EXPECT_EQ(split["arguments"][1]["operator"], "relative");
  EXPECT_EQ(split["arguments"][1]["operand"]["value"], 1.0);
  EXPECT_EQ(split["range"]["line"], 4);
  EXPECT_EQ(split["range"]["column"], 13);
  EXPECT_EQ(split["branches"][1]["successors"][0]["operation"], "predefined");
  const auto& comp = rules[2]["ruleParts"][0]["successors"][0];
  EXPECT_EQ(comp["operation"], "componentSplit");
  EXPECT_EQ(comp["branches"][1]["successors"][0]["kind"], "empty");
  expect_golden(model_json(p.grammar, p.source), transform_dir() / "paper_fig13.json");
}

TEST(CgaModelJson, StringsAreEscapedAndInvalidUtf8Replaced) {
  const Parsed p = parse_text("1: A ~> Pshape(\"a\x01b\\\"\xFF\xCE\xB5\") B");
  const nlohmann::json j = nlohmann::json::parse(model_json(p.grammar, p.source));
  const auto& pshape = j["prioritySets"][0]["rules"][0]["ruleParts"][0]["successors"][0];
  EXPECT_EQ(pshape["arguments"][0]["value"], "a\x01b\"\xEF\xBF\xBD\xCE\xB5");
}

// ---- derivation graph (§VII.B) ----

TEST(CgaDerivationGraph, PaperFig13IsFigure13sOutputModel) {
  // Fig. 13: nonterminals floor, window and corner, the predefined shape wall and the empty
  // shape; rule 0 splits floor into window and wall, rule 1 substitutes window by corner, rule 2
  // splits corner into its components wall and ε.
  const Parsed p = parse_path(data_dir() / "paper_fig13.cga");
  const DerivationGraph g = derivation_graph(p.grammar, p.source);
  ASSERT_EQ(g.nodes.size(), 5U);
  const auto node = [&](std::size_t i) {
    return g.nodes[i].name + "/" + std::string(node_kind_name(g.nodes[i].kind)) +
           (g.nodes[i].predefined ? "/predefined" : "") + (g.nodes[i].root ? "/root" : "");
  };
  EXPECT_EQ(node(0), "floor/nonTerminal/root");
  EXPECT_EQ(node(1), "window/nonTerminal");
  EXPECT_EQ(node(2), "corner/nonTerminal");
  EXPECT_EQ(node(3), "wall.obj/terminal/predefined");
  EXPECT_EQ(node(4), "\xCE\xB5/empty");
  ASSERT_EQ(g.edges.size(), 3U);
  EXPECT_EQ(g.edges[0].type, EdgeType::kBasicSplit);
  EXPECT_EQ(g.edges[0].rule_id, "0");
  EXPECT_EQ(g.edges[0].source, 0U);
  EXPECT_EQ(g.edges[0].targets, (std::vector<std::size_t>{1, 3}));
  EXPECT_EQ(g.edges[0].probability, 1.0);
  EXPECT_EQ(g.edges[1].type, EdgeType::kSubstitution);
  EXPECT_EQ(g.edges[1].targets, (std::vector<std::size_t>{2}));
  EXPECT_EQ(g.edges[2].type, EdgeType::kComponentSplit);
  EXPECT_EQ(g.edges[2].targets, (std::vector<std::size_t>{3, 4}));
  expect_golden(graph_dot(g), transform_dir() / "paper_fig13.dot");
  expect_golden(graph_json(g), transform_dir() / "paper_fig13.graph.json");
}

TEST(CgaDerivationGraph, ProbabilitiesConditionsAndExtensionSplits) {
  const Parsed p = parse_text(
      "1: A : Shape.sx > 2 ~> BS(\"X\", 1, 1){ B | C } : 0.25 ~> RR(\"X\", 1){ B } : (1 - 0.25)\n"
      "B --> split(\"y\"){ { ~1: C }* }\n"
      "C --> [ T(0, 0, 1) I(\"cube\") ] extrude(2) comp(\"f\"){ top: A | side: D } : 0.5\n"
      "   ~> split(\"x\"){ 1: D | { ~2: B }* } : (p)\n");
  const DerivationGraph g = derivation_graph(p.grammar, p.source);
  ASSERT_EQ(g.edges.size(), 5U);
  EXPECT_EQ(g.edges[0].type, EdgeType::kBasicSplit);
  EXPECT_EQ(g.edges[0].condition, "Shape.sx > 2");
  EXPECT_EQ(g.edges[0].probability, 0.25);
  EXPECT_EQ(g.edges[1].type, EdgeType::kRepeat);
  EXPECT_EQ(g.edges[1].probability, 0.75);
  EXPECT_EQ(g.edges[1].probability_text, "1 - 0.25");
  EXPECT_EQ(g.edges[2].type, EdgeType::kRepeat);  // a split made only of repeat patterns
  EXPECT_EQ(g.edges[3].type, EdgeType::kComponentSplit);
  EXPECT_EQ(g.edges[3].operations, (std::vector<std::string>{"T", "I", "extrude", "comp"}));
  EXPECT_EQ(g.edges[4].type, EdgeType::kBasicSplit);
  EXPECT_FALSE(g.edges[4].probability.has_value());
  EXPECT_EQ(g.edges[4].probability_text, "p");
  // Nodes: A B C (non-terminals), then cube (inserted object) and D (terminal).
  ASSERT_EQ(g.nodes.size(), 5U);
  EXPECT_EQ(g.nodes[3].name, "cube");
  EXPECT_TRUE(g.nodes[3].predefined);
  EXPECT_EQ(g.nodes[4].name, "D");
  EXPECT_EQ(g.nodes[4].kind, NodeKind::kTerminal);
  EXPECT_EQ(g.edges[3].targets, (std::vector<std::size_t>{3, 0, 4}));
  EXPECT_FALSE(g.nodes[0].root);  // A is reached back from C
}

// ---- BuildingGen XML (§VII.C) ----

TEST(CgaBuildingGen, CheckRuleCatalog) {
  const auto files = files_in(transform_dir() / "bad_buildinggen", ".cga");
  ASSERT_GE(files.size(), 10U);
  for (const auto& path : files) {
    const Parsed p = parse_path(path);
    EXPECT_EQ(rendered(check_buildinggen(p.grammar, p.source)),
              expected_diagnostics(read_file(path), path.filename().string()));
    EXPECT_FALSE(buildinggen_xml(p.grammar, p.source).ok());
  }
}

TEST(CgaBuildingGen, PaperFig13IsNotABuildingGenModel) {
  const Parsed p = parse_path(data_dir() / "paper_fig13.cga");
  EXPECT_EQ(rendered(check_buildinggen(p.grammar, p.source)),
            (std::vector<std::string>{
                "paper_fig13.cga:1:1: error[CGA502]: the default Facade shape is not defined "
                "(BuildingGen derives from it)",
                "paper_fig13.cga:6:14: error[CGA506]: component splits are not supported by "
                "BuildingGen XML ('CS')"}));
}

TEST(CgaBuildingGen, Fig16Structure) {
  const Parsed p = parse_path(transform_dir() / "fig16_facade.cga");
  const base::Result<std::string> xml = buildinggen_xml(p.grammar, p.source);
  ASSERT_TRUE(xml.ok()) << base::render(xml.diagnostics().front());
  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_string(xml.value().c_str()));
  const pugi::xml_node fixed =
      doc.child("BuildingGen").child("Rules").child("Balcony_1").child("R11").child("Fixed");
  ASSERT_TRUE(fixed);
  EXPECT_STREQ(fixed.child("xProportions").attribute("xr1").value(), "1.0");
  EXPECT_STREQ(fixed.child("xProportions").attribute("xr2").value(), "5.0");
  EXPECT_STREQ(fixed.child("xProportions").attribute("xr3").value(), "1.0");
  EXPECT_TRUE(fixed.child("yProportions").attributes().empty());
  std::vector<std::string> elements;
  for (pugi::xml_node e : fixed.child("Elements").children()) elements.emplace_back(e.name());
  EXPECT_EQ(elements, (std::vector<std::string>{"Wall", "Balcony_Center", "Wall"}));
  std::vector<std::string> terminals;
  for (pugi::xml_node e : doc.child("BuildingGen").child("Terminals").children()) {
    terminals.push_back(e.attribute("file") ? e.attribute("file").value() : e.name());
  }
  EXPECT_EQ(terminals,
            (std::vector<std::string>{"Wall", "door.obj", "window.obj", "balcony.obj", "Railing"}));
  expect_golden(xml.value(), transform_dir() / "fig16_facade.xml");
}

// cga -> xml -> cga gives the same AST for every grammar file the XML can express; the others
// are refused with CGA5xx errors at a position.
TEST(CgaBuildingGen, RoundTripEveryExpressibleGrammar) {
  int expressible = 0;
  for (const auto& path : grammar_files()) {
    const Parsed p = parse_path(path);
    const base::Result<std::string> xml = buildinggen_xml(p.grammar, p.source);
    if (!xml.ok()) {
      for (const auto& d : xml.diagnostics()) {
        EXPECT_EQ(d.code.substr(0, 4), "CGA5") << path;
        EXPECT_GE(d.span.line, 1U) << path;
      }
      continue;
    }
    ++expressible;
    const base::Source xml_source("back.xml", xml.value());
    base::Result<Grammar> back = read_buildinggen_xml(xml_source);
    ASSERT_TRUE(back.ok()) << base::render(back.diagnostics().front()) << "\n" << xml.value();
    const Parsed again = parse_text(print(back.value()), path.filename().string());
    EXPECT_EQ(stripped_dump(again), stripped_dump(p)) << path;
  }
  EXPECT_EQ(expressible, 3);  // fig16_facade.cga, its read-back golden, implicit_set.cga
}

// `insula transform` runs the checker first: the BuildingGen examples must be well-formed models.
TEST(CgaBuildingGen, ExamplesPassTheChecker) {
  for (const char* name : {"fig16_facade.cga", "implicit_set.cga"}) {
    const Parsed p = parse_path(transform_dir() / name);
    const CheckResult checked = check(p.grammar, p.source);
    EXPECT_TRUE(checked.ok) << name << "\n"
                            << (checked.diagnostics.empty() ? ""
                                                            : base::render(checked.diagnostics[0]));
  }
}

TEST(CgaBuildingGen, ReadBackGroupsRulesByPredecessor) {
  const Parsed p = parse_text("1: Facade ~> A B\n2: A ~> B\n3: Facade ~> A\n");
  const base::Result<std::string> xml = buildinggen_xml(p.grammar, p.source);
  ASSERT_TRUE(xml.ok());
  const base::Result<Grammar> back = read_buildinggen_xml(base::Source("x.xml", xml.value()));
  ASSERT_TRUE(back.ok());
  EXPECT_EQ(print(back.value()), "1: Facade ~> A B\n3: Facade ~> A\n2: A ~> B\n");
}

TEST(CgaXmlReader, BadInputCatalog) {
  const auto files = files_in(transform_dir() / "bad_xml", ".xml");
  ASSERT_GE(files.size(), 14U);
  for (const auto& path : files) {
    const std::string text = read_file(path);
    const base::Result<Grammar> g =
        read_buildinggen_xml(base::Source(path.filename().string(), text));
    ASSERT_FALSE(g.ok()) << path;
    EXPECT_EQ(rendered(g.diagnostics()), expected_diagnostics(text, path.filename().string()));
  }
}

TEST(CgaXmlReader, Fig16XmlReadsBackToTheGrammarText) {
  const base::Source xml("fig16_facade.xml", read_file(transform_dir() / "fig16_facade.xml"));
  const base::Result<Grammar> g = read_buildinggen_xml(xml);
  ASSERT_TRUE(g.ok()) << base::render(g.diagnostics().front());
  expect_golden(print(g.value()), transform_dir() / "fig16_facade.back.cga");
}

}  // namespace
}  // namespace insula::lang::cga
