// Generated documentation of the graph front-end: the node reference page (docs/graph-nodes.md)
// from the catalogue, and the graph column of docs/operations.md (how a graph reaches each
// registry operation).
#pragma once

#include <string>
#include <vector>

#include "shape/operation.h"

namespace insula::lang::graph {

// The node reference: every catalogue type with its ports, parameters, node attributes and
// augmentation kinds, by family, in catalogue order.
std::string node_reference_markdown();

// The graph spellings of a registry operation: the node type wrapping it, and `shape.op`.
std::vector<std::string> graph_spellings(const shape::Operation& op);

}  // namespace insula::lang::graph
