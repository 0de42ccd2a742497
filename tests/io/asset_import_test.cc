// Asset import: OBJ (+MTL) through io's reader, GLB/glTF (written by io's glTF writer: quantized,
// meshopt-compressed, GPU-instanced) through io's glTF reader, DAE (written here by hand) and FBX
// (written at test time by Assimp's own exporter, `assimp export`) through Assimp.
#include "io/asset_import.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <memory>
#include <set>

#include "asset_fixtures.h"
#include "io/gltf_writer.h"
#include "writer_fixtures.h"

namespace insula::io {
namespace {

using kernel::Vec3;
using testing::TempFolder;
using testing::write_file;

void expect_bounds(const kernel::Mesh& mesh, Vec3 min, Vec3 max) {
  const kernel::Bounds3 b = mesh.bounds();
  EXPECT_NEAR(b.min.x, min.x, 1e-6);
  EXPECT_NEAR(b.min.y, min.y, 1e-6);
  EXPECT_NEAR(b.min.z, min.z, 1e-6);
  EXPECT_NEAR(b.max.x, max.x, 1e-6);
  EXPECT_NEAR(b.max.y, max.y, 1e-6);
  EXPECT_NEAR(b.max.z, max.z, 1e-6);
}

std::size_t triangles(const kernel::Mesh& mesh) {
  std::size_t n = 0;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) n += mesh.face(f).size() == 3 ? 1 : 0;
  return n;
}

TEST(AssetImport, ObjKeepsQuadsAndReadsMtlColours) {
  const TempFolder dir;
  write_file(dir / "box.obj", testing::box_obj(1, 2, 3, "box.mtl"));
  write_file(dir / "box.mtl", testing::kBoxMtl);
  base::Result<ImportedAsset> a = import_asset(dir / "box.obj");
  ASSERT_TRUE(a.ok()) << base::render(a.diagnostics().front());
  EXPECT_EQ(a->mesh.vertex_count(), 8U);
  EXPECT_EQ(a->mesh.face_count(), 6U);  // n-gons stay
  expect_bounds(a->mesh, {0, 0, 0}, {1, 2, 3});
  EXPECT_NEAR(kernel::volume(a->mesh), 6, 1e-9);
  ASSERT_EQ(a->materials.size(), 2U);
  EXPECT_EQ(a->materials[0].name, "red");
  EXPECT_EQ(a->materials[0].rgba, (std::array<float, 4>{1, 0, 0, 1}));
  EXPECT_EQ(a->materials[1].name, "blue");
  EXPECT_EQ(a->materials[1].rgba, (std::array<float, 4>{0, 0, 1, 0.5F}));
  EXPECT_EQ(a->mesh.tag(0).material, 1);  // red
  EXPECT_EQ(a->mesh.tag(5).material, 2);  // blue
}

TEST(AssetImport, ObjWithoutItsMtlKeepsGrey) {
  const TempFolder dir;
  write_file(dir / "box.obj", testing::box_obj(1, 1, 1, "missing.mtl"));
  base::Result<ImportedAsset> a = import_asset(dir / "box.obj");
  ASSERT_TRUE(a.ok());
  ASSERT_EQ(a->materials.size(), 2U);
  EXPECT_EQ(a->materials[0].rgba, AssetMaterial{}.rgba);
}

// A 1 x 2 footprint 3 m high with a red roof.
shape::Scene box_scene() {
  shape::Scene scene;
  scene.materials.push_back({"Tile red", {0.7F, 0.2F, 0.1F, 1.0F}});
  shape::Building b;
  b.id = "b";
  b.parts.push_back({"main",
                     shape::PartKind::kBuildingPart,
                     {},
                     testing::prism({{0, 0}, {1, 0}, {1, 2}, {0, 2}}, 0, 3, 1)});
  scene.buildings.push_back(std::move(b));
  return scene;
}

// io's glTF writer stores the scene's z-up (x, y, z) as glTF's y-up (x, z, -y): a 1 x 2 footprint
// 3 m high comes back 3 m high on y.
void expect_box(const ImportedAsset& a) {
  EXPECT_EQ(a.mesh.face_count(), 12U);
  EXPECT_EQ(triangles(a.mesh), 12U);
  EXPECT_EQ(a.mesh.vertex_count(), 8U);
  expect_bounds(a.mesh, {0, 0, -2}, {1, 3, 0});
  EXPECT_NEAR(kernel::volume(a.mesh), 6, 1e-5);
  // The roof's colour is kept, on the two triangles at the top.
  std::size_t red_faces = 0;
  for (std::size_t f = 0; f < a.mesh.face_count(); ++f) {
    const kernel::MaterialId m = a.mesh.tag(f).material;
    ASSERT_GE(m, 1);
    ASSERT_LE(m, a.materials.size());
    const auto& rgba = a.materials[m - 1].rgba;
    if (std::abs(rgba[0] - 0.7F) > 1e-6F || std::abs(rgba[1] - 0.2F) > 1e-6F) continue;
    ++red_faces;
    for (std::uint32_t v : a.mesh.face(f)) EXPECT_NEAR(a.mesh.position(v).y, 3, 1e-6);
  }
  EXPECT_EQ(red_faces, 2U);
}

// The writer's default output: quantized positions (KHR_mesh_quantization), which Assimp 5.2
// misreads; the glTF reader dequantizes them by the node transform.
TEST(AssetImport, GlbFromTheGltfWriterIsYUpTriangulatedAndWelded) {
  const TempFolder dir;
  write_file(dir / "box.glb", glb_bytes(box_scene()));
  base::Result<ImportedAsset> a = import_asset(dir / "box.glb");
  ASSERT_TRUE(a.ok()) << base::render(a.diagnostics().front());
  expect_box(a.value());
}

// The same in a .gltf with its buffer embedded, and without quantization (float positions).
TEST(AssetImport, GltfTextAndFloatPositionsReadTheSame) {
  const TempFolder dir;
  write_file(dir / "box.gltf", gltf_text(box_scene()));
  base::Result<ImportedAsset> text = import_asset(dir / "box.gltf");
  ASSERT_TRUE(text.ok()) << base::render(text.diagnostics().front());
  expect_box(text.value());
  GltfOptions floats;
  floats.quantize = false;
  write_file(dir / "floats.GLB", glb_bytes(box_scene(), floats));
  base::Result<ImportedAsset> a = import_asset(dir / "floats.GLB");
  ASSERT_TRUE(a.ok()) << base::render(a.diagnostics().front());
  expect_box(a.value());
}

// EXT_meshopt_compression: the views' bytes are decoded with meshoptimizer into the fallback
// buffer; the asset reads back as the uncompressed one does.
TEST(AssetImport, CompressedGlbReadsBackIdentically) {
  const TempFolder dir;
  GltfOptions compress;
  compress.compress = true;
  const std::string bytes = glb_bytes(box_scene(), compress);
  ASSERT_NE(bytes.find("EXT_meshopt_compression"), std::string::npos);
  write_file(dir / "box.glb", bytes);
  base::Result<ImportedAsset> a = import_asset(dir / "box.glb");
  ASSERT_TRUE(a.ok()) << base::render(a.diagnostics().front());
  expect_box(a.value());
  write_file(dir / "plain.glb", glb_bytes(box_scene()));
  base::Result<ImportedAsset> plain = import_asset(dir / "plain.glb");
  ASSERT_TRUE(plain.ok());
  EXPECT_EQ(a->mesh.face_count(), plain->mesh.face_count());
  EXPECT_EQ(a->mesh.vertex_count(), plain->mesh.vertex_count());
  EXPECT_EQ(a->mesh.bounds().min, plain->mesh.bounds().min);
  EXPECT_EQ(a->mesh.bounds().max, plain->mesh.bounds().max);
  EXPECT_EQ(kernel::volume(a->mesh), kernel::volume(plain->mesh));
  ASSERT_EQ(a->materials.size(), plain->materials.size());
  for (std::size_t m = 0; m < a->materials.size(); ++m) {
    EXPECT_EQ(a->materials[m].name, plain->materials[m].name);
    EXPECT_EQ(a->materials[m].rgba, plain->materials[m].rgba);
  }
}

// Four parts instancing one unit cube: at the origin, 5 m east, 10 m north, and scaled by 2 and
// turned 90 degrees about z at 20 m east (x in [18, 20]).
shape::Scene instanced_scene() {
  shape::Scene scene;
  const auto cube =
      std::make_shared<const kernel::Mesh>(testing::prism({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0, 1));
  shape::Building b;
  b.id = "b";
  const std::array<kernel::Transform, 4> places{
      kernel::identity_transform(), kernel::translation({5, 0, 0}), kernel::translation({0, 10, 0}),
      kernel::translation({20, 0, 0}) * kernel::rotation({0, 0, 1}, 90) *
          kernel::scaling({2, 2, 2})};
  for (const kernel::Transform& place : places) {
    shape::Part part{"cube", shape::PartKind::kInstallation, {}, {}};
    part.instance_of = cube;
    part.instance_transform = place;
    b.parts.push_back(std::move(part));
  }
  scene.buildings.push_back(std::move(b));
  return scene;
}

// Every instance is placed, whether the writer makes a node per instance or one node with
// EXT_mesh_gpu_instancing (compressed too: its instance attributes then go through meshopt).
TEST(AssetImport, GlbInstancesAreAllPlaced) {
  const TempFolder dir;
  GltfOptions gpu;
  gpu.instancing = GltfOptions::Instancing::kGpu;
  GltfOptions gpu_compressed = gpu;
  gpu_compressed.compress = true;
  for (const GltfOptions& options : {GltfOptions{}, gpu, gpu_compressed}) {
    const std::string bytes = glb_bytes(instanced_scene(), options);
    EXPECT_EQ(bytes.find("EXT_mesh_gpu_instancing") != std::string::npos,
              options.instancing == GltfOptions::Instancing::kGpu);
    write_file(dir / "cubes.glb", bytes);
    base::Result<ImportedAsset> a = import_asset(dir / "cubes.glb");
    ASSERT_TRUE(a.ok()) << base::render(a.diagnostics().front());
    EXPECT_EQ(triangles(a->mesh), 4 * 12U);
    EXPECT_EQ(a->mesh.vertex_count(), 4 * 8U);
    // y up: (x, y, z) -> (x, z, -y).
    expect_bounds(a->mesh, {0, 0, -11}, {20, 2, 0});
    EXPECT_NEAR(kernel::volume(a->mesh), 1 + 1 + 1 + 8, 1e-4);
    // Each cube's corners where its instance puts them.
    std::array<std::size_t, 4> corners{};
    for (const Vec3& p : a->mesh.positions()) {
      if (p.x <= 1 + 1e-6 && p.z >= -1 - 1e-6) ++corners[0];
      if (p.x >= 5 - 1e-6 && p.x <= 6 + 1e-6) ++corners[1];
      if (p.z <= -10 + 1e-6) ++corners[2];
      if (p.x >= 18 - 1e-6 && p.y <= 2 + 1e-6 && p.z >= -2 - 1e-6) ++corners[3];
    }
    EXPECT_EQ(corners, (std::array<std::size_t, 4>{8, 8, 8, 8}));
  }
}

// A .gltf as other tools write it: an external .bin, BYTE normalized positions 4 bytes apart, a
// non-indexed triangle primitive and a LINES one (skipped), a node matrix under a TRS parent, and
// a mirroring node whose triangle keeps facing +z (glTF flips the winding of mirrored nodes).
TEST(AssetImport, HandWrittenGltfWithExternalBufferAndNodeTransforms) {
  const TempFolder dir;
  write_file(dir / "tri.bin", std::string("\0\0\0\0\x7f\0\0\0\0\x7f\0\0", 12));
  write_file(dir / "tri.gltf", R"({
    "asset": {"version": "2.0"},
    "extensionsUsed": ["KHR_mesh_quantization"],
    "extensionsRequired": ["KHR_mesh_quantization"],
    "buffers": [{"uri": "tri.bin", "byteLength": 12}],
    "bufferViews": [{"buffer": 0, "byteLength": 12, "byteStride": 4}],
    "accessors": [{"bufferView": 0, "componentType": 5120, "normalized": true, "count": 3,
                   "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]}],
    "materials": [{"name": "green", "pbrMetallicRoughness": {"baseColorFactor": [0, 1, 0, 0.5]}}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "material": 0},
                               {"attributes": {"POSITION": 0}, "mode": 1}]}],
    "nodes": [{"children": [1, 2], "translation": [10, 0, 0]},
              {"mesh": 0, "matrix": [2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 0, 0, 5, 1]},
              {"mesh": 0, "scale": [-1, 1, 1]}],
    "scenes": [{"nodes": [0]}],
    "scene": 0
  })");
  base::Result<ImportedAsset> a = import_asset(dir / "tri.gltf");
  ASSERT_TRUE(a.ok()) << base::render(a.diagnostics().front());
  ASSERT_EQ(a->mesh.face_count(), 2U);
  EXPECT_EQ(a->mesh.vertex_count(), 6U);
  expect_bounds(a->mesh, {9, 0, 0}, {12, 2, 5});
  for (std::size_t f = 0; f < 2; ++f) {
    EXPECT_NEAR(kernel::face_normal(a->mesh, f).z, 1, 1e-9) << f;
    EXPECT_EQ(a->mesh.tag(f).material, 1);
  }
  ASSERT_EQ(a->materials.size(), 1U);
  EXPECT_EQ(a->materials[0].name, "green");
  EXPECT_EQ(a->materials[0].rgba, (std::array<float, 4>{0, 1, 0, 0.5F}));
}

