// Runs the third-party validators on written files: the Khronos glTF validator and the CityJSON
// 2.0.2 schema (node tools/validate_*.mjs, npm packages in tools/node_modules), `assimp info` on
// OBJ and GLB, xmllint on SVG. Each validator is also shown a broken file and must reject it, so
// these tests can fail. Needs scripts/setup.sh to have run (node, npm tools, assimp-utils).
#include <sys/wait.h>

#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "io/cityjson_writer.h"
#include "io/gltf_writer.h"
#include "io/obj_writer.h"
#include "io/svg_writer.h"
#include "writer_fixtures.h"

namespace insula::io {
namespace {

namespace fs = std::filesystem;
using testing::test_scene;

struct Outcome {
  int exit_code = -1;
  std::string output;
};

std::string quote(const fs::path& path) {
  std::string out = "'";
  for (char c : path.string()) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

Outcome execute(const std::string& command, const fs::path& log) {
  const int status = std::system((command + " > " + quote(log) + " 2>&1").c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, testing::read_file(log)};
}

class Validators : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = testing::temp_dir(
        "validators_" +
        std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    tools_ = fs::path(INSULA_SOURCE_DIR) / "tools";
    ASSERT_TRUE(fs::exists(tools_ / "node_modules" / "gltf-validator"))
        << "npm test tools missing: run scripts/setup.sh";
  }
  void TearDown() override { fs::remove_all(dir_); }

  Outcome node(const std::string& script, const fs::path& file) {
    return execute("node " + quote(tools_ / script) + " " + quote(file), dir_ / "log.txt");
  }
  Outcome assimp(const fs::path& file) {
    return execute("assimp info " + quote(file), dir_ / "log.txt");
  }
  void write(const fs::path& path, const std::string& content) {
    std::ofstream(path, std::ios::binary) << content;
  }

  fs::path dir_;
  fs::path tools_;
};

// A scene with more variety than the fixture: a concave L starting at a corner a fan would get
// wrong, and a part with a translucent material.
shape::Scene richer_scene() {
  shape::Scene scene = test_scene();
  scene.materials.push_back({"glass", {0.5F, 0.7F, 0.9F, 0.4F}});
  shape::Building l_building;
  l_building.id = "L-3";
  l_building.parts.push_back(
      {"l",
       shape::PartKind::kRoom,
       {},
       testing::prism({{26, 2}, {22, 2}, {22, 5}, {20, 5}, {20, 0}, {26, 0}}, 0, 6, 2)});
  scene.buildings.push_back(std::move(l_building));
  return scene;
}

TEST_F(Validators, GltfValidatorAcceptsGlbAndGltf) {
  for (const char* name : {"scene.glb", "scene.gltf"}) {
    ASSERT_EQ(write_gltf(richer_scene(), dir_ / name), "");
    const Outcome result = node("validate_gltf.mjs", dir_ / name);
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_NE(result.output.find(": 0 errors, 0 warnings"), std::string::npos) << result.output;
  }
  ASSERT_EQ(write_gltf(shape::Scene{}, dir_ / "empty.glb"), "");
  EXPECT_EQ(node("validate_gltf.mjs", dir_ / "empty.glb").exit_code, 0);
}

TEST_F(Validators, GltfValidatorRejectsBrokenFiles) {
  const std::string glb = glb_bytes(test_scene());
  write(dir_ / "truncated.glb", glb.substr(0, glb.size() / 2));
  EXPECT_EQ(node("validate_gltf.mjs", dir_ / "truncated.glb").exit_code, 1);
  std::string text = gltf_text(test_scene());
  // The indices' UNSIGNED_SHORT (the last accessor's type) made INT, which glTF does not allow.
  const std::size_t at = text.rfind("\"componentType\": 5123");
  ASSERT_NE(at, std::string::npos);
  text.replace(at + 17, 4, "5124");
  write(dir_ / "bad_component.gltf", text);
  const Outcome result = node("validate_gltf.mjs", dir_ / "bad_component.gltf");
  EXPECT_EQ(result.exit_code, 1) << result.output;
}

TEST_F(Validators, CityJsonSchemaAcceptsTheOutput) {
  ASSERT_EQ(write_cityjson(richer_scene(), dir_ / "scene.city.json"), "");
  const Outcome result = node("validate_cityjson.mjs", dir_ / "scene.city.json");
  EXPECT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("valid CityJSON 2.0 (7 city objects"), std::string::npos)
      << result.output;
}

// Both broken files in one run: compiling the 300 KB schema costs ajv about 4 s of CPU.
TEST_F(Validators, CityJsonSchemaRejectsBrokenFiles) {
  std::string text = cityjson_text(test_scene());
  std::string wrong_version = text;
  wrong_version.replace(wrong_version.find("\"version\":\"2.0\""), 15, "\"version\":\"1.1\"");
  write(dir_ / "version.city.json", wrong_version);
  std::string wrong_semantic = text;
  wrong_semantic.replace(wrong_semantic.find("\"RoofSurface\""), 13, "\"RoofThing\"");
  write(dir_ / "semantic.city.json", wrong_semantic);
  const Outcome result =
      execute("node " + quote(tools_ / "validate_cityjson.mjs") + " " +
                  quote(dir_ / "version.city.json") + " " + quote(dir_ / "semantic.city.json"),
              dir_ / "log.txt");
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find(
                "version.city.json: 1 schema errors\n  /version: must be equal to constant"),
            std::string::npos)
      << result.output;
  EXPECT_NE(result.output.find("semantic.city.json: "), std::string::npos) << result.output;
  EXPECT_EQ(result.output.find("valid CityJSON"), std::string::npos) << result.output;
}

