// glTF writer, lights and textures: Scene::lights as KHR_lights_punctual (the lights array, one
// node per light at its Y-up position, spot lights turned so -Z points along their direction) and
// Material::image as an embedded PNG with a texture, a sampler and TEXCOORD_0 fitted to each face.
// Read back with tinygltf; the PNG is decoded with stb_image.
#include <array>
#include <cmath>
#include <cstring>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wold-style-cast"
#pragma GCC diagnostic ignored "-Wcast-align"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wpedantic"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-but-set-variable"
#define STBI_ONLY_PNG
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>
#pragma GCC diagnostic pop

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

using testing::prism;
using testing::read_accessor;

// tinygltf's image callback: the PNG decoded to RGBA.
bool decode_png(tinygltf::Image* image, const int /*index*/, std::string* error,
                std::string* /*warning*/, int /*width*/, int /*height*/, const unsigned char* bytes,
                int size, void* /*user*/) {
  int w = 0;
  int h = 0;
  int channels = 0;
  unsigned char* pixels = stbi_load_from_memory(bytes, size, &w, &h, &channels, 4);
  if (pixels == nullptr) {
    *error += "not a PNG";
    return false;
  }
  image->width = w;
  image->height = h;
  image->component = 4;
  image->bits = 8;
  image->pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
  image->image.assign(pixels,
                      pixels + 4 * static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
  stbi_image_free(pixels);
  return true;
}

tinygltf::Model load(const std::string& glb) {
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(decode_png, nullptr);
  tinygltf::Model model;
  std::string error;
  std::string warning;
  EXPECT_TRUE(loader.LoadBinaryFromMemory(&model, &error, &warning,
                                          reinterpret_cast<const unsigned char*>(glb.data()),
                                          static_cast<unsigned int>(glb.size())))
      << error;
  EXPECT_EQ(error, "");
  EXPECT_EQ(warning, "");
  return model;
}

nlohmann::json json_chunk(const std::string& glb) {
  std::uint32_t length = 0;
  std::memcpy(&length, glb.data() + 12, 4);
  return nlohmann::json::parse(glb.substr(20, length));
}

shape::Light light(std::string name, std::string kind, kernel::Vec3 position) {
  shape::Light l;
  l.name = std::move(name);
  l.kind = std::move(kind);
  l.position = position;
  return l;
}

// A 4 x 3 x 3 box plus three lights: a point light with a range, a spot pointing down (the
// default) and a spot pointing east.
shape::Scene lit_scene() {
  shape::Scene scene;
  shape::Building b;
  b.id = "b";
  b.parts.push_back(
      {"main", shape::PartKind::kBuildingPart, {}, prism({{0, 0}, {4, 0}, {4, 3}, {0, 3}}, 0, 3)});
  scene.buildings.push_back(std::move(b));
  scene.lights.push_back(light("lamp", "point", {1, 2, 3}));
  scene.lights.back().color = {1.0F, 0.5F, 0.25F};
  scene.lights.back().intensity = 250;
  scene.lights.back().range = 12;
  scene.lights.push_back(light("", "spot", {2, 1.5, 6}));
  scene.lights.push_back(light("east", "spot", {0, -4, 0.5}));
  scene.lights.back().direction = {1, 0, 0};
  return scene;
}

// v rotated by the unit quaternion q = (x, y, z, w).
std::array<double, 3> rotate(const std::vector<double>& q, std::array<double, 3> v) {
  const std::array<double, 3> u = {q[0], q[1], q[2]};
  const double w = q[3];
  const auto cross = [](std::array<double, 3> a, std::array<double, 3> b) {
    return std::array<double, 3>{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                                 a[0] * b[1] - a[1] * b[0]};
  };
  const std::array<double, 3> t = cross(u, v);
  const std::array<double, 3> t2 = {2 * t[0], 2 * t[1], 2 * t[2]};
  const std::array<double, 3> c = cross(u, t2);
  return {v[0] + w * t2[0] + c[0], v[1] + w * t2[1] + c[1], v[2] + w * t2[2] + c[2]};
}

TEST(GltfLights, LightsArrayAndExtensionUsed) {
  const std::string glb = glb_bytes(lit_scene());
  const tinygltf::Model model = load(glb);
  EXPECT_NE(
      std::find(model.extensionsUsed.begin(), model.extensionsUsed.end(), "KHR_lights_punctual"),
      model.extensionsUsed.end());
  ASSERT_EQ(model.lights.size(), 3U);
  const tinygltf::Light& lamp = model.lights[0];
  EXPECT_EQ(lamp.name, "lamp");
  EXPECT_EQ(lamp.type, "point");
  EXPECT_EQ(lamp.color, (std::vector<double>{1, 0.5, 0.25}));
  EXPECT_EQ(lamp.intensity, 250);
  EXPECT_EQ(lamp.range, 12);
  EXPECT_EQ(model.lights[1].name, "light1");
  EXPECT_EQ(model.lights[1].type, "spot");
  EXPECT_DOUBLE_EQ(model.lights[1].spot.outerConeAngle, std::numbers::pi / 4);
  EXPECT_EQ(model.lights[1].intensity, 1);
  // Range 0 means unlimited: the extension forbids writing it.
  const nlohmann::json lights = json_chunk(glb)["extensions"]["KHR_lights_punctual"]["lights"];
  EXPECT_TRUE(lights[0].contains("range"));
  EXPECT_FALSE(lights[1].contains("range"));
  EXPECT_FALSE(lights[0].contains("spot"));
}

TEST(GltfLights, OneNodePerLightAtItsYUpPosition) {
  const tinygltf::Model model = load(glb_bytes(lit_scene()));
  // The building's node, then the three lights; all lights are scene roots.
  ASSERT_EQ(model.nodes.size(), 4U);
  EXPECT_EQ(model.scenes[0].nodes, (std::vector<int>{0, 1, 2, 3}));
  const std::array<std::vector<double>, 3> translations = {std::vector<double>{1, 3, -2},
                                                           std::vector<double>{2, 6, -1.5},
                                                           std::vector<double>{0, 0.5, 4}};
  for (int i = 0; i < 3; ++i) {
    const tinygltf::Node& node = model.nodes[static_cast<std::size_t>(1 + i)];
    ASSERT_TRUE(node.extensions.contains("KHR_lights_punctual"));
    EXPECT_EQ(node.extensions.at("KHR_lights_punctual").Get("light").GetNumberAsInt(), i);
    EXPECT_EQ(node.translation, translations[static_cast<std::size_t>(i)]) << i;
    EXPECT_EQ(node.mesh, -1);
  }
  EXPECT_EQ(model.nodes[1].name, "lamp");
  EXPECT_TRUE(model.nodes[1].rotation.empty());  // point lights have no direction
}

TEST(GltfLights, SpotRotationTurnsMinusZOntoTheDirection) {
  const tinygltf::Model model = load(glb_bytes(lit_scene()));
  // Down (local -Z) is glTF -Y; east (local +X) is glTF +X.
  const std::array<std::pair<std::size_t, std::array<double, 3>>, 2> cases = {
      std::pair<std::size_t, std::array<double, 3>>{2, {0, -1, 0}}, {3, {1, 0, 0}}};
  for (const auto& [node, want] : cases) {
    const std::vector<double>& q = model.nodes[node].rotation;
    ASSERT_EQ(q.size(), 4U);
    EXPECT_NEAR(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3], 1, 1e-12);
    const std::array<double, 3> got = rotate(q, {0, 0, -1});
    for (std::size_t k = 0; k < 3; ++k) EXPECT_NEAR(got[k], want[k], 1e-12) << node << " " << k;
  }
  // Opposite to -Z (local -Y is glTF +Z): a half turn.
  shape::Scene scene;
  scene.lights.push_back(light("north", "spot", {0, 0, 0}));
  scene.lights.back().direction = {0, -1, 0};
  const tinygltf::Model opposite = load(glb_bytes(scene));
  const std::array<double, 3> got = rotate(opposite.nodes[0].rotation, {0, 0, -1});
  EXPECT_NEAR(got[2], 1, 1e-12);
}

