// Scenes and golden-file helpers shared by the writer tests (tests/io/*_test.cc). Meshes are built
// by hand so these tests do not depend on the kernel's extrusion.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <unistd.h>

#include "kernel/mesh.h"
#include "shape/scene.h"

namespace insula::io::testing {

using kernel::FaceTag;
using kernel::SemanticClass;
using kernel::Vec2;
using kernel::Vec3;

// A closed prism over a counter-clockwise footprint between z0 and z1, faces tagged ground
// (bottom), wall (sides) and roof (top); faces share vertex indices and point outwards.
inline kernel::Mesh prism(const std::vector<Vec2>& footprint, double z0, double z1,
                          kernel::MaterialId roof_material = 0) {
  kernel::Mesh mesh;
  const auto n = static_cast<std::uint32_t>(footprint.size());
  for (Vec2 p : footprint) mesh.add_vertex({p.x, p.y, z0});
  for (Vec2 p : footprint) mesh.add_vertex({p.x, p.y, z1});
  std::vector<std::uint32_t> bottom;
  std::vector<std::uint32_t> top;
  for (std::uint32_t i = 0; i < n; ++i) {
    bottom.push_back(n - 1 - i);
    top.push_back(n + i);
  }
  std::uint32_t face_id = 0;
  mesh.add_face(bottom, {SemanticClass::kGroundSurface, 0, face_id++});
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t j = (i + 1) % n;
    mesh.add_face({i, j, n + j, n + i}, {SemanticClass::kWallSurface, 0, face_id++});
  }
  mesh.add_face(top, {SemanticClass::kRoofSurface, roof_material, face_id++});
  return mesh;
}

// The L footprint: a concave hexagon of 18 m², reflex corner at (2, 2).
inline std::vector<Vec2> l_footprint(Vec2 at) {
  return {at + Vec2{0, 0}, at + Vec2{6, 0}, at + Vec2{6, 2},
          at + Vec2{2, 2}, at + Vec2{2, 5}, at + Vec2{0, 5}};
}

// Two buildings far from the CRS origin (UTM-like):
// - "b1": one part "main", a 4 x 3 x 3 box whose roof uses the scene material "Tile red";
// - "L-2": part "wing", an L prism 4 m high (concave roof and ground faces), and part "storey 0"
//   (kind kStorey), a single open floor face.
// 6 + 8 + 1 = 15 faces, 12 + 20 + 2 = 34 triangles.
inline shape::Scene test_scene() {
  shape::Scene scene;
  scene.origin = {500000.25, 5400000.5, 100};
  scene.crs = "EPSG:32633";
  scene.materials.push_back({"Tile red", {0.7F, 0.2F, 0.1F, 1.0F}});

  shape::Building box;
  box.id = "b1";
  box.attributes = {{"height", 3.0}, {"name", std::string("Box & <Co> \"1\"")}, {"listed", true}};
  box.parts.push_back({"main",
                       shape::PartKind::kBuildingPart,
                       {{"levels", 1.0}},
                       prism({{0, 0}, {4, 0}, {4, 3}, {0, 3}}, 0, 3, 1)});
  scene.buildings.push_back(std::move(box));

  shape::Building l_building;
  l_building.id = "L-2";
  l_building.attributes = {{"height", 4.0}, {"note", shape::Value{}}};
  l_building.parts.push_back(
      {"wing", shape::PartKind::kBuildingPart, {}, prism(l_footprint({10, 0}), 0, 4)});
  kernel::Mesh floor;
  for (Vec3 p : {Vec3{10, 0, 0.1}, Vec3{12, 0, 0.1}, Vec3{12, 2, 0.1}, Vec3{10, 2, 0.1}}) {
    floor.add_vertex(p);
  }
  floor.add_face({0, 1, 2, 3}, {SemanticClass::kFloorSurface, 0, 0});
  l_building.parts.push_back({"storey 0", shape::PartKind::kStorey, {}, std::move(floor)});
  scene.buildings.push_back(std::move(l_building));
  return scene;
}

inline std::filesystem::path golden_path(const std::string& name) {
  return std::filesystem::path(INSULA_TEST_DATA) / "golden" / name;
}

inline std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Compares `actual` with the golden file byte for byte; INSULA_UPDATE_GOLDEN=1 rewrites it instead.
inline void expect_golden(const std::string& name, const std::string& actual) {
  const std::filesystem::path path = golden_path(name);
  const char* update = std::getenv("INSULA_UPDATE_GOLDEN");
  if (update != nullptr && std::string(update) == "1") {
    std::filesystem::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << actual;
    return;
  }
  ASSERT_TRUE(std::filesystem::exists(path))
      << path << " is missing; run the test with INSULA_UPDATE_GOLDEN=1 to create it";
  EXPECT_TRUE(read_file(path) == actual)
      << name << " differs from " << path << "; if the change is intended, regenerate with "
      << "INSULA_UPDATE_GOLDEN=1 and review the diff";
}

// A fresh, empty directory for one test.
inline std::filesystem::path temp_dir(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    ("insula_io_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace insula::io::testing
