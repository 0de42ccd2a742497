#include "io/tileset_writer.h"

#include <oneapi/tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <system_error>

#include "io/atomic_file.h"
#include "io/crs.h"
#include "io/json_stream.h"
#include "io/tile_tree.h"
#include "kernel/transform.h"

namespace insula::io {
namespace {

// A 3D Tiles bounding region: longitudes and latitudes in radians, ellipsoidal heights in meters.
struct Region {
  double west = 1e300;
  double south = 1e300;
  double east = -1e300;
  double north = -1e300;
  double low = 1e300;
  double high = -1e300;

  void add(const Region& other) {
    west = std::min(west, other.west);
    south = std::min(south, other.south);
    east = std::max(east, other.east);
    north = std::max(north, other.north);
    low = std::min(low, other.low);
    high = std::max(high, other.high);
  }
};

// The box of a building's geometry, local coordinates (instances placed).
kernel::Bounds3 building_bounds(const shape::Building& building) {
  kernel::Bounds3 box;
  for (const shape::Part& part : building.parts) {
    if (!part.instance_of) {
      if (part.mesh.empty()) continue;
      const kernel::Bounds3 own = part.mesh.bounds();
      box.add(own.min);
      box.add(own.max);
      continue;
    }
    if (part.instance_of->empty()) continue;
    const kernel::Bounds3 own = part.instance_of->bounds();
    for (int corner = 0; corner < 8; ++corner) {
      const kernel::Vec3 p{(corner & 1) != 0 ? own.max.x : own.min.x,
                           (corner & 2) != 0 ? own.max.y : own.min.y,
                           (corner & 4) != 0 ? own.max.z : own.min.z};
      box.add(kernel::apply_point(part.instance_transform, p));
    }
  }
  return box;
}

std::size_t building_faces(const shape::Building& building) {
  std::size_t faces = 0;
  for (const shape::Part& part : building.parts) {
    faces += part.instance_of ? part.instance_of->face_count() : part.mesh.face_count();
  }
  return faces;
}

// `part` of `building` as a feature of a tile: moved by `offset` (a shared mesh stays shared: its
// placement moves), carrying its building's id and attributes where it has none of its own.
shape::Part tile_part(const shape::Building& building, const shape::Part& part,
                      const kernel::Transform& offset) {
  shape::Part out = part;
  if (out.instance_of) {
    out.instance_transform = offset * out.instance_transform;
  } else {
    kernel::transform_mesh(out.mesh, offset);
  }
  for (const auto& [key, value] : building.attributes) out.attributes.try_emplace(key, value);
  out.attributes["building"] = building.id;
  return out;
}

struct Leaf {
  std::size_t node = 0;
  kernel::Bounds3 box;  // of its buildings, local coordinates
  kernel::Vec3 centre;  // the tile's own origin, local coordinates
};

// The tree, its leaves' boxes and the building each item is.
struct Plan {
  TileTree tree;
  std::vector<std::size_t> building_of;  // item -> scene building
  std::vector<kernel::Bounds3> boxes;    // item -> box
  std::vector<Leaf> leaves;
};

Plan plan(const shape::Scene& scene, std::size_t tile_faces) {
  Plan out;
  std::vector<TileItem> items;
  for (std::size_t b = 0; b < scene.buildings.size(); ++b) {
    const kernel::Bounds3 box = building_bounds(scene.buildings[b]);
    if (box.empty()) continue;
    out.building_of.push_back(b);
    out.boxes.push_back(box);
    items.push_back({{box.min.x, box.min.y},
                     {box.max.x, box.max.y},
                     std::max<std::size_t>(building_faces(scene.buildings[b]), 1)});
  }
  out.tree = plan_tiles(items, tile_faces);
  for (std::size_t n = 0; n < out.tree.nodes.size(); ++n) {
    const TileNode& node = out.tree.nodes[n];
    if (!node.leaf()) continue;
    Leaf leaf{n, {}, {}};
    for (const std::size_t item : node.items) {
      leaf.box.add(out.boxes[item].min);
      leaf.box.add(out.boxes[item].max);
    }
    leaf.centre = {(leaf.box.min.x + leaf.box.max.x) / 2, (leaf.box.min.y + leaf.box.max.y) / 2, 0};
    out.leaves.push_back(leaf);
  }
  return out;
}

// Each leaf's region: its box's corners and edge midpoints taken to longitude and latitude (a
// projected box's edges are nearly straight there), widened by about a centimetre.
std::vector<Region> leaf_regions(const shape::Scene& scene, const Plan& plan, std::string& error) {
  std::vector<kernel::Vec2> points;
  for (const Leaf& leaf : plan.leaves) {
    for (int i = 0; i < 9; ++i) {
      const double u = (i % 3) / 2.0;
      const double v = (i / 3) / 2.0;
      points.push_back({scene.origin.x + leaf.box.min.x + u * (leaf.box.max.x - leaf.box.min.x),
                        scene.origin.y + leaf.box.min.y + v * (leaf.box.max.y - leaf.box.min.y)});
    }
  }
  error = reproject(scene.crs, "OGC:CRS84", points);
  if (!error.empty()) return {};
  constexpr double kRadians = std::numbers::pi / 180;
  constexpr double kMargin = 2e-9;  // radians, about 1.3 cm
  std::vector<Region> regions;
  for (std::size_t l = 0; l < plan.leaves.size(); ++l) {
    Region region;
    for (std::size_t i = 0; i < 9; ++i) {
      const kernel::Vec2 p = points[9 * l + i];
      if (!std::isfinite(p.x)) {
        error = "PROJ cannot place tile " + plan.tree.nodes[plan.leaves[l].node].name() + " of " +
                scene.crs + " on the globe";
        return {};
      }
      region.add({p.x * kRadians - kMargin, p.y * kRadians - kMargin, p.x * kRadians + kMargin,
                  p.y * kRadians + kMargin, 0, 0});
    }
    region.low = scene.origin.z + plan.leaves[l].box.min.z;
    region.high = scene.origin.z + plan.leaves[l].box.max.z;
    regions.push_back(region);
  }
  return regions;
}

// The tile's scene: one building, the tile, whose parts are the parts of its buildings, around
// the tile's centre (the scene's origin). One mesh then draws the whole tile, and a viewer picks
// every part as a feature with its building's properties.
shape::Scene tile_scene(const shape::Scene& scene, const Plan& plan, const Leaf& leaf) {
  shape::Scene tile;
  tile.crs = scene.crs;
  tile.origin = scene.origin + leaf.centre;
  tile.materials = scene.materials;
  const TileNode& node = plan.tree.nodes[leaf.node];
  shape::Building& content = tile.buildings.emplace_back();
  content.id = node.name();
  const kernel::Transform offset = kernel::translation(-leaf.centre);
  for (const std::size_t item : node.items) {
    const shape::Building& building = scene.buildings[plan.building_of[item]];
    for (const shape::Part& part : building.parts) {
      content.parts.push_back(tile_part(building, part, offset));
    }
  }
  return tile;
}

std::string tile_uri(const TileNode& node) {
  return "tiles/" + node.name() + ".glb";
}

double diagonal(const TileNode& node) {
  const kernel::Vec2 size = node.cell_max - node.cell_min;
  return std::hypot(size.x, size.y);
}

struct TilesetJson {
  const Plan& plan;
  const std::vector<Region>& regions;                 // by node
  const std::vector<std::array<double, 16>>& frames;  // by leaf
  std::vector<std::size_t> leaf_of;                   // node -> leaf index

