// Context-aware operations (graph-format.md §11; seed 003 §4.4-4.5, §6.1): nodes that decide by
// looking at other entities, over the kernel's queries (kernel/context_query.h,
// docs/context-queries.md). Every query skips an entity's own ancestors and descendants (§9.10).
#include <cmath>

#include "kernel/context_query.h"
#include "lang/graph/nodes.h"
#include "lang/graph/properties.h"
#include "lang/graph/shape_entities.h"
#include "shape/scope.h"

namespace insula::lang::graph {
namespace {

kernel::SkipPredicate related(NodeContext& c, std::span<const EntityId> a,
                              std::span<const EntityId> b) {
  return [&c, a, b](std::size_t i, std::size_t j) { return c.entities().related(a[i], b[j]); };
}

std::span<const EntityId> port(NodeContext& c, std::string_view name) {
  return c.input(0, c.input_port(name));
}

// Lloyd's k-means on each entity's `position` (Fig. 7).
void kmeans(NodeContext& c) {
  const std::span<const EntityId> in = port(c, "in");
  std::vector<kernel::Vec3> points;
  for (EntityId e : in) points.push_back(c.param_on(0, "position", e).vec());
  const kernel::KMeansResult result =
      kernel::kmeans(points, static_cast<int>(c.param(0, "k").integer()),
                     static_cast<int>(c.param(0, "max_iterations").integer()));
  for (std::size_t i = 0; i < in.size(); ++i) {
    const int cluster = result.cluster[i];
    c.write(in[i], "cluster", Value(std::int64_t{cluster}));
    c.write(in[i], "center", Value(result.centers[static_cast<std::size_t>(cluster)]));
    c.emit(c.output_port("out"), in[i]);
  }
}

kernel::Vec3 axis_direction(const shape::Scope& s, const std::string& axis) {
  const double sign = axis[0] == '-' ? -1.0 : 1.0;
  const kernel::Vec3 v = axis[1] == 'x' ? s.x : axis[1] == 'y' ? s.y : s.z;
  return v * sign;
}

// From each source's scope centre along a scope axis to the first target geometry (§4.5).
void ray_cast(NodeContext& c) {
  const std::span<const EntityId> sources = port(c, "sources");
  const std::span<const EntityId> targets = port(c, "targets");
  const std::string axis = c.param(0, "axis").text();
  const double max_distance = c.param(0, "max_distance").number();
  std::vector<kernel::Ray> rays;
  for (EntityId e : sources) {
    const shape::Scope& s = c.tree()[c.entities()[e].shape].scope;
    rays.push_back({s.center(), axis_direction(s, axis), max_distance});
  }
  std::vector<kernel::Mesh> meshes;
  for (EntityId e : targets) meshes.push_back(world_mesh(c, e));
  const kernel::RayCastResult result = kernel::ray_cast(rays, meshes, related(c, sources, targets));
  for (std::size_t i = 0; i < sources.size(); ++i) {
    const kernel::RayHit& hit = result.hits[i];
    c.write(sources[i], "hit", Value(hit.target >= 0));
    c.write(sources[i], "hit_position", Value(hit.position));
    c.write(sources[i], "hit_distance", Value(hit.distance));
    c.emit(c.output_port("sources"), sources[i]);
  }
  for (std::size_t j = 0; j < targets.size(); ++j) {
    c.emit(c.output_port(result.target_hit[j] ? "hit" : "miss"), targets[j]);
  }
}

// A flat shape's faces in world space, with its scope normal.
kernel::FlatShape flat_shape(NodeContext& c, EntityId e) {
  kernel::FlatShape flat;
  const kernel::Mesh mesh = world_mesh(c, e);
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    std::vector<kernel::Vec3> loop;
    for (std::uint32_t v : mesh.face(f)) loop.push_back(mesh.positions()[v]);
    flat.loops.push_back(std::move(loop));
  }
  flat.normal = c.tree()[c.entities()[e].shape].scope.z;
  return flat;
}

kernel::BoxEdges box_of(NodeContext& c, EntityId e) {
  const shape::Scope& s = c.tree()[c.entities()[e].shape].scope;
  return {s.origin, s.x * s.size.x, s.y * s.size.y, s.z * s.size.z};
}

// The fraction of each flat shape covered by occluder scope boxes in front of it (§6.1).
void occlusion(NodeContext& c) {
  const std::span<const EntityId> shapes = port(c, "shapes");
  const std::span<const EntityId> occluders = port(c, "occluders");
  std::vector<kernel::FlatShape> flats;
  for (EntityId e : shapes) flats.push_back(flat_shape(c, e));
  std::vector<kernel::BoxEdges> boxes;
  for (EntityId e : occluders) boxes.push_back(box_of(c, e));
  const std::vector<double> covered = kernel::occlusion(
      flats, boxes, c.param(0, "distance").number(), related(c, shapes, occluders));
  const double threshold = c.param(0, "threshold").number();
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    c.write(shapes[i], "occlusion", Value(covered[i]));
    c.emit(c.output_port(covered[i] >= threshold ? "occluded" : "visible"), shapes[i]);
  }
}