TEST(GltfLights, LightsWithoutBuildingsAreAValidAsset) {
  shape::Scene scene;
  scene.lights.push_back(light("only", "point", {0, 0, 2}));
  const std::string glb = glb_bytes(scene);
  const tinygltf::Model model = load(glb);
  EXPECT_TRUE(model.buffers.empty());
  EXPECT_TRUE(model.meshes.empty());
  ASSERT_EQ(model.nodes.size(), 1U);
  EXPECT_EQ(model.scenes[0].nodes, std::vector<int>{0});
  EXPECT_EQ(model.nodes[0].translation, (std::vector<double>{0, 2, 0}));
}

// A 3 x 2 image: red, green, blue over white, black, half-transparent grey.
std::shared_ptr<const shape::Image> image() {
  auto i = std::make_shared<shape::Image>();
  i->name = "sign";
  i->width = 3;
  i->height = 2;
  i->rgba = {255, 0,   0,   255, 0, 255, 0, 255, 0,   0,   255, 255,
             255, 255, 255, 255, 0, 0,   0, 255, 128, 128, 128, 128};
  return i;
}

// The box with its roof (face 5) and its south wall (face 1, y = 0) textured with one image
// through two materials, and a second box untextured.
shape::Scene textured_scene() {
  shape::Scene scene;
  const auto img = image();
  scene.materials.push_back({"roof sign", {1, 1, 1, 1}, img});
  scene.materials.push_back({"wall sign", {1, 1, 1, 1}, img});
  kernel::Mesh box = prism({{0, 0}, {4, 0}, {4, 3}, {0, 3}}, 0, 3, 1);
  box.tag(1).material = 2;
  shape::Building b;
  b.id = "b";
  b.parts.push_back({"main", shape::PartKind::kBuildingPart, {}, std::move(box)});
  b.parts.push_back({"plain",
                     shape::PartKind::kBuildingPart,
                     {},
                     prism({{10, 0}, {12, 0}, {12, 2}, {10, 2}}, 0, 1)});
  scene.buildings.push_back(std::move(b));
  return scene;
}