// A GLB cut short anywhere is an AST001 error, not a crash; so is a required extension the reader
// does not know, named in the message.
TEST(AssetImport, TruncatedGlbAndUnknownExtensionsAreErrors) {
  const TempFolder dir;
  GltfOptions compress;
  compress.compress = true;
  for (const std::string& whole : {glb_bytes(box_scene()), glb_bytes(box_scene(), compress)}) {
    for (std::size_t cut :
         {std::size_t{0}, std::size_t{11}, std::size_t{40}, whole.size() / 2, whole.size() - 1}) {
      write_file(dir / "cut.glb", whole.substr(0, cut));
      base::Result<ImportedAsset> a = import_asset(dir / "cut.glb");
      ASSERT_FALSE(a.ok()) << cut;
      EXPECT_EQ(a.diagnostics().front().code, "AST001") << cut;
    }
  }
  std::string text = gltf_text(box_scene());
  const std::size_t at = text.find("\"KHR_mesh_quantization\"");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 23, "\"KHR_draco_mesh_compression\"");
  write_file(dir / "draco.gltf", text);
  base::Result<ImportedAsset> draco = import_asset(dir / "draco.gltf");
  ASSERT_FALSE(draco.ok());
  EXPECT_EQ(base::render(draco.diagnostics().front()),
            (dir / "draco.gltf").string() +
                ": error[AST004]: the asset requires the glTF extension "
                "KHR_draco_mesh_compression, which Insula does not read");
}

