#include "apps/cli/build_command.h"

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "apps/cli/exit_codes.h"
#include "apps/cli/front_ends.h"
#include "apps/cli/geojson_options.h"
#include "apps/cli/height_unit.h"
#include "apps/cli/interrupt.h"
#include "apps/cli/ranks.h"
#include "apps/cli/tile_job.h"
#include "apps/cli/view_options.h"
#include "apps/cli/warnings.h"

namespace insula::cli {
namespace {

bool has_suffix(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

shape::Value parse_value(const std::string& text) {
  if (text == "true") return true;
  if (text == "false") return false;
  char* end = nullptr;
  const double number = std::strtod(text.c_str(), &end);
  if (!text.empty() && end == text.c_str() + text.size() && std::isfinite(number)) return number;
  return text;
}

}  // namespace

void add_build_command(CLI::App& app, BuildOptions& options) {
  CLI::App* build = app.add_subcommand(
      "build",
      "build a grammar or program: .cga (CGA grammar), .bldg (building grammar), .lua, "
      ".psm (PLaSM)");
  build->add_option("INPUT", options.input, "a .cga, .bldg, .lua or .psm file")->required();
  build->add_option(
      "-o,--output", options.outputs,
      "output file, format by extension (.obj .glb .gltf .city.json .city.jsonl .svg .png); "
      "repeatable; none: derive and report only");
  build->add_option("--lot", options.lot, "GeoJSON lots (CGA) or outline footprints (.bldg)");
  build->add_option("--seed", options.seed, "random seed (default 0; a graph's own seed)")
      ->each([&options](const std::string&) { options.seed_given = true; });
  build->add_option("--threads", options.threads, "worker threads (default: all cores)")
      ->check(CLI::Range(1, 1024));
  build->add_option("--set", options.sets, "override an attribute: name=value; repeatable");
  build->add_option("--start", options.start, "start symbol (CGA)");
  build->add_option("--rules", options.rules, "restriction rules file (.bldg)");
  build->add_option("--assets", options.assets, "asset folder a program may read (.lua)");
  build
      ->add_option("--workspace", options.workspace,
                   "CityEngine workspace that '/Project/...' asset names start from (.cga, "
                   ".graph.json; default: the parent of the project folder)")
      ->check(CLI::ExistingDirectory);
  build->add_option("--report", options.report, "write a JSON report (counts, timings)");
  build->add_option("--probe", options.probe,
                    "graphs: write what left node NODE ('sub/NODE' inside a subgraph node) "
                    "instead of the results");
  build->add_option("--report-entities", options.report_entities,
                    "graphs: list at most N result entities in the report (default: all)");
  build->add_flag("--keep-going", options.keep_going,
                  "leave out invalid --lot features and lots that cannot hold a .bldg grammar "
                  "(each with a warning) instead of failing");
  add_crs_option(*build, options.crs);
  add_height_unit_option(*build, options.height_unit,
                         "unit of bare numbers in the --lot features' 'height' property (not "
                         "OpenStreetMap buildings'), converted to meters for the grammar");
  build->add_flag("-q,--quiet", options.quiet, "no progress or warnings on stderr");
  add_view_options(*build, options.output);
}

bool city_by_tiles(const BuildOptions& options) {
  return !options.lot.empty() && streamable(options.outputs) && options.transaction == nullptr &&
         options.probe.empty();
}

int run_build(const BuildOptions& given) {
  // Under mpirun only a city built tile by tile (cga_tiles.h, bldg_village.h, graph_tiles.h: a
  // graph that is not per lot leaves the other ranks there) is shared among the ranks; any other
  // build is the leader's alone. The other ranks work silently: the leader reports for all.
  const bool by_tiles = (has_suffix(given.input, ".cga") || has_suffix(given.input, ".bldg") ||
                         has_suffix(given.input, ".graph.json")) &&
                        city_by_tiles(given);
  if (Ranks::shared() && !Ranks::leader() && !by_tiles) return kExitDone;
  BuildOptions options = given;
  if (!Ranks::leader()) options.quiet = true;
  if (!options.probe.empty() && !has_suffix(options.input, ".graph.json")) {
    std::fprintf(stderr, "insula: --probe: only a graph (.graph.json) has nodes to probe\n");
    return kExitUsage;
  }
  // A program that never reads --lot would build the same thing once, wherever the lots lie.
  if (!options.lot.empty() &&
      (has_suffix(options.input, ".lua") || has_suffix(options.input, ".psm"))) {
    std::fprintf(stderr,
                 "insula: --lot: %s does not read lots (a .cga or .bldg grammar or a graph does; a "
                 "graph's rule.lua node runs a Lua program on each lot)\n",
                 options.input.c_str());
    return kExitUsage;
  }
  if (has_suffix(options.input, ".cga")) return build_cga(options);
  if (has_suffix(options.input, ".bldg")) return build_bldg(options);
  if (has_suffix(options.input, ".lua")) return build_lua(options);
  if (has_suffix(options.input, ".psm")) return build_plasm(options);
  if (has_suffix(options.input, ".graph.json")) return build_graph(options);
  std::fprintf(stderr, "insula: %s: unknown input type (use .cga, .bldg, .lua or .psm)\n",
               options.input.c_str());
  return kExitUsage;
}

int check_outputs(const std::vector<std::string>& outputs, const std::string& report,
                  const io::OutputOptions& output) {
  for (const std::string& out : outputs) {
    if (!io::is_supported_output(out)) {
      std::fprintf(stderr,
                   "insula: %s: unknown output format (use .obj .glb .gltf .city.json .city.jsonl "
                   ".svg .png)\n",
                   out.c_str());
      return kExitUsage;
    }
    const std::string error =
        io::output_format_name(out) == "png" ? io::validate(output.render) : "";
    if (!error.empty()) {
      std::fprintf(stderr, "insula: %s: %s\n", out.c_str(), error.c_str());
      return kExitUsage;
    }
  }
  std::vector<std::string> targets = outputs;
  if (!report.empty()) targets.push_back(report);
  if (const std::string error = io::check_output_directories(targets); !error.empty()) {
    std::fprintf(stderr, "insula: error: %s\n", error.c_str());
    return kExitInput;
  }
  return kExitDone;
}

bool parse_sets(const std::vector<std::string>& sets,
                std::vector<std::pair<std::string, shape::Value>>& out, std::string& error) {
  for (const std::string& entry : sets) {
    const std::size_t eq = entry.find('=');
    if (eq == std::string::npos || eq == 0) {
      error = "--set '" + entry + "': expected name=value";
      return false;
    }
    out.emplace_back(entry.substr(0, eq), parse_value(entry.substr(eq + 1)));
  }
  return true;
}

int finish_build(const BuildOptions& options, const shape::Scene& scene, nlohmann::json& report,
                 const Stopwatch& total) {
  io::OutputTransaction own(interrupted);
  io::OutputTransaction& transaction = options.transaction ? *options.transaction : own;
  for (const std::string& out : options.outputs) {
    const Stopwatch write_clock;
    if (const std::string error = transaction.write_scene(scene, out, options.output);
        !error.empty()) {
      return write_failure(error);
    }
    report["seconds"]["write_" + io::output_format_name(out)] = write_clock.seconds();
  }
  return commit_build(options, report, total, transaction);
}

TileJobOptions build_tile_job_options(const BuildOptions& options, std::string crs,
                                      kernel::Vec3 origin, std::string counted,
                                      std::function<std::string(std::size_t)> id_of) {
  return {
      options.outputs,     std::move(crs),       origin,          {},
      options.output.gltf, options.output.tiles, options.threads, options.quiet || !Ranks::leader(),
      std::move(counted),  std::move(id_of)};
}

int commit_build_tiles(const BuildOptions& options, TileJob& job, const TileJobResult& built,
                       nlohmann::json& report, const Stopwatch& total,
                       const Stopwatch& build_clock) {
  report["tiles"] = job.tile_count();
  report["ranks"] = built.tiles_by_rank.size();
  report["tiles_by_rank"] = built.tiles_by_rank;
  report["seconds"]["build and write 3dtiles"] = build_clock.seconds();
  io::OutputTransaction transaction(interrupted);
  if (std::string error = job.publish(transaction); !error.empty()) return write_failure(error);
  const int code = commit_build(options, report, total, transaction);
  if (code == kExitDone) job.succeeded();
  return code;
}

int commit_build(const BuildOptions& options, nlohmann::json& report, const Stopwatch& total,
                 io::OutputTransaction& transaction) {
  report["seconds"]["total"] = total.seconds();
  // A batch (`insula random`) shares the process's warning counts between its buildings, so its
  // per-building reports leave them out.
  if (!options.transaction) report["warning_counts"] = warning_counts();
  if (options.amend_report) options.amend_report(report);
  if (!options.report.empty()) {
    if (const std::string error = transaction.write_text(options.report, report.dump(2) + "\n");
        !error.empty()) {
      return write_failure(error);
    }
  }
  if (options.transaction) return kExitDone;  // the batch commits and lists its files
  if (const std::string error = transaction.commit(); !error.empty()) return write_failure(error);
  for (const std::string& out : options.outputs) std::printf("%s\n", out.c_str());
  return kExitDone;
}

}  // namespace insula::cli