  // A tile's geometric error: none for leaves, else an eighth of its cell's diagonal (at least its
  // children's).
  double error(std::size_t n) const {
    const TileNode& node = plan.tree.nodes[n];
    if (node.leaf()) return 0;
    double e = diagonal(node) / 8;
    for (const std::size_t c : node.children) e = std::max(e, error(c));
    return e;
  }

  void tile(JsonStream& json, std::size_t n) const {
    const TileNode& node = plan.tree.nodes[n];
    const Region& r = regions[n];
    json.begin_object();
    json.key("boundingVolume").begin_object().key("region").begin_array();
    for (const double value : {r.west, r.south, r.east, r.north, r.low, r.high}) json.number(value);
    json.end_array().end_object();
    if (!node.leaf()) {
      json.key("children").begin_array();
      for (const std::size_t c : node.children) tile(json, c);
      json.end_array();
    } else {
      json.key("content").begin_object().key("uri").string(tile_uri(node)).end_object();
    }
    json.key("geometricError").number(error(n));
    if (n == 0) json.key("refine").string("REPLACE");
    if (node.leaf()) {
      json.key("transform").begin_array();
      for (const double value : frames[leaf_of[n]]) json.number(value);
      json.end_array();
    }
    json.end_object();
  }

  std::string text() const {
    std::string out;
    JsonStream json(out, 1);
    json.begin_object();
    json.key("asset").begin_object();
    json.key("generator").string("Insula");
    json.key("version").string("1.1");
    json.end_object();
    json.key("geometricError").number(std::max(error(0), diagonal(plan.tree.nodes[0]) / 4));
    json.key("root");
    tile(json, 0);
    json.end_object();
    out += '\n';
    return out;
  }
};

}  // namespace

std::filesystem::path tiles_folder(const std::filesystem::path& tileset_json) {
  return tileset_json.parent_path() / "tiles";
}

std::string write_tileset(const shape::Scene& scene, const std::filesystem::path& tileset_json,
                          const TilesetOptions& options) {
  const std::string name = tileset_json.string();
  if (scene.crs.empty()) {
    return name +
           ": 3D Tiles place the buildings on the globe, but they have no coordinate reference "
           "system (give --crs, or georeferenced input)";
  }
  const Plan tiles = plan(scene, options.tile_faces);
  if (tiles.leaves.empty()) return name + ": no building has geometry; no tiles written";
  std::string error;
  std::vector<Region> leaf_region = leaf_regions(scene, tiles, error);
  if (!error.empty()) return name + ": " + error;
  std::vector<kernel::Vec3> centres;
  for (const Leaf& leaf : tiles.leaves) centres.push_back(scene.origin + leaf.centre);
  const std::vector<std::array<double, 16>> frames = ecef_frames(scene.crs, centres, error);
  if (!error.empty()) return name + ": " + error;

  std::error_code made;
  std::filesystem::create_directories(tiles_folder(tileset_json), made);
  if (made) return tiles_folder(tileset_json).string() + ": " + made.message();
  GltfOptions gltf = options.gltf;
  gltf.nodes = GltfOptions::Nodes::kBuilding;
  std::vector<std::string> errors(tiles.leaves.size());
  tbb::parallel_for(std::size_t{0}, tiles.leaves.size(), [&](std::size_t l) {
    const Leaf& leaf = tiles.leaves[l];
    const std::filesystem::path file =
        tileset_json.parent_path() / tile_uri(tiles.tree.nodes[leaf.node]);
    errors[l] = write_gltf(tile_scene(scene, tiles, leaf), file, gltf);
  });
  for (const std::string& e : errors) {
    if (!e.empty()) return e;
  }

  // Regions of inner tiles: the union of their children's, children being added after parents.
  std::vector<Region> regions(tiles.tree.nodes.size());
  std::vector<std::size_t> leaf_of(tiles.tree.nodes.size(), 0);
  for (std::size_t l = 0; l < tiles.leaves.size(); ++l) {
    regions[tiles.leaves[l].node] = leaf_region[l];
    leaf_of[tiles.leaves[l].node] = l;
  }
  for (std::size_t n = tiles.tree.nodes.size(); n-- > 0;) {
    for (const std::size_t c : tiles.tree.nodes[n].children) regions[n].add(regions[c]);
  }
  const TilesetJson json{tiles, regions, frames, std::move(leaf_of)};
  return write_file_atomically(tileset_json, json.text());
}

}  // namespace insula::io
