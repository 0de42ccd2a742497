#include "apps/cli/cga_tiles.h"

#include <oneapi/tbb/global_control.h>
#include <oneapi/tbb/parallel_for.h>

#include <algorithm>
#include <map>
#include <optional>
#include <utility>

#include "apps/cli/assets.h"
#include "apps/cli/exit_codes.h"
#include "apps/cli/interrupt.h"
#include "apps/cli/ranks.h"
#include "apps/cli/tile_job.h"
#include "io/textures.h"

namespace insula::cli {

namespace cga = lang::cga;
using Json = nlohmann::json;

nlohmann::json cga_report(const cga::Program& program, const cga::Totals& t, std::size_t lots) {
  Json report;
  report["input"] = program.source->name();
  report["start"] = std::string(program.symbol_name(program.start));
  report["lots"] = lots;
  report["shapes"] = t.shapes;
  report["terminals"] = t.terminals;
  report["rule_applications"] = t.rule_applications;
  report["symbols"] = Json::object();
  for (const auto& [name, count] : t.symbols) report["symbols"][name] = count;
  if (!t.reports.empty()) {
    for (const auto& [name, e] : t.reports) {
      report["reports"][name] = {{"sum", e.sum}, {"count", e.count}};
    }
  }
  return report;
}

namespace {

// Faces per square metre of lot, from the sampled lots (derived again later, in their tiles).
double faces_per_square_metre(const CgaCity& city) {
  const std::vector<std::size_t> picked = sampled_lots(city.lots.size());
  std::vector<cga::LotResult> results(picked.size());
  tbb::parallel_for(std::size_t{0}, picked.size(), [&](std::size_t k) {
    results[k] = cga::derive_lot(city.program, city.lots[picked[k]], city.lots[picked[k]].number,
                                 city.derive);
  });
  std::vector<cga::Lot> lots;
  double area = 0;
  for (const std::size_t i : picked) {
    lots.push_back(city.lots[i]);
    area += area_of(city.lots[i].polygons);
  }
  const shape::Scene scene =
      cga::to_scene(city.program, lots, std::move(results), city.derive.share_inserts);
  std::size_t faces = 0;
  for (const shape::Building& building : scene.buildings) faces += io::building_faces(building);
  return area > 0 ? static_cast<double>(faces) / area : 0;
}

// Where each lot stands and about how many faces it will give.
std::vector<io::TileItem> lot_items(const CgaCity& city, std::size_t tile_faces) {
  const double density = faces_per_square_metre(city);
  std::vector<io::TileItem> items;
  items.reserve(city.lots.size());
  for (const cga::Lot& lot : city.lots) {
    items.push_back(lot_tile_item(lot.polygons, density, tile_faces));
  }
  return items;
}

std::map<std::string, std::size_t> failure_counts(const io::AssetLibrary& library) {
  std::map<std::string, std::size_t> counts;
  for (const io::AssetLibrary::Failure& f : library.failures()) counts[f.name] = f.count;
  return counts;
}

Json totals_json(const cga::Totals& t) {
  Json j = {{"shapes", t.shapes},
            {"terminals", t.terminals},
            {"rule_applications", t.rule_applications},
            {"symbols", t.symbols},
            {"reports", Json::object()}};
  for (const auto& [name, e] : t.reports) j["reports"][name] = {e.sum, e.count};
  return j;
}

void add_totals(const Json& j, cga::Totals& t) {
  t.shapes += j["shapes"].get<std::uint64_t>();
  t.terminals += j["terminals"].get<std::uint64_t>();
  t.rule_applications += j["rule_applications"].get<std::uint64_t>();
  for (const auto& [name, count] : j["symbols"].items())
    t.symbols[name] += count.get<std::uint64_t>();
  for (const auto& [name, e] : j["reports"].items()) {
    t.reports[name].sum += e[0].get<double>();
    t.reports[name].count += e[1].get<std::uint64_t>();
  }
}

// What the leader prints for a lot: its print() lines and its diagnostics, rendered where the lot
// was derived ([error?, code, text]).
Json lot_note(const cga::LotResult& r, const base::Source& source) {
  Json diagnostics = Json::array();
  for (const base::Diagnostic& d : r.diagnostics) {
    diagnostics.push_back({d.severity == base::Severity::kError, d.code, base::render(d, &source)});
  }
  return {{"ok", r.ok}, {"prints", r.prints}, {"diagnostics", std::move(diagnostics)}};
}

// One tile's lots derived (in parallel, each seeded by its feature's place in the input, as the
// whole-scene build seeds it) and turned into buildings with the tile's own material table.
TileContent derive_tile(const CgaCity& city, const std::vector<std::size_t>& members) {
  std::vector<cga::LotResult> results(members.size());
  tbb::parallel_for(std::size_t{0}, members.size(), [&](std::size_t k) {
    results[k] = cga::derive_lot(city.program, city.lots[members[k]], city.lots[members[k]].number,
                                 city.derive);
  });
  TileContent content;
  for (std::size_t k = 0; k < members.size(); ++k) {
    const cga::LotResult& r = results[k];
    if (!r.ok) content.failed = true;
    if (!r.ok || !r.prints.empty() || !r.diagnostics.empty()) {
      content.notes.emplace_back(members[k], lot_note(r, city.source));
    }
  }
  Json tally = totals_json(cga::totals(city.program, results));
  if (content.failed) {
    content.tally = std::move(tally);
    return content;
  }
  std::vector<cga::Lot> lots;
  lots.reserve(members.size());
  for (const std::size_t i : members) lots.push_back(city.lots[i]);
  // The terminal records are freed lot by lot as the buildings are made, before the meshes are
  // written.
  shape::Scene scene =
      cga::to_scene(city.program, lots, std::move(results), city.derive.share_inserts, true);
  tally["textures"] = Json::object();
  for (const io::TextureFailure& f : io::load_textures(scene, city.search)) {
    tally["textures"][f.name] = f.error;
  }
  content.buildings = std::move(scene.buildings);
  content.materials = std::move(scene.materials);
  content.own_materials = true;
  content.tally = std::move(tally);
  return content;
}

// Assets no rank could find, with every rank's requests summed; textures likewise.
void report_missing(const BuildOptions& options, const TileJobResult& built, Json& report) {
  std::map<std::string, io::AssetLibrary::Failure> assets;
  for (const Json& summary : built.summaries) {
    for (const Json& f : summary) {
      io::AssetLibrary::Failure& failure = assets[f[0].get<std::string>()];
      failure.name = f[0].get<std::string>();
      failure.error = f[1].get<std::string>();
      failure.count += f[2].get<std::size_t>();
    }
  }
  std::vector<io::AssetLibrary::Failure> failures;
  for (auto& [name, f] : assets) failures.push_back(std::move(f));
  report_missing_assets(failures, options.input, options.quiet, report);
  std::map<std::string, std::string> textures;
  for (const Json& tally : built.tallies) {
    for (const auto& [name, error] : tally["textures"].items()) textures.emplace(name, error);
  }
  std::vector<io::TextureFailure> missing;
  for (auto& [name, error] : textures) missing.push_back({name, std::move(error)});
  report_missing_textures(missing, options.input, options.quiet, report);
}

// The leader's part once every rank's tiles are in: diagnostics, report, tileset.json, commit.
int conclude(const BuildOptions& options, const CgaCity& city, TileJob& job, TileJobResult& built,
             Json& report, const Stopwatch& total, const Stopwatch& build_clock) {
  if (const int code = stop_if_interrupted(); code != 0) return code;
  if (print_tile_notes(built, options.quiet, false)) return kExitInput;
  if (!built.error.empty()) return write_failure(built.error);
  cga::Totals totals;
  for (const Json& tally : built.tallies) add_totals(tally, totals);
  report.update(cga_report(city.program, totals, city.lots.size()));
  report_missing(options, built, report);
  return commit_build_tiles(options, job, built, report, total, build_clock);
}

}  // namespace

int build_cga_tiles(const BuildOptions& options, const CgaCity& city, nlohmann::json report,
                    const Stopwatch& total) {
  std::optional<tbb::global_control> limit;
  if (options.threads > 0) {
    limit.emplace(tbb::global_control::max_allowed_parallelism,
                  static_cast<std::size_t>(options.threads));
  }
  Stopwatch clock;
  // The sampled lots ask for assets too; every rank samples, so their requests are taken out of
  // each rank's count, and the report counts each lot's requests once, as the whole scene does.
  const std::map<std::string, std::size_t> before = failure_counts(city.library);
  const std::vector<io::TileItem> items = lot_items(city, options.output.tiles.tile_faces);
  std::map<std::string, std::size_t> sampled = failure_counts(city.library);
  for (auto& [name, count] : sampled) {
    if (const auto it = before.find(name); it != before.end()) count -= it->second;
  }
  TileJob job(build_tile_job_options(options, city.crs, city.origin, "lots",
                                     [&city](std::size_t i) { return city.lots[i].id; }));
  if (const std::string error = job.plan(items); !error.empty()) {
    return Ranks::broadcast(Ranks::leader() ? write_failure(error) : 0);
  }
  report["seconds"]["plan"] = clock.seconds();
  clock = Stopwatch();
  TileJobResult built = job.run(
      [&city](const std::vector<std::size_t>& members) { return derive_tile(city, members); },
      [&city, &sampled] {
        Json failures = Json::array();
        for (const io::AssetLibrary::Failure& f : city.library.failures()) {
          const auto it = sampled.find(f.name);
          const std::size_t count = f.count - (it == sampled.end() ? 0 : it->second);
          if (count > 0) failures.push_back({f.name, f.error, count});
        }
        return failures;
      });
  int code = 0;
  if (Ranks::leader()) code = conclude(options, city, job, built, report, total, clock);
  return Ranks::broadcast(code);
}

}  // namespace insula::cli
