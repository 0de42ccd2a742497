// `insula transform`: the model-driven tooling of seed 004 (§IV metamodel, §VII transformations)
// on a CGA grammar, and the way back from BuildingGen XML. The output is produced whole in memory
// and written atomically, so bad input (exit 1) never leaves a file behind.
#include "apps/cli/transform_command.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <optional>
#include <string>

#include "apps/cli/exit_codes.h"
#include "apps/cli/front_ends.h"
#include "apps/cli/input_file.h"
#include "base/diagnostic.h"
#include "io/atomic_file.h"
#include "lang/cga/ast.h"
#include "lang/cga/buildinggen_xml.h"
#include "lang/cga/checker.h"
#include "lang/cga/derivation_graph.h"
#include "lang/cga/model_json.h"
#include "lang/cga/model_xmi.h"
#include "lang/cga/parser.h"
#include "lang/cga/printer.h"
#include "lang/cga/xml_reader.h"

namespace insula::cli {
namespace {

bool has_suffix(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// The text of `grammar` (parsed from `source`) in format `to`, or nullopt after printing the
// diagnostics that prevent it (only the BuildingGen checks can fail here).
std::optional<std::string> transform_grammar(const lang::cga::Grammar& grammar,
                                             const base::Source& source, const std::string& to,
                                             bool quiet) {
  if (to == "json") return lang::cga::model_json(grammar, source);
  if (to == "xmi") return lang::cga::model_xmi(grammar, source);
  if (to == "cga") return lang::cga::print(grammar);
  if (to == "dot" || to == "graph-json") {
    const lang::cga::DerivationGraph graph = lang::cga::derivation_graph(grammar, source);
    return to == "dot" ? lang::cga::graph_dot(graph) : lang::cga::graph_json(graph);
  }
  base::Result<std::string> xml = lang::cga::buildinggen_xml(grammar, source);
  print_diagnostics(xml.diagnostics(), source, quiet);
  if (!xml.ok()) return std::nullopt;
  return std::move(xml.value());
}

// BuildingGen XML -> `.cga`. The printed grammar is parsed again before it is written: a grammar
// the parser would reject is an internal error, never an output.
std::optional<std::string> xml_to_cga(const base::Source& source, bool quiet, int& exit_code) {
  base::Result<lang::cga::Grammar> grammar = lang::cga::read_buildinggen_xml(source);
  print_diagnostics(grammar.diagnostics(), source, quiet);
  if (!grammar.ok()) {
    exit_code = kExitInput;
    return std::nullopt;
  }
  std::string text = lang::cga::print(grammar.value());
  const base::Source printed(source.name() + ".cga", text);
  const base::Result<lang::cga::Grammar> check = lang::cga::parse(printed);
  if (!check.ok()) {
    std::fprintf(stderr, "insula: internal error: the grammar read from %s does not re-parse:\n",
                 source.name().c_str());
    print_diagnostics(check.diagnostics(), printed, quiet);
    exit_code = kExitInternal;
    return std::nullopt;
  }
  return text;
}

}  // namespace

void add_transform_command(CLI::App& app, TransformOptions& options) {
  CLI::App* transform =
      app.add_subcommand("transform", "model transformations of a CGA grammar (seed 004)");
  transform
      ->add_option("INPUT", options.input,
                   "a .cga grammar, or a BuildingGen .xml to turn back into a grammar")
      ->required();
  transform
      ->add_option("--to", options.to,
                   "json (AST model), xmi (EMF model of docs/cga.ecore), dot or graph-json "
                   "(derivation graph), xml (BuildingGen), cga (grammar text)")
      ->required()
      ->check(CLI::IsMember({"json", "xmi", "dot", "graph-json", "xml", "cga"}));
  transform->add_option("-o,--output", options.output, "output file (default: standard output)");
  transform->add_flag("-q,--quiet", options.quiet, "print errors only");
}

int run_transform(const TransformOptions& options) {
  const bool from_xml = has_suffix(options.input, ".xml");
  if (!from_xml && !has_suffix(options.input, ".cga")) {
    std::fprintf(stderr, "insula: %s: transform reads a .cga grammar or a BuildingGen .xml\n",
                 options.input.c_str());
    return kExitUsage;
  }
  if (from_xml && options.to != "cga") {
    std::fprintf(stderr, "insula: %s: a BuildingGen .xml transforms to --to cga only\n",
                 options.input.c_str());
    return kExitUsage;
  }
  const std::optional<std::string> text = read_input_or_report(options.input);
  if (!text) return kExitInput;
  const base::Source source(options.input, *text);
  int exit_code = kExitInput;
  std::optional<std::string> output;
  if (from_xml) {
    output = xml_to_cga(source, options.quiet, exit_code);
  } else {
    // A grammar is transformed only when it is a well-formed model (parser, then the static
    // semantics of §IV.B in checker.h), so no output describes a grammar `build` would reject.
    base::Result<lang::cga::Grammar> grammar = lang::cga::parse(source);
    print_diagnostics(grammar.diagnostics(), source, options.quiet);
    if (grammar.ok()) {
      const lang::cga::CheckResult checked = lang::cga::check(grammar.value(), source);
      print_diagnostics(checked.diagnostics, source, options.quiet);
      if (checked.ok) {
        output = transform_grammar(grammar.value(), source, options.to, options.quiet);
      }
    }
  }
  if (!output) return exit_code;
  if (options.output.empty()) {
    std::fwrite(output->data(), 1, output->size(), stdout);
    return kExitDone;
  }
  const std::string error = io::write_file_atomically(options.output, *output);
  if (!error.empty()) {
    std::fprintf(stderr, "insula: error: %s\n", error.c_str());
    return kExitInput;
  }
  if (!options.quiet) std::printf("%s\n", options.output.c_str());
  return kExitDone;
}

}  // namespace insula::cli
