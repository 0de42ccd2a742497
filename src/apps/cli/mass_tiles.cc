#include "apps/cli/mass_tiles.h"

#include <oneapi/tbb/parallel_for.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <optional>
#include <thread>

#include "apps/cli/exit_codes.h"
#include "apps/cli/interrupt.h"
#include "apps/cli/mass_outcome.h"
#include "apps/cli/progress.h"
#include "apps/cli/ranks.h"
#include "io/output.h"
#include "io/tileset_writer.h"

namespace insula::cli {
namespace {

using Json = nlohmann::json;

// What one rank made: per tile its box, error and counts; per building what the warnings and the
// report need (only where there is something to say: most buildings are closed and quiet).
struct RankWork {
  std::vector<std::size_t> tiles;
  std::vector<kernel::Bounds3> boxes;
  std::vector<std::string> errors;
  MassReport tally;                // buildings, watertight, parts, vertices, faces, triangles
  std::vector<std::size_t> units;  // with an outcome worth sending
  std::vector<BuildOutcome> outcomes;
  std::string failure;  // the rank's own: interrupted
};

Json box_json(const kernel::Bounds3& box) {
  return Json::array({box.min.x, box.min.y, box.min.z, box.max.x, box.max.y, box.max.z});
}

kernel::Bounds3 box_of(const Json& j) {
  kernel::Bounds3 box;
  box.min = {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()};
  box.max = {j[3].get<double>(), j[4].get<double>(), j[5].get<double>()};
  return box;
}

// CBOR bytes of a rank's work, for the leader (doubles travel exactly).
std::string encode(const RankWork& work) {
  Json tiles = Json::array();
  for (std::size_t i = 0; i < work.tiles.size(); ++i) {
    tiles.push_back({work.tiles[i], box_json(work.boxes[i]), work.errors[i]});
  }
  Json outcomes = Json::array();
  for (std::size_t i = 0; i < work.units.size(); ++i) {
    const BuildOutcome& o = work.outcomes[i];
    outcomes.push_back({work.units[i], o.watertight, o.messages, o.entry});
  }
  const MassReport& t = work.tally;
  const Json j = {
      {"failure", work.failure},
      {"tiles", tiles},
      {"outcomes", outcomes},
      {"tally", {t.buildings, t.watertight, t.parts, t.vertices, t.faces, t.triangles}}};
  const std::vector<std::uint8_t> bytes = Json::to_cbor(j);
  return {bytes.begin(), bytes.end()};
}

// Adds a rank's work to the whole: boxes to the writers, outcomes by unit, counts to the report.
// Returns how many tiles the rank built.
std::size_t merge(const std::string& bytes,
                  std::vector<std::unique_ptr<io::TilesetWriter>>& writers,
                  std::vector<BuildOutcome>& outcomes, std::vector<std::string>& errors,
                  MassReport& report) {
  const Json j = Json::from_cbor(bytes);
  if (const auto& failure = j["failure"].get_ref<const std::string&>(); !failure.empty()) {
    errors.push_back(failure);
  }
  for (const Json& tile : j["tiles"]) {
    const auto leaf = tile[0].get<std::size_t>();
    for (const auto& writer : writers) writer->set_tile_box(leaf, box_of(tile[1]));
    if (const auto& error = tile[2].get_ref<const std::string&>(); !error.empty()) {
      errors.push_back(error);
    }
  }
  for (const Json& o : j["outcomes"]) {
    BuildOutcome& outcome = outcomes[o[0].get<std::size_t>()];
    outcome.watertight = o[1].get<bool>();
    outcome.messages = o[2].get<std::vector<std::string>>();
    outcome.entry = o[3].get<std::string>();
  }
  const Json& t = j["tally"];
  report.buildings += t[0].get<std::size_t>();
  report.watertight += t[1].get<std::size_t>();
  report.parts += t[2].get<std::size_t>();
  report.vertices += t[3].get<std::size_t>();
  report.faces += t[4].get<std::size_t>();
  report.triangles += t[5].get<std::size_t>();
  return j["tiles"].size();
}

// One tile built and written: its box, its error, its counts, and what the warnings and the report
// need of its buildings that have something to say.
struct TileResult {
  kernel::Bounds3 box;
  std::string error;
  MassReport tally;
  std::vector<std::pair<std::size_t, BuildOutcome>> outcomes;
};

TileResult build_tile(const MassOptions& options, const io::FootprintSet& set, const MassPlan& plan,
                      const std::vector<MassUnit>& units,
                      std::vector<std::unique_ptr<io::TilesetWriter>>& writers, std::size_t leaf) {
  TileResult result;
  const std::vector<std::size_t>& members = writers.front()->leaf_items(leaf);
  std::vector<BuiltBuilding> built(members.size());
  tbb::parallel_for(std::size_t{0}, members.size(),
                    [&](std::size_t k) { built[k] = build_unit(set, plan, units[members[k]]); });
  std::vector<const shape::Building*> kept;
  for (const BuiltBuilding& b : built) {
    if (!b.watertight && options.keep_going) continue;
    kept.push_back(&b.building);
    result.tally.count_building(b.building, b.watertight);
  }
  for (const auto& writer : writers) {
    if (result.error.empty()) result.error = writer->write_tile(leaf, kept);
  }
  result.box = writers.front()->tile_box(leaf);
  for (std::size_t k = 0; k < members.size(); ++k) {
    std::string entry;
    if (options.report_buildings && (built[k].watertight || !options.keep_going)) {
      entry = building_entry(built[k].building);
    }
    if (built[k].watertight && built[k].messages.empty() && entry.empty()) continue;
    BuildOutcome outcome = outcome_of(std::move(built[k]));
    outcome.entry = std::move(entry);
    result.outcomes.emplace_back(members[k], std::move(outcome));
  }
  return result;
}

// This rank's share of the tiles: each of its threads takes the next tile from the shared queue
// until none is left (a tile's buildings are built in parallel too, so a thread that finds no
// tile helps the others finish theirs).
RankWork build_share(const MassOptions& options, const io::FootprintSet& set, const MassPlan& plan,
                     const std::vector<MassUnit>& units,
                     std::vector<std::unique_ptr<io::TilesetWriter>>& writers) {
  const std::size_t leaves = writers.front()->leaf_count();
  Ranks::Queue queue(leaves);
  const std::size_t takers =
      std::max<std::size_t>(1, options.threads > 0 ? static_cast<std::size_t>(options.threads)
                                                   : std::thread::hardware_concurrency());
  std::vector<std::optional<TileResult>> results(leaves);
  Progress progress("buildings", units.size(), options.quiet);
  tbb::parallel_for(std::size_t{0}, takers, [&](std::size_t) {
    for (std::size_t leaf = queue.next(); leaf < leaves && !interrupted(); leaf = queue.next()) {
      results[leaf] = build_tile(options, set, plan, units, writers, leaf);
      progress.advance(writers.front()->leaf_items(leaf).size());
    }
  });
  RankWork work;
  for (std::size_t leaf = 0; leaf < leaves; ++leaf) {
    if (!results[leaf]) continue;
    TileResult& r = *results[leaf];
    work.tiles.push_back(leaf);
    work.boxes.push_back(r.box);
    work.errors.push_back(std::move(r.error));
    work.tally.add_counts(r.tally);
    for (auto& [unit, outcome] : r.outcomes) {
      work.units.push_back(unit);
      work.outcomes.push_back(std::move(outcome));
    }
  }
  // An interrupted rank takes no more tiles (the others build the rest) and fails the run.
  if (interrupted()) work.failure = "interrupted";
  return work;
}

// Where the ranks write the tiles until the run succeeds: a folder beside the final one, renamed
// into place at the end, so a run that fails or is killed midway (a rank's crash aborts them all)
// leaves the earlier tileset as it was. The leader makes the output folder when missing and
// removes what it made unless the run succeeded.
class Staging {
 public:
  static std::filesystem::path folder_of(const std::string& out) {
    return io::tiles_folder(out).string() + ".insula-partial";
  }
  // The leader's preparation: the output folders, and no staging folder left by a killed run.
  std::string prepare(const std::vector<std::string>& outputs) {
    for (const std::string& out : outputs) {
      const std::filesystem::path dir = std::filesystem::path(out).parent_path();
      std::error_code error;
      if (!dir.empty() && !std::filesystem::is_directory(dir, error)) {
        if (!std::filesystem::create_directory(dir, error) || error) {
          return dir.string() + ": cannot create the folder: " + error.message();
        }
        made_.push_back(dir);
      }
      std::filesystem::remove_all(folder_of(out), error);
      staged_.push_back(folder_of(out));
    }
    return {};
  }
  // Moves the staged tiles into place (the transaction has claimed the final paths).
  std::string publish(const std::string& out) {
    std::error_code error;
    std::filesystem::rename(folder_of(out), io::tiles_folder(out), error);
    if (error) return io::tiles_folder(out).string() + ": " + error.message();
    return {};
  }
  void succeeded() { succeeded_ = true; }
  ~Staging() {
    if (succeeded_) return;
    std::error_code ignored;
    for (const std::filesystem::path& folder : staged_)
      std::filesystem::remove_all(folder, ignored);
    for (const std::filesystem::path& dir : made_) std::filesystem::remove(dir, ignored);
  }

