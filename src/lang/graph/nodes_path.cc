// Path (street) operations (graph-format.md §11 "Path (street) operations") over the kernel's
// street networks (kernel/street_network.h, docs/street-networks.md).
#include "kernel/street_network.h"
#include "lang/graph/nodes.h"
#include "lang/graph/shape_entities.h"

namespace insula::lang::graph {
namespace {

std::optional<kernel::Vec3> point_of(const Value& v) {
  if (v.type() == ValueType::kVec3) return v.vec();
  if (v.type() != ValueType::kList) return std::nullopt;
  std::vector<double> xyz;
  for (const Value& k : v.list()) {
    if (!k.is_number()) return std::nullopt;
    xyz.push_back(k.number());
  }
  if (xyz.size() == 2) return kernel::Vec3{xyz[0], xyz[1], 0};
  if (xyz.size() == 3) return kernel::Vec3{xyz[0], xyz[1], xyz[2]};
  return std::nullopt;
}

EntityId make_path(NodeContext& c, std::size_t round, kernel::StreetNetwork network) {
  const EntityId e = c.create(round, EntityType::kPath, 0);
  c.entities()[e].path = std::make_shared<const PathGeometry>(std::move(network));
  return e;
}

void create(NodeContext& c) {
  for (std::size_t r = 0; r < c.rounds(); ++r) {
    kernel::StreetNetwork network;
    for (const Value& v : c.param(r, "points").list()) {
      const std::optional<kernel::Vec3> p = point_of(v);
      if (!p) c.error("a path point must be [x, y] or [x, y, z]; got " + to_string(v));
      network.vertices.push_back(*p);
    }
    const auto n = static_cast<std::uint32_t>(network.vertices.size());
    if (n < 2) c.error("a path needs at least 2 points");
    for (std::uint32_t i = 0; i + 1 < n; ++i) network.edges.push_back({i, i + 1});
    if (c.param(r, "closed").boolean() && n > 2) network.edges.push_back({n - 1, 0});
    c.emit(c.output_port("out"), make_path(c, r, std::move(network)));
  }
}

void grid(NodeContext& c) {
  for (std::size_t r = 0; r < c.rounds(); ++r) {
    const Value origin = c.param(r, "origin");
    kernel::StreetNetwork network = kernel::grid_network(
        static_cast<int>(c.param(r, "columns").integer()),
        static_cast<int>(c.param(r, "rows").integer()), c.param(r, "spacing_x").number(),
        c.param(r, "spacing_y").number(), origin.vec());
    c.emit(c.output_port("out"), make_path(c, r, std::move(network)));
  }
}

// Roads (one shape per road polygon) and, for to_shapes, blocks with their index.
void surfaces(NodeContext& c, bool blocks) {
  for (std::size_t r = 0; r < c.rounds(); ++r) {
    const EntityId in = c.current(r);
    const double width = c.param(r, "width").number();
    const kernel::StreetSurfaces s = blocks ? kernel::street_surfaces(*c.entities()[in].path, width)
                                            : kernel::road_buffer(*c.entities()[in].path, width);
    if (!s.ok()) {
      c.fail(in, "street surfaces: " + std::string(kernel::to_string(s.status)));
      continue;
    }
    const std::size_t roads = c.output_port(blocks ? "roads" : "out");
    for (const kernel::Polygon& p : s.roads) {
      std::string error;
      if (const auto e = footprint_child(c, in, p, s.z, error)) c.emit(roads, *e);
    }
    std::int64_t index = 0;
    for (const kernel::Polygon& p : s.blocks) {
      std::string error;
      const auto e = footprint_child(c, in, p, s.z, error);
      if (!e) continue;
      c.write(*e, "index", Value(index++));
      c.emit(c.output_port("blocks"), *e);
    }
  }
}
void to_shapes(NodeContext& c) {
  surfaces(c, true);
}
void buffer(NodeContext& c) {
  surfaces(c, false);
}

void merge(NodeContext& c) {
  const std::span<const EntityId> in = c.input(0, c.input_port("in"));
  if (in.empty()) return;
  std::vector<kernel::StreetNetwork> networks;
  for (EntityId e : in) networks.push_back(*c.entities()[e].path);
  const EntityId out = c.entities().derive(in.front(), EntityType::kPath);
  c.entities()[out].path = std::make_shared<const PathGeometry>(
      kernel::merge_networks(networks, c.param(0, "tolerance").number()));
  c.emit(c.output_port("out"), out);
}

void decompose(NodeContext& c) {
  for (std::size_t r = 0; r < c.rounds(); ++r) {
    const EntityId in = c.current(r);
    kernel::StreetParts parts = kernel::decompose(*c.entities()[in].path);
    std::int64_t index = 0;
    for (kernel::StreetNetwork& edge : parts.edges) {
      const EntityId e = c.entities().derive(in, EntityType::kPath);
      c.entities()[e].path = std::make_shared<const PathGeometry>(std::move(edge));
      c.write(e, "index", Value(index++));
      c.emit(c.output_port("edges"), e);
    }
    index = 0;
    for (const kernel::Vec3& v : parts.vertices) {
      const EntityId e = c.entities().derive(in, EntityType::kPoint);
      c.entities()[e].position = v;
      c.write(e, "index", Value(index++));
      c.emit(c.output_port("vertices"), e);
    }
  }
}

constexpr NodeImpl kNodes[] = {
    {"path.create", create}, {"path.grid", grid},   {"path.to_shapes", to_shapes},
    {"path.buffer", buffer}, {"path.merge", merge}, {"path.decompose", decompose},
};

}  // namespace

std::span<const NodeImpl> path_nodes() {
  return kNodes;
}

}  // namespace insula::lang::graph
