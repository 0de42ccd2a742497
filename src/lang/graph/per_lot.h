// Whether a graph treats each lot on its own, so a city can be run a few lots at a time (tile by
// tile, apps/cli/graph_tiles.h) and give, lot for lot, what the whole run gives. A lot's result
// then depends on the lot alone: its seed follows from its number in the input (§9.9,
// LotInput::number) and nothing it passes through sees another entity.
#pragma once

#include <string>

#include "lang/graph/checker.h"

namespace insula::lang::graph {

// Empty when the checked top-level graph is per lot, else why not, naming the node. Per lot: one
// create.lots node reading the --lot file (no `file` parameter, no impulse), every other node fed
// from it, and none that relates entities to each other: no collective port, no second connected
// input port (it would pair entities of different lots), no subgraph, and none of the list,
// query, path, terrain or creation families; no light node either (tiles carry no lights).
std::string per_lot_obstacle(const CheckResult& checked);

// Whether some create.lots node of the checked graphs (subgraphs too) may read the --lot file:
// its `file` is absent, empty or computed.
bool reads_lot_file(const CheckResult& checked);

}  // namespace insula::lang::graph
