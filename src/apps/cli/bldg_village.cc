#include "apps/cli/bldg_village.h"

#include <oneapi/tbb/global_control.h>
#include <oneapi/tbb/parallel_for.h>

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "apps/cli/exit_codes.h"
#include "apps/cli/footprint_input.h"
#include "apps/cli/geojson_options.h"
#include "apps/cli/interrupt.h"
#include "apps/cli/progress.h"
#include "apps/cli/ranks.h"
#include "apps/cli/tile_job.h"
#include "apps/cli/warnings.h"

namespace insula::cli {
namespace {

using Json = nlohmann::json;

struct Village {
  const BuildOptions& options;
  const Parsed& input;
  const lang::bldg::Restrictions& rules;
  io::FootprintSet lots;
  std::map<std::string, Parsed> grammars;  // named by the lots' "bldg" properties
};

// The grammar a lot names in its "bldg" property, relative to the lot file; empty: INPUT.
std::string grammar_path(const BuildOptions& options, const io::Footprint& lot) {
  const std::optional<shape::Value> named = lot.properties.find("bldg");
  if (!named || !std::holds_alternative<std::string>(*named)) return {};
  return (std::filesystem::path(options.lot).parent_path() / std::get<std::string>(*named))
      .string();
}

// Every grammar the lots name, parsed before any lot is built. False: one failed (printed).
bool parse_grammars(Village& village) {
  for (const io::Footprint& lot : village.lots.footprints) {
    const std::string path = grammar_path(village.options, lot);
    if (path.empty() || village.grammars.contains(path)) continue;
    std::optional<Parsed> parsed = parse_file(village.options, path);
    if (!parsed) return false;
    village.grammars.emplace(path, std::move(*parsed));
  }
  return true;
}

const Parsed& grammar_of(const Village& village, const io::Footprint& lot) {
  const std::string path = grammar_path(village.options, lot);
  return path.empty() ? village.input : village.grammars.at(path);
}

// What one lot gave: its messages, and either a failure, a skip (--keep-going) or a building's
// report entry with its stages' seconds.
struct LotNote {
  Messages messages;
  bool failed = false;
  Json skipped;  // null, or [file, line, column, reason]
  Json entry;    // null unless built
  Json seconds;

