// libFuzzer target for the CGA front half and its model transformations (seed 004 §IV, §VII;
// docs/cga-language.md, docs/cga-model.md). The same bytes go through two readers:
//   - parse(): a failure carries at least one positioned CGA error, a success none; a parsed
//     grammar prints (printer.h) to text that parses again to the same AST dump (positions
//     aside); its JSON and XMI are well-formed; its derivation graph is consistent; when the
//     BuildingGen checks pass, XML -> grammar -> text gives the same AST dump again (rules of one
//     predecessor adjacent), else every check diagnostic is a positioned CGA5xx error;
//   - read_buildinggen_xml(): a failure carries one positioned CGA52x/CGA53x error, a success
//     prints to text that parses.
// Builds as fuzz/geojson_fuzz.cc: libFuzzer with clang and INSULA_FUZZ=ON, a replay main with
// INSULA_FUZZ_REPLAY; tests/lang/cga/cga_fuzz_replay_test.cc includes it with
// INSULA_FUZZ_NO_ENTRY.
#include <nlohmann/json.hpp>
#include <pugixml.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "base/diagnostic.h"
#include "lang/cga/ast.h"
#include "lang/cga/ast_dump.h"
#include "lang/cga/buildinggen_xml.h"
#include "lang/cga/derivation_graph.h"
#include "lang/cga/model_json.h"
#include "lang/cga/model_xmi.h"
#include "lang/cga/parser.h"
#include "lang/cga/printer.h"
#include "lang/cga/xml_reader.h"

