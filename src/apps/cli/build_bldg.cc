// `insula build FILE.bldg [--rules R.rules] [--lot F.geojson] [-o OUT]... [--report R.json]`
// (seed 000 end to end: rules' moderator §3.3 -> floor plan §3.2-3.4 -> 3D model §3.4/§4.1/§4.6 ->
// outputs §3.5). docs/bldg-building.md.
//
// The outline of a `geojson(file, feature)` building is read here (front-ends do no file I/O): from
// --lot when given, else from the file named in the grammar, relative to the .bldg file. With
// --lot and a grammar that names no feature, every feature of the lot file becomes a building (a
// village, Fig. 12; see build_lots). Any error (grammar, rules, outline, floor plan) is printed as
// `file:line:col: error...`, exits 1 and writes nothing.
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <variant>

#include <nlohmann/json.hpp>

#include "apps/cli/bldg_pipeline.h"
#include "apps/cli/bldg_village.h"
#include "apps/cli/exit_codes.h"
#include "apps/cli/footprint_input.h"
#include "apps/cli/front_ends.h"
#include "apps/cli/geojson_options.h"
#include "apps/cli/input_file.h"
#include "apps/cli/interrupt.h"
#include "apps/cli/progress.h"
#include "apps/cli/ranks.h"
#include "apps/cli/warnings.h"
#include "io/geojson_reader.h"
#include "lang/bldg/builder.h"
#include "lang/bldg/floorplan.h"
#include "lang/bldg/parser.h"
#include "lang/bldg/restrictions.h"

namespace insula::cli {
namespace {

using lang::bldg::Building;
using lang::bldg::FloorPlan;
using lang::bldg::Location;

// The restriction rules: the defaults (model.h), or the --rules file.
bool load_rules(const BuildOptions& options, lang::bldg::Restrictions& rules) {
  if (options.rules.empty()) return true;
  const auto text = read_input_file(options.rules);
  if (!text) {
    print_error(options.rules + ": " + read_failure(options.rules));
    return false;
  }
  const base::Source source(options.rules, *text);
  base::Result<lang::bldg::Restrictions> parsed = lang::bldg::parse_restrictions(source);
  print_diagnostics(parsed.diagnostics(), source, options.quiet);
  if (!parsed.ok()) return false;
  rules = std::move(parsed.value());
  return true;
}

base::Diagnostic outline_error(const Building& building, const std::string& file,
                               const std::string& message) {
  const lang::bldg::Location at =
      building.outline_where.line > 0 ? building.outline_where : building.where;
  return base::Diagnostic::error("BLD500", message, base::Span::at(file, at.line, at.column));
}

// Fills building.outline from a GeoJSON feature when the grammar asks for one or --lot is given.
// The scene takes the file's origin and CRS, so outputs land where the lot is.
bool load_outline(const BuildOptions& options, const base::Source& source, Building& building,
                  shape::Scene& scene, std::string& lot) {
  if (building.outline_file.empty() && options.lot.empty()) return true;
  std::string path = options.lot;
  if (path.empty()) {
    path = (std::filesystem::path(options.input).parent_path() / building.outline_file).string();
  }
  const auto fail = [&](const std::string& message) {
    print_diagnostics({outline_error(building, options.input, message)}, source, options.quiet);
    return false;
  };
  const auto text = read_input_file(path);
  if (!text)
    return fail("cannot read the outline file '" + path + "': " + read_failure_reason(path));
  base::Result<io::FootprintSet> set =
      io::read_geojson(*text, path, geojson_options(options.crs, false, false));
  if (!set.ok()) {
    const base::Source file(path, *text);
    print_diagnostics(set.diagnostics(), file, options.quiet);
    return fail("the outline file '" + path + "' is not valid GeoJSON");
  }
  const io::Footprint* chosen = nullptr;
  for (const io::Footprint& f : set->footprints) {
    if (building.outline_feature.empty() ? set->footprints.size() == 1
                                         : f.id == building.outline_feature) {
      chosen = &f;
    }
  }
  if (chosen == nullptr) {
    return fail(building.outline_feature.empty()
                    ? "'" + path + "' holds " + std::to_string(set->footprints.size()) +
                          " features; name one with geojson(file, feature)"
                    : "no feature '" + building.outline_feature + "' in '" + path + "'");
  }
  if (chosen->polygons.size() != 1) {
    return fail("feature '" + chosen->id + "' is a MultiPolygon of " +
                std::to_string(chosen->polygons.size()) + " polygons; a building needs one");
  }
  building.outline = chosen->polygons.front();
  lot = lot_name(*chosen);
  scene.origin = set->origin;
  scene.crs = set->crs;
  return true;
}

}  // namespace

int build_bldg(const BuildOptions& options) {
  const Stopwatch total;
  if (const int code = check_build_outputs(options); code != kExitDone) return code;
  Stopwatch stage;
  std::optional<Parsed> input = parse_file(options, options.input);
  if (!input) return kExitInput;
  nlohmann::json report;
  report["input"] = options.input;
  report["seconds"]["parse"] = stage.seconds();
  lang::bldg::Restrictions rules;
  if (!load_rules(options, rules)) return kExitInput;
  if (!options.lot.empty() && input->building.outline_feature.empty()) {
    for (const char* key :
         {"rooms", "doors", "entrances", "windows", "stairs", "unreachable_rooms", "warnings"}) {
      report[key] = nlohmann::json::array();
    }
    return build_village(options, *input, rules, report, total);
  }
  // One building is the leader's alone (the other ranks of an mpirun have nothing to share).
  if (!Ranks::leader()) return kExitDone;
  shape::Scene scene;
  std::string lot;
  if (!load_outline(options, *input->source, input->building, scene, lot)) return kExitInput;
  Messages messages;
  std::optional<Built> built =
      plan_and_build(*input->source, std::move(input->building), rules, lot, messages);
  messages.print(options.quiet);
  if (!built) return kExitInput;
  report.update(plan_report(built->plan, built->result));
  if (!lot.empty())
    for (auto& w : report["warnings"]) w = lot + ": " + w.get<std::string>();
  add_seconds(report, stage_seconds(*built));
  const kernel::Vec3 origin = scene.origin;
  const std::string crs = scene.crs;
  scene = lang::bldg::to_scene(std::move(built->result));
  scene.origin = origin;
  scene.crs = crs;
  return finish_build(options, scene, report, total);
}

}  // namespace insula::cli
