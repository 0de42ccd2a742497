// The 3D Tiles job shared by every verb that builds a city (issue 17; docs/formats.md "3D Tiles",
// docs/cluster.md): the buildings-to-be are grouped into tiles by where they stand, and each tile
// is built by the front-end (its buildings in parallel) and written before the next, so memory
// holds the tiles in flight, never the city's meshes. Under mpirun the tiles are shared among the
// ranks through a work queue and the leader hears what every rank built. The tiles are staged in a
// folder beside the final one and moved into place at the commit point, so a failed or killed run
// leaves the earlier tileset as it was.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/gltf_writer.h"
#include "io/output.h"
#include "io/tile_tree.h"
#include "io/tileset_writer.h"
#include "kernel/polygon.h"
#include "shape/scene.h"

namespace insula::cli {

class Progress;

struct TileJobOptions {
  std::vector<std::string> outputs;        // tileset.json and .city.jsonl files (streamable())
  std::string crs;                         // of the buildings' world coordinates
  kernel::Vec3 origin;                     // local coordinates are world - origin
  std::vector<shape::Material> materials;  // the tiles' table, unless a tile brings its own
  io::GltfOptions gltf;
  io::TilesetOptions tiles;
  int threads = 0;  // tiles built at once on this rank (0: all cores)
  bool quiet = false;
  std::string counted = "buildings";  // what the progress line counts (one per item)
  // The id of the building item i becomes (a CityJSONSeq's part ids avoid every building's id,
  // whichever tile it is in); may be empty.
  std::function<std::string(std::size_t)> id_of;
};

// What the front-end made of one tile's items.
struct TileContent {
  std::vector<shape::Building> buildings;  // local coordinates; written, then dropped
  std::vector<shape::Material> materials;  // the tile's own table when `own_materials`
  bool own_materials = false;
  nlohmann::json tally;  // the front-end's counts for this tile, summed by it at the end
  // What the leader must hear about single items (warnings, failures, report entries), by item.
  std::vector<std::pair<std::size_t, nlohmann::json>> notes;
  bool failed = false;  // the run will fail: this rank takes no more tiles
};

// Builds the tile of these items (ascending); called from several threads at once.
using BuildTile = std::function<TileContent(const std::vector<std::size_t>& items)>;

// What the leader knows once every rank has built its share (empty on the other ranks).
struct TileJobResult {
  std::vector<nlohmann::json> tallies;                        // one per built tile, in tile order
  std::vector<std::pair<std::size_t, nlohmann::json>> notes;  // in item order
  std::vector<nlohmann::json> summaries;                      // one per rank, in rank order
  std::vector<std::size_t> tiles_by_rank;
  bool failed = false;  // a tile said so
  std::string error;    // the first write error, or "interrupted"
};

class TileJob {
 public:
  explicit TileJob(TileJobOptions options);
  ~TileJob();  // the staged tiles and the folders this run made go unless published
  TileJob(const TileJob&) = delete;
  TileJob& operator=(const TileJob&) = delete;

  // Collective: the leader makes the output folders, then every rank plans the same tiles (the
  // plan depends on the items alone). Empty string, or the reason (the same on every rank).
  std::string plan(std::span<const io::TileItem> items);
  std::size_t tile_count() const;

  // Collective: this rank builds and writes its share of the tiles, taking the next one from the
  // shared queue until none is left; `summary` (may be empty) tells what the rank as a whole
  // learnt (e.g. assets it could not find). The result is the leader's.
  TileJobResult run(const BuildTile& build, const std::function<nlohmann::json()>& summary = {});

  // The leader's commit: claims every output in `transaction`, moves the staged tiles into place
  // and writes tileset.json, joins a CityJSONSeq's lines behind its header. Empty string, or the
  // reason. Then call succeeded() once the transaction has committed.
  std::string publish(io::OutputTransaction& transaction);
  void succeeded() { succeeded_ = true; }

 private:
  struct RankShare;
  RankShare build_share(const BuildTile& build, Progress& progress);
  void merge(const std::string& bytes, TileJobResult& result,
             std::vector<std::pair<std::size_t, nlohmann::json>>& tallies);
  std::string write_lines(std::size_t tile, const std::vector<shape::Building>& buildings) const;
  std::string join_lines(const std::string& out) const;

  TileJobOptions options_;
  io::TileTree tree_;
  std::vector<std::size_t> leaves_;                          // tree nodes, in tile order
  std::vector<std::unique_ptr<io::TilesetWriter>> writers_;  // one per tileset output
  std::vector<std::string> tilesets_;                        // their outputs
  std::vector<std::string> sequences_;                       // the .city.jsonl outputs
  std::shared_ptr<const std::unordered_set<std::string>> building_ids_;  // with sequences_
  std::vector<std::filesystem::path> staged_;
  std::vector<std::filesystem::path> made_;  // output folders this run made
  bool succeeded_ = false;
};

// Up to 16 of `count` lots, spread over them: built once before planning to learn how many faces a
// square metre of lot gives (tiles are split by faces, and a lot's faces are known only once it is
// built). Every rank samples the same lots, so every rank plans the same tiles.
std::vector<std::size_t> sampled_lots(std::size_t count);
double area_of(const std::vector<kernel::Polygon>& polygons);
// A lot's tile item: the plan box of its polygons, and `faces_per_square_metre` times its area as
// its weight (at least 1). When the samples showed no faces at all (every one failed or built
// nothing), each lot weighs 1/256 of a tile of `tile_faces`, so no tile holds more than 256 lots.
io::TileItem lot_tile_item(const std::vector<kernel::Polygon>& polygons,
                           double faces_per_square_metre, std::size_t tile_faces);

// Where an output's tiles (a tileset's GLBs, a CityJSONSeq's lines per tile) wait until the run
// succeeds.
std::filesystem::path staging_folder(const std::string& out);

// Prints what the tiles told the leader about their items, in item order: each note's `prints`
// lines (the front-end's print output), then its `diagnostics` ([error?, code, text], warnings
// through the warning switches), each text once when `once`. True when a note says `ok` false.
bool print_tile_notes(const TileJobResult& built, bool quiet, bool once);

// True when every output can be written tile by tile (3D Tiles tilesets and CityJSONSeq): the
// city is built tile by tile, never whole.
bool streamable(const std::vector<std::string>& outputs);

}  // namespace insula::cli
