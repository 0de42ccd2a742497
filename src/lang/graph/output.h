// What a graph run gives the outside (graph-format.md §13): the export scene of its result
// entities, and the report's `graph` section.
#pragma once

#include <cstddef>
#include <limits>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "lang/graph/executor.h"
#include "shape/scene.h"

namespace insula::lang::graph {

// Result shapes as buildings: entities sharing a value of the top-level attribute `building`
// (when the graph declares it) form one building, in order of first appearance; every other
// result shape is a building of its own, named after its lot when it descends from one. Each shape
// is a part named after its leaf port (its node id), a rule node's model contributes its parts.
// Lights go to Scene::lights.
// `lot_ids` (when the run had only some of the input's lots): every lot id of the input, which
// the names of a lot's later buildings avoid.
shape::Scene to_scene(const RunResult& run, const std::set<std::string>* lot_ids = nullptr);

// The `graph` section of the report (§13): cyclic_edges, node_runs, leaves, blocked,
// unprocessed, failed and one record per result entity, at most `listed` of them (then
// `entities_listed` says so: a city's records are megabytes an editor does not show).
nlohmann::ordered_json graph_report(const RunResult& run,
                                    std::size_t listed = std::numeric_limits<std::size_t>::max());

}  // namespace insula::lang::graph
