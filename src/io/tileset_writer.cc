#include "io/tileset_writer.h"

#include <oneapi/tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <numbers>
#include <optional>
#include <system_error>

#include "io/atomic_file.h"
#include "io/crs.h"
#include "io/gltf_metadata.h"
#include "io/json_stream.h"
#include "io/tile_tree.h"
#include "kernel/transform.h"
#include "shape/alike_parts.h"
#include "shape/ops.h"

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

// `part` as a feature of a tile: moved by `offset` (a shared mesh stays shared: its placement
// moves), pointing at its building's attributes (gltf::make_feature).
shape::Part tile_part(shape::Part out, const std::shared_ptr<const shape::AttributeMap>& building,
                      const kernel::Transform& offset) {
  if (out.instance_of) {
    out.instance_transform = offset * out.instance_transform;
  } else {
    kernel::transform_mesh(out.mesh, offset);
  }
  gltf::make_feature(out, building);
  return out;
}

std::string tile_uri(const TileNode& node) {
  return "tiles/" + node.name() + ".glb";
}

double diagonal(const TileNode& node) {
  const kernel::Vec2 size = node.cell_max - node.cell_min;
  return std::hypot(size.x, size.y);
}

// An unwrapped longitude (regions_of) in [-pi, pi], as 3D Tiles regions hold them.
double written_longitude(double radians) {
  if (radians > std::numbers::pi) return radians - 2 * std::numbers::pi;
  if (radians < -std::numbers::pi) return radians + 2 * std::numbers::pi;
  return radians;
}

// Each box's region: its corners and edge midpoints taken to longitude and latitude (a projected
// box's edges are nearly straight there), widened by about a centimetre.
std::vector<Region> regions_of(const std::string& crs, kernel::Vec3 origin,
                               const std::vector<kernel::Bounds3>& boxes, std::string& error) {
  std::vector<kernel::Vec2> points;
  for (const kernel::Bounds3& box : boxes) {
    for (int i = 0; i < 9; ++i) {
      const double u = (i % 3) / 2.0;
      const double v = (i / 3) / 2.0;
      points.push_back({origin.x + box.min.x + u * (box.max.x - box.min.x),
                        origin.y + box.min.y + v * (box.max.y - box.min.y)});
    }
  }
  error = reproject(crs, "OGC:CRS84", points);
  if (!error.empty()) return {};
  constexpr double kRadians = std::numbers::pi / 180;
  constexpr double kMargin = 2e-9;  // radians, about 1.3 cm
  // Longitudes are unwrapped around the first point's, so a city on the antimeridian (Fiji,
  // Chukotka) gets a narrow region and not one around the globe; written_longitude() wraps them
  // back, and such a region then has west > east, as 3D Tiles regions may.
  const double reference = points.empty() ? 0.0 : points.front().x;
  std::vector<Region> regions;
  for (std::size_t b = 0; b < boxes.size(); ++b) {
    Region region;
    for (std::size_t i = 0; i < 9; ++i) {
      const kernel::Vec2 p = points[9 * b + i];
      if (!std::isfinite(p.x)) {
        error = "PROJ cannot place (" + std::to_string(p.x) + ", " + std::to_string(p.y) + ") of " +
                crs + " on the globe";
        return {};
      }
      const double lon = (reference + std::remainder(p.x - reference, 360.0)) * kRadians;
      region.add(
          {lon - kMargin, p.y * kRadians - kMargin, lon + kMargin, p.y * kRadians + kMargin, 0, 0});
    }
    region.low = origin.z + boxes[b].min.z;
    region.high = origin.z + boxes[b].max.z;
    regions.push_back(region);
  }
  return regions;
}

using Frame = std::array<double, 16>;  // column-major 4x4, as 3D Tiles' `transform`

// a * b.
Frame multiply(const Frame& a, const Frame& b) {
  Frame out{};
  for (int column = 0; column < 4; ++column) {
    for (int row = 0; row < 4; ++row) {
      double sum = 0;
      for (int k = 0; k < 4; ++k) sum += a[k * 4 + row] * b[column * 4 + k];
      out[column * 4 + row] = sum;
    }
  }
  return out;
}