 private:
  std::vector<std::filesystem::path> staged_;
  std::vector<std::filesystem::path> made_;  // output folders this run made
  bool succeeded_ = false;
};

// The leader's part once every rank's work is in: warnings, checks, tileset.json, report, commit.
int conclude(const MassOptions& options, const io::FootprintSet& set,
             const std::vector<MassUnit>& units,
             std::vector<std::unique_ptr<io::TilesetWriter>>& writers,
             const std::vector<std::string>& gathered, std::vector<Warning>& warnings,
             MassReport& report, const Stopwatch& total, const Stopwatch& build_clock,
             Staging& staging) {
  std::vector<BuildOutcome> outcomes(units.size());
  for (std::size_t u = 0; u < units.size(); ++u) {
    outcomes[u].id = set.footprints[units[u].front()].id;
    outcomes[u].feature = units[u].front();
  }
  std::vector<std::string> errors;
  report.ranks = static_cast<int>(gathered.size());
  for (const std::string& bytes : gathered) {
    report.tiles_by_rank.push_back(merge(bytes, writers, outcomes, errors, report));
  }
  if (const int code = stop_if_interrupted(); code != 0) return code;
  if (!errors.empty()) return write_failure(errors.front());
  const std::size_t failed = account(options, set, outcomes, warnings);
  for (BuildOutcome& outcome : outcomes) {
    if (!outcome.entry.empty()) report.building_entries.push_back(std::move(outcome.entry));
  }
  if (const int code = check_built(options, failed, report.buildings, outcomes.size()); code != 0) {
    return code;
  }
  report.failed = failed;
  report.stage("build and write 3dtiles", build_clock.seconds());
  emit_mass_warnings(options, warnings, report);
  io::OutputTransaction transaction(interrupted);
  for (std::size_t i = 0; i < writers.size(); ++i) {
    const std::string& out = options.outputs[i];
    if (std::string error = transaction.claim_output(out); !error.empty()) {
      return write_failure(error);
    }
    if (std::string error = staging.publish(out); !error.empty()) return write_failure(error);
    if (std::string error = writers[i]->finish(); !error.empty()) return write_failure(error);
  }
  const int code = finish_mass(options, report, total, transaction);
  if (code == kExitDone) staging.succeeded();
  return code;
}

}  // namespace

int run_mass_tiles(const MassOptions& options, const io::FootprintSet& set, const MassPlan& plan,
                   const std::vector<MassUnit>& units, std::vector<Warning>& warnings,
                   MassReport& report, const Stopwatch& total) {
  const Stopwatch build_clock;
  std::vector<io::TileItem> items;
  items.reserve(units.size());
  for (const MassUnit& unit : units) items.push_back(unit_tile_item(set, unit, options.overhang));
  // The leader makes the folders; then every rank plans the same tiles (the plan depends on the
  // input alone) and writes its share into the staging folders.
  Staging staging;
  std::string error;
  if (Ranks::leader()) error = staging.prepare(options.outputs);
  // Collective: the others wait here for the leader, and all stop if it failed.
  if (Ranks::broadcast(error.empty() ? 0 : 1) != 0) {
    return Ranks::broadcast(Ranks::leader() ? write_failure(error) : 0);
  }
  std::vector<std::unique_ptr<io::TilesetWriter>> writers;
  for (const std::string& out : options.outputs) {
    writers.push_back(std::make_unique<io::TilesetWriter>(
        out, set.crs, set.origin, plan.materials, options.output.gltf, options.output.tiles));
    writers.back()->stage_tiles_in(Staging::folder_of(out));
    if (error.empty()) error = writers.back()->plan(items);
  }
  // A plan fails alike on every rank (the CRS); the leader's word decides.
  if (Ranks::broadcast(error.empty() ? 0 : 1) != 0) {
    return Ranks::broadcast(Ranks::leader() ? write_failure(error) : 0);
  }
  const RankWork work = build_share(options, set, plan, units, writers);
  const std::vector<std::string> gathered = Ranks::gather(encode(work));
  int code = 0;
  if (Ranks::leader()) {
    code = conclude(options, set, units, writers, gathered, warnings, report, total, build_clock,
                    staging);
  }
  return Ranks::broadcast(code);
}

}  // namespace insula::cli
