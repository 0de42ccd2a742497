// Terrain (surface) nodes, an extension of §11 after seed 003 §5.1 ("surface manipulation (e.g.,
// noise, smoothing, and leveling)"): heightfields made, roughened, smoothed, levelled under
// footprints and roads, and actors placed on them (kernel/heightfield.h; decisions in
// docs/graph-executor.md, "Terrain").
#include <cmath>

#include "kernel/heightfield.h"
#include "kernel/transform.h"
#include "lang/graph/nodes.h"
#include "lang/graph/shape_entities.h"
#include "shape/scope.h"

namespace insula::lang::graph {
namespace {

EntityId with_field(NodeContext& c, EntityId in, kernel::Heightfield field) {
  const EntityId out = c.entities().derive(in, EntityType::kTerrain);
  c.entities()[out].terrain = std::make_shared<const kernel::Heightfield>(std::move(field));
  return out;
}

void create(NodeContext& c) {
  for (std::size_t r = 0; r < c.rounds(); ++r) {
    const kernel::Vec3 origin = c.param(r, "origin").vec();
    std::string error;
    std::optional<kernel::Heightfield> field = kernel::make_heightfield(
        {origin.x, origin.y}, c.param(r, "width").number(), c.param(r, "depth").number(),
        c.param(r, "cell").number(), origin.z + c.param(r, "height").number(), error);
    if (!field) c.error(error);
    const EntityId e = c.create(r, EntityType::kTerrain, 0);
    c.entities()[e].terrain = std::make_shared<const kernel::Heightfield>(std::move(*field));
    c.emit(c.output_port("out"), e);
  }
}

void noise(NodeContext& c) {
  for (std::size_t r = 0; r < c.rounds(); ++r) {
    const EntityId in = c.current(r);
    const double wavelength = c.param(r, "wavelength").number();
    if (!(wavelength > 0)) c.error("a noise wavelength must be positive");
    // Of the graph seed, the node and `seed`, not of the entity: noise is a function of world
    // position, so terrains side by side through one node join without a seam.
    const std::uint64_t seed =
        c.rng(kNoEntity, "noise:" + std::to_string(c.param(r, "seed").integer())).next();
    kernel::Heightfield field = *c.entities()[in].terrain;
    kernel::add_noise(field, {c.param(r, "amplitude").number(), wavelength,
                              static_cast<int>(c.param(r, "octaves").integer()), seed});
    c.emit(c.output_port("out"), with_field(c, in, std::move(field)));
  }
}

void smooth(NodeContext& c) {
  for (std::size_t r = 0; r < c.rounds(); ++r) {
    const EntityId in = c.current(r);
    kernel::Heightfield field = *c.entities()[in].terrain;
    kernel::smooth(field, static_cast<int>(c.param(r, "iterations").integer()));
    c.emit(c.output_port("out"), with_field(c, in, std::move(field)));
  }
}

std::vector<kernel::Polygon> footprints(NodeContext& c, std::string_view port) {
  std::vector<kernel::Polygon> out;
  for (EntityId e : c.input(0, c.input_port(port))) {
    kernel::Polygon p = ground_footprint(c, e);
    if (!p.outer.empty()) out.push_back(std::move(p));
  }
  return out;
}

// Every terrain arriving, flattened under all the footprints and roads that arrive.
void level(NodeContext& c) {
  const std::span<const EntityId> terrains = c.input(0, c.input_port("in"));
  const std::vector<kernel::Polygon> shapes = footprints(c, "shapes");
  const std::vector<kernel::Polygon> roads = footprints(c, "roads");
  const double margin = c.param(0, "margin").number();
  for (EntityId in : terrains) {
    kernel::Heightfield field = *c.entities()[in].terrain;
    kernel::level(field, {shapes, roads, margin});
    c.emit(c.output_port("out"), with_field(c, in, std::move(field)));
  }
}

// The terrain under world (x, y): the first whose extent holds it, else the first.
const kernel::Heightfield& terrain_under(NodeContext& c, std::span<const EntityId> terrains,
                                         double x, double y) {
  for (EntityId t : terrains) {
    const kernel::Heightfield& f = *c.entities()[t].terrain;
    if (x >= f.origin.x && x <= f.origin.x + f.width() && y >= f.origin.y &&
        y <= f.origin.y + f.depth()) {
      return f;
    }
  }
  return *c.entities()[terrains.front()].terrain;
}

// A shape moved up or down so its lowest point meets the terrain under its footprint's centroid.
void place_shape(NodeContext& c, std::span<const EntityId> terrains, EntityId in) {
  const kernel::Polygon footprint = ground_footprint(c, in);
  const shape::Scope& scope = c.tree()[c.entities()[in].shape].scope;
  const kernel::Vec2 at = footprint.outer.empty() ? kernel::Vec2{scope.center().x, scope.center().y}
                                                  : kernel::centroid(footprint);
  double base = scope.origin.z;
  const kernel::Mesh mesh = world_mesh(c, in);
  if (!mesh.empty()) base = mesh.bounds().min.z;
  const double dz = kernel::height_at(terrain_under(c, terrains, at.x, at.y), at.x, at.y) - base;
  const kernel::Vec3 up{0, 0, dz};
  const std::vector<shape::ArgInput> args = {{"x", kernel::dot(up, scope.x)},
                                             {"y", kernel::dot(up, scope.y)},
                                             {"z", kernel::dot(up, scope.z)}};
  std::vector<EntityId> children;
  if (!run_operation(c, in, "translate", args, children)) return;
  const std::shared_ptr<const Model>& model = c.entities()[in].model;
  for (EntityId child : children) {
    if (model != nullptr) {
      // A rule node's parts are world meshes: they move with the shape.
      auto moved = std::make_shared<Model>(*model);
      const kernel::Transform shift = kernel::translation(up);
      for (shape::Part& part : moved->parts) {
        kernel::transform_mesh(part.mesh, shift);
        if (part.instance_of != nullptr) part.instance_transform = shift * part.instance_transform;
      }
      c.entities()[child].model = moved;
    }
    c.emit(c.output_port("out"), child);
  }
}

void place(NodeContext& c) {
  const std::span<const EntityId> terrains = c.input(0, c.input_port("terrain"));
  const auto height = [&](kernel::Vec3 p) {
    return kernel::height_at(terrain_under(c, terrains, p.x, p.y), p.x, p.y);
  };
  for (EntityId in : c.input(0, c.input_port("in"))) {
    const EntityType type = c.entities()[in].type;
    if (type == EntityType::kShape) {
      place_shape(c, terrains, in);
      continue;
    }
    if (type != EntityType::kPath && type != EntityType::kPoint && type != EntityType::kLight) {
      c.fail(in, "terrain.place places shapes, paths, points and lights; not a " +
                     std::string(entity_type_name(type)));
      continue;
    }
    const EntityId out = c.entities().derive(in, type);
    Entity& e = c.entities()[out];
    const Entity& src = c.entities()[in];
    e.light = src.light;
    if (type == EntityType::kPath) {
      auto path = std::make_shared<PathGeometry>(*src.path);
      for (kernel::Vec3& v : path->vertices) v.z = height(v);
      e.path = path;
    } else if (type == EntityType::kPoint) {
      e.position = {src.position.x, src.position.y, height(src.position)};
    } else {
      // A light keeps its height, now above the ground under it.
      e.position = {src.position.x, src.position.y, src.position.z + height(src.position)};
    }
    c.emit(c.output_port("out"), out);
  }
}

constexpr NodeImpl kNodes[] = {
    {"terrain.create", create}, {"terrain.noise", noise}, {"terrain.smooth", smooth},
    {"terrain.level", level},   {"terrain.place", place},
};

}  // namespace

std::span<const NodeImpl> terrain_nodes() {
  return kNodes;
}

}  // namespace insula::lang::graph