// A Z_UP COLLADA file comes back y up: its 3 m height on y.
TEST(AssetImport, DaeZUpIsTurnedYUp) {
  const TempFolder dir;
  write_file(dir / "box.dae", testing::box_dae());
  base::Result<ImportedAsset> a = import_asset(dir / "box.dae");
  ASSERT_TRUE(a.ok()) << base::render(a.diagnostics().front());
  EXPECT_EQ(triangles(a->mesh), 12U);
  EXPECT_EQ(a->mesh.vertex_count(), 8U);
  const Vec3 size = a->mesh.bounds().size();
  EXPECT_NEAR(size.x, 1, 1e-6);
  EXPECT_NEAR(size.y, 3, 1e-6);
  EXPECT_NEAR(size.z, 2, 1e-6);
  EXPECT_NEAR(std::abs(kernel::volume(a->mesh)), 6, 1e-5);
  ASSERT_EQ(a->materials.size(), 1U);
  EXPECT_EQ(a->materials[0].rgba, (std::array<float, 4>{0, 1, 0, 1}));
}

// FBX written by Assimp's exporter (assimp-utils, scripts/setup.sh) from the OBJ box, as ASCII
// FBX (Assimp 5.2 cannot read its own binary FBX back).
base::Result<ImportedAsset> fbx_box(const TempFolder& dir, int up_axis, double unit) {
  write_file(dir / "box.obj", testing::box_obj(1, 2, 3, "box.mtl"));
  write_file(dir / "box.mtl", testing::kBoxMtl);
  const std::string command = "assimp export '" + (dir / "box.obj").string() + "' '" +
                              (dir / "box.fbx").string() + "' -ffbxa >/dev/null 2>&1";
  EXPECT_EQ(std::system(command.c_str()), 0) << command;
  std::ifstream in(dir / "box.fbx");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto set = [&](const std::string& property, const std::string& value) {
    const std::string key = "P: \"" + property + "\", ";
    const std::size_t at = text.find(key);
    ASSERT_NE(at, std::string::npos) << property;
    const std::size_t last = text.rfind(", ", text.find('\n', at));
    text.replace(last + 2, text.find('\n', at) - last - 2, value);
  };
  set("UpAxis", std::to_string(up_axis));
  set("UnitScaleFactor", std::to_string(unit));
  write_file(dir / "box.fbx", text);
  return import_asset(dir / "box.fbx");
}

