// Shape entities (internal to the node implementations): making them from footprints and from
// the children of a registry operation, and reading a shape's world outline.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "kernel/mesh.h"
#include "kernel/polygon.h"
#include "lang/graph/node_context.h"

namespace insula::lang::graph {

// A new shape entity (create(round, position)) whose shape is a flat root over `footprint`
// (world XY at `elevation`; scope x along the first edge as given). nullopt with `error` for a
// degenerate footprint.
std::optional<EntityId> footprint_entity(NodeContext& c, std::size_t round, std::uint32_t position,
                                         const kernel::Polygon& footprint, double elevation,
                                         std::string& error);

// A shape entity descending from `parent` (a path's blocks, a query's pieces) whose shape is a
// flat root over `footprint` at `elevation`; nullopt with `error` for a degenerate footprint.
std::optional<EntityId> footprint_child(NodeContext& c, EntityId parent,
                                        const kernel::Polygon& footprint, double elevation,
                                        std::string& error);

// The world-space mesh of a shape entity (a rule node's model: its parts), empty for others.
kernel::Mesh world_mesh(NodeContext& c, EntityId entity);

// Runs registry operation `op` on the shape of `entity`; each child becomes a shape entity
// descending from it (keeping its material). Returns false (after c.fail) when the operation
// fails. `pieces` receives the operation's piece numbers.
bool run_operation(NodeContext& c, EntityId entity, const std::string& op,
                   const std::vector<shape::ArgInput>& args, std::vector<EntityId>& children,
                   std::vector<std::uint32_t>* pieces = nullptr);

// A new shape entity (create(round, position)) holding `world_mesh` in a scope along the world
// axes fitted around it, with the material of the first of `sources` and the attributes all of
// them share (the merging nodes: shape.merge, shape.adjacency_merge).
EntityId merged_entity(NodeContext& c, std::size_t round, std::uint32_t position,
                       std::span<const EntityId> sources, const kernel::Mesh& world_mesh);

// A descendant shape entity of `parent` for an existing shape.
EntityId shape_child(NodeContext& c, EntityId parent, shape::ShapeId shape);

// The outline of a flat shape entity in world XY (scope z must be vertical), or nullopt.
std::optional<kernel::Polygon> world_footprint(NodeContext& c, EntityId entity,
                                               double* elevation = nullptr);

// The XY footprint of a shape entity: its world outline when flat and horizontal, else the
// convex hull of its geometry's XY projection (empty when that has no area).
kernel::Polygon ground_footprint(NodeContext& c, EntityId entity);

// A graph value as a registry argument for `decl` (sizes from their notation "'0.5", "~1").
std::optional<shape::ArgValue> to_argument(const Value& value, const shape::ParamDecl& decl);

// The registry arguments of the node's parameters that the registry operation declares,
// given in the file (the others take the registry's defaults), evaluated for `round`.
std::vector<shape::ArgInput> registry_arguments(NodeContext& c, std::size_t round,
                                                const shape::Operation& op);

}  // namespace insula::lang::graph
