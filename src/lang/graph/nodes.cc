#include "lang/graph/nodes.h"

#include <array>

namespace insula::lang::graph {

const NodeImpl* find_node_impl(std::string_view type) {
  static const std::array<std::span<const NodeImpl> (*)(), 10> kFamilies = {
      creation_nodes, shape_nodes, merge_nodes,         path_nodes, list_nodes,
      query_nodes,    flow_nodes,  light_texture_nodes, rule_nodes, terrain_nodes};
  for (const auto family : kFamilies) {
    for (const NodeImpl& impl : family()) {
      if (impl.type == type) return &impl;
    }
  }
  return nullptr;
}

}  // namespace insula::lang::graph
