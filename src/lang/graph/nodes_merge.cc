// Unification and adjacency merge (graph-format.md §11; seed 003, §4.1 and Fig. 6): the shape
// nodes over kernel/mesh_unify (docs/graph-executor.md, "Merging and unification").
#include <memory>
#include <vector>

#include "kernel/mesh_unify.h"
#include "lang/graph/nodes.h"
#include "lang/graph/shape_entities.h"
#include "shape/scope.h"

namespace insula::lang::graph {
namespace {

// "Unification": the shape's mesh unified in its own scope space, whose axes are orthonormal, so
// the tolerance means metres there as in the world and the geometry needs no round trip. The
// result is a child of the shape with the same scope.
void unify(NodeContext& c) {
  for (std::size_t r = 0; r < c.rounds(); ++r) {
    const EntityId in = c.current(r);
    const shape::ShapeId id = c.entities()[in].shape;
    const shape::Shape& s = c.tree()[id];
    std::shared_ptr<const kernel::Mesh> mesh = s.mesh;
    if (mesh != nullptr) {
      mesh = std::make_shared<kernel::Mesh>(kernel::unify(*mesh, c.param(r, "tolerance").number()));
    }
    const shape::ShapeId child = c.tree().add_child(id, s.scope, mesh, s.outline);
    c.emit(c.output_port("out"), shape_child(c, in, child));
  }
}

// "Adjacency merge": the inputs grouped by shared edges in world space, each group merged (as
// shape.merge: world axes, the attributes its members share) and unified.
void adjacency_merge(NodeContext& c) {
  for (std::size_t r = 0; r < c.rounds(); ++r) {
    const std::span<const EntityId> in = c.input(r, 0);
    if (in.empty()) continue;
    const double tolerance = c.param(r, "tolerance").number();
    std::vector<kernel::Mesh> world;
    world.reserve(in.size());
    for (EntityId e : in) {
      const shape::Shape& s = c.tree()[c.entities()[e].shape];
      world.push_back(s.mesh != nullptr ? shape::mesh_to_world(*s.mesh, s.scope) : kernel::Mesh{});
    }
    const std::vector<std::vector<std::size_t>> groups =
        kernel::group_by_shared_edges(world, tolerance);
    for (std::size_t g = 0; g < groups.size(); ++g) {
      kernel::Mesh merged;
      std::vector<EntityId> members;
      for (std::size_t i : groups[g]) {
        merged.append(world[i]);
        members.push_back(in[i]);
      }
      const EntityId out = merged_entity(c, r, static_cast<std::uint32_t>(g), members,
                                         kernel::unify(merged, tolerance));
      c.emit(c.output_port("out"), out);
    }
  }
}

constexpr NodeImpl kNodes[] = {
    {"shape.unify", unify},
    {"shape.adjacency_merge", adjacency_merge},
};

}  // namespace

std::span<const NodeImpl> merge_nodes() {
  return kNodes;
}

}  // namespace insula::lang::graph
