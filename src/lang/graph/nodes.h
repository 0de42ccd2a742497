// The implementations of the catalogue's node types (§11), one function per type, grouped by
// family in nodes_<family>.cc. The executor looks them up by type name; tests/lang/graph checks
// that every catalogue type has one.
#pragma once

#include <span>
#include <string_view>

#include "lang/graph/node_context.h"

namespace insula::lang::graph {

using NodeFn = void (*)(NodeContext&);

struct NodeImpl {
  std::string_view type;
  NodeFn run = nullptr;
};

// Each family's table (nodes_<family>.cc).
std::span<const NodeImpl> creation_nodes();
std::span<const NodeImpl> shape_nodes();
std::span<const NodeImpl> merge_nodes();
std::span<const NodeImpl> path_nodes();
std::span<const NodeImpl> list_nodes();
std::span<const NodeImpl> query_nodes();
std::span<const NodeImpl> flow_nodes();
std::span<const NodeImpl> light_texture_nodes();
std::span<const NodeImpl> rule_nodes();
std::span<const NodeImpl> terrain_nodes();

// The implementation of `type`, or null.
const NodeImpl* find_node_impl(std::string_view type);

}  // namespace insula::lang::graph
