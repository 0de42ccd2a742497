// `insula build G.graph.json --lot LOTS -o DIR/tileset.json` (issue 17) for a graph that treats
// each lot on its own (lang/graph/per_lot.h): the lots are grouped into tiles by where they stand
// and each tile's lots run through the graph together (one run a tile, every lot numbered as in
// the whole input, so it gives what the whole run gives it) and are written before the next tile,
// on the tile job every front-end shares (tile_job.h); under mpirun the tiles are shared among
// the ranks. Diagnostics are printed once each, in the order of the tiles' first lots.
#pragma once

#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "apps/cli/build_command.h"
#include "apps/cli/graph_input.h"
#include "apps/cli/stopwatch.h"
#include "io/asset_search.h"
#include "lang/graph/executor.h"

namespace insula::cli {

// What a graph build runs, once the graph is checked and the lots are read.
struct GraphCity {
  const LoadedGraph& loaded;
  const lang::graph::RunOptions& run;       // seed, sets, threads, assets, rules; not the lots
  std::vector<lang::graph::LotInput> lots;  // every lot of --lot, numbered
  std::set<std::string> lot_ids;            // theirs (lot_<n> for a lot without one)
  kernel::Vec3 origin;
  std::string crs;
  const io::AssetSearch& search;
};

// Runs, writes and reports, tile by tile; `report` comes with the build's earlier fields. Every
// rank calls it and returns the exit code.
int build_graph_tiles(const BuildOptions& options, const GraphCity& city, nlohmann::json report,
                      const Stopwatch& total);

}  // namespace insula::cli
