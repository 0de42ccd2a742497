// glTF writer: the .glb is read back with tinygltf's loader (an independent reader) and checked for
// node names, triangle counts, extras, Y-up positions, flat normals and concave-face triangulation.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <memory>
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
#include "io/gltf_writer.h"
#include "writer_fixtures.h"

namespace insula::io {
namespace {

using testing::json_of;
using testing::load_glb;
using testing::table_column;
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

// The JSON chunk of a .glb.
constexpr GltfOptions kElements{GltfOptions::Nodes::kElement, GltfOptions::Instancing::kNodes,
                                false, false};

TEST(GltfWriter, OneNodeAndOneMeshPerBuilding) {
  const tinygltf::Model model = load_glb(glb_bytes(test_scene()));
  ASSERT_EQ(model.scenes.size(), 1U);
  ASSERT_EQ(model.scenes[0].nodes.size(), 2U);
  EXPECT_EQ(model.nodes.size(), 2U);
  ASSERT_EQ(model.meshes.size(), 2U);
  for (int index : model.scenes[0].nodes) {
    const tinygltf::Node& node = model.nodes[static_cast<std::size_t>(index)];
    EXPECT_TRUE(node.children.empty());
    ASSERT_GE(node.mesh, 0);
    EXPECT_EQ(model.meshes[static_cast<std::size_t>(node.mesh)].name, node.name);
  }
  EXPECT_EQ(node_named(model, "b1").name, "b1");
  // One primitive per material: b1 shows walls, roof (Tile red) and ground; L-2 walls, roof,
  // ground and the storey's floor.
  EXPECT_EQ(model.meshes[static_cast<std::size_t>(node_named(model, "b1").mesh)].primitives.size(),
            3U);
  EXPECT_EQ(model.meshes[static_cast<std::size_t>(node_named(model, "L-2").mesh)].primitives.size(),
            4U);
  // The primitives of a mesh share their vertex attributes.
  for (const tinygltf::Mesh& mesh : model.meshes) {
    for (const tinygltf::Primitive& primitive : mesh.primitives) {
      EXPECT_EQ(primitive.attributes, mesh.primitives[0].attributes);
    }
  }
}

TEST(GltfWriter, ElementNodesPerBuildingAndPartWithNames) {
  const tinygltf::Model model = load_glb(glb_bytes(test_scene(), kElements));
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
  EXPECT_EQ(node_named(model, "main").extras.Get("kind").Get<std::string>(), "BuildingPart");
  EXPECT_EQ(node_named(model, "main").extras.Get("levels").GetNumberAsDouble(), 1.0);
  EXPECT_EQ(node_named(model, "storey 0").extras.Get("kind").Get<std::string>(), "Storey");
  EXPECT_TRUE(model.extensionsUsed.empty());  // floats, no feature table
}

TEST(GltfWriter, TrianglesCoverEveryFace) {
  for (const GltfOptions& options : {GltfOptions{}, kElements}) {
    const tinygltf::Model model = load_glb(glb_bytes(test_scene(), options));
    EXPECT_EQ(triangle_count(model), 34U);
  }
  // Small meshes index with 16 bits.
  const tinygltf::Model model = load_glb(glb_bytes(test_scene()));
  for (const tinygltf::Mesh& mesh : model.meshes) {
    for (const tinygltf::Primitive& primitive : mesh.primitives) {
      EXPECT_EQ(model.accessors[static_cast<std::size_t>(primitive.indices)].componentType,
                TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
    }
  }
}

TEST(GltfWriter, AttributesAndOriginGoToExtras) {
  const tinygltf::Model model = load_glb(glb_bytes(test_scene()));
  const tinygltf::Value& b1 = node_named(model, "b1").extras;
  EXPECT_EQ(b1.Get("height").GetNumberAsDouble(), 3.0);
  EXPECT_EQ(b1.Get("name").Get<std::string>(), "Box & <Co> \"1\"");
  EXPECT_TRUE(b1.Get("listed").Get<bool>());
  const tinygltf::Value& extras = model.scenes[0].extras;
  ASSERT_TRUE(extras.Get("origin").IsArray());
  EXPECT_EQ(extras.Get("origin").Get(0).GetNumberAsDouble(), 500000.25);
  EXPECT_EQ(extras.Get("origin").Get(1).GetNumberAsDouble(), 5400000.5);
  EXPECT_EQ(extras.Get("origin").Get(2).GetNumberAsDouble(), 100.0);
  EXPECT_EQ(extras.Get("crs").Get<std::string>(), "EPSG:32633");
}

// EXT_structural_metadata: the parts in scene order, their name and kind dictionary-coded and
// their attributes as columns; every vertex's _FEATURE_ID_0 is its part's row.
TEST(GltfWriter, PartsAreFeaturesWithAPropertyTable) {
  const std::string glb = glb_bytes(test_scene());
  const tinygltf::Model model = load_glb(glb);
  const nlohmann::json json = json_of(glb);
  const nlohmann::json& metadata = json["extensions"]["EXT_structural_metadata"];
  const nlohmann::json& table = metadata["propertyTables"][0];
  EXPECT_EQ(table["class"], "part");
  ASSERT_EQ(table["count"], 3);
  // Three rows: strings cost less than enums here.
  const nlohmann::json& properties = metadata["schema"]["classes"]["part"]["properties"];
  EXPECT_EQ(properties["part_name"]["type"], "STRING");
  // Only "main" has levels: a number column with noData for the others (not text: a tile with
  // one gap in a register's heights had STRING heights where its neighbours had SCALAR ones).
  EXPECT_EQ(properties["levels"]["type"], "SCALAR");
  EXPECT_EQ(properties["levels"]["componentType"], "FLOAT64");
  EXPECT_EQ(properties["levels"]["noData"], std::numeric_limits<double>::lowest());
  EXPECT_FALSE(properties["levels"].contains("required"));
  EXPECT_EQ(table_column(model, json, "part_name"),
            (std::vector<std::string>{"main", "wing", "storey 0"}));
  EXPECT_EQ(table_column(model, json, "kind"),
            (std::vector<std::string>{"BuildingPart", "BuildingPart", "Storey"}));
  EXPECT_EQ(table_column(model, json, "levels"), (std::vector<std::string>{"1", "", ""}));
  std::vector<std::string> extensions = model.extensionsUsed;
  EXPECT_EQ(extensions, (std::vector<std::string>{"EXT_mesh_features", "EXT_structural_metadata",
                                                  "KHR_mesh_quantization"}));
  // The floor (only in "storey 0", row 2) carries feature 2; b1's vertices all feature 0.
  for (const testing::PlacedPrimitive& p : testing::placed_primitives(model)) {
    for (double feature : p.features) {
      if (p.node == "b1") {
        EXPECT_EQ(feature, 0);
      }
      if (p.material == "FloorSurface") {
        EXPECT_EQ(feature, 2);
      }
      if (p.node == "L-2" && p.material == "RoofSurface") {
        EXPECT_EQ(feature, 1);
      }
    }
  }
  for (const nlohmann::json& mesh : json["meshes"]) {
    for (const nlohmann::json& primitive : mesh["primitives"]) {
      const nlohmann::json& ids = primitive["extensions"]["EXT_mesh_features"]["featureIds"][0];
      EXPECT_EQ(ids["attribute"], 0);
      EXPECT_EQ(ids["propertyTable"], 0);
      EXPECT_EQ(ids["featureCount"], 1);  // one part shows each material here
    }
  }
}

// A part whose faces all collapse where they are written (a sliver 0.1 um wide: one grid point,
// one float32) shows no triangle, so it has no row, no feature id and no node: rows are the parts
// a vertex points at, numbered without gaps, and an attribute only it has makes no column.
kernel::Mesh sliver() {
  kernel::Mesh mesh;
  mesh.add_polygon(std::vector<kernel::Vec3>{{5, 5, 0}, {6, 5, 0}, {6, 5.0000001, 0}}, {});
  return mesh;
}

shape::Scene lot_with_a_collapsed_part() {
  shape::Scene scene;
  scene.buildings.push_back({"lot",
                             {},
                             {{"Lawn", shape::PartKind::kBuildingPart, {{"grass", true}}, sliver()},
                              {"Paving",
                               shape::PartKind::kBuildingPart,
                               {},
                               testing::prism({{0, 0}, {1, 0}, {1, 1}}, 0, 1)},
                              {"Lawn", shape::PartKind::kBuildingPart, {{"grass", true}}, sliver()},
                              {"Bed",
                               shape::PartKind::kBuildingPart,
                               {},
                               testing::prism({{2, 0}, {3, 0}, {3, 1}}, 0, 1)}}});
  return scene;
}

TEST(GltfWriter, PartsWithoutATriangleHaveNoRow) {
  const std::string glb = glb_bytes(lot_with_a_collapsed_part());
  const tinygltf::Model model = load_glb(glb);
  const nlohmann::json json = json_of(glb);
  const nlohmann::json& metadata = json["extensions"]["EXT_structural_metadata"];
  EXPECT_EQ(metadata["propertyTables"][0]["count"], 2);
  EXPECT_EQ(table_column(model, json, "part_name"), (std::vector<std::string>{"Paving", "Bed"}));
  EXPECT_FALSE(metadata["schema"]["classes"]["part"]["properties"].contains("grass"));
  std::set<double> features;
  for (const testing::PlacedPrimitive& p : testing::placed_primitives(model)) {
    features.insert(p.features.begin(), p.features.end());
  }
  EXPECT_EQ(features, (std::set<double>{0, 1}));
  for (const nlohmann::json& mesh : json["meshes"]) {
    for (const nlohmann::json& primitive : mesh["primitives"]) {
      EXPECT_EQ(primitive["extensions"]["EXT_mesh_features"]["featureIds"][0]["featureCount"], 2);
    }
  }
}

TEST(GltfWriter, PartsWithoutATriangleHaveNoElementNode) {
  const tinygltf::Model model = load_glb(glb_bytes(lot_with_a_collapsed_part(), kElements));
  const tinygltf::Node& lot = node_named(model, "lot");
  ASSERT_EQ(lot.children.size(), 2U);
  EXPECT_EQ(model.nodes[static_cast<std::size_t>(lot.children[0])].name, "Paving");
  EXPECT_EQ(model.nodes[static_cast<std::size_t>(lot.children[1])].name, "Bed");
}

// Many parts with few distinct texts (a façade's symbols and colours): enum-coded, the rows'
// codes one byte each; a column present in some parts only gets the noData code elsewhere;
// numbers every part has stay FLOAT64.
TEST(GltfWriter, RepeatedTextsAreDictionaryCoded) {
  shape::Scene scene;
  shape::Building b;
  b.id = "facade";
  for (int i = 0; i < 200; ++i) {
    const double x = 2.0 * i;
    shape::AttributeMap attributes{{"height", 3.0 + i}};
    if (i % 3 == 0) attributes["colour"] = std::string(i % 2 == 0 ? "#ffffff" : "#336699");
    b.parts.push_back({i % 2 == 0 ? "Wall" : "Window", shape::PartKind::kBuildingPart, attributes,
                       testing::prism({{x, 0}, {x + 1, 0}, {x + 1, 1}, {x, 1}}, 0, 1)});
  }
  scene.buildings.push_back(std::move(b));
  const std::string glb = glb_bytes(scene);
  const tinygltf::Model model = load_glb(glb);
  const nlohmann::json json = json_of(glb);
  const nlohmann::json& metadata = json["extensions"]["EXT_structural_metadata"];
  const nlohmann::json& properties = metadata["schema"]["classes"]["part"]["properties"];
  EXPECT_EQ(properties["part_name"]["type"], "ENUM");
  EXPECT_EQ(metadata["schema"]["enums"]["part_name"]["valueType"], "UINT8");
  EXPECT_EQ(properties["colour"]["type"], "ENUM");
  EXPECT_EQ(properties["colour"]["noData"], "(none)");
  EXPECT_EQ(properties["height"]["type"], "SCALAR");
  EXPECT_EQ(properties["height"]["componentType"], "FLOAT64");
  const std::vector<std::string> names = table_column(model, json, "part_name");
  const std::vector<std::string> colours = table_column(model, json, "colour");
  ASSERT_EQ(names.size(), 200U);
  ASSERT_EQ(colours.size(), 200U);
  for (std::size_t i = 0; i < 200; ++i) {
    EXPECT_EQ(names[i], i % 2 == 0 ? "Wall" : "Window");
    EXPECT_EQ(colours[i], i % 3 != 0 ? "(none)" : i % 2 == 0 ? "#ffffff" : "#336699");
  }
  const tinygltf::BufferView& codes =
      model.bufferViews[metadata["propertyTables"][0]["properties"]["part_name"]["values"]
                            .get<std::size_t>()];
  EXPECT_EQ(codes.byteLength, 200U);
}

// A 3D Tiles tile's parts point at their building's attributes (shape::Part::inherited): the
// table shows them where a part has none of its own, its own value (or an own null, which lets
// the inherited one through) otherwise; one map shared by many parts reads as if copied.
TEST(GltfWriter, InheritedAttributesFillWhatAPartLacks) {
  const auto building = std::make_shared<const shape::AttributeMap>(
      shape::AttributeMap{{"building", std::string("b7")},
                          {"height", 12.5},
                          {"roof", "hip"},
                          {"note", shape::Value{}}});  // a null makes no column
  shape::Scene scene;
  shape::Building& tile = scene.buildings.emplace_back();
  tile.id = "tile";
  const std::vector<shape::AttributeMap> own{
      {}, {{"roof", std::string("flat")}}, {{"height", shape::Value{}}}, {{"colour", "#fff"}}};
  for (std::size_t i = 0; i < own.size(); ++i) {
    const double x = 2.0 * static_cast<double>(i);
    shape::Part part{"p" + std::to_string(i), shape::PartKind::kBuildingPart, own[i],
                     testing::prism({{x, 0}, {x + 1, 0}, {x + 1, 1}, {x, 1}}, 0, 1)};
    part.inherited = building;
    tile.parts.push_back(std::move(part));
  }
  shape::Part loose{"loose",
                    shape::PartKind::kBuildingPart,
                    {},
                    testing::prism({{9, 0}, {10, 0}, {10, 1}, {9, 1}}, 0, 1)};
  tile.parts.push_back(std::move(loose));
  const std::string glb = glb_bytes(scene);
  const tinygltf::Model model = load_glb(glb);
  const nlohmann::json json = json_of(glb);
  const nlohmann::json& properties =
      json["extensions"]["EXT_structural_metadata"]["schema"]["classes"]["part"]["properties"];
  EXPECT_EQ(table_column(model, json, "building"),
            (std::vector<std::string>{"b7", "b7", "b7", "b7", ""}));
  EXPECT_EQ(table_column(model, json, "roof"),
            (std::vector<std::string>{"hip", "flat", "hip", "hip", ""}));
  EXPECT_EQ(table_column(model, json, "height"),
            (std::vector<std::string>{"12.5", "12.5", "12.5", "12.5", ""}));
  EXPECT_EQ(table_column(model, json, "colour"),
            (std::vector<std::string>{"", "", "", "#fff", ""}));
  // A number column still: "loose" lacks it and gets the noData value.
  EXPECT_EQ(properties["height"]["type"], "SCALAR");
  EXPECT_TRUE(properties["height"].contains("noData"));
  EXPECT_FALSE(properties.contains("note"));
  // Without the loose part every row has a height: a required number column.
  scene.buildings[0].parts.pop_back();
  const std::string whole = glb_bytes(scene);
  const nlohmann::json whole_json = json_of(whole);
  const nlohmann::json& height = whole_json["extensions"]["EXT_structural_metadata"]["schema"]
                                           ["classes"]["part"]["properties"]["height"];
  EXPECT_EQ(height["type"], "SCALAR");
  EXPECT_EQ(height["required"], true);
  // The same as parts carrying copies of what they inherit.
  shape::Scene copied = scene;
  for (shape::Part& part : copied.buildings[0].parts) {
    for (const auto& [key, value] : *building) {
      auto it = part.attributes.find(key);
      if (it == part.attributes.end()) {
        part.attributes.emplace(key, value);
      } else if (shape::is_null(it->second)) {
        it->second = value;
      }
    }
    part.inherited = nullptr;
  }
  EXPECT_EQ(glb_bytes(copied), whole);
}

// --gltf-nodes scene: one node and one mesh for every building, each part a feature whose row
// names its building and carries the building's attributes where the part has none of its own.
TEST(GltfWriter, SceneLayoutKeepsBuildingsAsFeatures) {
  GltfOptions options;
  options.nodes = GltfOptions::Nodes::kScene;
  shape::Scene scene = test_scene();
  scene.buildings[0].attributes["building"] = std::string("hospital");  // OpenStreetMap's tag
  const std::string glb = glb_bytes(scene, options);
  const tinygltf::Model model = load_glb(glb);
  const nlohmann::json json = json_of(glb);
  EXPECT_EQ(model.nodes.size(), 1U);
  EXPECT_EQ(model.meshes.size(), 1U);
  EXPECT_EQ(model.nodes[0].name, "scene");
  EXPECT_EQ(triangle_count(model), triangle_count(load_glb(glb_bytes(scene))));
  EXPECT_EQ(table_column(model, json, "building_id"),
            (std::vector<std::string>{"b1", "L-2", "L-2"}));
  EXPECT_EQ(table_column(model, json, "building"), (std::vector<std::string>{"hospital", "", ""}));
  EXPECT_EQ(table_column(model, json, "part_name"),
            (std::vector<std::string>{"main", "wing", "storey 0"}));
  EXPECT_EQ(table_column(model, json, "levels"), (std::vector<std::string>{"1", "", ""}));
  // Box & Co's name is the first building's attribute, under its own name; the second building has
  // none.
  EXPECT_EQ(table_column(model, json, "name"),
            (std::vector<std::string>{"Box & <Co> \"1\"", "", ""}));
}

// --gltf-colours class: every face shows its semantic class's colour, whatever material it has.
TEST(GltfWriter, ColoursByClassIgnoreTheFacesOwnMaterials) {
  GltfOptions options;
  options.by_class = true;
  const tinygltf::Model own = load_glb(glb_bytes(test_scene()));
  const tinygltf::Model by_class = load_glb(glb_bytes(test_scene(), options));
  const auto names = [](const tinygltf::Model& model) {
    std::vector<std::string> out;
    for (const tinygltf::Material& m : model.materials) out.push_back(m.name);
    return out;
  };
  const std::vector<std::string> own_names = names(own);
  EXPECT_NE(std::find(own_names.begin(), own_names.end(), "Tile_red"), own_names.end());
  for (const std::string& name : names(by_class)) {
    EXPECT_TRUE(name.ends_with("Surface")) << name;
  }
  EXPECT_EQ(triangle_count(own), triangle_count(by_class));
}

TEST(GltfWriter, PositionsAreLocalYUpAndQuantizedWithinAMillimetre) {
  for (const GltfOptions& options : {GltfOptions{}, kElements}) {
    const tinygltf::Model model = load_glb(glb_bytes(test_scene(), options));
    // The L wing spans local x 10..16, y 0..5, z 0..4: in glTF x 10..16, y (up) 0..4, z -5..0.
    std::array<double, 3> min{1e9, 1e9, 1e9};
    std::array<double, 3> max{-1e9, -1e9, -1e9};
    for (const testing::PlacedPrimitive& p : testing::placed_primitives(model)) {
      const bool wing = p.node == "wing" || (p.node == "L-2" && p.material != "FloorSurface");
      if (!wing) continue;
      for (const auto& position : p.positions) {
        for (std::size_t k = 0; k < 3; ++k) {
          min[k] = std::min(min[k], position[k]);
          max[k] = std::max(max[k], position[k]);
          // On the grid of 1/1024 m, these coordinates are exact.
          EXPECT_NEAR(position[k], std::round(position[k]), 1e-9);
        }
      }
    }
    for (std::size_t k = 0; k < 3; ++k) {
      EXPECT_NEAR(min[k], (std::array<double, 3>{10, 0, -5})[k], 1e-9);
      EXPECT_NEAR(max[k], (std::array<double, 3>{16, 4, 0})[k], 1e-9);
    }
  }
}

TEST(GltfWriter, QuantizedPositionsMoveLessThanAMillimetre) {
  shape::Scene scene;
  shape::Building building;
  building.id = "odd";
  building.parts.push_back({"p",
                            shape::PartKind::kBuildingPart,
                            {},
                            testing::prism({{0.1234567, 0.7654321},
                                            {23.456789, 1.1111111},
                                            {20.987654, 17.3456789},
                                            {1.3579246, 15.2468013}},
                                           0.3333333, 12.7777777)});
  scene.buildings.push_back(std::move(building));
  const std::string glb = glb_bytes(scene);
  const tinygltf::Model model = load_glb(glb);
  EXPECT_EQ(model.accessors[0].componentType, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
  const kernel::Mesh& mesh = scene.buildings[0].parts[0].mesh;
  std::size_t checked = 0;
  for (const testing::PlacedPrimitive& p : testing::placed_primitives(model)) {
    for (const auto& position : p.positions) {
      // The nearest vertex of the input (in glTF's frame) is under 1 mm away.
      double nearest = 1e9;
      for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
        const kernel::Vec3 q = mesh.position(v);
        nearest =
            std::min(nearest, std::hypot(position[0] - q.x, position[1] - q.z, position[2] + q.y));
      }
      EXPECT_LT(nearest, 0.001);
      ++checked;
    }
  }
  EXPECT_GT(checked, 0U);
  // With floats, a float32 apart.
  const tinygltf::Model floats = load_glb(glb_bytes(scene, kElements));
  EXPECT_EQ(floats.accessors[0].componentType, TINYGLTF_COMPONENT_TYPE_FLOAT);
}

// A mesh wider than 16 bits of 1/1024 m (64 m) keeps float positions.
TEST(GltfWriter, WideMeshesKeepFloatPositions) {
  shape::Scene scene;
  shape::Building building;
  building.id = "long";
  building.parts.push_back({"p",
                            shape::PartKind::kBuildingPart,
                            {},
                            testing::prism({{0, 0}, {200, 0}, {200, 10}, {0, 10}}, 0, 5)});
  scene.buildings.push_back(std::move(building));
  const tinygltf::Model model = load_glb(glb_bytes(scene));
  EXPECT_EQ(model.accessors[0].componentType, TINYGLTF_COMPONENT_TYPE_FLOAT);
  EXPECT_TRUE(model.nodes[0].scale.empty());
  EXPECT_EQ(model.accessors[0].maxValues, (std::vector<double>{200, 5, 0}));
}

// A mesh of more than 65,535 vertices indexes with 32 bits; a table of more than 65,535 parts
// gives FLOAT feature ids (exact to 2^24), each vertex still carrying its own part's row.
TEST(GltfWriter, BigMeshesAndTablesWidenTheirTypes) {
  shape::Scene scene;
  shape::Building building;
  building.id = "grid";
  constexpr int kSide = 260;  // 261^2 = 68,121 shared corners on one plane
  kernel::Mesh grid;
  for (int y = 0; y <= kSide; ++y) {
    for (int x = 0; x <= kSide; ++x) grid.add_vertex({0.2 * x, 0.2 * y, 0});
  }
  for (int y = 0; y < kSide; ++y) {
    for (int x = 0; x < kSide; ++x) {
      const auto at = [](int i, int j) { return static_cast<std::uint32_t>(j * (kSide + 1) + i); };
      grid.add_face({at(x, y), at(x + 1, y), at(x + 1, y + 1), at(x, y + 1)},
                    {kernel::SemanticClass::kGroundSurface, 0, 0});
    }
  }
  building.parts.push_back({"grid", shape::PartKind::kBuildingPart, {}, std::move(grid)});
  scene.buildings.push_back(std::move(building));
  shape::Building many;
  many.id = "many";
  for (int i = 0; i < 66000; ++i) {
    const double x = 0.01 * (i % 1000);
    const double y = 60 + 0.01 * (i / 1000);
    kernel::Mesh tile;
    tile.add_vertex({x, y, 0});
    tile.add_vertex({x + 0.005, y, 0});
    tile.add_vertex({x, y + 0.005, 0});
    tile.add_face({0, 1, 2}, {kernel::SemanticClass::kRoofSurface, 0, 0});
    many.parts.push_back({"t", shape::PartKind::kBuildingPart, {}, std::move(tile)});
  }
  scene.buildings.push_back(std::move(many));
  const tinygltf::Model model = load_glb(glb_bytes(scene));
  const tinygltf::Primitive& big = model.meshes[0].primitives[0];
  EXPECT_EQ(model.accessors[static_cast<std::size_t>(big.indices)].componentType,
            TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
  EXPECT_EQ(model.accessors[static_cast<std::size_t>(big.attributes.at("POSITION"))].count,
            static_cast<std::size_t>((kSide + 1) * (kSide + 1)));
  EXPECT_EQ(
      model.accessors[static_cast<std::size_t>(big.attributes.at("_FEATURE_ID_0"))].componentType,
      TINYGLTF_COMPONENT_TYPE_FLOAT);
  std::size_t triangles = 0;
  for (const testing::PlacedPrimitive& p : testing::placed_primitives(model)) {
    if (p.node != "many") continue;
    for (std::size_t t = 0; t < p.indices.size(); t += 3) {
      // Part i's triangle: its corners carry row 1 + i (row 0 is the grid), at its own place.
      const double feature = p.features[p.indices[t]];
      EXPECT_EQ(p.features[p.indices[t + 1]], feature);
      const auto i = static_cast<int>(feature) - 1;
      const auto& corner = p.positions[p.indices[t]];
      EXPECT_NEAR(
          std::min({corner[0], p.positions[p.indices[t + 1]][0], p.positions[p.indices[t + 2]][0]}),
          0.01 * (i % 1000), 1e-3);
      ++triangles;
    }
  }
  EXPECT_EQ(triangles, 66000U);
}

TEST(GltfWriter, NormalsAreFlatAndUnit) {
  for (const GltfOptions& options : {GltfOptions{}, kElements}) {
    const tinygltf::Model model = load_glb(glb_bytes(test_scene(), options));
    for (const testing::PlacedPrimitive& p : testing::placed_primitives(model)) {
      if (p.node != "b1" && p.node != "main") continue;
      for (const auto& n : p.normals) {
        EXPECT_NEAR(std::hypot(n[0], n[1], n[2]), 1.0, 1e-6);
        // Roof up, ground down, walls level.
        const double up = p.material == "Tile_red" ? 1 : p.material == "GroundSurface" ? -1 : 0;
        EXPECT_EQ(n[1], up) << p.material;
      }
      // Flat shading: every face has its own corners, 4 per quad here.
      EXPECT_EQ(p.positions.size() * 6, 4 * p.indices.size()) << p.material;
    }
  }
}

// A face whose corners lie on one line (a zero-width strip a setback cut from a round outline)
// has no normal: it is not written, and every written normal is a unit vector (the Khronos
// validator's ACCESSOR_VECTOR3_NON_UNIT).
TEST(GltfWriter, FacesWithoutAreaAreNotWritten) {
  kernel::Mesh mesh;
  const std::uint32_t a = mesh.add_vertex({0, 0, 0});
  const std::uint32_t b = mesh.add_vertex({4, 0, 0});
  const std::uint32_t c = mesh.add_vertex({4, 3, 0});
  const std::uint32_t d = mesh.add_vertex({0, 3, 0});
  const std::uint32_t e = mesh.add_vertex({8, 0, 0});
  const std::uint32_t f = mesh.add_vertex({12, 0, 0});
  // 0.1 mm from c: both round to one written position, so the part's faces are contracted one
  // by one (the path a collinear face took from a real round outline).
  const std::uint32_t g = mesh.add_vertex({4.0001, 3, 0});
  mesh.add_face({a, b, c, d}, {});
  mesh.add_face({b, e, f}, {});  // three corners on the x axis
  mesh.add_face({b, g, c}, {});  // a sliver that the rounding collapses
  shape::Scene scene;
  shape::Building building;
  building.id = "strip";
  building.parts.push_back({"paving", shape::PartKind::kBuildingPart, {}, std::move(mesh)});
  scene.buildings.push_back(std::move(building));
  for (const GltfOptions& options : {GltfOptions{}, kElements}) {
    const tinygltf::Model model = load_glb(glb_bytes(scene, options));
    std::size_t triangles = 0;
    for (const testing::PlacedPrimitive& p : testing::placed_primitives(model)) {
      triangles += p.indices.size() / 3;
      for (const auto& n : p.normals) EXPECT_NEAR(std::hypot(n[0], n[1], n[2]), 1.0, 1e-6);
      // Only the collinear face reaches past x = 4.5.
      for (const auto& q : p.positions) EXPECT_LT(q[0], 4.5);
    }
    EXPECT_GE(triangles, 2U);  // the quad's (and, where float32 tells g from c, the sliver's)
  }
}

// A building whose parts are: its walls, a 1 m cube placed twice (turned, scaled, mirrored),
// a further wall, and the cube sheared (no TRS can hold it).
shape::Scene instanced_scene() {
  auto cube =
      std::make_shared<const kernel::Mesh>(testing::prism({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0, 1));
  shape::Scene scene;
  shape::Building b;
  b.id = "with instances";
  b.parts.push_back({"walls",
                     shape::PartKind::kBuildingPart,
                     {},
                     testing::prism({{0, 0}, {20, 0}, {20, 10}, {0, 10}}, 0, 6)});
  const auto instance = [&](std::string name, kernel::Transform t) {
    shape::Part part{std::move(name), shape::PartKind::kInstallation, {}, {}};
    part.instance_of = cube;
    part.instance_transform = t;
    b.parts.push_back(std::move(part));
  };
  instance("turned", kernel::Transform{{0, 1, 0}, {-1, 0, 0}, {0, 0, 1}, {5, 2, 6}});
  b.parts.push_back({"annex",
                     shape::PartKind::kBuildingPart,
                     {},
                     testing::prism({{20, 0}, {24, 0}, {24, 4}, {20, 4}}, 0, 3)});
  instance("mirrored", kernel::Transform{{-2, 0, 0}, {0, 1, 0}, {0, 0, 3}, {12, 3, 6}});
  instance("sheared", kernel::Transform{{1, 0, 0}, {0.5, 1, 0}, {0, 0, 1}, {2, 8, 6}});
  scene.buildings.push_back(std::move(b));
  return scene;
}

// The glTF-frame box of the primitives `keep` accepts.
std::array<double, 6> box_of(const std::vector<testing::PlacedPrimitive>& primitives,
                             const std::function<bool(const testing::PlacedPrimitive&)>& keep) {
  std::array<double, 6> box{1e9, 1e9, 1e9, -1e9, -1e9, -1e9};
  for (const testing::PlacedPrimitive& p : primitives) {
    if (!keep(p)) continue;
    for (const auto& q : p.positions) {
      for (std::size_t k = 0; k < 3; ++k) {
        box[k] = std::min(box[k], q[k]);
        box[3 + k] = std::max(box[3 + k], q[k]);
      }
    }
  }
  return box;
}

void expect_box(const std::array<double, 6>& got, const std::array<double, 6>& want,
                const std::string& what) {
  for (std::size_t k = 0; k < 6; ++k) EXPECT_NEAR(got[k], want[k], 1e-5) << what << " " << k;
}

// Where each instance must be, in glTF's frame (x, z, -y).
void expect_instances_placed(const tinygltf::Model& model, const std::string& what) {
  const std::vector<testing::PlacedPrimitive> placed = testing::placed_primitives(model);
  const auto named = [&](const std::string& node, double feature) {
    return [node, feature](const testing::PlacedPrimitive& p) {
      if (p.mesh == "with instances" || p.features.empty()) return false;
      // A GPU instance is known by its feature id, a node's instance by the node's name.
      return p.features[0] >= 0 ? p.features[0] == feature : p.node == node;
    };
  };
  // turned: x from 4 to 5, y 2..3, z 6..7 (local) -> glTF x 4..5, y 6..7, z -3..-2.
  expect_box(box_of(placed, named("turned", 1)), {4, 6, -3, 5, 7, -2}, what + " turned");
  // mirrored: x 10..12, y 3..4, z 6..9.
  expect_box(box_of(placed, named("mirrored", 3)), {10, 6, -4, 12, 9, -3}, what + " mirrored");
  // sheared: x 2..3.5, y 8..9, z 6..7.
  expect_box(box_of(placed, named("sheared", 4)), {2, 6, -9, 3.5, 7, -8}, what + " sheared");
  // The building's own faces: walls and annex, x 0..24, y 0..10, z 0..6.
  expect_box(
      box_of(placed, [](const testing::PlacedPrimitive& p) { return p.mesh == "with instances"; }),
      {0, 0, -10, 24, 6, 0}, what + " building");
}

TEST(GltfWriter, InstancesShareOneMeshPlacedByTheirNodes) {
  const tinygltf::Model model = load_glb(glb_bytes(instanced_scene()));
  ASSERT_EQ(model.meshes.size(), 2U);  // the cube once, the building's own faces
  EXPECT_EQ(model.meshes[1].name, "with instances");
  const tinygltf::Node& building = node_named(model, "with instances");
  ASSERT_EQ(building.children.size(), 3U);
  for (int child : building.children) {
    const tinygltf::Node& node = model.nodes[static_cast<std::size_t>(child)];
    EXPECT_EQ(node.mesh, 0);
    EXPECT_EQ(node.matrix.size(), 16U);
    EXPECT_EQ(node.extras.Get("kind").Get<std::string>(), "Installation");
  }
  expect_instances_placed(model, "nodes");
}

TEST(GltfWriter, GpuInstancingPlacesEveryTrsInstanceFromOneNode) {
  GltfOptions options;
  options.instancing = GltfOptions::Instancing::kGpu;
  const std::string glb = glb_bytes(instanced_scene(), options);
  const tinygltf::Model model = load_glb(glb);
  const tinygltf::Node& building = node_named(model, "with instances");
  // One node places "turned" and "mirrored"; "sheared" keeps a node of its own.
  ASSERT_EQ(building.children.size(), 2U);
  const tinygltf::Node& group = model.nodes[static_cast<std::size_t>(building.children[0])];
  ASSERT_TRUE(group.extensions.contains("EXT_mesh_gpu_instancing"));
  // The instances' feature ids are named by EXT_instance_features (CesiumJS reads only that on a
  // node; EXT_mesh_features is for a primitive's vertices).
  ASSERT_TRUE(group.extensions.contains("EXT_instance_features"));
  EXPECT_FALSE(group.extensions.contains("EXT_mesh_features"));
  EXPECT_EQ(model.nodes[static_cast<std::size_t>(building.children[1])].name, "sheared");
  const nlohmann::json json = json_of(glb);
  EXPECT_EQ(json["extensionsRequired"],
            (nlohmann::json{"EXT_mesh_gpu_instancing", "KHR_mesh_quantization"}));
  EXPECT_EQ(json["extensionsUsed"],
            (nlohmann::json{"EXT_instance_features", "EXT_mesh_features", "EXT_mesh_gpu_instancing",
                            "EXT_structural_metadata", "KHR_mesh_quantization"}));
  const nlohmann::json& ids =
      json["nodes"][building.children[0]]["extensions"]["EXT_instance_features"]["featureIds"][0];
  EXPECT_EQ(ids["attribute"], 0);
  EXPECT_EQ(ids["propertyTable"], 0);
  expect_instances_placed(model, "gpu");
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
  for (const testing::PlacedPrimitive& primitive : testing::placed_primitives(model)) {
    if (primitive.material != "RoofSurface") continue;
    const std::vector<std::uint32_t>& index = primitive.indices;
    ASSERT_EQ(index.size(), 12U);
    for (std::size_t t = 0; t < index.size(); t += 3) {
      // glTF (X, Z) is local (x, -y); the roof is seen from +Y, so counter-clockwise means the
      // signed area in the (X, -Z) = (x, y) plane is positive.
      const auto at = [&](std::size_t k) {
        const auto& p = primitive.positions[index[t + k]];
        return std::pair<double, double>{p[0], -p[2]};
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
  EXPECT_NEAR(roof_area, 18.0, 1e-9);  // 6 x 2 + 2 x 3
}

// Regular 48-gon prisms: the clipped roof and ground of each reload vertices a 16-vertex cache
// has let go, so their runs are reordered for the cache and the vertices renumbered for fetch.
// Each part's triangles still carry its feature id, lie over its footprint and cover its area.
TEST(GltfWriter, ReorderedRunsKeepEachPartsTrianglesAndFeature) {
  constexpr int kSides = 48;
  constexpr double kPi = 3.14159265358979323846;
  shape::Scene scene;
  shape::Building building;
  building.id = "round";
  double polygon_area = 0;
  for (int part = 0; part < 3; ++part) {
    std::vector<kernel::Vec2> footprint;
    for (int i = 0; i < kSides; ++i) {
      const double a = 2 * kPi * i / kSides;
      footprint.push_back({20.0 * part + 5 * std::cos(a), 5 * std::sin(a)});
    }
    polygon_area = kSides * 25 * std::sin(2 * kPi / kSides) / 2;
    building.parts.push_back({"part " + std::to_string(part),
                              shape::PartKind::kBuildingPart,
                              {},
                              testing::prism(footprint, 0, 3)});
  }
  scene.buildings.push_back(std::move(building));
  std::array<double, 3> roof_area{};
  std::size_t triangles = 0;
  for (const testing::PlacedPrimitive& p : testing::placed_primitives(load_glb(glb_bytes(scene)))) {
    ASSERT_EQ(p.features.size(), p.positions.size());
    for (std::size_t t = 0; t < p.indices.size(); t += 3) {
      ++triangles;
      const double feature = p.features[p.indices[t]];
      double x = 0;
      for (std::size_t k = 0; k < 3; ++k) {
        EXPECT_EQ(p.features[p.indices[t + k]], feature);
        x += p.positions[p.indices[t + k]][0] / 3;
      }
      ASSERT_TRUE(feature == 0 || feature == 1 || feature == 2);
      const auto part = static_cast<std::size_t>(feature);
      EXPECT_NEAR(x, 20.0 * static_cast<double>(part), 5.01);
      if (p.material != "RoofSurface") continue;
      const auto& a = p.positions[p.indices[t]];
      const auto& b = p.positions[p.indices[t + 1]];
      const auto& c = p.positions[p.indices[t + 2]];
      // Seen from +Y: (X, -Z) is the local (x, y) plane.
      roof_area[part] += ((b[0] - a[0]) * (a[2] - c[2]) - (a[2] - b[2]) * (c[0] - a[0])) / 2;
    }
  }
  EXPECT_EQ(triangles, 3U * (2 * kSides + 2 * (kSides - 2)));
  for (double area : roof_area) EXPECT_NEAR(area, polygon_area, 0.05);  // quantized corners
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
