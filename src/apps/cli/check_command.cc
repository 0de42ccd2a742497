#include "apps/cli/check_command.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <optional>

#include "apps/cli/exit_codes.h"
#include "apps/cli/input_file.h"
#include "base/diagnostic.h"
#include "io/geojson_reader.h"
#include "lang/cga/parser.h"

namespace insula::cli {
namespace {

bool has_suffix(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

void print(const std::vector<base::Diagnostic>& diagnostics, const base::Source& source,
           bool quiet) {
  for (const base::Diagnostic& d : diagnostics) {
    if (quiet && d.severity != base::Severity::kError) continue;
    std::fprintf(stderr, "%s\n", base::render(d, &source).c_str());
  }
}

// A one-line summary of what was checked, or nullopt when the input has errors.
std::optional<std::string> check_geojson(const base::Source& source, bool quiet) {
  base::Result<io::FootprintSet> set = io::read_geojson(source.text(), source.name());
  print(set.diagnostics(), source, quiet);
  if (!set.ok()) return std::nullopt;
  return std::to_string(set->footprints.size()) + " footprints";
}

std::optional<std::string> check_cga(const base::Source& source, bool quiet) {
  base::Result<lang::cga::Grammar> grammar = lang::cga::parse(source);
  print(grammar.diagnostics(), source, quiet);
  if (!grammar.ok()) return std::nullopt;
  std::size_t rules = 0;
  for (const auto& set : grammar->sets) rules += set.rules.size();
  return std::to_string(rules) + " rules, " + std::to_string(grammar->attrs.size()) + " attributes";
}

}  // namespace

void add_check_command(CLI::App& app, CheckOptions& options) {
  CLI::App* check =
      app.add_subcommand("check", "parse and check an input without building anything");
  check->add_option("INPUT", options.input, "a .geojson footprint file or a .cga grammar")
      ->required();
  check->add_flag("-q,--quiet", options.quiet, "print errors only");
}

int run_check(const CheckOptions& options) {
  const bool geojson = has_suffix(options.input, ".geojson") || has_suffix(options.input, ".json");
  const bool cga = has_suffix(options.input, ".cga");
  if (!geojson && !cga) {
    std::fprintf(stderr, "insula: %s: unknown input type (use .geojson or .cga)\n",
                 options.input.c_str());
    return kExitUsage;
  }
  const std::optional<std::string> text = read_input_file(options.input);
  if (!text) {
    std::fprintf(stderr, "%s: error: cannot read file\n", options.input.c_str());
    return kExitInput;
  }
  const base::Source source(options.input, *text);
  const std::optional<std::string> summary =
      geojson ? check_geojson(source, options.quiet) : check_cga(source, options.quiet);
  if (!summary) return kExitInput;
  if (!options.quiet) std::printf("%s: ok: %s\n", options.input.c_str(), summary->c_str());
  return kExitDone;
}

}  // namespace insula::cli
