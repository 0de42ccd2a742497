#include "apps/cli/tile_job.h"

#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <fstream>
#include <optional>
#include <set>
#include <thread>
#include <utility>

#include "apps/cli/interrupt.h"
#include "apps/cli/progress.h"
#include "apps/cli/ranks.h"
#include "apps/cli/warnings.h"
#include "io/cityjsonseq_writer.h"

namespace insula::cli {

using Json = nlohmann::json;

namespace {

Json box_json(const kernel::Bounds3& box) {
  return Json::array({box.min.x, box.min.y, box.min.z, box.max.x, box.max.y, box.max.z});
}

kernel::Bounds3 box_of(const Json& j) {
  kernel::Bounds3 box;
  box.min = {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()};
  box.max = {j[3].get<double>(), j[4].get<double>(), j[5].get<double>()};
  return box;
}

std::vector<const shape::Building*> pointers_to(const std::vector<shape::Building>& buildings) {
  std::vector<const shape::Building*> pointers;
  for (const shape::Building& b : buildings) pointers.push_back(&b);
  return pointers;
}

}  // namespace

bool is_tileset(const std::string& out) {
  return io::output_format_name(out) == "3dtiles";
}

std::filesystem::path staging_folder(const std::string& out) {
  if (!is_tileset(out)) return out + ".insula-partial";
  return io::tiles_folder(out).string() + ".insula-partial";
}

std::vector<std::size_t> sampled_lots(std::size_t count) {
  constexpr std::size_t kSamples = 16;
  const std::size_t samples = std::min(count, kSamples);
  std::vector<std::size_t> picked;
  for (std::size_t k = 0; k < samples; ++k) picked.push_back(k * count / samples);
  return picked;
}

double area_of(const std::vector<kernel::Polygon>& polygons) {
  double area = 0;
  for (const kernel::Polygon& polygon : polygons) area += kernel::area(polygon);
  return area;
}

io::TileItem lot_tile_item(const std::vector<kernel::Polygon>& polygons,
                           double faces_per_square_metre, std::size_t tile_faces) {
  kernel::Bounds2 box;
  for (const kernel::Polygon& polygon : polygons) {
    const kernel::Bounds2 own = kernel::bounds(polygon);
    box.add(own.min);
    box.add(own.max);
  }
  if (box.empty()) box.add({0, 0});
  const double faces = faces_per_square_metre > 0 ? faces_per_square_metre * area_of(polygons)
                                                  : static_cast<double>(tile_faces) / 256;
  return {box.min, box.max, std::max<std::size_t>(1, static_cast<std::size_t>(faces))};
}

bool print_tile_notes(const TileJobResult& built, bool quiet, bool once) {
  bool failed = false;
  std::set<std::string> printed;
  for (const auto& [item, note] : built.notes) {
    for (const nlohmann::json& line : note.value("prints", nlohmann::json::array())) {
      std::fprintf(stderr, "%s\n", line.get_ref<const std::string&>().c_str());
    }
    for (const nlohmann::json& d : note["diagnostics"]) {
      const std::string& text = d[2].get_ref<const std::string&>();
      if (once && !printed.insert(text).second) continue;
      if (d[0].get<bool>()) {
        clear_progress_line();
        std::fprintf(stderr, "%s\n", text.c_str());
      } else {
        emit_warning(d[1].get<std::string>(), text, quiet);
      }
    }
    failed = failed || !note["ok"].get<bool>();
  }
  return failed;
}

bool streamable(const std::vector<std::string>& outputs) {
  if (outputs.empty()) return false;
  return std::all_of(outputs.begin(), outputs.end(), [](const std::string& out) {
    return is_tileset(out) || io::output_format_name(out) == "cityjsonseq";
  });
}

// One rank's tiles: per tile its index, box, write error, tally; the notes of its items; whether a
// tile failed; the rank's summary.
struct TileJob::RankShare {
  Json tiles = Json::array();
  Json notes = Json::array();
  bool failed = false;
  std::string failure;  // the rank's own: interrupted
};

TileJob::TileJob(TileJobOptions options) : options_(std::move(options)) {
  // An output named twice is written once (its staging folder is one).
  std::vector<std::string> unique;
  for (std::string& out : options_.outputs) {
    if (std::find(unique.begin(), unique.end(), out) == unique.end()) unique.push_back(out);
  }
  options_.outputs = std::move(unique);
}

TileJob::~TileJob() {
  if (succeeded_) return;
  std::error_code ignored;
  for (const std::filesystem::path& folder : staged_) std::filesystem::remove_all(folder, ignored);
  for (const std::filesystem::path& dir : made_) std::filesystem::remove(dir, ignored);
}

std::string TileJob::plan(std::span<const io::TileItem> items) {
  std::string error;
  if (Ranks::leader()) {
    // The output folders, and no staging folder left by a killed run.
    for (const std::string& out : options_.outputs) {
      const std::filesystem::path dir = std::filesystem::path(out).parent_path();
      std::error_code failed;
      if (!dir.empty() && !std::filesystem::is_directory(dir, failed)) {
        if (!std::filesystem::create_directory(dir, failed) || failed) {
          error = dir.string() + ": cannot create the folder: " + failed.message();
          break;
        }
        made_.push_back(dir);
      }
      std::filesystem::remove_all(staging_folder(out), failed);
      staged_.push_back(staging_folder(out));
      // A tileset's writer makes its own; a CityJSONSeq's lines wait here, a file per tile.
      if (!is_tileset(out) && !std::filesystem::create_directory(staging_folder(out), failed)) {
        error = staging_folder(out).string() + ": cannot create the folder: " + failed.message();
        break;
      }
    }
  }
  // Collective: the others wait here for the leader, and all stop if it failed.
  if (Ranks::broadcast(error.empty() ? 0 : 1) != 0) {
    return error.empty() ? "the leader could not prepare the output folders" : error;
  }
  // Every writer plans the same tiles as this job (io/tile_tree.h), in the same order.
  tree_ = io::plan_tiles(items, options_.tiles.tile_faces);
  for (std::size_t n = 0; n < tree_.nodes.size(); ++n) {
    if (tree_.nodes[n].leaf()) leaves_.push_back(n);
  }
  for (const std::string& out : options_.outputs) {
    if (!is_tileset(out)) {
      sequences_.push_back(out);
      continue;
    }
    tilesets_.push_back(out);
    writers_.push_back(std::make_unique<io::TilesetWriter>(
        out, options_.crs, options_.origin, options_.materials, options_.gltf, options_.tiles));
    writers_.back()->stage_tiles_in(staging_folder(out));
    if (error.empty()) error = writers_.back()->plan(items);
  }
  if (!sequences_.empty() && options_.id_of) {
    auto ids = std::make_shared<std::unordered_set<std::string>>();
    for (std::size_t i = 0; i < items.size(); ++i) ids->insert(options_.id_of(i));
    building_ids_ = std::move(ids);
  }
  // A plan fails alike on every rank (the CRS); the leader's word decides.
  if (Ranks::broadcast(error.empty() ? 0 : 1) != 0) {
    return error.empty() ? "the leader could not plan the tiles" : error;
  }
  return {};
}

std::size_t TileJob::tile_count() const {
  return leaves_.size();
}

// A tile's CityJSONSeq lines, one per building (ids are the buildings' own: the readers make the
// input's unique), into each sequence's staging folder.
std::string TileJob::write_lines(std::size_t tile,
                                 const std::vector<shape::Building>& buildings) const {
  if (sequences_.empty()) return {};
  io::CityJsonSeqWriter writer(options_.origin, options_.crs);
  writer.avoid(building_ids_);
  std::string lines;
  for (const shape::Building& building : buildings) lines += writer.feature_line(building);
  for (const std::string& out : sequences_) {
    const std::filesystem::path file = staging_folder(out) / (std::to_string(tile) + ".jsonl");
    std::ofstream stream(file, std::ios::binary);
    stream << lines;
    if (!stream.flush()) return file.string() + ": cannot write";
  }
  return {};
}

// Header, then every tile's lines in tile order, into a file in the staging folder (removed with
// it on failure) renamed into place.
std::string TileJob::join_lines(const std::string& out) const {
  const std::filesystem::path partial = staging_folder(out) / "joined.city.jsonl";
  {
    std::ofstream joined(partial, std::ios::binary);
    joined << io::CityJsonSeqWriter(options_.origin, options_.crs).header_line();
    for (std::size_t tile = 0; tile < leaves_.size(); ++tile) {
      const std::filesystem::path file = staging_folder(out) / (std::to_string(tile) + ".jsonl");
      std::ifstream lines(file, std::ios::binary);
      if (!lines) return file.string() + ": a tile's lines are missing";
      if (lines.peek() != std::ifstream::traits_type::eof()) joined << lines.rdbuf();
    }
    if (!joined.flush()) return out + ": cannot write";
  }
  std::error_code error;
  std::filesystem::rename(partial, out, error);
  if (error) return out + ": " + error.message();
  std::filesystem::remove_all(staging_folder(out), error);
  return {};
}

// Each of this rank's threads takes the next tile from the shared queue until none is left (a
// tile's buildings are built in parallel too, so a thread that finds no tile helps the others).
// Asking for the next tile tells the leader how many items the last one held, so the leader's
// progress counts every rank's.
TileJob::RankShare TileJob::build_share(const BuildTile& build, Progress& progress) {
  const std::size_t tiles = tile_count();
  Ranks::Queue queue(tiles);
  const std::size_t takers =
      std::max<std::size_t>(1, options_.threads > 0 ? static_cast<std::size_t>(options_.threads)
                                                    : std::thread::hardware_concurrency());
  std::vector<std::optional<Json>> done(tiles);
  std::vector<std::vector<std::pair<std::size_t, Json>>> notes(tiles);
  std::atomic<bool> failed = false;
  tbb::parallel_for(std::size_t{0}, takers, [&](std::size_t) {
    std::size_t finished = 0;  // items of the tile this thread last built
    for (std::size_t t = queue.next(); t < tiles; t = queue.next(std::exchange(finished, 0))) {
      if (interrupted() || failed) continue;  // the rest go to other ranks, which stop too
      const std::vector<std::size_t>& members = tree_.nodes[leaves_[t]].items;
      TileContent content;
      std::string error;
      // Isolated: a thread waiting in the tile's own parallel loops takes no other tile meanwhile.
      // An exception (memory) fails the tile, so every rank still reaches the gather.
      tbb::this_task_arena::isolate([&] {
        try {
          content = build(members);
        } catch (const std::exception& e) {
          error = "tile " + std::to_string(t) + ": " + e.what();
          content.failed = true;
        }
      });
      if (error.empty()) error = write_lines(t, content.buildings);
      const std::vector<shape::Material>* materials =
          content.own_materials ? &content.materials : nullptr;
      for (std::size_t w = 0; w < writers_.size() && error.empty(); ++w) {
        // The last writer may take the buildings apart; the others write copies.
        error = w + 1 == writers_.size()
                    ? writers_[w]->write_tile(t, std::move(content.buildings), materials)
                    : writers_[w]->write_tile(t, pointers_to(content.buildings), materials);
      }
      Json blocks = Json::array();
      kernel::Bounds3 box;
      if (!writers_.empty()) {
        box = writers_.front()->tile_box(t);
        for (const kernel::Bounds3& block : writers_.front()->tile_blocks(t)) {
          blocks.push_back(box_json(block));
        }
      }
      done[t] = Json::array({t, box_json(box), error, std::move(content.tally), std::move(blocks)});
      notes[t] = std::move(content.notes);
      if (content.failed || !error.empty()) failed = true;
      finished = members.size();
      // Only the leader shows progress; the others ask nothing more of it.
      if (Ranks::leader()) progress.reach(queue.finished() + finished);
    }
  });
  RankShare share;
  share.failed = failed;
  for (std::size_t t = 0; t < tiles; ++t) {
    if (!done[t]) continue;
    share.tiles.push_back(std::move(*done[t]));
    for (auto& [item, note] : notes[t]) share.notes.push_back({item, std::move(note)});
  }
  // An interrupted rank takes no more tiles and fails the run.
  if (interrupted()) share.failure = "interrupted";
  return share;
}

// Adds a rank's share to the whole: boxes to the writers, tallies by tile, notes and errors.
void TileJob::merge(const std::string& bytes, TileJobResult& result,
                    std::vector<std::pair<std::size_t, Json>>& tallies) {
  Json j = Json::from_cbor(bytes);
  if (const auto& failure = j["failure"].get_ref<const std::string&>();
      !failure.empty() && result.error.empty()) {
    result.error = failure;
  }
  result.failed = result.failed || j["failed"].get<bool>();
  for (Json& tile : j["tiles"]) {
    const auto t = tile[0].get<std::size_t>();
    std::vector<kernel::Bounds3> blocks;
    for (const Json& block : tile[4]) blocks.push_back(box_of(block));
    for (const auto& writer : writers_) {
      writer->set_tile_box(t, box_of(tile[1]));
      writer->set_tile_blocks(t, blocks);
    }
    if (const auto& error = tile[2].get_ref<const std::string&>();
        !error.empty() && result.error.empty()) {
      result.error = error;
    }
    tallies.emplace_back(t, std::move(tile[3]));
  }
  for (Json& note : j["notes"])
    result.notes.emplace_back(note[0].get<std::size_t>(), std::move(note[1]));
  result.tiles_by_rank.push_back(j["tiles"].size());
  result.summaries.push_back(std::move(j["summary"]));
}

TileJobResult TileJob::run(const BuildTile& build, const std::function<Json()>& summary) {
  std::size_t items = 0;
  for (const std::size_t node : leaves_) items += tree_.nodes[node].items.size();
  Progress progress(options_.counted, items, options_.quiet);
  const RankShare share = build_share(build, progress);
  const Json mine = {{"failure", share.failure},
                     {"failed", share.failed},
                     {"tiles", share.tiles},
                     {"notes", share.notes},
                     {"summary", summary ? summary() : Json()}};
  const std::vector<std::uint8_t> cbor = Json::to_cbor(mine);
  const std::vector<std::string> gathered = Ranks::gather({cbor.begin(), cbor.end()});
  TileJobResult result;
  if (!Ranks::leader()) return result;
  // Tallies and notes in tile and item order, whichever rank built them: the outcome does not
  // depend on how the tiles were shared.
  std::vector<std::pair<std::size_t, Json>> tallies;
  for (const std::string& bytes : gathered) merge(bytes, result, tallies);
  std::sort(tallies.begin(), tallies.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  // Every rank's tiles are in: the last line counts all they built (the ranks' last tiles may
  // end after the leader's).
  std::size_t built = 0;
  for (const auto& [tile, tally] : tallies) built += tree_.nodes[leaves_[tile]].items.size();
  progress.reach(built);
  for (auto& [tile, tally] : tallies) result.tallies.push_back(std::move(tally));
  std::sort(result.notes.begin(), result.notes.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  return result;
}

std::string TileJob::publish(io::OutputTransaction& transaction) {
  for (std::size_t i = 0; i < writers_.size(); ++i) {
    const std::string& out = tilesets_[i];
    if (std::string error = transaction.claim_output(out); !error.empty()) return error;
    std::error_code error;
    std::filesystem::rename(staging_folder(out), io::tiles_folder(out), error);
    if (error) return io::tiles_folder(out).string() + ": " + error.message();
    if (std::string failed = writers_[i]->finish(); !failed.empty()) return failed;
  }
  for (const std::string& out : sequences_) {
    if (std::string error = transaction.claim_output(out); !error.empty()) return error;
    if (std::string error = join_lines(out); !error.empty()) return error;
  }
  return {};
}

}  // namespace insula::cli
