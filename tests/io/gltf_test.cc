// glTF writer: the .glb is read back with tinygltf's loader (an independent reader) and checked for
// node names, triangle counts, extras, Y-up positions, flat normals and concave-face triangulation.
#include <cmath>
#include <cstring>
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
#include "io/gltf_writer.h"
#include "writer_fixtures.h"

namespace insula::io {
namespace {

using testing::load_glb;
using testing::read_accessor;
using testing::test_scene;

const tinygltf::Node& node_named(const tinygltf::Model& model, const std::string& name) {
  for (const tinygltf::Node& node : model.nodes) {
    if (node.name == name) return node;
  }
  ADD_FAILURE() << "no node " << name;
  return model.nodes.front();
}

std::size_t triangle_count(const tinygltf::Model& model) {
  std::size_t count = 0;
  for (const tinygltf::Mesh& mesh : model.meshes) {
    for (const tinygltf::Primitive& primitive : mesh.primitives) {
      EXPECT_EQ(primitive.mode, TINYGLTF_MODE_TRIANGLES);
      count += model.accessors[static_cast<std::size_t>(primitive.indices)].count / 3;
    }
  }
  return count;
}

TEST(GltfWriter, GlbHeaderAndChunksAreWellFormed) {
  const std::string bytes = glb_bytes(test_scene());
  ASSERT_GE(bytes.size(), 28U);
  EXPECT_EQ(bytes.substr(0, 4), "glTF");
  std::uint32_t header[3];
  std::memcpy(header, bytes.data(), sizeof header);
  EXPECT_EQ(header[1], 2U);
  EXPECT_EQ(header[2], bytes.size());
  EXPECT_EQ(bytes.size() % 4, 0U);
  EXPECT_EQ(bytes.substr(16, 4), "JSON");
}

TEST(GltfWriter, NodesPerBuildingAndPartWithNames) {
  const tinygltf::Model model = load_glb(glb_bytes(test_scene()));
  ASSERT_EQ(model.scenes.size(), 1U);
  ASSERT_EQ(model.scenes[0].nodes.size(), 2U);
  const auto root = [&](std::size_t i) {
    return model.nodes[static_cast<std::size_t>(model.scenes[0].nodes[i])];
  };
  EXPECT_EQ(root(0).name, "b1");
  EXPECT_EQ(root(1).name, "L-2");
  ASSERT_EQ(root(1).children.size(), 2U);
  EXPECT_EQ(model.nodes[static_cast<std::size_t>(root(1).children[0])].name, "wing");
  EXPECT_EQ(model.nodes[static_cast<std::size_t>(root(1).children[1])].name, "storey 0");
  EXPECT_GE(node_named(model, "main").mesh, 0);
}

TEST(GltfWriter, TrianglesCoverEveryFace) {
  const tinygltf::Model model = load_glb(glb_bytes(test_scene()));
  EXPECT_EQ(triangle_count(model), 34U);
  for (const tinygltf::Accessor& accessor : model.accessors) {
    if (accessor.type == TINYGLTF_TYPE_SCALAR) {
      EXPECT_EQ(accessor.componentType, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
    }
  }
}

TEST(GltfWriter, AttributesAndOriginGoToExtras) {
  const tinygltf::Model model = load_glb(glb_bytes(test_scene()));
  const tinygltf::Value& b1 = node_named(model, "b1").extras;
  EXPECT_EQ(b1.Get("height").GetNumberAsDouble(), 3.0);
  EXPECT_EQ(b1.Get("name").Get<std::string>(), "Box & <Co> \"1\"");
  EXPECT_TRUE(b1.Get("listed").Get<bool>());
  EXPECT_EQ(node_named(model, "main").extras.Get("kind").Get<std::string>(), "BuildingPart");
  EXPECT_EQ(node_named(model, "main").extras.Get("levels").GetNumberAsDouble(), 1.0);
  EXPECT_EQ(node_named(model, "storey 0").extras.Get("kind").Get<std::string>(), "Storey");
  const tinygltf::Value& extras = model.scenes[0].extras;
  ASSERT_TRUE(extras.Get("origin").IsArray());
  EXPECT_EQ(extras.Get("origin").Get(0).GetNumberAsDouble(), 500000.25);
  EXPECT_EQ(extras.Get("origin").Get(1).GetNumberAsDouble(), 5400000.5);
  EXPECT_EQ(extras.Get("origin").Get(2).GetNumberAsDouble(), 100.0);
  EXPECT_EQ(extras.Get("crs").Get<std::string>(), "EPSG:32633");
}

TEST(GltfWriter, PositionsAreLocalAndYUp) {
  const tinygltf::Model model = load_glb(glb_bytes(test_scene()));
  // The L wing spans local x 10..16, y 0..5, z 0..4: in glTF x 10..16, y (up) 0..4, z -5..0.
  const tinygltf::Mesh& wing =
      model.meshes[static_cast<std::size_t>(node_named(model, "wing").mesh)];
  std::vector<double> min{1e9, 1e9, 1e9};
  std::vector<double> max{-1e9, -1e9, -1e9};
  for (const tinygltf::Primitive& primitive : wing.primitives) {
    const tinygltf::Accessor& position =
        model.accessors[static_cast<std::size_t>(primitive.attributes.at("POSITION"))];
    ASSERT_EQ(position.minValues.size(), 3U);
    const std::vector<float> values =
        read_accessor<float>(model, primitive.attributes.at("POSITION"));
    for (std::size_t i = 0; i < values.size(); ++i) {
      min[i % 3] = std::min(min[i % 3], static_cast<double>(values[i]));
      max[i % 3] = std::max(max[i % 3], static_cast<double>(values[i]));
      EXPECT_GE(values[i], position.minValues[i % 3]);
      EXPECT_LE(values[i], position.maxValues[i % 3]);
    }
  }
  EXPECT_EQ(min, (std::vector<double>{10, 0, -5}));
  EXPECT_EQ(max, (std::vector<double>{16, 4, 0}));
}

TEST(GltfWriter, NormalsAreFlatAndUnit) {
  const tinygltf::Model model = load_glb(glb_bytes(test_scene()));
  const tinygltf::Mesh& main =
      model.meshes[static_cast<std::size_t>(node_named(model, "main").mesh)];
  for (const tinygltf::Primitive& primitive : main.primitives) {
    const std::string& material =
        model.materials[static_cast<std::size_t>(primitive.material)].name;
    const std::vector<float> normals =
        read_accessor<float>(model, primitive.attributes.at("NORMAL"));
    for (std::size_t i = 0; i < normals.size(); i += 3) {
      EXPECT_NEAR(std::hypot(normals[i], normals[i + 1], normals[i + 2]), 1.0, 1e-6);
      if (material == "Tile_red") {
        EXPECT_EQ(normals[i + 1], 1.0F);
      }  // roof: up
      if (material == "GroundSurface") {
        EXPECT_EQ(normals[i + 1], -1.0F);
      }  // ground: down
      if (material == "WallSurface") {
        EXPECT_EQ(normals[i + 1], 0.0F);
      }  // walls: level
    }
    // Flat shading: every face has its own corners, 4 per quad here.
    EXPECT_EQ(normals.size() / 3,
              4 * model.accessors[static_cast<std::size_t>(primitive.indices)].count / 6);
  }
}

// Inside test for the L footprint used below (local x, y).
bool inside_l(double x, double y) {
  return (x > 0 && x < 6 && y > 0 && y < 2) || (x > 0 && x < 2 && y > 0 && y < 5);
}

TEST(GltfWriter, ConcaveFacesAreTriangulatedInsideTheirOutline) {
  // Starting the loop at (6, 2) makes a fan from the first corner leave the L.
  shape::Scene scene;
  shape::Building building;
  building.id = "L";
  building.parts.push_back(
      {"l",
       shape::PartKind::kBuildingPart,
       {},
       testing::prism({{6, 2}, {2, 2}, {2, 5}, {0, 5}, {0, 0}, {6, 0}}, 0, 4)});
  scene.buildings.push_back(std::move(building));
  const tinygltf::Model model = load_glb(glb_bytes(scene));
  double roof_area = 0;
  for (const tinygltf::Primitive& primitive : model.meshes[0].primitives) {
    if (model.materials[static_cast<std::size_t>(primitive.material)].name != "RoofSurface")
      continue;
    const std::vector<float> p = read_accessor<float>(model, primitive.attributes.at("POSITION"));
    const std::vector<std::uint32_t> index = read_accessor<std::uint32_t>(model, primitive.indices);
    ASSERT_EQ(index.size(), 12U);
    for (std::size_t t = 0; t < index.size(); t += 3) {
      // glTF (X, Z) is local (x, -y); the roof is seen from +Y, so counter-clockwise means the
      // signed area in the (X, -Z) = (x, y) plane is positive.
      const auto at = [&](std::size_t k) {
        return std::pair<double, double>{p[3 * index[t + k]], -p[3 * index[t + k] + 2]};
      };
      const auto [ax, ay] = at(0);
      const auto [bx, by] = at(1);
      const auto [cx, cy] = at(2);
      const double area = ((bx - ax) * (cy - ay) - (by - ay) * (cx - ax)) / 2;
      EXPECT_GT(area, 0);
      roof_area += area;
      EXPECT_TRUE(inside_l((ax + bx + cx) / 3, (ay + by + cy) / 3));
    }
  }
  EXPECT_DOUBLE_EQ(roof_area, 18.0);  // 6 x 2 + 2 x 3
}

TEST(GltfWriter, GltfTextEmbedsTheBuffer) {
  const std::string text = gltf_text(test_scene());
  const nlohmann::json json = nlohmann::json::parse(text);
  EXPECT_EQ(json["asset"]["version"], "2.0");
  EXPECT_TRUE(json["buffers"][0]["uri"].get<std::string>().starts_with(
      "data:application/octet-stream;base64,"));
  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  std::string error;
  std::string warning;
  ASSERT_TRUE(loader.LoadASCIIFromString(&model, &error, &warning, text.data(),
                                         static_cast<unsigned int>(text.size()), ""))
      << error;
  EXPECT_EQ(triangle_count(model), 34U);
  EXPECT_EQ(model.buffers[0].data.size(), load_glb(glb_bytes(test_scene())).buffers[0].data.size());
}

TEST(GltfWriter, EmptySceneIsAValidAsset) {
  const tinygltf::Model model = load_glb(glb_bytes(shape::Scene{}));
  EXPECT_TRUE(model.nodes.empty());
  EXPECT_TRUE(model.meshes.empty());
}

TEST(GltfWriter, IsDeterministic) {
  EXPECT_TRUE(glb_bytes(test_scene()) == glb_bytes(test_scene()));
}

TEST(GltfWriter, WritesByExtensionAndFailsWithoutLeavingFiles) {
  const auto dir = testing::temp_dir("gltf_write");
  ASSERT_EQ(write_gltf(test_scene(), dir / "city.glb"), "");
  ASSERT_EQ(write_gltf(test_scene(), dir / "city.GLTF"), "");
  EXPECT_TRUE(testing::read_file(dir / "city.glb") == glb_bytes(test_scene()));
  EXPECT_EQ(testing::read_file(dir / "city.GLTF"), gltf_text(test_scene()));
  const std::string error = write_gltf(test_scene(), dir / "missing" / "city.glb");
  EXPECT_NE(error.find("city.glb"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir / "missing"));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace insula::io
