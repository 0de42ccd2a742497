#include "lang/graph/properties.h"

#include <algorithm>
#include <cmath>

#include "kernel/mesh.h"
#include "kernel/polygon.h"

namespace insula::lang::graph {
namespace {

shape::Scope bounds_scope(std::span<const kernel::Vec3> points) {
  shape::Scope s;
  if (points.empty()) return s;
  kernel::Vec3 lo = points.front();
  kernel::Vec3 hi = points.front();
  for (const kernel::Vec3& p : points) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  s.origin = lo;
  s.size = hi - lo;
  return s;
}

double path_length(const PathGeometry& path) {
  double total = 0;
  for (const auto& [a, b] : path.edges) total += length(path.vertices[b] - path.vertices[a]);
  return total;
}

}  // namespace

std::optional<shape::Scope> entity_scope(const EntityStore& entities, const shape::ShapeTree& tree,
                                         EntityId id) {
  const Entity& e = entities[id];
  switch (e.type) {
    case EntityType::kShape:
      return tree[e.shape].scope;
    case EntityType::kPath:
      return bounds_scope(e.path->vertices);
    case EntityType::kPoint:
    case EntityType::kLight: {
      shape::Scope s;
      s.origin = e.position;
      return s;
    }
    case EntityType::kTerrain: {
      // Its bounds: the grid's extent and the lowest and highest sample.
      const kernel::Heightfield& f = *e.terrain;
      const auto [lo, hi] = std::minmax_element(f.z.begin(), f.z.end());
      shape::Scope s;
      s.origin = {f.origin.x, f.origin.y, *lo};
      s.size = {f.width(), f.depth(), *hi - *lo};
      return s;
    }
    default:
      return std::nullopt;
  }
}

std::optional<Value> entity_property(const EntityStore& entities, const shape::ShapeTree& tree,
                                     EntityId id, std::string_view name, std::string& error) {
  const Entity& e = entities[id];
  if (name == "type") return Value(std::string(entity_type_name(e.type)));
  const std::optional<shape::Scope> scope = entity_scope(entities, tree, id);
  const auto not_for = [&]() -> std::optional<Value> {
    std::string message(1, '\'');
    message += name;
    message += "()' does not apply to a ";
    message += entity_type_name(e.type);
    message += " entity";
    error = std::move(message);
    return std::nullopt;
  };
  if (!scope) return not_for();
  if (name == "sx") return Value(scope->size.x);
  if (name == "sy") return Value(scope->size.y);
  if (name == "sz") return Value(scope->size.z);
  if (name == "pos") {
    return Value(e.type == EntityType::kPoint || e.type == EntityType::kLight ? e.position
                                                                              : scope->center());
  }
  if (e.type == EntityType::kPath) {
    if (name == "perimeter") return Value(path_length(*e.path));
    if (name == "area" || name == "volume") return Value(0.0);
    if (name == "centroid") return Value(scope->center());
    return not_for();
  }
  if (e.type != EntityType::kShape) {
    if (name == "area" || name == "volume" || name == "perimeter") return Value(0.0);
    if (name == "centroid") return Value(e.position);
    return not_for();
  }
  const shape::Shape& s = tree[e.shape];
  if (name == "area") return Value(measure(entities, tree, id).area);
  if (name == "volume") return Value(measure(entities, tree, id).volume);
  if (name == "perimeter") {
    if (s.outline == nullptr) {
      error = "'perimeter()' needs a flat shape";
      return std::nullopt;
    }
    return Value(kernel::perimeter(*s.outline));
  }
  if (name == "centroid") {
    if (s.outline != nullptr) {
      const kernel::Vec2 c = kernel::centroid(*s.outline);
      return Value(s.scope.to_world({c.x, c.y, 0}));
    }
    if (s.mesh == nullptr || s.mesh->vertex_count() == 0) return Value(s.scope.center());
    kernel::Vec3 sum;
    for (const kernel::Vec3& p : s.mesh->positions()) sum = sum + p;
    return Value(s.scope.to_world(sum / static_cast<double>(s.mesh->vertex_count())));
  }
  if (name == "normal") {
    if (s.outline == nullptr) {
      error = "'normal()' needs a flat shape";
      return std::nullopt;
    }
    return Value(s.scope.z);
  }
  error.assign("unknown property '").append(name).append("()'");
  return std::nullopt;
}

Measures measure(const EntityStore& entities, const shape::ShapeTree& tree, EntityId id) {
  Measures m;
  const Entity& e = entities[id];
  if (e.type != EntityType::kShape) return m;
  if (e.model != nullptr) {
    for (const shape::Part& part : e.model->parts) {
      m.area += kernel::surface_area(part.mesh);
      m.volume += std::abs(kernel::volume(part.mesh));
      m.faces += part.mesh.face_count();
    }
    return m;
  }
  const shape::Shape& s = tree[e.shape];
  if (s.outline != nullptr) {
    m.area = kernel::area(*s.outline);
  } else if (s.mesh != nullptr) {
    m.area = kernel::surface_area(*s.mesh);
    m.volume = std::abs(kernel::volume(*s.mesh));
  }
  m.faces = s.mesh != nullptr ? s.mesh->face_count() : 0;
  return m;
}

}  // namespace insula::lang::graph
