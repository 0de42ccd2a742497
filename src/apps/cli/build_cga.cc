// `insula build FILE.cga [--lot LOTS.geojson] [--seed N] [--threads N] [--set a=b] [--start S]
// [-o OUT]... [--report R.json]`: parse, check, compile, derive every lot in parallel (each seeded
// by its feature's place in the file, so the output does not depend on --threads), then write the
// outputs and the report (docs/cga-derivation.md).
#include <oneapi/tbb/global_control.h>
#include <oneapi/tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "apps/cli/assets.h"
#include "apps/cli/cga_files.h"
#include "apps/cli/cga_source.h"
#include "apps/cli/cga_tiles.h"
#include "apps/cli/exit_codes.h"
#include "apps/cli/footprint_input.h"
#include "apps/cli/front_ends.h"
#include "apps/cli/geojson_options.h"
#include "apps/cli/input_file.h"
#include "apps/cli/interrupt.h"
#include "apps/cli/plasm_assets.h"
#include "apps/cli/progress.h"
#include "io/asset_search.h"
#include "io/crs.h"
#include "io/geojson_reader.h"
#include "io/obj_reader.h"
#include "io/output.h"
#include "lang/cga/annotations.h"
#include "lang/cga/checker.h"
#include "lang/cga/compile.h"
#include "lang/cga/derive.h"
#include "lang/cga/parser.h"

namespace insula::cli {

namespace {

namespace cga = lang::cga;

struct Lots {
  std::vector<cga::Lot> lots;
  kernel::Vec3 origin;
  std::string crs;
  std::string source_crs;
  std::size_t invalid = 0;  // features skipped with --keep-going
  LeftOutLots left;
};

// --lot: one lot per GeoJSON feature (a MultiPolygon gives one lot of several start shapes).
// Without --lot the lot list stays empty here; the default lot needs the compiled grammar.
std::optional<Lots> read_lots(const BuildOptions& options) {
  Lots out;
  if (options.lot.empty()) return out;
  std::optional<io::FootprintSet> set =
      read_lot_footprints(options.lot, geojson_options(options.crs, options.keep_going),
                          options.quiet, options.height_unit, out.left);
  if (!set) return std::nullopt;
  out.origin = set->origin;
  out.crs = set->crs;
  out.source_crs = set->source_crs;
  out.invalid = set->skipped_invalid;
  for (io::Footprint& f : set->footprints) {
    // The file's first edge, so a lot's x axis follows it even where the reader reversed a
    // clockwise ring.
    out.lots.push_back({std::move(f.id), std::move(f.polygons), f.properties.map(),
                        std::move(f.first_edges), f.feature_index});
  }
  return out;
}

// Names given from outside (--set and lot properties): the checker and the compiler accept them
// in expressions.
// getGeoCoord's lon and lat: the lots' CRS to WGS 84 through PROJ (one transformation per call;
// rules ask it once per lot or so).
class LotsGeoReference final : public cga::GeoReference {
 public:
  LotsGeoReference(kernel::Vec3 lots_origin, std::string crs) : crs_(std::move(crs)) {
    origin = lots_origin;
  }
  std::optional<kernel::Vec2> lon_lat(kernel::Vec2 crs_xy) const override {
    if (crs_.empty()) return std::nullopt;
    std::vector<kernel::Vec2> points{crs_xy};
    if (!io::reproject(crs_, "EPSG:4326", points).empty()) return std::nullopt;
    if (!std::isfinite(points[0].x) || !std::isfinite(points[0].y)) return std::nullopt;
    return points[0];
  }

