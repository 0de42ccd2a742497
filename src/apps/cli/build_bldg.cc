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

#include "apps/cli/exit_codes.h"
#include "apps/cli/footprint_input.h"
#include "apps/cli/front_ends.h"
#include "apps/cli/geojson_options.h"
#include "apps/cli/input_file.h"
#include "apps/cli/interrupt.h"
#include "apps/cli/progress.h"
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

void print_error(const std::string& message) {
  std::fprintf(stderr, "insula: error: %s\n", message.c_str());
}

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

// Names a lot in warnings and in the report: its position in the file and its id.
std::string lot_name(const io::Footprint& lot) {
  return "lot " + std::to_string(lot.feature_index) + " (id \"" + lot.id + "\")";
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
  if (!room.merged.empty()) r["merged"] = room.merged;
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

// What the floor plan changed to fit the grammar to the lot (docs/bldg-floorplan.md, "Rooms that
// fit").
nlohmann::json adaptations_report(const lang::bldg::PlanAdaptations& a) {
  return {{"rooms_merged", a.rooms_merged}, {"rooms_dropped", a.rooms_dropped},
          {"doors_added", a.doors_added},   {"entrances_added", a.entrances_added},
          {"stairs_added", a.stairs_added}, {"transitions_dropped", a.transitions_dropped}};
}

void add_adaptations(nlohmann::json& total, const nlohmann::json& one) {
  for (const auto& [key, value] : one.items()) total[key] = total.value(key, 0) + value.get<int>();
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
  report["adaptations"] = adaptations_report(plan.adaptations);
  report["vertices"] = s.vertices;
  report["triangles"] = s.triangles;
  report["warnings"] = nlohmann::json::array();
  for (const auto& w : plan.warnings) report["warnings"].push_back(w.message);
  for (const auto& w : built.warnings) report["warnings"].push_back(w);
  return report;
}

// One grammar through the pipeline: parsed (already), floor plan, 3D model.
struct Built {
  FloorPlan plan;
  lang::bldg::BuildResult result;
  double plan_seconds = 0;
  double build_seconds = 0;
};

// A lot the floor plan cannot use: an outline that is no polygon, or one that cannot hold the
// grammar (PLAN007). --keep-going skips such a lot; grammar errors still stop the run.
bool lot_error(const base::Diagnostic& d) {
  return d.code == "PLAN004" || d.code == "PLAN007";
}

// `lot` names the lot the building stands on in its warnings (empty: an inline outline). With
// `skipped` given (a lot under --keep-going), a lot error is not printed but returned there.
std::optional<Built> plan_and_build(const BuildOptions& options, const base::Source& source,
                                    const Building& building, const lang::bldg::Restrictions& rules,
                                    const std::string& lot,
                                    std::optional<base::Diagnostic>* skipped = nullptr) {
  Stopwatch stage;
  lang::bldg::FloorPlanOptions plan_options;
  plan_options.file = source.name();
  plan_options.on_lot = !lot.empty();
  base::Result<FloorPlan> plan = lang::bldg::make_floor_plan(building, rules, plan_options);
  if (!plan.ok() && skipped != nullptr && lot_error(plan.diagnostics().front())) {
    *skipped = plan.diagnostics().front();
    return std::nullopt;
  }
  print_diagnostics(plan.diagnostics(), source, options.quiet);
  if (!plan.ok()) {
    if (!lot.empty() && lot_error(plan.diagnostics().front()))
      print_error(lot + " cannot be built; --keep-going skips such lots");
    return std::nullopt;
  }
  Built built;
  built.plan_seconds = stage.seconds();
  stage = Stopwatch();
  built.result = lang::bldg::build_building(building, plan.value(), rules);
  built.build_seconds = stage.seconds();
  // The floor planner's and the builder's warnings carry no code of their own; BLD600 and BLD601
  // name the two kinds, so a village's hundreds of them are capped (warnings.h). On a lot, each
  // names the lot, so a user finds the building among thousands.
  // Rooms merged or dropped to fit the lot have their own code (BLD602), capped apart.
  const std::string on = lot.empty() ? "" : lot + ": ";
  for (const auto& w : plan->warnings) {
    const std::string code = w.code.empty() ? "BLD600" : w.code;
    emit_warning(code,
                 source.name() + ":" + std::to_string(w.where.line) + ":" +
                     std::to_string(w.where.column) + ": warning[" + code + "]: " + on + w.message,
                 options.quiet);
  }
  for (const auto& w : built.result.warnings) {
    emit_warning("BLD601", source.name() + ": warning[BLD601]: " + on + w, options.quiet);
  }
  built.plan = std::move(plan.value());
  return built;
}

struct Parsed {
  std::unique_ptr<base::Source> source;
  Building building;
};

std::optional<Parsed> parse_file(const BuildOptions& options, const std::string& path) {
  const auto text = read_input_file(path);
  if (!text) {
    print_error(path + ": " + read_failure(path));
    return std::nullopt;
  }
  Parsed parsed;
  parsed.source = std::make_unique<base::Source>(path, *text);
  base::Result<Building> building = lang::bldg::parse_building(*parsed.source);
  print_diagnostics(building.diagnostics(), *parsed.source, options.quiet);
  if (!building.ok()) return std::nullopt;
  parsed.building = std::move(building.value());
  return parsed;
}

void add_seconds(nlohmann::json& report, const Built& built) {
  const auto add = [&](const char* key, double seconds) {
    report["seconds"][key] = report["seconds"].value(key, 0.0) + seconds;
  };
  add("floor_plan", built.plan_seconds);
  add("build", built.build_seconds);
  add("walls", built.result.stats.seconds_walls);
  add("slabs", built.result.stats.seconds_slabs);
  add("stairs", built.result.stats.seconds_stairs);
  add("roofs", built.result.stats.seconds_roofs);
}

// A village (seed 000, Fig. 12): every feature of --lot is one building, built from the grammar
// its "bldg" property names (relative to the GeoJSON file), else from INPUT, on the feature's
// polygon as outline. Buildings are named after the features.
int build_lots(const BuildOptions& options, const Parsed& input, const Stopwatch& total,
               const lang::bldg::Restrictions& rules, nlohmann::json& report) {
  std::optional<io::FootprintSet> lots =
      read_footprints(options.lot, geojson_options(options.crs, options.keep_going), options.quiet);
  if (!lots) return kExitInput;
  report["invalid_lots"] = lots->skipped_invalid;
  // Lots that cannot hold their grammar, left out under --keep-going, each with its reason.
  report["skipped_lots"] = nlohmann::json::array();
  report["adaptations"] = adaptations_report({});
  const auto skip = [&](const io::Footprint& lot, const std::string& file, Location where,
                        const std::string& reason) {
    emit_warning("BLD603",
                 file + ":" + std::to_string(where.line) + ":" + std::to_string(where.column) +
                     ": warning[BLD603]: " + lot_name(lot) + ": skipped: " + reason,
                 options.quiet);
    report["skipped_lots"].push_back(
        {{"id", lot.id}, {"feature", lot.feature_index}, {"reason", reason}});
  };
  std::map<std::string, Parsed> grammars;
  std::vector<lang::bldg::BuildResult> results;
  report["buildings"] = nlohmann::json::array();
  Progress progress("buildings", lots->footprints.size(), options.quiet);
  for (const io::Footprint& lot : lots->footprints) {
    if (const int code = stop_if_interrupted(); code != 0) return code;
    const Parsed* grammar = &input;
    const auto named = lot.properties.find("bldg");
    if (named != lot.properties.end() && std::holds_alternative<std::string>(named->second)) {
      const std::string path =
          (std::filesystem::path(options.lot).parent_path() / std::get<std::string>(named->second))
              .string();
      if (!grammars.contains(path)) {
        std::optional<Parsed> parsed = parse_file(options, path);
        if (!parsed) return kExitInput;
        grammars.emplace(path, std::move(*parsed));
      }
      grammar = &grammars.at(path);
    }
    if (lot.polygons.size() != 1) {
      const std::string why = "feature '" + lot.id + "' is a MultiPolygon of " +
                              std::to_string(lot.polygons.size()) +
                              " polygons; a building needs one";
      if (options.keep_going) {
        skip(lot, options.lot, {}, why);
        progress.advance();
        continue;
      }
      print_error(options.lot + ": " + why + " (--keep-going skips it)");
      return kExitInput;
    }
    Building building = grammar->building;
    building.outline = lot.polygons.front();
    building.symbol = lot.id;
    std::optional<base::Diagnostic> skipped;
    std::optional<Built> built =
        plan_and_build(options, *grammar->source, building, rules, lot_name(lot),
                       options.keep_going ? &skipped : nullptr);
    if (skipped) {
      skip(lot, grammar->source->name(), {skipped->span.line, skipped->span.column},
           skipped->message);
      progress.advance();
      continue;
    }
    if (!built) return kExitInput;
    nlohmann::json one = plan_report(built->plan, built->result);
    one["id"] = lot.id;
    one["grammar"] = grammar->source->name();
    add_adaptations(report["adaptations"], one["adaptations"]);
    for (const char* key :
         {"rooms", "doors", "entrances", "windows", "stairs", "unreachable_rooms"}) {
      for (nlohmann::json item : one[key]) {
        item["building"] = lot.id;
        report[key].push_back(item);
      }
    }
    for (const auto& w : one["warnings"])
      report["warnings"].push_back(lot_name(lot) + ": " + w.get<std::string>());
    report["vertices"] = report.value("vertices", std::size_t{0}) + built->result.stats.vertices;
    report["triangles"] = report.value("triangles", std::size_t{0}) + built->result.stats.triangles;
    add_seconds(report, *built);
    report["buildings"].push_back(std::move(one));
    results.push_back(std::move(built->result));
    progress.advance();
  }
  progress.finish();
  shape::Scene scene;
  for (lang::bldg::BuildResult& r : results) {
    // One material table for the scene: the builder's tables only differ by the rules' colours,
    // which are the same for every building here.
    if (scene.buildings.empty()) scene.materials = r.materials;
    scene.buildings.push_back(std::move(r.building));
  }
  scene.origin = lots->origin;
  scene.crs = lots->crs;
  report["crs"] = lots->crs.empty() ? nlohmann::json() : nlohmann::json(lots->crs);
  if (!lots->source_crs.empty()) report["reprojected_from"] = lots->source_crs;
  return finish_build(options, scene, report, total);
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
    return build_lots(options, *input, total, rules, report);
  }
  shape::Scene scene;
  std::string lot;
  if (!load_outline(options, *input->source, input->building, scene, lot)) return kExitInput;
  std::optional<Built> built = plan_and_build(options, *input->source, input->building, rules, lot);
  if (!built) return kExitInput;
  report.update(plan_report(built->plan, built->result));
  if (!lot.empty())
    for (auto& w : report["warnings"]) w = lot + ": " + w.get<std::string>();
  add_seconds(report, *built);
  const kernel::Vec3 origin = scene.origin;
  const std::string crs = scene.crs;
  scene = lang::bldg::to_scene(std::move(built->result));
  scene.origin = origin;
  scene.crs = crs;
  return finish_build(options, scene, report, total);
}

}  // namespace insula::cli
