#include "apps/cli/graph_tiles.h"

#include <map>
#include <optional>
#include <utility>

#include "apps/cli/assets.h"
#include "apps/cli/exit_codes.h"
#include "apps/cli/interrupt.h"
#include "apps/cli/ranks.h"
#include "apps/cli/tile_job.h"
#include "io/textures.h"
#include "lang/graph/output.h"

namespace insula::cli {
namespace {

namespace graph = lang::graph;
using Json = nlohmann::json;

// The graph run on the lots `members` (indices into city.lots) alone.
graph::RunResult run_lots(const GraphCity& city, const std::vector<std::size_t>& members) {
  std::vector<graph::LotInput> lots;
  lots.reserve(members.size());
  for (const std::size_t m : members) lots.push_back(city.lots[m]);
  graph::RunOptions run = city.run;
  run.lots = [&lots](const std::string& /*file: --lot*/, std::vector<graph::LotInput>& out,
                     std::string& /*error*/) {
    out = lots;
    return true;
  };
  return graph::run_graph(*city.loaded.document, city.loaded.checked, run);
}

// Faces per square metre of lot, from the sampled lots (run again later, in their tiles).
double faces_per_square_metre(const GraphCity& city) {
  const std::vector<std::size_t> picked = sampled_lots(city.lots.size());
  const graph::RunResult result = run_lots(city, picked);
  if (!result.ok) return 0;
  double area = 0;
  for (const std::size_t i : picked) area += area_of({city.lots[i].footprint});
  std::size_t faces = 0;
  for (const shape::Building& building : graph::to_scene(result, &city.lot_ids).buildings) {
    faces += io::building_faces(building);
  }
  return area > 0 ? static_cast<double>(faces) / area : 0;
}

std::vector<io::TileItem> lot_items(const GraphCity& city, std::size_t tile_faces) {
  const double density = faces_per_square_metre(city);
  std::vector<io::TileItem> items;
  items.reserve(city.lots.size());
  for (const graph::LotInput& lot : city.lots) {
    items.push_back(lot_tile_item({lot.footprint}, density, tile_faces));
  }
  return items;
}

// One tile's lots run through the graph and turned into buildings with the tile's own materials;
// its diagnostics (rendered here: ranks share text) go to the leader with the tile's first lot.
TileContent run_tile(const GraphCity& city, const std::vector<std::size_t>& members) {
  const graph::RunResult result = run_lots(city, members);
  TileContent content;
  Json diagnostics = Json::array();
  for (const base::Diagnostic& d : result.diagnostics) {
    diagnostics.push_back({d.severity == base::Severity::kError, d.code, city.loaded.render(d)});
  }
  if (!diagnostics.empty()) {
    content.notes.emplace_back(members.front(),
                               Json{{"ok", result.ok}, {"diagnostics", std::move(diagnostics)}});
  }
  Json tally = {{"entities", result.entities.size()},
                {"results", result.results.size()},
                {"leaves", Json::object()},
                {"textures", Json::object()}};
  // As the whole run's report has them (§13): per leaf port, its count and its entity types.
  for (const auto& [port, count] : result.leaves) {
    tally["leaves"][port] = {{"count", count.count}, {"types", count.types}};
  }
  if (!result.ok) {
    content.failed = true;
    content.tally = std::move(tally);
    return content;
  }
  shape::Scene scene = graph::to_scene(result, &city.lot_ids);
  for (const io::TextureFailure& f : io::load_textures(scene, city.search)) {
    tally["textures"][f.name] = f.error;
  }
  content.buildings = std::move(scene.buildings);
  content.materials = std::move(scene.materials);
  content.own_materials = true;
  content.tally = std::move(tally);
  return content;
}

// The report's counts: entities and results summed over the tiles' runs, leaves by port.
void add_counts(const BuildOptions& options, const TileJobResult& built, std::size_t lots,
                Json& report) {
  std::uint64_t entities = 0;
  std::uint64_t results = 0;
  Json leaves = Json::object();
  std::map<std::string, std::string> textures;
  for (const Json& tally : built.tallies) {
    entities += tally["entities"].get<std::uint64_t>();
    results += tally["results"].get<std::uint64_t>();
    for (const auto& [port, count] : tally["leaves"].items()) {
      Json& sum = leaves[port];
      if (sum.is_null()) sum = {{"count", 0}, {"types", Json::object()}};
      sum["count"] = sum["count"].get<std::uint64_t>() + count["count"].get<std::uint64_t>();
      for (const auto& [type, n] : count["types"].items()) {
        sum["types"][type] = sum["types"].value(type, std::uint64_t{0}) + n.get<std::uint64_t>();
      }
    }
    for (const auto& [name, error] : tally["textures"].items()) textures.emplace(name, error);
  }
  report["lots"] = lots;
  report["entities"] = entities;
  report["results"] = results;
  report["graph"] = {{"leaves", std::move(leaves)}};
  std::vector<io::TextureFailure> missing;
  for (auto& [name, error] : textures) missing.push_back({name, std::move(error)});
  report_missing_textures(missing, options.input, options.quiet, report);
}

}  // namespace

int build_graph_tiles(const BuildOptions& options, const GraphCity& city, Json report,
                      const Stopwatch& total) {
  Stopwatch clock;
  const std::vector<io::TileItem> items = lot_items(city, options.output.tiles.tile_faces);
  TileJob job(
      build_tile_job_options(options, city.crs, city.origin, "lots", [&city](std::size_t i) {
        const graph::LotInput& lot = city.lots[i];
        return lot.id.empty() ? "lot_" + std::to_string(i) : lot.id;
      }));
  if (const std::string error = job.plan(items); !error.empty()) {
    return Ranks::broadcast(Ranks::leader() ? write_failure(error) : 0);
  }
  report["seconds"]["plan"] = clock.seconds();
  clock = Stopwatch();
  TileJobResult built =
      job.run([&city](const std::vector<std::size_t>& members) { return run_tile(city, members); });
  int code = 0;
  if (Ranks::leader()) {
    if (code = stop_if_interrupted(); code == 0) {
      // A warning about the input's properties comes from every tile: each text once.
      if (print_tile_notes(built, options.quiet, true)) {
        code = kExitInput;
      } else if (!built.error.empty()) {
        code = write_failure(built.error);
      } else {
        add_counts(options, built, city.lots.size(), report);
        code = commit_build_tiles(options, job, built, report, total, clock);
      }
    }
  }
  return Ranks::broadcast(code);
}

}  // namespace insula::cli