TEST(GltfTextures, ImageTextureSamplerAndBaseColorTexture) {
  const tinygltf::Model model = load(glb_bytes(textured_scene()));
  // One image for the two materials that share it.
  ASSERT_EQ(model.images.size(), 1U);
  ASSERT_EQ(model.textures.size(), 1U);
  ASSERT_EQ(model.samplers.size(), 1U);
  const tinygltf::Image& img = model.images[0];
  EXPECT_EQ(img.name, "sign");
  EXPECT_EQ(img.mimeType, "image/png");
  EXPECT_GE(img.bufferView, 0);
  EXPECT_EQ(img.width, 3);
  EXPECT_EQ(img.height, 2);
  EXPECT_EQ(img.image, image()->rgba);
  EXPECT_EQ(model.textures[0].source, 0);
  EXPECT_EQ(model.textures[0].sampler, 0);
  EXPECT_EQ(model.samplers[0].wrapS, TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE);
  int textured = 0;
  for (const tinygltf::Material& m : model.materials) {
    const int index = m.pbrMetallicRoughness.baseColorTexture.index;
    if (m.name == "roof_sign" || m.name == "wall_sign") {
      EXPECT_EQ(index, 0) << m.name;
      ++textured;
    } else {
      EXPECT_EQ(index, -1) << m.name;
    }
  }
  EXPECT_EQ(textured, 2);
}

TEST(GltfTextures, TexturedPrimitivesHaveFittedTexcoords) {
  const tinygltf::Model model = load(glb_bytes(textured_scene()));
  std::size_t with_uv = 0;
  for (const testing::PlacedPrimitive& p : testing::placed_primitives(model)) {
    const bool textured = p.material == "roof_sign" || p.material == "wall_sign";
    // The building's one mesh shares its attributes: texture coordinates reach every primitive.
    ASSERT_EQ(p.uvs.size(), p.positions.size()) << p.material;
    if (!textured) continue;
    ++with_uv;
    // Positions are Y-up (x, z, -y); each face shows the whole image, top-left at (0, 0).
    for (std::size_t v = 0; v < p.positions.size(); ++v) {
      const double x = p.positions[v][0];
      const double y = -p.positions[v][2];
      const double z = p.positions[v][1];
      if (p.material == "roof_sign") {  // seen from above, north up: u = x / 4, v = 1 - y / 3
        EXPECT_NEAR(p.uvs[v][0], x / 4, 1e-6);
        EXPECT_NEAR(p.uvs[v][1], 1 - y / 3, 1e-6);
      } else {  // the south wall seen from the south: u = x / 4, v = 1 - z / 3
        EXPECT_NEAR(p.uvs[v][0], x / 4, 1e-6);
        EXPECT_NEAR(p.uvs[v][1], 1 - z / 3, 1e-6);
      }
    }
  }
  EXPECT_EQ(with_uv, 2U);
  const tinygltf::Accessor& uv = model.accessors[static_cast<std::size_t>(
      model.meshes[0].primitives[0].attributes.at("TEXCOORD_0"))];
  EXPECT_EQ(uv.type, TINYGLTF_TYPE_VEC2);
  EXPECT_EQ(uv.componentType, TINYGLTF_COMPONENT_TYPE_FLOAT);
}

TEST(GltfTextures, BufferLayoutAndDeterminism) {
  const std::string glb = glb_bytes(textured_scene());
  EXPECT_EQ(glb, glb_bytes(textured_scene()));
  const nlohmann::json j = json_chunk(glb);
  // The image has a view of its own (no target, 8-byte aligned, as every view).
  const nlohmann::json& view = j["bufferViews"][j["images"][0]["bufferView"].get<std::size_t>()];
  EXPECT_FALSE(view.contains("target"));
  EXPECT_EQ(view["byteOffset"].get<std::size_t>() % 8, 0U);
  // The PNG sits in the buffer as is.
  std::uint32_t json_length = 0;
  std::memcpy(&json_length, glb.data() + 12, 4);
  const std::size_t bin = 20 + json_length + 8;
  EXPECT_EQ(glb.substr(bin + view["byteOffset"].get<std::size_t>(), 8), "\x89PNG\r\n\x1a\n");
}

TEST(GltfTextures, ScenesWithoutImagesOrLightsAreUnchanged) {
  const nlohmann::json j = json_chunk(glb_bytes(testing::test_scene()));
  for (const char* key : {"images", "textures", "samplers"}) {
    EXPECT_FALSE(j.contains(key)) << key;
  }
  // The root's only extension is the parts' property table.
  EXPECT_EQ(j["extensions"].size(), 1U);
  EXPECT_TRUE(j["extensions"].contains("EXT_structural_metadata"));
}

}  // namespace
}  // namespace insula::io
