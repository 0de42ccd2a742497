// Entity properties readable in expressions without an attribute (graph-format.md §5): area,
// perimeter, volume, scope size, position, centroid, normal and type, in world space.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "lang/graph/entity.h"
#include "lang/graph/value.h"
#include "shape/scope.h"
#include "shape/shape_tree.h"

namespace insula::lang::graph {

// The scope of an actor: a shape's own; a path's, point's, light's or terrain's axis-aligned
// bounds.
std::optional<shape::Scope> entity_scope(const EntityStore& entities, const shape::ShapeTree& tree,
                                         EntityId id);

// `name` (area, perimeter, volume, sx, sy, sz, pos, centroid, normal, type) of the entity, or
// nullopt with `error` saying why it does not apply.
std::optional<Value> entity_property(const EntityStore& entities, const shape::ShapeTree& tree,
                                     EntityId id, std::string_view name, std::string& error);

// Measures for reports: area (a flat shape's outline, else the mesh's faces), volume (closed
// meshes), face count; a model's parts summed.
struct Measures {
  double area = 0;
  double volume = 0;
  std::size_t faces = 0;
};
Measures measure(const EntityStore& entities, const shape::ShapeTree& tree, EntityId id);

}  // namespace insula::lang::graph