// The inverse of an affine frame (its last row 0 0 0 1): the 3x3 part by its adjugate.
Frame inverse_affine(const Frame& f) {
  const auto m = [&f](int row, int column) { return f[column * 4 + row]; };
  const double c00 = m(1, 1) * m(2, 2) - m(1, 2) * m(2, 1);
  const double c01 = m(1, 2) * m(2, 0) - m(1, 0) * m(2, 2);
  const double c02 = m(1, 0) * m(2, 1) - m(1, 1) * m(2, 0);
  const double det = m(0, 0) * c00 + m(0, 1) * c01 + m(0, 2) * c02;
  double inv[3][3] = {{c00 / det, (m(0, 2) * m(2, 1) - m(0, 1) * m(2, 2)) / det,
                       (m(0, 1) * m(1, 2) - m(0, 2) * m(1, 1)) / det},
                      {c01 / det, (m(0, 0) * m(2, 2) - m(0, 2) * m(2, 0)) / det,
                       (m(0, 2) * m(1, 0) - m(0, 0) * m(1, 2)) / det},
                      {c02 / det, (m(0, 1) * m(2, 0) - m(0, 0) * m(2, 1)) / det,
                       (m(0, 0) * m(1, 1) - m(0, 1) * m(1, 0)) / det}};
  Frame out{};
  for (int row = 0; row < 3; ++row) {
    double t = 0;
    for (int k = 0; k < 3; ++k) {
      out[k * 4 + row] = inv[row][k];
      t -= inv[row][k] * m(k, 3);
    }
    out[12 + row] = t;
  }
  out[15] = 1;
  return out;
}

// The tileset's JSON: tiles with content, and inner tiles over them.
struct TilesetJson {
  const TileTree& tree;
  std::vector<std::optional<Region>> regions;         // by node; none: no content below
  std::vector<const std::array<double, 16>*> frames;  // by node; those with content

  // A tile's geometric error: none for leaves, else an eighth of its cell's diagonal (at least its
  // children's).
  double error(std::size_t n) const {
    const TileNode& node = tree.nodes[n];
    if (node.leaf()) return 0;
    double e = diagonal(node) / 8;
    for (const std::size_t c : node.children) e = std::max(e, error(c));
    return e;
  }

