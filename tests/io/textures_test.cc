// Textures read from files (io/textures.h): PNG and JPEG decoded and kept as they are, found as
// assets are, failures named; the glTF writer embeds a JPEG as image/jpeg with a repeating sampler
// and TEXCOORD_0 from the part's uv map; the OBJ writer's vt, map_Kd and copied image.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

// A JPEG encoder for the test's image (a system header: its warnings are not ours).
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

#include "io/gltf_writer.h"
#include "io/obj_writer.h"
#include "io/textures.h"

namespace insula::io {
namespace {

namespace fs = std::filesystem;

// An 8 x 8 image, left half red, right half blue, as JPEG bytes.
std::string jpeg_bytes() {
  std::vector<unsigned char> rgb(8 * 8 * 3, 0);
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 8; ++x)
      rgb[static_cast<std::size_t>((y * 8 + x) * 3 + (x < 4 ? 0 : 2))] = 255;
  }
  std::string out;
  stbi_write_jpg_to_func(
      [](void* context, void* data, int size) {
        static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                                   static_cast<std::size_t>(size));
      },
      &out, 8, 8, 3, rgb.data(), 95);
  return out;
}

TEST(Textures, DecodesJpegAndKeepsItsBytes) {
  const std::string bytes = jpeg_bytes();
  std::string error;
  const auto image = decode_texture("wall.jpg", bytes, error);
  ASSERT_NE(image, nullptr) << error;
  EXPECT_EQ(image->mime_type, "image/jpeg");
  EXPECT_EQ(image->encoded, bytes);
  EXPECT_EQ(image->width, 8);
  EXPECT_EQ(image->height, 8);
  EXPECT_GT(image->rgba[0], 200);          // left: red
  EXPECT_GT(image->rgba[4 * 7 + 2], 200);  // right: blue
  EXPECT_EQ(decode_texture("x.png", "GIF89a....", error), nullptr);
  EXPECT_EQ(error, "not a PNG or JPEG image");
}

TEST(Textures, FoundAsAssetsAreAndFailuresNamed) {
  const fs::path dir = fs::temp_directory_path() / "insula_textures_test";
  fs::remove_all(dir);
  fs::create_directories(dir / "rules");
  fs::create_directories(dir / "assets" / "walls");
  std::ofstream(dir / "assets" / "walls" / "wall.jpg", std::ios::binary) << jpeg_bytes();
  std::ofstream(dir / "assets" / "bad.png", std::ios::binary) << "not an image";
  shape::Scene scene;
  for (const char* name : {"walls/wall.jpg", "walls/none.jpg", "bad.png", "walls/wall.jpg"}) {
    shape::Material m{name, {1, 1, 1, 1}};
    m.texture = name;
    scene.materials.push_back(m);
  }
  const std::vector<TextureFailure> failures =
      load_textures(scene, AssetSearch(dir / "rules" / "facade.cga"));
  ASSERT_EQ(failures.size(), 2U);
  EXPECT_EQ(failures[0].name, "walls/none.jpg");
  EXPECT_TRUE(failures[0].error.starts_with("not found (looked in ")) << failures[0].error;
  EXPECT_EQ(failures[1].name, "bad.png");
  EXPECT_TRUE(failures[1].error.ends_with("bad.png': not a PNG or JPEG image"))
      << failures[1].error;
  ASSERT_NE(scene.materials[1].image, nullptr);
  EXPECT_EQ(scene.materials[1].image, scene.materials[4].image);  // read once
  EXPECT_EQ(scene.materials[2].image, nullptr);
  fs::remove_all(dir);
}

// A 4 x 3 m wall in the xz plane with a uv map of 2 m x 1 m repeats, showing a JPEG.
shape::Scene textured_wall() {
  shape::Scene scene;
  std::string error;
  shape::Material m{"wall", {1, 1, 1, 1}};
  m.image = decode_texture("wall.jpg", jpeg_bytes(), error);
  m.texture = "walls/wall.jpg";
  scene.materials.push_back(m);
  shape::Part part;
  part.name = "Wall";
  const kernel::FaceTag tag{kernel::SemanticClass::kWallSurface, 1, 0};
  const std::array<kernel::Vec3, 4> loop = {kernel::Vec3{0, 0, 0}, kernel::Vec3{4, 0, 0},
                                            kernel::Vec3{4, 0, 3}, kernel::Vec3{0, 0, 3}};
  part.mesh.add_polygon(loop, tag);
  part.uv = shape::UvMap{{0.5, 0, 0}, 0, {0, 0, 1}, 0};
  scene.buildings.push_back({"b", {}, {part}});
  return scene;
}

TEST(Textures, GlbEmbedsTheJpegWithARepeatingSampler) {
  const std::string glb = glb_bytes(textured_wall());
  std::uint32_t length = 0;
  std::memcpy(&length, glb.data() + 12, 4);
  const nlohmann::json gltf = nlohmann::json::parse(glb.substr(20, length));
  ASSERT_EQ(gltf["images"].size(), 1U);
  EXPECT_EQ(gltf["images"][0]["mimeType"], "image/jpeg");
  EXPECT_EQ(gltf["samplers"][0]["wrapS"], 10497);
  EXPECT_EQ(gltf["textures"][0]["sampler"], 0);
  EXPECT_NE(glb.find(jpeg_bytes()), std::string::npos);  // embedded byte for byte
  const nlohmann::json& accessor =
      gltf["accessors"][gltf["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"].get<int>()];
  const nlohmann::json& view = gltf["bufferViews"][accessor["bufferView"].get<int>()];
  const std::size_t start =
      20 + length + 8 + view.value("byteOffset", 0U) + accessor.value("byteOffset", 0U);
  float u_max = -1, v_min = 1;
  for (std::size_t k = 0; k < accessor["count"].get<std::size_t>(); ++k) {
    float uv[2];
    std::memcpy(uv, glb.data() + start + 8 * k, 8);
    u_max = std::max(u_max, uv[0]);
    v_min = std::min(v_min, uv[1]);
  }
  EXPECT_FLOAT_EQ(u_max, 2);   // 4 m at 2 m per repeat
  EXPECT_FLOAT_EQ(v_min, -2);  // 3 m up, glTF's v = 1 - v
}

TEST(Textures, ObjWritesVtMapKdAndCopiesTheImage) {
  const ObjText text = obj_text(textured_wall(), "wall.mtl");
  EXPECT_NE(text.obj.find("vt 2 0\n"), std::string::npos) << text.obj;
  EXPECT_NE(text.obj.find("vt 0 3\n"), std::string::npos) << text.obj;
  EXPECT_NE(text.obj.find("f 1/1 2/2 3/3 4/4\n"), std::string::npos) << text.obj;
  EXPECT_NE(text.mtl.find("map_Kd wall.jpg\n"), std::string::npos) << text.mtl;
  ASSERT_EQ(text.textures.size(), 1U);
  EXPECT_EQ(text.textures[0].first, "wall.jpg");
  EXPECT_EQ(text.textures[0].second, jpeg_bytes());
}

}  // namespace
}  // namespace insula::io
