// `insula build FILE.bldg [--rules R.rules] [--lot F.geojson] [-o OUT]... [--report R.json]`
// (seed 000 end to end: rules' moderator §3.3 -> floor plan §3.2-3.4 -> 3D model §3.4/§4.1/§4.6 ->
// outputs §3.5). docs/bldg-building.md.
//
// The outline of a `geojson(file, feature)` building is read here (front-ends do no file I/O): from
// --lot when given, else from the file named in the grammar, relative to the .bldg file. Any error
// (grammar, rules, outline, floor plan) is printed as `file:line:col: error...`, exits 1 and writes
// nothing.
#include <cstdio>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "apps/cli/exit_codes.h"
#include "apps/cli/front_ends.h"
#include "apps/cli/input_file.h"
#include "io/geojson_reader.h"
#include "lang/bldg/builder.h"
#include "lang/bldg/floorplan.h"
#include "lang/bldg/parser.h"
#include "lang/bldg/restrictions.h"

namespace insula::cli {
namespace {

using lang::bldg::Building;
using lang::bldg::FloorPlan;

void print_error(const std::string& message) {
  std::fprintf(stderr, "insula: error: %s\n", message.c_str());
}

// The restriction rules: the defaults (model.h), or the --rules file.
bool load_rules(const BuildOptions& options, lang::bldg::Restrictions& rules) {
  if (options.rules.empty()) return true;
  const auto text = read_input_file(options.rules);
  if (!text) {
    print_error(options.rules + ": cannot read file");
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
                  shape::Scene& scene) {
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
  if (!text) return fail("cannot read the outline file '" + path + "'");
  base::Result<io::FootprintSet> set = io::read_geojson(*text, path);
  if (!set.ok()) {
    const base::Source lot(path, *text);
    print_diagnostics(set.diagnostics(), lot, options.quiet);
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
  scene.origin = set->origin;
  scene.crs = set->crs;
  return true;
}

nlohmann::json room_report(const lang::bldg::PlanStorey& storey, const lang::bldg::PlanRoom& room,
                           const shape::Building& built) {
  nlohmann::json r;
  r["name"] = room.symbol;
  r["type"] = room.type;
  r["storey"] = storey.level;
  r["part"] = room.part;
  r["area"] = room.area;
  r["target_area"] = room.target_area;
  r["walls"] = room.walls;
  for (const shape::Part& part : built.parts) {
    if (part.kind != shape::PartKind::kRoom) continue;
    const auto name = part.attributes.find("name");
    const auto level = part.attributes.find("storey");
    if (name == part.attributes.end() || level == part.attributes.end()) continue;
    if (std::get_if<std::string>(&name->second) == nullptr ||
        *std::get_if<std::string>(&name->second) != room.symbol ||
        std::get_if<double>(&level->second) == nullptr ||
        *std::get_if<double>(&level->second) != storey.level) {
      continue;
    }
    r["floor_area"] = std::get<double>(part.attributes.at("area"));
  }
  r["neighbors"] = nlohmann::json::array();
  for (int n : room.neighbors) {
    r["neighbors"].push_back(storey.rooms[static_cast<std::size_t>(n)].symbol);
  }
  return r;
}

nlohmann::json door_report(const lang::bldg::PlanStorey& storey, const lang::bldg::PlanDoor& d) {
  const auto name = [&](int room) {
    return room >= 0 ? storey.rooms[static_cast<std::size_t>(room)].symbol : std::string();
  };
  nlohmann::json j;
  if (!d.symbol.empty()) j["symbol"] = d.symbol;
  j["storey"] = storey.level;
  j["from"] = name(d.room_a);
  if (d.room_b >= 0) j["to"] = name(d.room_b);
  j["width"] = d.width;
  j["added"] = d.added;
  return j;
}

nlohmann::json plan_report(const FloorPlan& plan, const lang::bldg::BuildResult& built) {
  nlohmann::json report;
  report["rooms"] = nlohmann::json::array();
  report["doors"] = nlohmann::json::array();
  report["entrances"] = nlohmann::json::array();
  report["windows"] = nlohmann::json::array();
  report["stairs"] = nlohmann::json::array();
  for (const lang::bldg::PlanStorey& storey : plan.storeys) {
    for (const auto& room : storey.rooms) {
      report["rooms"].push_back(room_report(storey, room, built.building));
    }
    for (const auto& d : storey.doors) report["doors"].push_back(door_report(storey, d));
    for (const auto& d : storey.entrances) report["entrances"].push_back(door_report(storey, d));
    for (const auto& w : storey.windows) {
      report["windows"].push_back({{"storey", storey.level},
                                   {"room", storey.rooms[static_cast<std::size_t>(w.room)].symbol},
                                   {"width", w.width}});
    }
    for (const auto& s : storey.stairs) {
      report["stairs"].push_back(
          {{"storey", storey.level},
           {"from", storey.rooms[static_cast<std::size_t>(s.lower_room)].symbol},
           {"to", plan.storeys[static_cast<std::size_t>(storey.level + 1)]
                      .rooms[static_cast<std::size_t>(s.upper_room)]
                      .symbol},
           {"risers", s.risers}});
    }
  }
  report["unreachable_rooms"] = nlohmann::json::array();
  for (const auto& u : plan.unreachable_rooms) {
    report["unreachable_rooms"].push_back(
        {{"name", u.symbol}, {"storey", u.storey}, {"reason", u.reason}});
  }
  const lang::bldg::BuildStats& s = built.stats;
  report["storeys"] = s.storeys;
  report["counts"] = {{"rooms", s.rooms},         {"walls", s.walls},     {"doors", s.doors},
                      {"entrances", s.entrances}, {"windows", s.windows}, {"stairs", s.stairs},
                      {"roofs", s.roofs}};
  report["vertices"] = s.vertices;
  report["triangles"] = s.triangles;
  report["warnings"] = nlohmann::json::array();
  for (const auto& w : plan.warnings) report["warnings"].push_back(w.message);
  for (const auto& w : built.warnings) report["warnings"].push_back(w);
  return report;
}

}  // namespace

int build_bldg(const BuildOptions& options) {
  const Stopwatch total;
  if (const int code = check_build_outputs(options); code != kExitDone) return code;
  const auto text = read_input_file(options.input);
  if (!text) {
    print_error(options.input + ": cannot read file");
    return kExitInput;
  }
  const base::Source source(options.input, *text);
  Stopwatch stage;
  base::Result<Building> parsed = lang::bldg::parse_building(source);
  print_diagnostics(parsed.diagnostics(), source, options.quiet);
  if (!parsed.ok()) return kExitInput;
  const double parse_seconds = stage.seconds();
  lang::bldg::Restrictions rules;
  if (!load_rules(options, rules)) return kExitInput;
  Building& building = parsed.value();
  shape::Scene scene;
  if (!load_outline(options, source, building, scene)) return kExitInput;

  stage = Stopwatch();
  lang::bldg::FloorPlanOptions plan_options;
  plan_options.file = options.input;
  base::Result<FloorPlan> plan = lang::bldg::make_floor_plan(building, rules, plan_options);
  print_diagnostics(plan.diagnostics(), source, options.quiet);
  if (!plan.ok()) return kExitInput;
  const double plan_seconds = stage.seconds();

  stage = Stopwatch();
  lang::bldg::BuildResult built = lang::bldg::build_building(building, plan.value(), rules);
  const double build_seconds = stage.seconds();
  if (!options.quiet) {
    for (const auto& w : plan->warnings) {
      std::fprintf(stderr, "%s:%u:%u: warning: %s\n", options.input.c_str(), w.where.line,
                   w.where.column, w.message.c_str());
    }
    for (const auto& w : built.warnings) {
      std::fprintf(stderr, "%s: warning: %s\n", options.input.c_str(), w.c_str());
    }
  }
  nlohmann::json report = plan_report(plan.value(), built);
  report["input"] = options.input;
  report["seconds"] = {{"parse", parse_seconds},
                       {"floor_plan", plan_seconds},
                       {"build", build_seconds},
                       {"walls", built.stats.seconds_walls},
                       {"slabs", built.stats.seconds_slabs},
                       {"stairs", built.stats.seconds_stairs},
                       {"roofs", built.stats.seconds_roofs}};
  const kernel::Vec3 origin = scene.origin;
  const std::string crs = scene.crs;
  scene = lang::bldg::to_scene(std::move(built));
  scene.origin = origin;
  scene.crs = crs;
  return finish_build(options, scene, report, total);
}

}  // namespace insula::cli
