#include "apps/cli/check_command.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <optional>

#include "apps/cli/exit_codes.h"
#include "apps/cli/footprint_input.h"
#include "apps/cli/front_ends.h"
#include "apps/cli/geojson_options.h"
#include "apps/cli/input_file.h"
#include "apps/cli/progress.h"
#include "apps/cli/warnings.h"
#include "base/diagnostic.h"
#include "io/geojson_reader.h"
#include "io/osm_reader.h"

namespace insula::cli {
namespace {

bool has_suffix(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// A one-line summary of what was checked, or nullopt when the input has errors. Reads GeoJSON
// and OpenStreetMap files as `mass` and `build --lot` do, so the three agree on every file.
std::optional<std::string> check_footprints(const CheckOptions& options) {
  const std::optional<io::FootprintSet> set = read_footprints(
      options.input, geojson_options(options.crs, options.keep_going), options.quiet);
  if (!set) return std::nullopt;
  std::string summary = std::to_string(set->footprints.size()) + " footprints";
  if (set->skipped_invalid > 0) {
    summary += ", " + std::to_string(set->skipped_invalid) + " invalid skipped";
  }
  if (!set->crs.empty()) summary += ", in " + set->crs;
  if (!set->source_crs.empty()) summary += " (reprojected from " + set->source_crs + ")";
  return summary;
}

}  // namespace

void add_check_command(CLI::App& app, CheckOptions& options) {
  CLI::App* check =
      app.add_subcommand("check", "parse and check an input without building anything");
  check
      ->add_option(
          "INPUT", options.input,
          "a .geojson, .geojsonl, .osm or .osm.pbf footprint file, a .cga or .bldg grammar, "
          "a .lua program, a .psm PLaSM program or a .graph.json procedural content "
          "graph")
      ->required();
  check->add_flag("-q,--quiet", options.quiet, "print errors only");
  check->add_option("--start", options.start,
                    "CGA: derive from this symbol instead of the first rule of the lowest "
                    "priority set (reachability is checked from it)");
  check->add_flag("--keep-going", options.keep_going,
                  "footprints: skip invalid features with a warning, as mass and build do");
  check
      ->add_option("--workspace", options.workspace,
                   "CGA: the CityEngine workspace that '/Project/...' names start from "
                   "(default: the parent of the project folder)")
      ->check(CLI::ExistingDirectory);
  add_crs_option(*check, options.crs);
}

int run_check(const CheckOptions& options) {
  using Checker = std::optional<std::string> (*)(const base::Source&, bool);
  Checker checker = nullptr;
  bool cga = false;         // check_cga also takes --start
  bool footprints = false;  // check_footprints takes --crs and --keep-going
  if (io::is_osm_path(options.input)) {
    footprints = true;
  } else if (has_suffix(options.input, ".graph.json")) {
    checker = check_graph;
  } else if (has_suffix(options.input, ".geojson") || has_suffix(options.input, ".json") ||
             io::is_geojson_sequence_path(options.input)) {
    footprints = true;
  } else if (has_suffix(options.input, ".cga")) {
    cga = true;
  } else if (has_suffix(options.input, ".bldg")) {
    checker = check_bldg;
  } else if (has_suffix(options.input, ".lua")) {
    checker = check_lua;
  } else if (has_suffix(options.input, ".psm")) {
    checker = check_plasm;
  } else {
    std::fprintf(
        stderr,
        "insula: %s: unknown input type (use .geojson, .geojsonl, .osm, .osm.pbf, .cga, .bldg, "
        ".lua, .psm or .graph.json)\n",
        options.input.c_str());
    return kExitUsage;
  }
  std::optional<std::string> summary;
  if (footprints) {
    summary = check_footprints(options);
  } else {
    const std::optional<std::string> text = read_input_or_report(options.input);
    if (!text) return kExitInput;
    const base::Source source(options.input, *text);
    summary = cga ? check_cga(source, options.quiet, options.start, options.workspace)
                  : checker(source, options.quiet);
  }
  if (!summary) return kExitInput;
  if (!options.quiet) std::printf("%s: ok: %s\n", options.input.c_str(), summary->c_str());
  return kExitDone;
}

void print_diagnostics(const std::vector<base::Diagnostic>& diagnostics, const base::Source& source,
                       bool quiet) {
  for (const base::Diagnostic& d : diagnostics) {
    if (d.severity == base::Severity::kError || (d.severity == base::Severity::kNote && !quiet)) {
      clear_progress_line();
      std::fprintf(stderr, "%s\n", base::render(d, &source).c_str());
    } else if (d.severity == base::Severity::kWarning) {
      emit_warning(d.code, base::render(d, &source), quiet);
    }
  }
}

}  // namespace insula::cli
