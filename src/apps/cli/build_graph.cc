// `insula build G.graph.json [-o OUT]... [--lot LOTS.geojson] [--seed N] [--set name=value]...
// [--report R.json] [--threads N]`: reads and checks the graph (graph_input.h), runs it
// (lang/graph executor) with the other front-ends behind its rule nodes, and writes the result
// entities (graph-format.md §13; docs/graph-executor.md).
#include <oneapi/tbb/global_control.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <set>
#include <string>
#include <thread>

#include "apps/cli/asset_folders.h"
#include "apps/cli/assets.h"
#include "apps/cli/exit_codes.h"
#include "apps/cli/footprint_input.h"
#include "apps/cli/front_ends.h"
#include "apps/cli/geojson_options.h"
#include "apps/cli/graph_input.h"
#include "apps/cli/graph_rules.h"
#include "apps/cli/graph_tiles.h"
#include "apps/cli/input_file.h"
#include "apps/cli/interrupt.h"
#include "apps/cli/plasm_assets.h"
#include "apps/cli/ranks.h"
#include "apps/cli/s3db_parts.h"
#include "io/asset_search.h"
#include "io/geojson_reader.h"
#include "io/osm_reader.h"
#include "lang/graph/output.h"
#include "lang/graph/per_lot.h"

namespace insula::cli {
namespace {

// Where lots come from: --lot for `file: ""`, else a file in the graph's folder. All lots share
// the first file's origin and CRS (a second file elsewhere is an error).
struct LotFiles {
  const BuildOptions& options;
  std::string folder;
  bool read_any = false;
  kernel::Vec3 origin;
  std::string crs;
  std::string source_crs;  // the lots' own CRS when they were reprojected
  // Over every file read: features skipped as invalid (--keep-going) and lots left out.
  std::size_t invalid = 0;
  LeftOutLots left;
  std::set<std::string> reported;  // files whose reader warnings were printed

  // The report's counts of the lots not built; nothing when no lots file was read.
  void add_counts(nlohmann::json& report) const {
    if (!read_any) return;
    if (!source_crs.empty()) report["reprojected_from"] = source_crs;
    report["invalid_lots"] = invalid;
    add_left_out_lots(report, left);
  }

