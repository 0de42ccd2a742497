#include "lang/graph/shape_entities.h"
#include "lang/graph/executor.h"

#include <cmath>
#include <memory>

#include "kernel/convex_hull.h"
#include "shape/scope.h"

namespace insula::lang::graph {

namespace {

// The flat root over `footprint` for a shape entity `make()` returns, or nullopt with `error`.
template <typename Make>
std::optional<EntityId> footprint_shape(NodeContext& c, const kernel::Polygon& footprint,
                                        double elevation, std::string& error, Make make) {
  const shape::RootResult root = c.tree().create_root(footprint, elevation);
  if (!root.ok()) {
    error = root.error;
    return std::nullopt;
  }
  const EntityId e = make();
  c.entities()[e].shape = root.id;
  return e;
}

}  // namespace

std::optional<EntityId> footprint_entity(NodeContext& c, std::size_t round, std::uint32_t position,
                                         const kernel::Polygon& footprint, double elevation,
                                         std::string& error) {
  return footprint_shape(c, footprint, elevation, error,
                         [&] { return c.create(round, EntityType::kShape, position); });
}

std::optional<EntityId> footprint_child(NodeContext& c, EntityId parent,
                                        const kernel::Polygon& footprint, double elevation,
                                        std::string& error) {
  return footprint_shape(c, footprint, elevation, error,
                         [&] { return c.entities().derive(parent, EntityType::kShape); });
}

kernel::Mesh world_mesh(NodeContext& c, EntityId entity) {
  const Entity& e = c.entities()[entity];
  kernel::Mesh out;
  if (e.type != EntityType::kShape) return out;
  if (e.model != nullptr) {
    for (const shape::Part& part : e.model->parts) out.append(part.mesh);
    return out;
  }
  const shape::Shape& s = c.tree()[e.shape];
  if (s.mesh != nullptr) out = shape::mesh_to_world(*s.mesh, s.scope);
  return out;
}

EntityId merged_entity(NodeContext& c, std::size_t round, std::uint32_t position,
                       std::span<const EntityId> sources, const kernel::Mesh& world_mesh) {
  const shape::Scope scope = shape::fit_scope(world_mesh, {1, 0, 0}, {0, 1, 0}, {0, 0, 1});
  const EntityId out = c.create(round, EntityType::kShape, position);
  c.entities()[out].shape = c.tree().add_root(
      scope, std::make_shared<kernel::Mesh>(shape::mesh_to_local(world_mesh, scope)));
  c.entities()[out].material = c.entities()[sources.front()].material;
  for (const auto& [key, value] : c.entities().attributes(sources.front())) {
    bool common = true;
    for (EntityId e : sources) {
      const Value* v = c.entities().attribute(e, key);
      common = common && v != nullptr && *v == *value;
    }
    if (common) c.entities().set_attribute(out, key, *value);
  }
  return out;
}

EntityId shape_child(NodeContext& c, EntityId parent, shape::ShapeId shape) {
  const EntityId e = c.entities().derive(parent, EntityType::kShape);
  Entity& child = c.entities()[e];
  child.shape = shape;
  child.material = c.entities()[parent].material;
  return e;
}

bool run_operation(NodeContext& c, EntityId entity, const std::string& op,
                   const std::vector<shape::ArgInput>& args, std::vector<EntityId>& children,
                   std::vector<std::uint32_t>* pieces) {
  const shape::ShapeId id = c.entities()[entity].shape;
  shape::Context context;
  context.assets = c.options().assets;
  const shape::OpResult result = shape::registry().run(c.tree(), id, op, args, context);
  if (!result.ok()) {
    // Registry messages mostly name their operation already ("extrude: needs a flat shape").
    const bool named = result.error.starts_with(op + ":");
    c.fail(entity, named ? result.error : op + ": " + result.error);
    return false;
  }
  for (std::size_t i = 0; i < result.children.size(); ++i) {
    children.push_back(shape_child(c, entity, result.children[i]));
    if (pieces != nullptr) pieces->push_back(result.pieces[i]);
  }
  return true;
}

std::optional<kernel::Polygon> world_footprint(NodeContext& c, EntityId entity, double* elevation) {
  const Entity& e = c.entities()[entity];
  if (e.type != EntityType::kShape) return std::nullopt;
  const shape::Shape& s = c.tree()[e.shape];
  if (s.outline == nullptr || std::abs(s.scope.z.z) < 1 - 1e-9) return std::nullopt;
  const auto to_world = [&](const kernel::Ring& ring) {
    kernel::Ring out;
    for (const kernel::Vec2& p : ring) {
      const kernel::Vec3 w = s.scope.to_world({p.x, p.y, 0});
      out.push_back({w.x, w.y});
    }
    return out;
  };
  kernel::Polygon polygon{to_world(s.outline->outer), {}};
  for (const kernel::Ring& hole : s.outline->holes) polygon.holes.push_back(to_world(hole));
  kernel::normalize(polygon);
  if (elevation != nullptr) *elevation = s.scope.origin.z;
  return polygon;
}

kernel::Polygon ground_footprint(NodeContext& c, EntityId e) {
  if (std::optional<kernel::Polygon> flat = world_footprint(c, e)) return *flat;
  const kernel::Mesh mesh = world_mesh(c, e);
  std::vector<kernel::Vec2> points;
  for (const kernel::Vec3& p : mesh.positions()) points.push_back({p.x, p.y});
  kernel::Polygon polygon;
  const kernel::Hull2Result hull = kernel::convex_hull_2d(points);
  if (hull.status == kernel::HullStatus::kOk) polygon.outer = hull.ring;
  return polygon;
}

std::optional<shape::ArgValue> to_argument(const Value& value, const shape::ParamDecl& decl) {
  using shape::ParamType;
  switch (value.type()) {
    case ValueType::kNumber:
      if (decl.type == ParamType::kSize) return shape::SizeSpec{value.number()};
      return value.number();
    case ValueType::kInteger:
      if (decl.type == ParamType::kSize) return shape::SizeSpec{value.number()};
      return value.integer();
    case ValueType::kBool:
      return value.boolean();
    case ValueType::kString:
      if (decl.type == ParamType::kSize) {
        const std::optional<shape::SizeSpec> size = shape::parse_size(value.text());
        if (!size) return std::nullopt;
        return *size;
      }
      return value.text();
    case ValueType::kList: {
      std::vector<shape::SizeSpec> sizes;
      for (const Value& v : value.list()) {
        std::optional<shape::SizeSpec> size;
        if (v.is_number()) size = shape::SizeSpec{v.number()};
        if (v.type() == ValueType::kString) size = shape::parse_size(v.text());
        if (!size) return std::nullopt;
        sizes.push_back(*size);
      }
      return sizes;
    }
    default:
      return std::nullopt;
  }
}

std::vector<shape::ArgInput> registry_arguments(NodeContext& c, std::size_t round,
                                                const shape::Operation& op) {
  std::vector<shape::ArgInput> args;
  for (const shape::ParamDecl& decl : op.params) {
    if (c.checked().type->param(decl.name) == nullptr || !c.has_param(decl.name)) continue;
    const Value v = c.param(round, decl.name);
    const std::optional<shape::ArgValue> arg = to_argument(v, decl);
    if (!arg) {
      c.error("parameter '" + decl.name + "' of " + op.name + " cannot take " + to_string(v));
    }
    args.push_back({decl.name, *arg});
  }
  return args;
}

}  // namespace insula::lang::graph