std::vector<kernel::StreetSegment> street_segments(NodeContext& c, std::span<const EntityId> in) {
  std::vector<kernel::StreetSegment> out;
  for (EntityId e : in) {
    const PathGeometry& path = *c.entities()[e].path;
    for (const auto& [a, b] : path.edges) {
      const kernel::Vec3 p = path.vertices[a];
      const kernel::Vec3 q = path.vertices[b];
      out.push_back({{p.x, p.y}, {q.x, q.y}});
    }
  }
  return out;
}

// "Is oriented to" (§4.5, Fig. 1): faces that see a street, past the occluders' footprints.
void is_oriented_to(NodeContext& c) {
  const std::span<const EntityId> shapes = port(c, "shapes");
  const std::span<const EntityId> occluders = port(c, "occluders");
  std::vector<kernel::OrientedFace> faces;
  for (EntityId e : shapes) {
    const shape::Scope& s = c.tree()[c.entities()[e].shape].scope;
    // A facade's scope (comp) runs x along its bottom edge, y up and z out of the wall.
    const kernel::Vec3 base = s.to_world({s.size.x / 2, 0, 0});
    faces.push_back({{base.x, base.y}, s.z});
  }
  std::vector<kernel::Polygon> footprints;
  for (EntityId e : occluders) footprints.push_back(ground_footprint(c, e));
  const std::vector<bool> oriented =
      kernel::is_oriented_to(faces, street_segments(c, port(c, "streets")), footprints,
                             c.param(0, "tolerance").number(), 1e9, related(c, shapes, occluders));
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    c.write(shapes[i], "oriented", Value(static_cast<bool>(oriented[i])));
    c.emit(c.output_port(oriented[i] ? "oriented" : "other"), shapes[i]);
  }
}

kernel::Footprint footprint_of(NodeContext& c, EntityId e) {
  kernel::Footprint f;
  const Entity& entity = c.entities()[e];
  switch (entity.type) {
    case EntityType::kShape:
      f.polygons.push_back(ground_footprint(c, e));
      break;
    case EntityType::kPath: {
      const std::vector<EntityId> one{e};
      f.segments = street_segments(c, one);
      break;
    }
    default:
      f.points.push_back({entity.position.x, entity.position.y});
  }
  return f;
}

// The least ground-plane distance to the targets, and which one (Fig. 1's levels of detail).
void distance(NodeContext& c) {
  const std::span<const EntityId> in = port(c, "in");
  const std::span<const EntityId> targets = port(c, "targets");
  std::vector<kernel::Footprint> a;
  for (EntityId e : in) a.push_back(footprint_of(c, e));
  std::vector<kernel::Footprint> b;
  for (EntityId e : targets) b.push_back(footprint_of(c, e));
  const std::vector<kernel::NearestTarget> nearest =
      kernel::nearest_targets(a, b, related(c, in, targets));
  for (std::size_t i = 0; i < in.size(); ++i) {
    c.write(in[i], "distance", Value(nearest[i].distance));
    c.write(in[i], "nearest", Value(std::int64_t{nearest[i].target}));
    c.emit(c.output_port("out"), in[i]);
  }
}

constexpr NodeImpl kNodes[] = {
    {"query.kmeans", kmeans},       {"query.ray_cast", ray_cast},
    {"query.occlusion", occlusion}, {"query.is_oriented_to", is_oriented_to},
    {"query.distance", distance},
};

}  // namespace

std::span<const NodeImpl> query_nodes() {
  return kNodes;
}

}  // namespace insula::lang::graph