  bool read(const std::string& file, std::vector<lang::graph::LotInput>& lots, std::string& error) {
    std::string path = options.lot;
    if (!file.empty()) {
      std::string why;
      const std::optional<std::filesystem::path> found = find_in_folders({folder}, file, file, why);
      if (!found) {
        error = "cannot read lots '" + file + "': " + why;
        return false;
      }
      path = found->string();
    } else if (path.empty()) {
      error = "create.lots reads the --lot file, and none was given";
      return false;
    }
    const io::GeoJsonOptions reading =
        building_options(geojson_options(options.crs, options.keep_going));
    std::optional<base::Result<io::FootprintSet>> read;
    std::optional<std::string> text;
    if (io::is_osm_path(path)) {
      read = read_osm_footprints(path, reading);
    } else if ((text = read_input_file(path))) {
      read = io::read_geojson(*text, path, reading);
    } else {
      error = path + ": " + read_failure(path);
      return false;
    }
    base::Result<io::FootprintSet>& set = *read;
    const auto source = [&] {
      return text ? base::Source(path, std::move(*text)) : osm_source(path, set);
    };
    if (!set.ok()) {
      // Every finding of the reader, quoted where it is, then the node's error that points at
      // them (before 2026-11-29 the node quoted the first diagnostic, often a warning).
      print_footprint_read(set, source(), options.quiet);
      const auto errors = std::count_if(
          set.diagnostics().begin(), set.diagnostics().end(),
          [](const base::Diagnostic& d) { return d.severity == base::Severity::kError; });
      error = path + ": the lots could not be read (" + std::to_string(errors) + " error" +
              (errors == 1 ? "" : "s") + " above)";
      return false;
    }
    // The reader's warnings (repairs, geometries skipped), once per file however often a graph's
    // create.lots reads it.
    if (reported.insert(path).second) print_footprint_read(set, source(), options.quiet);
    if (read_any && (set->origin.x != origin.x || set->origin.y != origin.y || set->crs != crs)) {
      error = path + ": its coordinates are in another frame than the first lots file's";
      return false;
    }
    left += leave_out_for_lots(set.value(), options.quiet);
    invalid += set->skipped_invalid;
    lot_heights_in_meters(set.value(), options.height_unit);
    read_any = true;
    origin = set->origin;
    crs = set->crs;
    source_crs = set->source_crs;
    // Lots are numbered in file order, a feature skipped (invalid, under --keep-going) counting as
    // one lot: mending a bad footprint then leaves the other lots' numbers, and so their seeds, as
    // they were (docs/graph-executor.md, create.lots).
    std::uint32_t number = 0;
    std::size_t next_feature = 0;
    for (io::Footprint& f : set->footprints) {
      number += static_cast<std::uint32_t>(f.feature_index - next_feature);
      next_feature = f.feature_index + 1;
      for (std::size_t k = 0; k < f.polygons.size(); ++k) {
        const std::string id = f.polygons.size() == 1 ? f.id : f.id + "#" + std::to_string(k);
        lots.push_back({std::move(f.polygons[k]), f.properties.map(), id, number++});
      }
    }
    return true;
  }
};

std::vector<std::pair<std::string, std::string>> split_sets(const std::vector<std::string>& sets,
                                                            std::string& error) {
  std::vector<std::pair<std::string, std::string>> out;
  for (const std::string& s : sets) {
    const std::size_t eq = s.find('=');
    if (eq == std::string::npos || eq == 0) {
      error = "--set '" + s + "': expected name=value";
      return {};
    }
    out.emplace_back(s.substr(0, eq), s.substr(eq + 1));
  }
  return out;
}

// True when the first step of `path` ("door", "houseA/door") is a node of `root`; what lies
// inside a subgraph node shows only when it runs.
bool has_top_node(const lang::graph::Graph& root, const std::string& path) {
  const std::string first = path.substr(0, path.find('/'));
  return std::any_of(root.nodes.begin(), root.nodes.end(),
                     [&first](const lang::graph::Node& n) { return n.id == first; });
}

}  // namespace

int build_graph(const BuildOptions& options) {
  const Stopwatch total;
  if (const int code = check_build_outputs(options); code != kExitDone) return code;
  nlohmann::json seconds;
  Stopwatch clock;
  const std::optional<std::string> text = read_input_or_report(options.input);
  if (!text) return kExitInput;
  const base::Source source(options.input, *text);
  const std::optional<LoadedGraph> loaded = load_graph(source, options.quiet);
  if (!loaded) return kExitInput;
  if (!options.lot.empty() && !lang::graph::reads_lot_file(loaded->checked)) {
    std::fprintf(stderr,
                 "insula: --lot: %s has no create.lots node that reads the --lot file (its lots "
                 "come from its own nodes)\n",
                 options.input.c_str());
    return kExitUsage;
  }
  seconds["check"] = clock.seconds();

  const std::filesystem::path own = std::filesystem::path(options.input).parent_path();
  const std::string folder = own.empty() ? "." : own.string();
  const io::AssetSearch search(options.input, options.workspace);
  // A graph's missing asset stays an error of the node that asks for it.
  const io::AssetLibrary library(search, io::AssetLibrary::Missing::kError);
  const PlasmAssets assets({folder}, &library);
  std::vector<std::string> attributes;
  for (const lang::graph::Declaration& d : loaded->document->root->attributes) {
    attributes.push_back(d.name);
  }
  const FrontEndRules rules(folder, attributes, &assets);
  LotFiles lot_files{options, folder, false, {}, {}, {}, 0, {}, {}};

  lang::graph::RunOptions run;
  if (!options.probe.empty()) {
    if (!has_top_node(*loaded->document->root, options.probe)) {
      std::fprintf(stderr, "insula: --probe: the graph has no node '%s'\n", options.probe.c_str());
      return kExitUsage;
    }
    run.probe = options.probe;
  }
  if (options.seed_given) run.seed = options.seed;
  std::string error;
  run.sets = split_sets(options.sets, error);
  if (!error.empty()) {
    std::fprintf(stderr, "insula: error: %s\n", error.c_str());
    return kExitUsage;
  }
  run.threads = options.threads > 0
                    ? options.threads
                    : static_cast<int>(std::max(1U, std::thread::hardware_concurrency()));
  run.assets = &assets;
  run.rules = &rules;
  run.lots = [&lot_files](const std::string& file, std::vector<lang::graph::LotInput>& lots,
                          std::string& why) { return lot_files.read(file, lots, why); };
  run.interrupted = [] { return interrupted(); };

  // A city written tile by tile runs its lots a tile at a time when the graph treats each lot on
  // its own; otherwise the graph runs whole (on the leader) and the report says why.
  std::string whole_because;
  if (city_by_tiles(options)) {
    whole_because = lang::graph::per_lot_obstacle(loaded->checked);
    if (whole_because.empty()) {
      std::vector<lang::graph::LotInput> lots;
      if (!lot_files.read("", lots, error)) {
        std::fprintf(stderr, "%s\n", error.c_str());
        return kExitInput;
      }
      seconds["lots"] = clock.seconds();
      nlohmann::json report;
      report["input"] = options.input;
      report["seed"] = run.seed.value_or(static_cast<std::uint64_t>(loaded->document->root->seed));
      report["threads"] = run.threads;
      report["crs"] = lot_files.crs.empty() ? nlohmann::json() : nlohmann::json(lot_files.crs);
      lot_files.add_counts(report);
      report["seconds"] = seconds;
      std::set<std::string> lot_ids;
      for (std::size_t i = 0; i < lots.size(); ++i) {
        lot_ids.insert(lots[i].id.empty() ? "lot_" + std::to_string(i) : lots[i].id);
      }
      const GraphCity city{*loaded,          run,           std::move(lots), std::move(lot_ids),
                           lot_files.origin, lot_files.crs, search};
      return build_graph_tiles(options, city, std::move(report), total);
    }
    if (!Ranks::leader()) return kExitDone;
  }

  clock = Stopwatch();
  std::optional<lang::graph::RunResult> result;
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism,
                              static_cast<std::size_t>(run.threads));
    result.emplace(lang::graph::run_graph(*loaded->document, loaded->checked, run));
  }
  if (const int code = stop_if_interrupted(); code != 0) return code;
  loaded->print(result->diagnostics, options.quiet);
  if (!result->ok) return kExitInput;
  seconds["run"] = clock.seconds();

  // The export scene only when something is written: a report-only run measures the graph.
  clock = Stopwatch();
  shape::Scene scene;
  if (!options.outputs.empty()) {
    scene = lang::graph::to_scene(*result);
    scene.origin = lot_files.origin;
    scene.crs = lot_files.crs;
  }
  // Rule files' textures are found from the graph's folder, as their assets are.
  const std::vector<io::TextureFailure> textures = io::load_textures(scene, search);
  seconds["scene"] = clock.seconds();

  nlohmann::json report;
  report["input"] = options.input;
  report["seed"] = result->seed;
  report["threads"] = run.threads;
  report["entities"] = result->entities.size();
  report["results"] = result->results.size();
  if (!options.outputs.empty()) {
    report["buildings"] = scene.buildings.size();
    report["lights"] = scene.lights.size();
  }
  report["graph"] =
      nlohmann::json::parse(lang::graph::graph_report(*result, options.report_entities).dump());
  if (!whole_because.empty()) report["whole_scene_because"] = whole_because;
  lot_files.add_counts(report);
  report_missing_textures(textures, options.input, options.quiet, report);
  report["seconds"] = seconds;
  return finish_build(options, scene, report, total);
}

}  // namespace insula::cli
