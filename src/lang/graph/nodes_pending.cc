// Families whose implementations are being written (path, context queries, lights and
// textures, rule files): empty tables until they land; the executor reports such a node type.
#include "lang/graph/nodes.h"

namespace insula::lang::graph {

std::span<const NodeImpl> path_nodes() { return {}; }
std::span<const NodeImpl> query_nodes() { return {}; }

}  // namespace insula::lang::graph
