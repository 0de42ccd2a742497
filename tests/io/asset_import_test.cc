// Asset import: OBJ (+MTL) through io's reader, GLB (written by io's glTF writer), DAE (written
// here by hand) and FBX (written at test time by Assimp's own exporter, `assimp export`) through
// Assimp.
#include "io/asset_import.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <iterator>
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

// io's glTF writer stores the scene's z-up (x, y, z) as glTF's y-up (x, z, -y): a 1 x 2 footprint
// 3 m high comes back 3 m high on y.
TEST(AssetImport, GlbFromTheGltfWriterIsYUpTriangulatedAndWelded) {
  const TempFolder dir;
  shape::Scene scene;
  scene.materials.push_back({"Tile red", {0.7F, 0.2F, 0.1F, 1.0F}});
  shape::Building b;
  b.id = "b";
  b.parts.push_back({"main",
                     shape::PartKind::kBuildingPart,
                     {},
                     testing::prism({{0, 0}, {1, 0}, {1, 2}, {0, 2}}, 0, 3, 1)});
  scene.buildings.push_back(std::move(b));
  write_file(dir / "box.glb", glb_bytes(scene));
  base::Result<ImportedAsset> a = import_asset(dir / "box.glb");
  ASSERT_TRUE(a.ok()) << base::render(a.diagnostics().front());
  EXPECT_EQ(a->mesh.face_count(), 12U);
  EXPECT_EQ(triangles(a->mesh), 12U);
  EXPECT_EQ(a->mesh.vertex_count(), 8U);
  expect_bounds(a->mesh, {0, 0, -2}, {1, 3, 0});
  EXPECT_NEAR(kernel::volume(a->mesh), 6, 1e-5);
  // The roof's colour is kept, on the two triangles at the top.
  std::size_t red_faces = 0;
  for (std::size_t f = 0; f < a->mesh.face_count(); ++f) {
    const kernel::MaterialId m = a->mesh.tag(f).material;
    ASSERT_GE(m, 1);
    ASSERT_LE(m, a->materials.size());
    const auto& rgba = a->materials[m - 1].rgba;
    if (std::abs(rgba[0] - 0.7F) > 1e-6F || std::abs(rgba[1] - 0.2F) > 1e-6F) continue;
    ++red_faces;
    for (std::uint32_t v : a->mesh.face(f)) EXPECT_NEAR(a->mesh.position(v).y, 3, 1e-6);
  }
  EXPECT_EQ(red_faces, 2U);
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