 private:
  std::string crs_;
};

std::vector<std::string> outside_names(const cga::DeriveOptions& derive, const Lots& lots) {
  std::vector<std::string> names;
  for (const auto& [name, value] : derive.sets) names.push_back(name);
  for (const cga::Lot& lot : lots.lots) {
    for (const auto& [name, value] : lot.properties) names.push_back(name);
  }
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  return names;
}

}  // namespace

int build_cga(const BuildOptions& options) {
  const Stopwatch total;
  if (const int code = check_build_outputs(options); code != kExitDone) return code;
  nlohmann::json seconds;

  Stopwatch clock;
  const std::optional<std::string> text = read_input_or_report(options.input);
  if (!text) return kExitInput;
  CgaSource loaded = load_cga(options.input, *text, options.workspace);
  const base::Source& source = *loaded.source;
  base::Result<cga::Grammar>& grammar = loaded.grammar;
  print_diagnostics(grammar.diagnostics(), source, options.quiet);
  if (!grammar.ok()) return kExitInput;
  seconds["parse"] = clock.seconds();

  cga::DeriveOptions derive;
  derive.seed = options.seed;
  std::string error;
  if (!parse_sets(options.sets, derive.sets, error)) {
    std::fprintf(stderr, "insula: error: %s\n", error.c_str());
    return kExitUsage;
  }
  clock = Stopwatch();
  std::optional<Lots> lots = read_lots(options);
  if (!lots) return kExitInput;
  seconds["read_lots"] = clock.seconds();

  // The static checks (checker.h) before anything is derived; errors stop the build.
  clock = Stopwatch();
  cga::CheckOptions check_options;
  check_options.start = options.start;
  check_options.known_attributes = outside_names(derive, *lots);
  const cga::CheckResult checked = cga::check(grammar.value(), source, check_options);
  print_diagnostics(checked.diagnostics, source, options.quiet);
  if (!checked.ok) return kExitInput;
  if (checked.start_symbol.empty()) {
    std::fprintf(stderr,
                 "%s: error: no rule to start from (a library: no rules, or every rule takes "
                 "parameters; give --start or build a file that imports it)\n",
                 options.input.c_str());
    return kExitInput;
  }
  seconds["check"] = clock.seconds();

  clock = Stopwatch();
  cga::CompileOptions compile_options;
  // The checker's choice (--start, else the dialect's default start rule).
  compile_options.start = checked.start_symbol;
  compile_options.extra_attributes = check_options.known_attributes;
  auto program = cga::compile(grammar.value(), source, compile_options);
  print_diagnostics(program.diagnostics(), source, options.quiet);
  if (!program.ok()) return kExitInput;
  const cga::Program& p = *program.value();
  seconds["compile"] = clock.seconds();

  for (const auto& set : derive.sets) {
    const std::string& name = set.first;  // clang 14 cannot capture a structured binding
    const bool declared = std::any_of(grammar->attrs.begin(), grammar->attrs.end(),
                                      [&](const cga::AttrDecl& a) { return a.name == name; });
    if (!declared) {
      std::fprintf(stderr, "%s: error: --set '%s': the grammar declares no attr '%s'\n",
                   options.input.c_str(), name.c_str(), name.c_str());
      return kExitInput;
    }
    // CityEngine's @Range / @Enum bound the values a user may give (docs/cga-cityengine.md).
    for (const cga::AttrDecl& a : grammar->attrs) {
      if (a.name != name) continue;
      if (const std::optional<std::string> why = cga::annotation_violation(a, set.second)) {
        std::fprintf(stderr, "%s: error: --set %s=%s: %s\n", options.input.c_str(), name.c_str(),
                     shape::to_string(set.second).c_str(), why->c_str());
        return kExitInput;
      }
    }
  }
  derive.keep_terminals = !options.outputs.empty();
  // Equal i() results become instances of one mesh where the GLB places them on the GPU.
  derive.share_inserts = options.output.gltf.instancing == io::GltfOptions::Instancing::kGpu;
  const std::filesystem::path grammar_dir = std::filesystem::path(options.input).parent_path();
  // Assets as CityEngine finds them (docs/assets.md); a missing one inserts nothing and is
  // reported once after the derivation.
  const io::AssetSearch search(options.input, options.workspace);
  const io::AssetLibrary library(search, io::AssetLibrary::Missing::kNothing);
  // PLaSM parts (FILE.psm#EXPRESSION) come from the grammar's folder.
  const PlasmAssets assets({grammar_dir.empty() ? "." : grammar_dir.string()}, &library);
  derive.assets = &assets;
  const io::FileFunctions file_functions(search, library);
  const CgaFiles files(file_functions);
  derive.files = &files;
  const LotsGeoReference geo(lots->origin, lots->crs);
  derive.geo = &geo;
  // Without --lot the grammar's start rule gets the default lot; a --lot file whose every feature
  // was left out (parts above the ground) builds nothing, like the other front-ends.
  if (options.lot.empty()) lots->lots.push_back(cga::default_lot(p, derive));
  const int threads = options.threads > 0
                          ? options.threads
                          : static_cast<int>(std::max(1U, std::thread::hardware_concurrency()));
  nlohmann::json report;
  report["threads"] = threads;
  report["seed"] = options.seed;
  if (!options.lot.empty()) {
    report["invalid_lots"] = lots->invalid;
    add_left_out_lots(report, lots->left);
    report["crs"] = lots->crs.empty() ? nlohmann::json() : nlohmann::json(lots->crs);
    if (!lots->source_crs.empty()) report["reprojected_from"] = lots->source_crs;
  }
  report["seconds"] = seconds;
  if (city_by_tiles(options)) {
    const CgaCity city{p, source, lots->lots, lots->origin, lots->crs, derive, search, library};
    return build_cga_tiles(options, city, std::move(report), total);
  }

  clock = Stopwatch();
  std::vector<cga::LotResult> results(lots->lots.size());
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism,
                              static_cast<std::size_t>(threads));
    Progress progress("lots", results.size(), options.quiet);
    tbb::parallel_for(std::size_t{0}, results.size(), [&](std::size_t i) {
      if (interrupted()) return;
      results[i] = cga::derive_lot(p, lots->lots[i], lots->lots[i].number, derive);
      progress.advance();
    });
  }
  if (const int code = stop_if_interrupted(); code != 0) return code;
  seconds["derive"] = clock.seconds();

  // Diagnostics and print() lines in lot order, whatever the thread count.
  bool failed = false;
  for (const cga::LotResult& r : results) {
    for (const std::string& line : r.prints) std::fprintf(stderr, "%s\n", line.c_str());
    print_diagnostics(r.diagnostics, source, options.quiet);
    failed = failed || !r.ok;
  }
  if (failed) return kExitInput;

  report.update(cga_report(p, cga::totals(p, results), lots->lots.size()));
  clock = Stopwatch();
  shape::Scene scene;
  // CityJSON and 3D Tiles have a part per set of alike terminals, as when written tile by tile
  // (formats.md); the scene keeps a part per terminal only for a GLB's or OBJ's picking.
  BuildOptions written = options;
  written.output.cityjson.merge_alike_parts = true;
  written.output.tiles.merge_alike_parts = true;
  const bool per_terminal =
      std::any_of(options.outputs.begin(), options.outputs.end(), [](const std::string& out) {
        const std::string format = io::output_format_name(out);
        return format == "obj" || format == "glb" || format == "gltf";
      });
  if (!options.outputs.empty()) {
    scene = cga::to_scene(p, lots->lots, std::move(results), derive.share_inserts, !per_terminal);
    scene.origin = lots->origin;
    scene.crs = lots->crs;
  }
  // Textures are found as assets are; a missing one leaves its faces their colour.
  const std::vector<io::TextureFailure> textures = io::load_textures(scene, search);
  seconds["scene"] = clock.seconds();

  report_missing_assets(library.failures(), options.input, options.quiet, report);
  report_missing_textures(textures, options.input, options.quiet, report);
  report["seconds"].update(seconds);
  return finish_build(written, scene, report, total);
}

}  // namespace insula::cli