TEST_F(Validators, AssimpReadsObjAndGlb) {
  ASSERT_EQ(write_obj(richer_scene(), dir_ / "scene.obj"), "");
  ASSERT_EQ(write_gltf(richer_scene(), dir_ / "scene.glb"), "");
  // 34 triangles of the fixture + 20 of the L prism (4 + 4 caps, 12 walls).
  for (const char* name : {"scene.obj", "scene.glb"}) {
    const Outcome result = assimp(dir_ / name);
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_NE(result.output.find("Faces:              54\n"), std::string::npos) << name << "\n"
                                                                                 << result.output;
  }
}

TEST_F(Validators, AssimpRejectsBrokenFiles) {
  write(dir_ / "bad.obj", "v 0 0 0\nv 1 0 0\nf 1 2 9\n");
  EXPECT_NE(assimp(dir_ / "bad.obj").exit_code, 0);
  const std::string glb = glb_bytes(test_scene());
  write(dir_ / "bad.glb", glb.substr(0, 40));
  EXPECT_NE(assimp(dir_ / "bad.glb").exit_code, 0);
}

TEST_F(Validators, XmllintAcceptsTheSvg) {
  if (std::system("command -v xmllint > /dev/null 2>&1") != 0) {
    GTEST_SKIP() << "xmllint (Debian libxml2-utils) is not installed";
  }
  SvgOptions options;
  options.section_height = 1.5;
  shape::Scene scene = richer_scene();
  scene.buildings[0].id = "A&B <\"x\">";
  ASSERT_EQ(write_svg(scene, dir_ / "plan.svg", options), "");
  const Outcome good = execute("xmllint --noout " + quote(dir_ / "plan.svg"), dir_ / "log.txt");
  EXPECT_EQ(good.exit_code, 0) << good.output;
  write(dir_ / "bad.svg", "<svg><g></svg>");
  EXPECT_NE(execute("xmllint --noout " + quote(dir_ / "bad.svg"), dir_ / "log.txt").exit_code, 0);
}

}  // namespace
}  // namespace insula::io
