// 3D Tiles writer: the quadtree of tiles (every building in one leaf, weights, addresses), the
// CRS-to-ECEF frames against the WGS 84 formulas, and a written tileset read back: regions that
// hold their buildings and their children, geometric errors, and every tile's vertices placed by
// its transform landing on the ECEF points of the input within a centimetre.
#include <cmath>
#include <fstream>
#include <map>
#include <numbers>
#include <set>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#define TINYGLTF_NO_INCLUDE_JSON
#include <tiny_gltf.h>

#include "gltf_read.h"
#include "io/crs.h"
#include "io/tile_tree.h"
#include "io/tileset_writer.h"
#include "writer_fixtures.h"

namespace insula::io {
namespace {

using kernel::length;
using kernel::Vec2;
using kernel::Vec3;
using testing::prism;

// ECEF of a WGS 84 longitude, latitude (degrees) and ellipsoidal height, by the textbook formula.
Vec3 wgs84_ecef(double lon, double lat, double h) {
  constexpr double a = 6378137.0;
  constexpr double f = 1 / 298.257223563;
  constexpr double e2 = f * (2 - f);
  const double phi = lat * std::numbers::pi / 180;
  const double lambda = lon * std::numbers::pi / 180;
  const double n = a / std::sqrt(1 - e2 * std::sin(phi) * std::sin(phi));
  return {(n + h) * std::cos(phi) * std::cos(lambda), (n + h) * std::cos(phi) * std::sin(lambda),
          (n * (1 - e2) + h) * std::sin(phi)};
}

TEST(TileTree, EveryItemInOneLeafAndLeavesWithinTheirWeight) {
  std::vector<TileItem> items;
  for (int i = 0; i < 40; ++i) {
    for (int j = 0; j < 25; ++j) {
      const Vec2 at{i * 20.0, j * 30.0};
      items.push_back({at, at + Vec2{10, 12}, static_cast<std::size_t>(1 + (i * j) % 7)});
    }
  }
  const TileTree tree = plan_tiles(items, 200);
  ASSERT_FALSE(tree.nodes.empty());
  std::vector<int> seen(items.size(), 0);
  std::set<std::string> names;
  for (const TileNode& node : tree.nodes) {
    EXPECT_TRUE(names.insert(node.name()).second) << node.name();
    if (!node.leaf()) {
      EXPECT_TRUE(node.items.empty());
      std::size_t below = 0;
      for (const std::size_t c : node.children) {
        EXPECT_EQ(tree.nodes[c].level, node.level + 1);
        EXPECT_EQ(tree.nodes[c].x / 2, node.x);
        EXPECT_EQ(tree.nodes[c].y / 2, node.y);
        below += tree.nodes[c].weight;
      }
      EXPECT_EQ(below, node.weight);
      EXPECT_GT(node.weight, 200U);
      continue;
    }
    EXPECT_TRUE(node.weight <= 200 || node.items.size() == 1) << node.name();
    for (const std::size_t i : node.items) {
      ++seen[i];
      const Vec2 c = (items[i].min + items[i].max) * 0.5;
      EXPECT_GE(c.x, node.cell_min.x);
      EXPECT_LT(c.x, node.cell_max.x);
      EXPECT_GE(c.y, node.cell_min.y);
      EXPECT_LT(c.y, node.cell_max.y);
    }
  }
  for (const int count : seen) EXPECT_EQ(count, 1);
  EXPECT_EQ(tree.nodes[0].name(), "0-0-0");
}

TEST(TileTree, ItemsOnOnePointStayOneTile) {
  const std::vector<TileItem> items(10, TileItem{{0, 0}, {4, 4}, 100});
  const TileTree tree = plan_tiles(items, 50);
  ASSERT_EQ(tree.nodes.size(), 1U);
  EXPECT_EQ(tree.nodes[0].items.size(), 10U);
  EXPECT_TRUE(plan_tiles({}, 50).nodes.empty());
}

TEST(EcefFrames, UtmFrameOnTheCentralMeridianIsEastNorthUpScaled) {
  // UTM zone 33N's central meridian is 15 E; 52 N lies 5,762,000 m or so north of the equator.
  std::vector<kernel::Vec2> at = {{15, 52}};
  ASSERT_EQ(reproject("OGC:CRS84", "EPSG:32633", at), "");
  std::string error;
  const auto frames = ecef_frames("EPSG:32633", {{at[0].x, at[0].y, 0}}, error);
  ASSERT_EQ(error, "");
  ASSERT_EQ(frames.size(), 1U);
  const auto& m = frames[0];
  const Vec3 origin{m[12], m[13], m[14]};
  const Vec3 expected = wgs84_ecef(15, 52, 0);
  EXPECT_LT(length(origin - expected), 1e-3);
  const Vec3 x{m[0], m[1], m[2]};
  const Vec3 y{m[4], m[5], m[6]};
  const Vec3 z{m[8], m[9], m[10]};
  // A UTM metre on the central meridian is 1 / 0.9996 ground metres (the scale factor).
  EXPECT_NEAR(length(x), 1 / 0.9996, 2e-6);
  EXPECT_NEAR(length(y), 1 / 0.9996, 2e-6);
  EXPECT_NEAR(length(z), 1.0, 1e-6);
  EXPECT_NEAR(kernel::dot(x, y), 0, 1e-6);
  EXPECT_NEAR(kernel::dot(x, z), 0, 1e-6);
  // East at 15 E is (-sin 15, cos 15, 0); up is the ellipsoid normal.
  const double lambda = 15 * std::numbers::pi / 180;
  EXPECT_NEAR(x.x * 0.9996, -std::sin(lambda), 1e-6);
  EXPECT_NEAR(x.y * 0.9996, std::cos(lambda), 1e-6);
  EXPECT_NEAR(x.z, 0, 1e-6);
  EXPECT_GT(z.z, 0.7);
}

TEST(EcefFrames, UnknownCrsIsAnError) {
  std::string error;
  EXPECT_TRUE(ecef_frames("EPSG:999999", {{0, 0, 0}}, error).empty());
  EXPECT_NE(error, "");
}

// A georeferenced city block: a grid of prisms of different heights around a UTM origin.
shape::Scene city(int columns, int rows) {
  shape::Scene scene;
  scene.crs = "EPSG:32633";
  scene.origin = {500000, 5761000, 40};
  for (int i = 0; i < columns; ++i) {
    for (int j = 0; j < rows; ++j) {
      const Vec2 at{i * 25.0 - 400, j * 25.0 - 300};
      shape::Building building;
      building.id = "b";  // appended, not concatenated: GCC 12's -Wrestrict misfires on a + chain
      building.id.append(std::to_string(i)).append("-").append(std::to_string(j));
      building.attributes = {{"height", 6.0 + (i + j) % 5}, {"roof", std::string("flat")}};
      shape::Part part;
      part.name = "mass";
      part.mesh =
          prism({at, at + Vec2{12, 0}, at + Vec2{12, 9}, at + Vec2{0, 9}}, 0, 6.0 + (i + j) % 5);
      building.parts.push_back(std::move(part));
      scene.buildings.push_back(std::move(building));
    }
  }
  return scene;
}

nlohmann::json read_json(const std::filesystem::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

// Checks a tile and its children; adds every leaf's content to `leaves`.
void check_tile(const nlohmann::json& tile, const nlohmann::json* parent,
                std::vector<const nlohmann::json*>& leaves) {
  const auto& r = tile.at("boundingVolume").at("region");
  ASSERT_EQ(r.size(), 6U);
  EXPECT_LT(r[0].get<double>(), r[2].get<double>());
  EXPECT_LT(r[1].get<double>(), r[3].get<double>());
  EXPECT_LE(r[4].get<double>(), r[5].get<double>());
  if (parent != nullptr) {
    const auto& p = parent->at("boundingVolume").at("region");
    for (int k : {0, 1, 4}) EXPECT_GE(r[k].get<double>(), p[k].get<double>());
    for (int k : {2, 3, 5}) EXPECT_LE(r[k].get<double>(), p[k].get<double>());
    EXPECT_LE(tile.at("geometricError").get<double>(), parent->at("geometricError").get<double>());
  }
  if (tile.contains("children")) {
    EXPECT_FALSE(tile.contains("content"));
    EXPECT_GT(tile.at("geometricError").get<double>(), 0);
    for (const auto& child : tile.at("children")) check_tile(child, &tile, leaves);
  } else {
    EXPECT_EQ(tile.at("geometricError").get<double>(), 0);
    EXPECT_EQ(tile.at("transform").size(), 16U);
    leaves.push_back(&tile);
  }
}

TEST(TilesetWriter, TilesPlaceEveryBuildingOnTheGlobe) {
  const shape::Scene scene = city(30, 20);
  const std::filesystem::path dir = testing::temp_dir("tileset_city");
  TilesetOptions options;
  options.tile_faces = 600;  // 7 faces a building: about 85 buildings a tile
  ASSERT_EQ(write_tileset(scene, dir / "tileset.json", {}, options), "");
  const nlohmann::json tileset = read_json(dir / "tileset.json");
  EXPECT_EQ(tileset.at("asset").at("version"), "1.1");
  EXPECT_GT(tileset.at("geometricError").get<double>(),
            tileset.at("root").at("geometricError").get<double>() - 1e-9);
  std::vector<const nlohmann::json*> leaves;
  check_tile(tileset.at("root"), nullptr, leaves);
  EXPECT_GE(leaves.size(), 8U);

  // Every building's corners on the globe, from the scene itself.
  struct Corners {
    std::vector<Vec3> ecef;
    std::vector<kernel::Vec2> lonlat;
  };
  std::map<std::string, Corners> corners_of;
  std::vector<Vec3> all;
  std::vector<kernel::Vec2> all_plan;
  for (const shape::Building& b : scene.buildings) {
    for (const Vec3 v : b.parts[0].mesh.positions()) {
      all.push_back(v + scene.origin);
      all_plan.push_back({all.back().x, all.back().y});
    }
  }
  ASSERT_EQ(to_ecef(scene.crs, all), "");
  ASSERT_EQ(reproject(scene.crs, "OGC:CRS84", all_plan), "");
  std::size_t next = 0;
  for (const shape::Building& b : scene.buildings) {
    Corners& c = corners_of[b.id];
    for (std::size_t k = 0; k < b.parts[0].mesh.vertex_count(); ++k, ++next) {
      c.ecef.push_back(all[next]);
      c.lonlat.push_back(all_plan[next]);
    }
  }

  std::set<std::string> buildings;
  for (const nlohmann::json* leaf : leaves) {
    const std::string uri = leaf->at("content").at("uri");
    const std::string bytes = testing::read_file(dir / uri);
    const tinygltf::Model model = testing::load_glb(bytes);
    std::array<double, 16> m{};
    for (int k = 0; k < 16; ++k) m[k] = leaf->at("transform")[k].get<double>();
    const auto& r = leaf->at("boundingVolume").at("region");
    // One node and one mesh draw the tile; every vertex's feature names its building.
    EXPECT_EQ(model.meshes.size(), 1U);
    const nlohmann::json json = testing::json_of(bytes);
    const std::vector<std::string> building_of = testing::table_column(model, json, "building_id");
    // The buildings' attributes are columns too.
    EXPECT_EQ(testing::table_column(model, json, "roof"),
              std::vector<std::string>(building_of.size(), "flat"));
    buildings.insert(building_of.begin(), building_of.end());
    // Every vertex: glTF's y-up back to z-up, then the tile's transform, gives the ECEF point of
    // a corner of its building in the scene, and the building lies inside the tile's region.
    for (const testing::PlacedPrimitive& p : testing::placed_primitives(model)) {
      ASSERT_EQ(p.features.size(), p.positions.size());
      for (std::size_t v = 0; v < p.positions.size(); ++v) {
        const std::string& id = building_of.at(static_cast<std::size_t>(p.features[v]));
        ASSERT_TRUE(corners_of.contains(id)) << id;
        const Corners& corners = corners_of.at(id);
        for (const kernel::Vec2 ll : corners.lonlat) {
          const double lon = ll.x * std::numbers::pi / 180;
          const double lat = ll.y * std::numbers::pi / 180;
          EXPECT_GE(lon, r[0].get<double>());
          EXPECT_LE(lon, r[2].get<double>());
          EXPECT_GE(lat, r[1].get<double>());
          EXPECT_LE(lat, r[3].get<double>());
        }
        const auto& q = p.positions[v];
        const Vec3 local{q[0], -q[2], q[1]};
        const Vec3 ecef{m[0] * local.x + m[4] * local.y + m[8] * local.z + m[12],
                        m[1] * local.x + m[5] * local.y + m[9] * local.z + m[13],
                        m[2] * local.x + m[6] * local.y + m[10] * local.z + m[14]};
        double nearest = 1e300;
        for (const Vec3 e : corners.ecef) nearest = std::min(nearest, length(ecef - e));
        EXPECT_LT(nearest, 0.01) << id;
      }
    }
  }
  EXPECT_EQ(buildings.size(), scene.buildings.size());
}

TEST(TilesetWriter, SameTilesetWhateverTheRun) {
  const shape::Scene scene = city(12, 9);
  const std::filesystem::path a = testing::temp_dir("tileset_a");
  const std::filesystem::path b = testing::temp_dir("tileset_b");
  TilesetOptions options;
  options.tile_faces = 100;
  ASSERT_EQ(write_tileset(scene, a / "tileset.json", {}, options), "");
  ASSERT_EQ(write_tileset(scene, b / "tileset.json", {}, options), "");
  EXPECT_EQ(testing::read_file(a / "tileset.json"), testing::read_file(b / "tileset.json"));
  for (const auto& entry : std::filesystem::directory_iterator(a / "tiles")) {
    EXPECT_EQ(testing::read_file(entry.path()),
              testing::read_file(b / "tiles" / entry.path().filename()));
  }
}

// Column-major 4x4 product, as 3D Tiles composes a tile's transform with its ancestors'.
std::array<double, 16> compose(const std::array<double, 16>& a, const std::array<double, 16>& b) {
  std::array<double, 16> out{};
  for (int column = 0; column < 4; ++column) {
    for (int row = 0; row < 4; ++row) {
      for (int k = 0; k < 4; ++k) out[column * 4 + row] += a[k * 4 + row] * b[column * 4 + k];
    }
  }
  return out;
}

// Every content's transform composed down the tree, by content uri.
void absolute_frames(const nlohmann::json& tile, const std::array<double, 16>& above,
                     std::map<std::string, std::array<double, 16>>& out) {
  std::array<double, 16> frame = above;
  if (tile.contains("transform")) {
    frame = compose(above, tile.at("transform").get<std::array<double, 16>>());
  }
  if (tile.contains("content")) out[tile.at("content").at("uri").get<std::string>()] = frame;
  if (tile.contains("children")) {
    for (const auto& child : tile.at("children")) absolute_frames(child, frame, out);
  }
}

// Coarse parents: inner tiles over few enough buildings get a GLB of blocks and a transform of
// their own; the leaves' transforms, composed with their ancestors', place them where they are
// without parents, to a micrometre.
TEST(TilesetWriter, CoarseParentsKeepEveryLeafInPlace) {
  const shape::Scene scene = city(16, 12);
  const std::filesystem::path plain = testing::temp_dir("tileset_plain");
  const std::filesystem::path blocks = testing::temp_dir("tileset_blocks");
  TilesetOptions options;
  options.tile_faces = 150;
  ASSERT_EQ(write_tileset(scene, plain / "tileset.json", {}, options), "");
  options.block_buildings = 60;
  ASSERT_EQ(write_tileset(scene, blocks / "tileset.json", {}, options), "");
  const std::array<double, 16> identity{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  std::map<std::string, std::array<double, 16>> without, with;
  absolute_frames(read_json(plain / "tileset.json").at("root"), identity, without);
  absolute_frames(read_json(blocks / "tileset.json").at("root"), identity, with);
  std::size_t parents = 0;
  for (const auto& [uri, frame] : with) {
    const auto leaf = without.find(uri);
    if (leaf == without.end()) {
      ++parents;
      EXPECT_TRUE(std::filesystem::exists(blocks / uri)) << uri;
      continue;
    }
    for (int k = 0; k < 16; ++k) EXPECT_NEAR(frame[k], leaf->second[k], 1e-6) << uri << " " << k;
  }
  EXPECT_EQ(with.size() - parents, without.size());
  EXPECT_GE(parents, 2U);  // 192 buildings, parents over at most 60
}

TEST(TilesetWriter, NoCrsIsAClearError) {
  shape::Scene scene = city(2, 2);
  scene.crs.clear();
  const std::filesystem::path dir = testing::temp_dir("tileset_nocrs");
  const std::string error = write_tileset(scene, dir / "tileset.json");
  EXPECT_NE(error.find("no coordinate reference system"), std::string::npos) << error;
  EXPECT_FALSE(std::filesystem::exists(dir / "tileset.json"));
  EXPECT_FALSE(std::filesystem::exists(dir / "tiles"));
}

}  // namespace
}  // namespace insula::io