  // A tile's transform applies to its descendants too (3D Tiles 1.1, "Transforms"): below a tile
  // with a frame (a coarse parent), a tile's transform is its frame relative to that one.
  void tile(JsonStream& json, std::size_t n, const Frame* above = nullptr) const {
    const TileNode& node = tree.nodes[n];
    const Region& r = *regions[n];
    json.begin_object();
    json.key("boundingVolume").begin_object().key("region").begin_array();
    for (const double value :
         {written_longitude(r.west), r.south, written_longitude(r.east), r.north, r.low, r.high}) {
      json.number(value);
    }
    json.end_array().end_object();
    if (!node.leaf()) {
      json.key("children").begin_array();
      for (const std::size_t c : node.children) {
        if (regions[c]) tile(json, c, frames[n] != nullptr ? frames[n] : above);
      }
      json.end_array();
    }
    if (frames[n] != nullptr) {
      json.key("content").begin_object().key("uri").string(tile_uri(node)).end_object();
    }
    json.key("geometricError").number(error(n));
    if (n == 0) json.key("refine").string("REPLACE");
    if (frames[n] != nullptr) {
      const Frame relative =
          above == nullptr ? *frames[n] : multiply(inverse_affine(*above), *frames[n]);
      json.key("transform").begin_array();
      for (const double value : relative) json.number(value);
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
    json.key("geometricError").number(std::max(error(0), diagonal(tree.nodes[0]) / 4));
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

TilesetWriter::TilesetWriter(std::filesystem::path tileset_json, std::string crs,
                             kernel::Vec3 origin, std::vector<shape::Material> materials,
                             GltfOptions gltf, TilesetOptions options)
    : path_(std::move(tileset_json)),
      crs_(std::move(crs)),
      origin_(origin),
      materials_(std::move(materials)),
      gltf_(gltf),
      options_(options),
      tile_folder_(tiles_folder(path_)) {
  gltf_.nodes = GltfOptions::Nodes::kBuilding;
}

std::string TilesetWriter::plan(std::span<const TileItem> items) {
  const std::string name = path_.string();
  if (crs_.empty()) {
    return name +
           ": 3D Tiles place the buildings on the globe, but they have no coordinate reference "
           "system (give --crs, or georeferenced input)";
  }
  tree_ = plan_tiles(items, options_.tile_faces);
  leaves_.clear();
  std::vector<kernel::Vec3> centres;
  for (std::size_t n = 0; n < tree_.nodes.size(); ++n) {
    const TileNode& node = tree_.nodes[n];
    if (!node.leaf()) continue;
    kernel::Bounds3 plan_box;
    for (const std::size_t item : node.items) {
      plan_box.add({items[item].min.x, items[item].min.y, 0});
      plan_box.add({items[item].max.x, items[item].max.y, 0});
    }
    Leaf& leaf = leaves_.emplace_back();
    leaf.node = n;
    leaf.centre = {(plan_box.min.x + plan_box.max.x) / 2, (plan_box.min.y + plan_box.max.y) / 2, 0};
    centres.push_back(origin_ + leaf.centre);
  }
  std::string error;
  const std::vector<std::array<double, 16>> frames = ecef_frames(crs_, centres, error);
  if (!error.empty()) return name + ": " + error;
  for (std::size_t l = 0; l < leaves_.size(); ++l) leaves_[l].frame = frames[l];
  if (options_.block_buildings > 0) {
    if (std::string failed = plan_parents(); !failed.empty()) return name + ": " + failed;
  }
  std::error_code made;
  std::filesystem::create_directories(tile_folder_, made);
  if (made) return tile_folder_.string() + ": " + made.message();
  return {};
}

const std::vector<std::size_t>& TilesetWriter::leaf_items(std::size_t leaf) const {
  return tree_.nodes[leaves_[leaf].node].items;
}

// The tile's scene: one building, the tile, whose parts are the parts of its buildings, around
// the tile's centre (the scene's origin). One mesh then draws the whole tile, and a viewer picks
// every part as a feature with its building's properties.
std::string TilesetWriter::write_tile(std::size_t leaf,
                                      const std::vector<const shape::Building*>& buildings,
                                      const std::vector<shape::Material>* materials) {
  std::vector<shape::Building> copies;
  copies.reserve(buildings.size());
  for (const shape::Building* building : buildings) copies.push_back(*building);
  return write_tile(leaf, std::move(copies), materials);
}

std::string TilesetWriter::write_tile(std::size_t l, std::vector<shape::Building>&& buildings,
                                      const std::vector<shape::Material>* materials) {
  Leaf& leaf = leaves_[l];
  shape::Scene tile;
  tile.crs = crs_;
  tile.origin = origin_ + leaf.centre;
  tile.materials = materials ? *materials : materials_;
  shape::Building& content = tile.buildings.emplace_back();
  content.id = tree_.nodes[leaf.node].name();
  const kernel::Transform offset = kernel::translation(-leaf.centre);
  for (shape::Building& building : buildings) {
    const kernel::Bounds3 box = building_bounds(building);
    if (box.empty()) continue;
    leaf.box.add(box.min);
    leaf.box.add(box.max);
    if (options_.block_buildings > 0) leaf.blocks.push_back(box);
    const auto attributes = gltf::building_feature_attributes(building);
    for (shape::Part& part : building.parts) {
      content.parts.push_back(tile_part(std::move(part), attributes, offset));
    }
    building = shape::Building{};  // its parts are the tile's now
  }
  if (leaf.box.empty()) return {};
  return write_gltf(tile, tile_folder_ / (tree_.nodes[leaf.node].name() + ".glb"), gltf_);
}

// Every inner tile's own origin (its cell's centre) and frame, for the blocks it may show.
std::string TilesetWriter::plan_parents() {
  parents_.assign(tree_.nodes.size(), Parent{});
  std::vector<std::size_t> inner;
  std::vector<kernel::Vec3> centres;
  for (std::size_t n = 0; n < tree_.nodes.size(); ++n) {
    const TileNode& node = tree_.nodes[n];
    if (node.leaf()) continue;
    parents_[n].centre = {(node.cell_min.x + node.cell_max.x) / 2,
                          (node.cell_min.y + node.cell_max.y) / 2, 0};
    inner.push_back(n);
    centres.push_back(origin_ + parents_[n].centre);
  }
  std::string error;
  const std::vector<std::array<double, 16>> frames = ecef_frames(crs_, centres, error);
  if (!error.empty()) return error;
  for (std::size_t k = 0; k < inner.size(); ++k) parents_[inner[k]].frame = frames[k];
  return {};
}

// Coarse parents (TilesetOptions::block_buildings): an inner tile over at most that many buildings
// shows each as its bounding box, walls and roof, so a city seen from afar is not empty; nearer,
// REPLACE refinement swaps the blocks for the leaves' buildings.
std::string TilesetWriter::write_parents() {
  std::vector<std::vector<const kernel::Bounds3*>> below(tree_.nodes.size());
  for (const Leaf& leaf : leaves_) {
    for (const kernel::Bounds3& block : leaf.blocks) below[leaf.node].push_back(&block);
  }
  // Children come after their parents: gather bottom-up.
  for (std::size_t n = tree_.nodes.size(); n-- > 0;) {
    for (const std::size_t c : tree_.nodes[n].children) {
      below[n].insert(below[n].end(), below[c].begin(), below[c].end());
    }
  }
  std::vector<std::string> errors(tree_.nodes.size());
  tbb::parallel_for(std::size_t{0}, tree_.nodes.size(), [&](std::size_t n) {
    const TileNode& node = tree_.nodes[n];
    if (node.leaf() || below[n].empty() || below[n].size() > options_.block_buildings) return;
    shape::Scene blocks;
    blocks.crs = crs_;
    blocks.origin = origin_ + parents_[n].centre;
    shape::Part& part = blocks.buildings.emplace_back().parts.emplace_back();
    blocks.buildings.front().id = node.name();
    part.name = "blocks";
    const std::array<kernel::FaceTag, 6> tags = shape::mass_box_tags();
    for (const kernel::Bounds3* box : below[n]) {
      kernel::Mesh mesh = *shape::box_mesh(box->size(), tags);
      kernel::transform_mesh(mesh, kernel::translation(box->min - parents_[n].centre));
      part.mesh.append(mesh);
    }
    errors[n] = write_gltf(blocks, tiles_folder(path_) / (node.name() + ".glb"), gltf_);
    parents_[n].written = errors[n].empty();
  });
  for (const std::string& e : errors) {
    if (!e.empty()) return e;
  }
  return {};
}

std::string TilesetWriter::finish() {
  const std::string name = path_.string();
  std::vector<kernel::Bounds3> boxes;
  for (const Leaf& leaf : leaves_) {
    if (!leaf.box.empty()) boxes.push_back(leaf.box);
  }
  if (boxes.empty()) return name + ": no building has geometry; no tiles written";
  std::string error;
  const std::vector<Region> leaf_regions = regions_of(crs_, origin_, boxes, error);
  if (!error.empty()) return name + ": " + error;
  TilesetJson json{tree_, std::vector<std::optional<Region>>(tree_.nodes.size()),
                   std::vector<const std::array<double, 16>*>(tree_.nodes.size(), nullptr)};
  std::size_t next = 0;
  for (const Leaf& leaf : leaves_) {
    if (leaf.box.empty()) continue;
    json.regions[leaf.node] = leaf_regions[next++];
    json.frames[leaf.node] = &leaf.frame;
  }
  if (options_.block_buildings > 0) {
    if (std::string failed = write_parents(); !failed.empty()) return failed;
    for (std::size_t n = 0; n < parents_.size(); ++n) {
      if (parents_[n].written) json.frames[n] = &parents_[n].frame;
    }
  }
  // Inner tiles: the union of their children's regions (children come after their parents).
  for (std::size_t n = tree_.nodes.size(); n-- > 0;) {
    for (const std::size_t c : tree_.nodes[n].children) {
      if (!json.regions[c]) continue;
      if (!json.regions[n]) json.regions[n] = Region{};
      json.regions[n]->add(*json.regions[c]);
    }
  }
  return write_file_atomically(path_, json.text());
}

std::size_t building_faces(const shape::Building& building) {
  std::size_t faces = 0;
  for (const shape::Part& part : building.parts) {
    faces += part.instance_of ? part.instance_of->face_count() : part.mesh.face_count();
  }
  return faces;
}

std::string write_tileset(const shape::Scene& scene, const std::filesystem::path& tileset_json,
                          const GltfOptions& gltf, const TilesetOptions& options) {
  TilesetWriter writer(tileset_json, scene.crs, scene.origin, scene.materials, gltf, options);
  std::vector<TileItem> items;
  std::vector<const shape::Building*> building_of;
  for (const shape::Building& building : scene.buildings) {
    const kernel::Bounds3 box = building_bounds(building);
    if (box.empty()) continue;
    building_of.push_back(&building);
    items.push_back({{box.min.x, box.min.y},
                     {box.max.x, box.max.y},
                     std::max<std::size_t>(building_faces(building), 1)});
  }
  if (items.empty()) return tileset_json.string() + ": no building has geometry; no tiles written";
  if (std::string error = writer.plan(items); !error.empty()) return error;
  std::vector<std::string> errors(writer.leaf_count());
  tbb::parallel_for(std::size_t{0}, writer.leaf_count(), [&](std::size_t l) {
    std::vector<const shape::Building*> buildings;
    std::deque<shape::Building> merged;  // the tile's buildings whose alike parts were merged
    for (const std::size_t item : writer.leaf_items(l)) {
      const shape::Building* building = building_of[item];
      if (options.merge_alike_parts && shape::has_alike_parts(*building)) {
        building = &merged.emplace_back(shape::merge_alike_parts(*building));
      }
      buildings.push_back(building);
    }
    errors[l] = writer.write_tile(l, buildings);
  });
  for (const std::string& e : errors) {
    if (!e.empty()) return e;
  }
  return writer.finish();
}

}  // namespace insula::io
