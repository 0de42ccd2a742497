// Files for the asset tests (tests/io/asset_*_test.cc, file_functions_test.cc), written at test
// time into a fresh temporary folder: no third-party asset is copied into the repository.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace insula::io::testing {

// A temporary folder named after the running test, removed afterwards.
class TempFolder {
 public:
  TempFolder() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = std::filesystem::temp_directory_path() /
            ("insula_" + std::string(info->test_suite_name()) + "_" + info->name() + "_" +
             std::to_string(::getpid()));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempFolder() { std::filesystem::remove_all(path_); }
  TempFolder(const TempFolder&) = delete;
  TempFolder& operator=(const TempFolder&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

inline void write_file(const std::filesystem::path& path, const std::string& bytes) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << bytes;
}

// An OBJ box [0, sx] x [0, sy] x [0, sz] (y up): 8 vertices, 6 quads, the top and bottom with
// material "red", the sides "blue", both defined in `mtl` (written beside it when not empty).
inline std::string box_obj(double sx, double sy, double sz, const std::string& mtl = "") {
  auto v = [](double x, double y, double z) {
    return "v " + std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(z) + "\n";
  };
  std::string s = mtl.empty() ? "" : "mtllib " + mtl + "\n";
  s += v(0, 0, 0) + v(sx, 0, 0) + v(sx, 0, sz) + v(0, 0, sz);
  s += v(0, sy, 0) + v(sx, sy, 0) + v(sx, sy, sz) + v(0, sy, sz);
  s += "usemtl red\nf 1 2 3 4\nf 5 8 7 6\n";
  s += "usemtl blue\nf 1 5 6 2\nf 2 6 7 3\nf 3 7 8 4\nf 4 8 5 1\n";
  return s;
}

inline const char* kBoxMtl = "newmtl red\nKd 1 0 0\nnewmtl blue\nKd 0 0 1\nd 0.5\n";

}  // namespace insula::io::testing

namespace insula::io::testing {

// A COLLADA box [0, 1] x [0, 2] x [0, 3] in a Z_UP file (3 m tall), six quads (a polylist) with
// one green material.
inline std::string box_dae() {
  return R"(<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit name="meter" meter="1"/><up_axis>Z_UP</up_axis></asset>
  <library_effects>
    <effect id="green-fx"><profile_COMMON><technique sid="common"><phong>
      <diffuse><color>0 1 0 1</color></diffuse>
    </phong></technique></profile_COMMON></effect>
  </library_effects>
  <library_materials>
    <material id="green" name="green"><instance_effect url="#green-fx"/></material>
  </library_materials>
  <library_geometries>
    <geometry id="box" name="box"><mesh>
      <source id="box-pos">
        <float_array id="box-pos-array" count="24">0 0 0 1 0 0 1 2 0 0 2 0 0 0 3 1 0 3 1 2 3 0 2 3</float_array>
        <technique_common><accessor source="#box-pos-array" count="8" stride="3">
          <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
        </accessor></technique_common>
      </source>
      <vertices id="box-vtx"><input semantic="POSITION" source="#box-pos"/></vertices>
      <polylist material="mat" count="6">
        <input semantic="VERTEX" source="#box-vtx" offset="0"/>
        <vcount>4 4 4 4 4 4</vcount>
        <p>0 3 2 1 4 5 6 7 0 1 5 4 1 2 6 5 2 3 7 6 3 0 4 7</p>
      </polylist>
    </mesh></geometry>
  </library_geometries>
  <library_visual_scenes>
    <visual_scene id="scene">
      <node id="box-node" name="box-node">
        <instance_geometry url="#box"><bind_material><technique_common>
          <instance_material symbol="mat" target="#green"/>
        </technique_common></bind_material></instance_geometry>
      </node>
    </visual_scene>
  </library_visual_scenes>
  <scene><instance_visual_scene url="#scene"/></scene>
</COLLADA>
)";
}

}  // namespace insula::io::testing
