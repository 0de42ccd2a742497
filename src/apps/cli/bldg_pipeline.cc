#include "apps/cli/bldg_pipeline.h"

#include <cmath>
#include <cstdio>
#include <variant>

#include "apps/cli/front_ends.h"
#include "apps/cli/input_file.h"
#include "apps/cli/progress.h"
#include "apps/cli/stopwatch.h"
#include "apps/cli/warnings.h"
#include "lang/bldg/parser.h"

namespace insula::cli {

using lang::bldg::Building;
using lang::bldg::FloorPlan;

void print_error(const std::string& message) {
  std::fprintf(stderr, "insula: error: %s\n", message.c_str());
}

void Messages::diagnostics(const std::vector<base::Diagnostic>& diagnostics,
                           const base::Source& source) {
  for (const base::Diagnostic& d : diagnostics) {
    if (d.severity == base::Severity::kError) {
      error(base::render(d, &source));
    } else {
      warning(d.code, base::render(d, &source));
    }
  }
}

void Messages::print(bool quiet) const {
  for (const auto& [code, line] : lines_) {
    if (code.empty()) {
      clear_progress_line();
      std::fprintf(stderr, "%s\n", line.c_str());
    } else {
      emit_warning(code, line, quiet);
    }
  }
}

nlohmann::json Messages::json() const {
  nlohmann::json j = nlohmann::json::array();
  for (const auto& [code, line] : lines_) j.push_back({code, line});
  return j;
}

Messages Messages::from_json(const nlohmann::json& j) {
  Messages m;
  for (const nlohmann::json& line : j) {
    m.lines_.emplace_back(line[0].get<std::string>(), line[1].get<std::string>());
  }
  return m;
}

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

std::string lot_name(const io::Footprint& lot) {
  return "lot " + std::to_string(lot.feature_index) + " (id \"" + lot.id + "\")";
}

namespace {

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

}  // namespace

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

namespace {

// A lot the floor plan cannot use: an outline that is no polygon, or one that cannot hold the
// grammar (PLAN007). --keep-going skips such a lot; grammar errors still stop the run.
bool lot_error(const base::Diagnostic& d) {
  return d.code == "PLAN004" || d.code == "PLAN007";
}

// The frame a lot is planned and built in: its outline's first vertex rounded down to whole
// metres. The floor plan and the builder round (the boolean grid, the building's frame) and decide
// (does a stair fit?) on coordinates, so a lot planned in its file's frame came out differently,
// even built or skipped, with its distance from the file's origin, which moves with the file's
// other lots. In its own frame a lot has the same coordinates, bit for bit, whatever else the file
// holds: the file's origin is whole metres too, subtracting whole metres from a coordinate is
// exact, and floor(x - n) = floor(x) - n. The plan makes no random choice: it depends on the
// grammar, the rules and the outline in this frame only.
kernel::Vec2 lot_origin(const kernel::Polygon& outline) {
  if (outline.outer.empty()) return {};
  return {std::floor(outline.outer.front().x), std::floor(outline.outer.front().y)};
}

std::optional<Built> plan_and_build_here(const base::Source& source, const Building& building,
                                         const lang::bldg::Restrictions& rules,
                                         const std::string& lot, Messages& messages,
                                         std::optional<base::Diagnostic>* skipped) {
  Stopwatch stage;
  lang::bldg::FloorPlanOptions plan_options;
  plan_options.file = source.name();
  plan_options.on_lot = !lot.empty();
  base::Result<FloorPlan> plan = lang::bldg::make_floor_plan(building, rules, plan_options);
  if (!plan.ok() && skipped != nullptr && lot_error(plan.diagnostics().front())) {
    *skipped = plan.diagnostics().front();
    return std::nullopt;
  }
  messages.diagnostics(plan.diagnostics(), source);
  if (!plan.ok()) {
    if (!lot.empty() && lot_error(plan.diagnostics().front()))
      messages.error("insula: error: " + lot + " cannot be built; --keep-going skips such lots");
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
    messages.warning(code, source.name() + ":" + std::to_string(w.where.line) + ":" +
                               std::to_string(w.where.column) + ": warning[" + code + "]: " + on +
                               w.message);
  }
  for (const auto& w : built.result.warnings) {
    messages.warning("BLD601", source.name() + ": warning[BLD601]: " + on + w);
  }
  built.plan = std::move(plan.value());
  return built;
}

}  // namespace

std::optional<Built> plan_and_build(const base::Source& source, Building building,
                                    const lang::bldg::Restrictions& rules, const std::string& lot,
                                    Messages& messages, std::optional<base::Diagnostic>* skipped) {
  const kernel::Vec2 origin = lot.empty() ? kernel::Vec2{} : lot_origin(building.outline);
  kernel::translate(building.outline, -origin);
  std::optional<Built> built = plan_and_build_here(source, building, rules, lot, messages, skipped);
  if (built && origin != kernel::Vec2{}) {
    lang::bldg::translate(built->plan, origin);
    shape::translate(built->result.building, {origin.x, origin.y, 0});
  }
  return built;
}

nlohmann::json stage_seconds(const Built& built) {
  return {{"floor_plan", built.plan_seconds},
          {"build", built.build_seconds},
          {"walls", built.result.stats.seconds_walls},
          {"slabs", built.result.stats.seconds_slabs},
          {"stairs", built.result.stats.seconds_stairs},
          {"roofs", built.result.stats.seconds_roofs}};
}

void add_seconds(nlohmann::json& report, const nlohmann::json& seconds) {
  for (const auto& [key, value] : seconds.items()) {
    report["seconds"][key] = report["seconds"].value(key, 0.0) + value.get<double>();
  }
}

}  // namespace insula::cli