namespace insula::fuzz {

// An AST dump without its ` @line:col` positions.
inline std::string strip_positions(const std::string& dump) {
  std::string out;
  out.reserve(dump.size());
  for (std::size_t i = 0; i < dump.size(); ++i) {
    if (dump[i] == ' ' && i + 1 < dump.size() && dump[i + 1] == '@') {
      std::size_t j = i + 2;
      while (j < dump.size() && ((dump[j] >= '0' && dump[j] <= '9') || dump[j] == ':')) ++j;
      i = j - 1;
      continue;
    }
    out += dump[i];
  }
  return out;
}

// Empty when `diagnostics` are a proper failure: at least one error, every error positioned and
// coded with `prefix`.
inline std::string check_failure(const std::vector<base::Diagnostic>& diagnostics,
                                 std::string_view prefix) {
  if (!base::has_errors(diagnostics)) return "failure without an error diagnostic";
  for (const base::Diagnostic& d : diagnostics) {
    if (d.message.empty()) return "empty diagnostic message";
    if (d.span.line == 0 || d.span.column == 0)
      return "diagnostic without a position: " + d.message;
    if (d.code.rfind(prefix, 0) != 0) return "unexpected diagnostic code " + d.code;
  }
  return {};
}

// Rules of each predecessor adjacent within their set: the XML groups rules by predecessor, so
// only then does the round trip keep the rule order.
inline bool rules_grouped(const lang::cga::Grammar& g) {
  for (const lang::cga::PrioritySet& set : g.sets) {
    std::set<std::string> closed;
    for (std::size_t i = 0; i < set.rules.size(); ++i) {
      const std::string& p = set.rules[i].predecessor;
      if (closed.count(p)) return false;
      if (i + 1 == set.rules.size() || set.rules[i + 1].predecessor != p) closed.insert(p);
    }
  }
  return true;
}

// The stripped dump of `text` parsed as `name`, or empty with `problem` set.
// Printing may add grouping parentheses (`!(a > 6)` for `!a > 6`), which count as nesting: an
// input right at the parser's depth limit can print one level past it. That is no broken
// contract, so `too_deep` says so and the caller skips the comparison.
inline std::string reparse(const std::string& text, const std::string& name, std::string& problem,
                           bool* too_deep = nullptr) {
  const base::Source source(name, text);
  const base::Result<lang::cga::Grammar> again = lang::cga::parse(source);
  const auto nesting = [](const base::Diagnostic& d) { return d.code == "CGA105"; };
  if (!again.ok() && too_deep != nullptr &&
      std::all_of(again.diagnostics().begin(), again.diagnostics().end(),
                  [&](const base::Diagnostic& d) {
                    return d.severity != base::Severity::kError || nesting(d);
                  })) {
    *too_deep = true;
    return {};
  }
  if (!again.ok()) {
    problem = "printed grammar does not parse: " + base::render(again.diagnostics().front()) +
              "\n--- printed ---\n" + text;
    return {};
  }
  return strip_positions(lang::cga::dump(again.value(), source));
}

inline std::string check_graph(const lang::cga::Grammar& g, const base::Source& source) {
  const lang::cga::DerivationGraph graph = lang::cga::derivation_graph(g, source);
  std::size_t parts = 0;
  for (const auto& set : g.sets) {
    for (const auto& rule : set.rules) parts += rule.alternatives.size();
  }
  if (graph.edges.size() != parts) return "one rule edge per rule part expected";
  for (const lang::cga::RuleEdge& e : graph.edges) {
    if (e.source >= graph.nodes.size()) return "edge source out of range";
    if (graph.nodes[e.source].kind != lang::cga::NodeKind::kNonTerminal) {
      return "edge from a node that is not a non-terminal";
    }
    for (const std::size_t t : e.targets) {
      if (t >= graph.nodes.size()) return "edge target out of range";
    }
  }
  if (!nlohmann::json::accept(lang::cga::graph_json(graph))) return "graph JSON is not JSON";
  if (lang::cga::graph_dot(graph).rfind("digraph", 0) != 0) return "DOT without digraph";
  return {};
}

inline std::string check_grammar(const lang::cga::Grammar& g, const base::Source& source) {
  const std::string expected = strip_positions(lang::cga::dump(g, source));
  std::string problem;
  bool too_deep = false;
  const std::string printed = reparse(lang::cga::print(g), source.name(), problem, &too_deep);
  if (!problem.empty()) return problem;
  if (!too_deep && printed != expected) {
    return "print/parse changed the AST:\n" + expected + "---\n" + printed;
  }
  if (!nlohmann::json::accept(lang::cga::model_json(g, source))) return "model JSON is not JSON";
  pugi::xml_document xmi;
  const std::string xmi_text = lang::cga::model_xmi(g, source);
  if (!xmi.load_buffer(xmi_text.data(), xmi_text.size())) return "XMI is not well-formed";
  if (std::string graph = check_graph(g, source); !graph.empty()) return graph;
  const base::Result<std::string> xml = lang::cga::buildinggen_xml(g, source);
  if (!xml.ok()) return check_failure(xml.diagnostics(), "CGA5");
  const base::Source xml_source("fuzz.xml", xml.value());
  const base::Result<lang::cga::Grammar> back = lang::cga::read_buildinggen_xml(xml_source);
  if (!back.ok()) {
    return "written BuildingGen XML does not read back: " +
           base::render(back.diagnostics().front()) + "\n" + xml.value();
  }
  const std::string round = reparse(lang::cga::print(back.value()), source.name(), problem);
  if (!problem.empty()) return problem;
  if (rules_grouped(g) && round != expected) {
    return "BuildingGen round trip changed the AST:\n" + expected + "---\n" + round;
  }
  return {};
}

inline std::string check_xml_reader(std::string_view bytes) {
  const base::Source source("fuzz.xml", std::string(bytes));
  const base::Result<lang::cga::Grammar> g = lang::cga::read_buildinggen_xml(source);
  if (!g.ok()) {
    if (g.diagnostics().size() != 1) return "the XML reader reports exactly one error";
    return check_failure(g.diagnostics(), "CGA5");
  }
  if (!g.diagnostics().empty()) return "XML read with diagnostics";
  std::string problem;
  reparse(lang::cga::print(g.value()), "fuzz.cga", problem);
  return problem;
}

// Empty when every contract above holds for `bytes`, else what broke.
inline std::string check_cga(std::string_view bytes) {
  const base::Source source("fuzz.cga", std::string(bytes));
  const base::Result<lang::cga::Grammar> result = lang::cga::parse(source);
  std::string problem;
  if (!result.ok()) {
    problem = check_failure(result.diagnostics(), "CGA");
  } else if (base::has_errors(result.diagnostics())) {
    problem = "success with an error diagnostic";
  } else {
    problem = check_grammar(result.value(), source);
  }
  if (!problem.empty()) return problem;
  return check_xml_reader(bytes);
}

}  // namespace insula::fuzz

#ifndef INSULA_FUZZ_NO_ENTRY
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string problem =
      insula::fuzz::check_cga(std::string_view(reinterpret_cast<const char*>(data), size));
  if (!problem.empty()) {
    std::fprintf(stderr, "cga_fuzz: %s\n", problem.c_str());
    std::abort();
  }
  return 0;
}
#endif

#ifdef INSULA_FUZZ_REPLAY
#define INSULA_FUZZ_REPLAY_NAME "cga_fuzz_replay"
#define INSULA_FUZZ_REPLAY_RECURSIVE  // corpus folders nest
#include "replay_main.h"
#endif