  Json json() const { return {messages.json(), failed, skipped, entry, seconds}; }
  static LotNote from_json(const Json& j) {
    return {Messages::from_json(j[0]), j[1].get<bool>(), j[2], j[3], j[4]};
  }
};

struct LotBuild {
  LotNote note;
  std::optional<lang::bldg::BuildResult> result;
};

// The feature's properties become the building's attributes, as on the CGA and mass paths (an
// OpenStreetMap lot keeps its tags in every output). A property wins over what the grammar gave
// the building (its `name`), as a CGA lot property wins over an attr's default.
void add_lot_properties(const io::Footprint& lot, shape::AttributeMap& attributes) {
  shape::AttributeMap merged = lot.properties.map();
  merged.merge(attributes);  // moves only the names the feature lacks
  attributes = std::move(merged);
}

LotBuild build_lot(const Village& village, const io::Footprint& lot) {
  const BuildOptions& options = village.options;
  LotBuild out;
  if (lot.polygons.size() != 1) {
    const std::string why = "feature '" + lot.id + "' is a MultiPolygon of " +
                            std::to_string(lot.polygons.size()) + " polygons; a building needs one";
    if (options.keep_going) {
      out.note.skipped = {options.lot, 0, 0, why};
    } else {
      out.note.messages.error("insula: error: " + options.lot + ": " + why +
                              " (--keep-going skips it)");
      out.note.failed = true;
    }
    return out;
  }
  const Parsed& grammar = grammar_of(village, lot);
  lang::bldg::Building building = grammar.building;
  building.outline = lot.polygons.front();
  building.symbol = lot.id;
  std::optional<base::Diagnostic> skipped;
  std::optional<Built> built =
      plan_and_build(*grammar.source, std::move(building), village.rules, lot_name(lot),
                     out.note.messages, options.keep_going ? &skipped : nullptr);
  if (skipped) {
    out.note.skipped = {grammar.source->name(), skipped->span.line, skipped->span.column,
                        skipped->message};
    return out;
  }
  if (!built) {
    out.note.failed = true;
    return out;
  }
  out.note.entry = plan_report(built->plan, built->result);
  out.note.entry["id"] = lot.id;
  out.note.entry["grammar"] = grammar.source->name();
  out.note.seconds = stage_seconds(*built);
  out.result = std::move(built->result);
  add_lot_properties(lot, out.result->building.attributes);
  return out;
}

// Tells what a lot gave and adds its entry to the report (its rooms, doors, ... named by the
// building). False when the lot failed.
bool account_lot(const BuildOptions& options, const io::Footprint& lot, LotNote note,
                 Json& report) {
  note.messages.print(options.quiet);
  if (note.failed) return false;
  if (!note.skipped.is_null()) {
    const std::string reason = note.skipped[3].get<std::string>();
    emit_warning("BLD603",
                 note.skipped[0].get<std::string>() + ":" +
                     std::to_string(note.skipped[1].get<int>()) + ":" +
                     std::to_string(note.skipped[2].get<int>()) +
                     ": warning[BLD603]: " + lot_name(lot) + ": skipped: " + reason,
                 options.quiet);
    report["skipped_lots"].push_back(
        {{"id", lot.id}, {"feature", lot.feature_index}, {"reason", reason}});
    return true;
  }
  Json& one = note.entry;
  add_adaptations(report["adaptations"], one["adaptations"]);
  for (const char* key :
       {"rooms", "doors", "entrances", "windows", "stairs", "unreachable_rooms"}) {
    for (Json item : one[key]) {
      item["building"] = lot.id;
      report[key].push_back(item);
    }
  }
  for (const auto& w : one["warnings"]) {
    report["warnings"].push_back(lot_name(lot) + ": " + w.get<std::string>());
  }
  report["vertices"] =
      report.value("vertices", std::size_t{0}) + one["vertices"].get<std::size_t>();
  report["triangles"] =
      report.value("triangles", std::size_t{0}) + one["triangles"].get<std::size_t>();
  add_seconds(report, note.seconds);
  report["buildings"].push_back(std::move(one));
  return true;
}

void report_crs(const io::FootprintSet& lots, Json& report) {
  report["crs"] = lots.crs.empty() ? Json() : Json(lots.crs);
  if (!lots.source_crs.empty()) report["reprojected_from"] = lots.source_crs;
}

// The whole village in memory, lot after lot, then every output.
int build_whole(const Village& village, Json& report, const Stopwatch& total) {
  const BuildOptions& options = village.options;
  std::vector<lang::bldg::BuildResult> results;
  Progress progress("buildings", village.lots.footprints.size(), options.quiet);
  for (const io::Footprint& lot : village.lots.footprints) {
    if (const int code = stop_if_interrupted(); code != 0) return code;
    LotBuild built = build_lot(village, lot);
    if (!account_lot(options, lot, std::move(built.note), report)) return kExitInput;
    if (built.result) results.push_back(std::move(*built.result));
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
  scene.origin = village.lots.origin;
  scene.crs = village.lots.crs;
  report_crs(village.lots, report);
  return finish_build(options, scene, report, total);
}

// Faces per square metre of lot, from the sampled lots (built again later, in their tiles).
double faces_per_square_metre(const Village& village) {
  const std::vector<std::size_t> picked = sampled_lots(village.lots.footprints.size());
  std::vector<double> faces(picked.size(), 0);
  tbb::parallel_for(std::size_t{0}, picked.size(), [&](std::size_t k) {
    LotBuild built = build_lot(village, village.lots.footprints[picked[k]]);
    if (built.result) faces[k] = static_cast<double>(io::building_faces(built.result->building));
  });
  double area = 0;
  double sum = 0;
  for (std::size_t k = 0; k < picked.size(); ++k) {
    area += area_of(village.lots.footprints[picked[k]].polygons);
    sum += faces[k];
  }
  return area > 0 ? sum / area : 0;
}

// One tile's lots built in parallel; every lot's note goes to the leader (the report lists every
// building).
TileContent build_tile(const Village& village, const std::vector<std::size_t>& members) {
  std::vector<LotBuild> built(members.size());
  tbb::parallel_for(std::size_t{0}, members.size(), [&](std::size_t k) {
    built[k] = build_lot(village, village.lots.footprints[members[k]]);
  });
  TileContent content;
  for (std::size_t k = 0; k < members.size(); ++k) {
    content.failed = content.failed || built[k].note.failed;
    content.notes.emplace_back(members[k], built[k].note.json());
    if (!built[k].result) continue;
    if (!content.own_materials) {  // the same table for every building (see build_whole)
      content.materials = built[k].result->materials;
      content.own_materials = true;
    }
    content.buildings.push_back(std::move(built[k].result->building));
  }
  return content;
}

// The leader's part once every rank's tiles are in: messages, report, tileset.json, commit.
int conclude(const Village& village, TileJob& job, TileJobResult& built, Json& report,
             const Stopwatch& total, const Stopwatch& build_clock) {
  const BuildOptions& options = village.options;
  if (const int code = stop_if_interrupted(); code != 0) return code;
  for (auto& [lot, note] : built.notes) {
    if (!account_lot(options, village.lots.footprints[lot], LotNote::from_json(note), report)) {
      return kExitInput;
    }
  }
  if (!built.error.empty()) return write_failure(built.error);
  report_crs(village.lots, report);
  return commit_build_tiles(options, job, built, report, total, build_clock);
}

// Tile by tile (tile_job.h); every rank calls it.
int build_by_tiles(const Village& village, Json& report, const Stopwatch& total) {
  const BuildOptions& options = village.options;
  Stopwatch clock;
  const double density = faces_per_square_metre(village);
  std::vector<io::TileItem> items;
  for (const io::Footprint& lot : village.lots.footprints) {
    items.push_back(lot_tile_item(lot.polygons, density, options.output.tiles.tile_faces));
  }
  TileJob job(
      build_tile_job_options(options, village.lots.crs, village.lots.origin, "buildings",
                             [&village](std::size_t i) { return village.lots.footprints[i].id; }));
  if (const std::string error = job.plan(items); !error.empty()) {
    return Ranks::broadcast(Ranks::leader() ? write_failure(error) : 0);
  }
  report["seconds"]["plan"] = clock.seconds();
  clock = Stopwatch();
  TileJobResult built = job.run(
      [&village](const std::vector<std::size_t>& members) { return build_tile(village, members); });
  int code = 0;
  if (Ranks::leader()) code = conclude(village, job, built, report, total, clock);
  return Ranks::broadcast(code);
}

}  // namespace

int build_village(const BuildOptions& options, const Parsed& input,
                  const lang::bldg::Restrictions& rules, nlohmann::json report,
                  const Stopwatch& total) {
  std::optional<tbb::global_control> limit;
  if (options.threads > 0) {
    limit.emplace(tbb::global_control::max_allowed_parallelism,
                  static_cast<std::size_t>(options.threads));
  }
  Village village{options, input, rules, {}, {}};
  LeftOutLots left;
  std::optional<io::FootprintSet> lots =
      read_lot_footprints(options.lot, geojson_options(options.crs, options.keep_going),
                          options.quiet, options.height_unit, left);
  if (!lots) return kExitInput;
  village.lots = std::move(*lots);
  if (!parse_grammars(village)) return kExitInput;
  report["invalid_lots"] = village.lots.skipped_invalid;
  add_left_out_lots(report, left);
  // Lots that cannot hold their grammar, left out under --keep-going, each with its reason.
  report["skipped_lots"] = Json::array();
  report["adaptations"] = adaptations_report({});
  report["buildings"] = Json::array();
  if (city_by_tiles(options)) return build_by_tiles(village, report, total);
  return build_whole(village, report, total);
}

}  // namespace insula::cli