TEST(AssetImport, FbxInCentimetersYUp) {
  const TempFolder dir;
  base::Result<ImportedAsset> a = fbx_box(dir, 1, 1);
  ASSERT_TRUE(a.ok()) << base::render(a.diagnostics().front());
  EXPECT_EQ(triangles(a->mesh), 12U);
  EXPECT_EQ(a->mesh.vertex_count(), 8U);
  // UnitScaleFactor 1: a unit is a centimeter, so the 1 x 2 x 3 box is 1 x 2 x 3 cm.
  expect_bounds(a->mesh, {0, 0, 0}, {0.01, 0.02, 0.03});
  std::set<std::array<float, 4>> colours;
  for (const AssetMaterial& m : a->materials) colours.insert(m.rgba);
  EXPECT_TRUE(colours.count({1, 0, 0, 1})) << "red kept";
}

TEST(AssetImport, FbxInMetersZUpIsTurnedYUp) {
  const TempFolder dir;
  base::Result<ImportedAsset> a = fbx_box(dir, 2, 100);
  ASSERT_TRUE(a.ok()) << base::render(a.diagnostics().front());
  EXPECT_EQ(triangles(a->mesh), 12U);
  // (x, y, z) -> (x, z, -y): 2 m deep and 3 m tall.
  expect_bounds(a->mesh, {0, 0, -2}, {1, 3, 0});
}

TEST(AssetImport, BadFiles) {
  const TempFolder dir;
  write_file(dir / "junk.glb", "not a glb at all");
  base::Result<ImportedAsset> junk = import_asset(dir / "junk.glb");
  ASSERT_FALSE(junk.ok());
  EXPECT_EQ(junk.diagnostics().front().code, "AST001");
  EXPECT_EQ(base::render(junk.diagnostics().front()).rfind((dir / "junk.glb").string(), 0), 0U);

  base::Result<ImportedAsset> missing = import_asset(dir / "none.fbx");
  ASSERT_FALSE(missing.ok());
  EXPECT_EQ(base::render(missing.diagnostics().front()),
            (dir / "none.fbx").string() + ": error[AST001]: cannot read the file");

  write_file(dir / "empty.obj", "v 0 0 0\n");
  base::Result<ImportedAsset> empty = import_asset(dir / "empty.obj");
  ASSERT_FALSE(empty.ok());
  EXPECT_EQ(empty.diagnostics().front().code, "OBJ007");
}

}  // namespace
}  // namespace insula::io
