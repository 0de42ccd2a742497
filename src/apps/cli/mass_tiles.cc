#include "apps/cli/mass_tiles.h"

#include <oneapi/tbb/parallel_for.h>
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "apps/cli/exit_codes.h"
#include "apps/cli/interrupt.h"
#include "apps/cli/mass_outcome.h"
#include "apps/cli/ranks.h"
#include "apps/cli/tile_job.h"
#include "io/output.h"

namespace insula::cli {
namespace {

using Json = nlohmann::json;

// A tile's buildings: built in parallel, the closed ones (all, without --keep-going) kept for
// writing and counted; per building what the warnings and the report need, where there is
// something to say (most buildings are closed and quiet).
TileContent build_tile(const MassOptions& options, const io::FootprintSet& set,
                       const MassPlan& plan, const std::vector<MassUnit>& units,
                       const std::vector<std::size_t>& members) {
  std::vector<BuiltBuilding> built(members.size());
  tbb::parallel_for(std::size_t{0}, members.size(),
                    [&](std::size_t k) { built[k] = build_unit(set, plan, units[members[k]]); });
  TileContent content;
  MassReport tally;
  for (std::size_t k = 0; k < members.size(); ++k) {
    BuiltBuilding& b = built[k];
    const bool kept = b.watertight || !options.keep_going;
    std::string entry;
    if (kept) {
      tally.count_building(b.building, b.watertight);
      if (options.report_buildings) entry = building_entry(b.building);
    }
    if (!b.watertight || !b.messages.empty() || !entry.empty()) {
      content.notes.emplace_back(members[k], Json::array({b.watertight, b.messages, entry}));
    }
    if (kept) content.buildings.push_back(std::move(b.building));
  }
  content.tally = tally.counts();
  return content;
}

// The leader's part once every rank's work is in: warnings, checks, tileset.json, report, commit.
int conclude(const MassOptions& options, const io::FootprintSet& set,
             const std::vector<MassUnit>& units, TileJob& job, TileJobResult& built,
             std::vector<Warning>& warnings, MassReport& report, const Stopwatch& total,
             const Stopwatch& build_clock) {
  // Only the buildings with a note have something to tell (most are closed and quiet): a
  // million outcomes of the others would cost about 100 MB at the end of the run.
  std::vector<BuildOutcome> outcomes;
  outcomes.reserve(built.notes.size());
  for (auto& [unit, note] : built.notes) {
    const std::size_t feature = units[unit].front();
    outcomes.push_back({set.footprints[feature].id, feature, note[0].get<bool>(),
                        note[1].get<std::vector<std::string>>(), note[2].get<std::string>()});
  }
  for (const Json& counts : built.tallies) report.add_counts(counts);
  report.ranks = static_cast<int>(built.tiles_by_rank.size());
  report.tiles_by_rank = built.tiles_by_rank;
  if (const int code = stop_if_interrupted(); code != 0) return code;
  if (!built.error.empty()) return write_failure(built.error);
  const std::size_t failed = account(options, set, outcomes, warnings);
  for (BuildOutcome& outcome : outcomes) {
    if (!outcome.entry.empty()) report.building_entries.push_back(std::move(outcome.entry));
  }
  if (const int code = check_built(options, failed, report.buildings, units.size()); code != 0) {
    return code;
  }
  report.failed = failed;
  report.stage("build and write 3dtiles", build_clock.seconds());
  emit_mass_warnings(options, warnings, report);
  io::OutputTransaction transaction(interrupted);
  if (std::string error = job.publish(transaction); !error.empty()) return write_failure(error);
  const int code = finish_mass(options, report, total, transaction);
  if (code == kExitDone) job.succeeded();
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
  TileJob job({options.outputs, set.crs, set.origin, plan.materials, options.output.gltf,
               options.output.tiles, options.threads, options.quiet, "buildings",
               [&](std::size_t u) { return set.footprints[units[u].front()].id; }});
  if (const std::string error = job.plan(items); !error.empty()) {
    return Ranks::broadcast(Ranks::leader() ? write_failure(error) : 0);
  }
  TileJobResult built = job.run([&](const std::vector<std::size_t>& members) {
    return build_tile(options, set, plan, units, members);
  });
  int code = 0;
  if (Ranks::leader()) {
    code = conclude(options, set, units, job, built, warnings, report, total, build_clock);
  }
  return Ranks::broadcast(code);
}

}  // namespace insula::cli
