// Families whose implementations are being written (lights and textures): empty tables until
// they land; the executor reports such a node type.
#include "lang/graph/nodes.h"

namespace insula::lang::graph {

std::span<const NodeImpl> light_texture_nodes() {
  return {};
}

}  // namespace insula::lang::graph
