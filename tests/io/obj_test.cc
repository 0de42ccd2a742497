// OBJ writer (goldens, world coordinates, n-gons, atomic writes) and OBJ reader (forms, round trip,
// bad-input catalog with exact messages).
#include <string>

#include <gtest/gtest.h>

#include "base/diagnostic.h"
#include "io/obj_reader.h"
#include "io/obj_writer.h"
#include "writer_fixtures.h"

namespace insula::io {
namespace {

using kernel::SemanticClass;
using kernel::Vec3;
using testing::test_scene;

std::size_t count_lines_starting(const std::string& text, const std::string& prefix) {
  std::size_t count = 0;
  std::size_t start = 0;
  while (start < text.size()) {
    if (text.compare(start, prefix.size(), prefix) == 0) ++count;
    const std::size_t end = text.find('\n', start);
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return count;
}

TEST(ObjWriter, MatchesGoldenFiles) {
  const ObjText text = obj_text(test_scene(), "scene.mtl");
  testing::expect_golden("scene.obj", text.obj);
  testing::expect_golden("scene.mtl", text.mtl);
}

TEST(ObjWriter, OneObjectPerBuildingAndGroupsPerPartAndClass) {
  const ObjText text = obj_text(test_scene(), "scene.mtl");
  EXPECT_EQ(count_lines_starting(text.obj, "o "), 2U);
  EXPECT_EQ(count_lines_starting(text.obj, "v "), 8U + 12U + 4U);
  EXPECT_EQ(count_lines_starting(text.obj, "f "), 15U);
  EXPECT_NE(text.obj.find("o b1\n"), std::string::npos);
  EXPECT_NE(text.obj.find("g b1.main.RoofSurface\nusemtl Tile_red\n"), std::string::npos);
  EXPECT_NE(text.obj.find("g L-2.wing.WallSurface\nusemtl WallSurface\n"), std::string::npos);
  EXPECT_NE(text.obj.find("g L-2.storey_0.FloorSurface\n"), std::string::npos);
  EXPECT_NE(text.obj.find("mtllib scene.mtl\n"), std::string::npos);
}

TEST(ObjWriter, WritesWorldCoordinatesWithMicrometreDigits) {
  shape::Scene scene = test_scene();
  scene.buildings[0].parts[0].mesh.positions()[1] = {4.123456789, 0, 0};
  const ObjText text = obj_text(scene, "scene.mtl", {.world = true});
  EXPECT_NE(text.obj.find("\nv 500000.25 5400000.5 100\n"), std::string::npos);
  EXPECT_NE(text.obj.find("\nv 500004.373457 5400000.5 100\n"), std::string::npos);
  EXPECT_NE(
      text.obj.find("# Insula OBJ export: meters, Z up, world coordinates; world = (x, y, z)\n"),
      std::string::npos);
}

TEST(ObjWriter, LocalYUpByDefaultWithTheOriginBeside) {
  // Blender, Maya and three.js read OBJ Y up: Insula's (x, y, z) is written (x, z, -y), local, so
  // float32 readers keep millimetres; the way back is in the header and the sidecar.
  shape::Scene scene = test_scene();
  scene.buildings[0].parts[0].mesh.positions()[1] = {1.0005, 2, 3};
  const ObjText text = obj_text(scene, "scene.mtl");
  EXPECT_NE(text.obj.find("\nv 1.0005 3 -2\n"), std::string::npos) << text.obj.substr(0, 400);
  EXPECT_NE(text.obj.find("# Insula OBJ export: meters, Y up, local coordinates; world = (x, -z, "
                          "y) + origin\n# origin 500000.25 5400000.5 100\n"),
            std::string::npos);
  EXPECT_EQ(text.origin_json,
            "{\n  \"origin\": [500000.25, 5400000.5, 100],\n  \"crs\": \"EPSG:32633\",\n"
            "  \"units\": \"m\",\n  \"up\": \"y\",\n  \"coordinates\": \"local\",\n"
            "  \"toWorld\": \"world = (x, -z, y) + origin\"\n}\n");
  // Z up on request, still local.
  EXPECT_NE(obj_text(scene, "scene.mtl", {.up = 'z'}).obj.find("\nv 1.0005 2 3\n"),
            std::string::npos);
}

TEST(ObjWriter, KeepsConcaveFacesAsNgons) {
  const ObjText text = obj_text(test_scene(), "scene.mtl");
  // The L's roof: its 6 top vertices are OBJ vertices 15..20 (after the box's 8 and L's bottom 6).
  EXPECT_NE(text.obj.find("\nf 15 16 17 18 19 20\n"), std::string::npos);
}

// Two vertices closer than the 1 um the text keeps are one point in the file (a PLaSM column's
// capital has them where its surface pinches): a quad with two of its corners there is written as
// the triangle it looks like, and a sliver triangle, which would have no area in the file, is not
// written; a face lost so does not take its group's header with it.
TEST(ObjWriter, FacesAreWrittenAsTheTextShowsThem) {
  shape::Scene scene;
  scene.origin = {500000.25, 5400000.5, 100};
  kernel::Mesh mesh;
  for (Vec3 p : {Vec3{0, 0, 0}, Vec3{4, 0, 0}, Vec3{4, 0, 3}, Vec3{4, 2e-7, 3}, Vec3{0, 0, 3},
                 Vec3{4, 1e-7, 0}}) {
    mesh.add_vertex(p);
  }
  mesh.add_face({1, 5, 2}, {SemanticClass::kWallSurface, 0, 0});        // 1 and 5: one point
  mesh.add_face({0, 1, 2, 3, 4}, {SemanticClass::kWallSurface, 0, 1});  // 2 and 3: one point
  mesh.add_face({4, 3, 2}, {SemanticClass::kRoofSurface, 0, 2});        // 3 and 2: one point
  shape::Building building;
  building.id = "b";
  building.parts.push_back({"wall", shape::PartKind::kBuildingPart, {}, std::move(mesh)});
  scene.buildings.push_back(std::move(building));
  const std::string obj = obj_text(scene, "scene.mtl", {.up = 'z'}).obj;
  EXPECT_EQ(count_lines_starting(obj, "v "), 6U);
  EXPECT_EQ(count_lines_starting(obj, "f "), 1U) << obj;
  EXPECT_NE(obj.find("\nv 4 0 3\nv 4 0 3\n"), std::string::npos);
  EXPECT_NE(obj.find("\ng b.wall.WallSurface\nusemtl WallSurface\nf 1 2 3 5\n"), std::string::npos)
      << obj;
  EXPECT_EQ(obj.find("RoofSurface"), std::string::npos);
}

TEST(ObjWriter, MaterialsHaveDiffuseColour) {
  const ObjText text = obj_text(test_scene(), "scene.mtl");
  EXPECT_NE(text.mtl.find("newmtl Tile_red\nKa 0 0 0\nKd 0.7 0.2 0.1\n"), std::string::npos);
  EXPECT_NE(text.mtl.find("newmtl RoofSurface\n"), std::string::npos);
  EXPECT_EQ(count_lines_starting(text.mtl, "newmtl "), 5U);  // Tile red, ground, wall, roof, floor
}

TEST(ObjWriter, IsDeterministic) {
  EXPECT_EQ(obj_text(test_scene(), "a.mtl").obj, obj_text(test_scene(), "a.mtl").obj);
}

TEST(ObjWriter, WritesObjAndMtlFiles) {
  const auto dir = testing::temp_dir("obj_write");
  ASSERT_EQ(write_obj(test_scene(), dir / "city.obj"), "");
  const std::string obj = testing::read_file(dir / "city.obj");
  EXPECT_NE(obj.find("mtllib city.mtl\n"), std::string::npos);
  EXPECT_EQ(testing::read_file(dir / "city.mtl"), obj_text(test_scene(), "city.mtl").mtl);
  EXPECT_EQ(testing::read_file(dir / "city.origin.json"),
            obj_text(test_scene(), "city.mtl").origin_json);
  std::filesystem::remove_all(dir);
}

TEST(ObjWriter, FailedWriteNamesTheFileAndLeavesNothing) {
  const auto dir = testing::temp_dir("obj_fail");
  const auto path = dir / "missing" / "city.obj";
  const std::string error = write_obj(test_scene(), path);
  EXPECT_NE(error.find(path.parent_path().string()), std::string::npos) << error;
  EXPECT_FALSE(std::filesystem::exists(dir / "missing"));
  std::filesystem::remove_all(dir);
}

TEST(ObjReader, ReadsBackWhatTheWriterWrote) {
  const shape::Scene scene = test_scene();
  const ObjText text = obj_text(scene, "scene.mtl", {.world = true});
  const base::Result<ObjModel> model = parse_obj(text.obj, "scene.obj");
  ASSERT_TRUE(model.ok());
  EXPECT_TRUE(model.diagnostics().empty());
  const kernel::Mesh& mesh = model->mesh;
  EXPECT_EQ(mesh.vertex_count(), 24U);
  EXPECT_EQ(mesh.face_count(), 15U);
  EXPECT_EQ(mesh.position(0), (kernel::Vec3{500000.25, 5400000.5, 100}));
  std::size_t roofs = 0;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    roofs += mesh.tag(f).semantic == SemanticClass::kRoofSurface ? 1 : 0;
  }
  EXPECT_EQ(roofs, 2U);
  EXPECT_EQ(mesh.face(14).size(), 4U);
  EXPECT_EQ(mesh.tag(14).semantic, SemanticClass::kFloorSurface);
  ASSERT_FALSE(model->materials.empty());
  EXPECT_EQ(model->materials[0], "GroundSurface");
}

TEST(ObjReader, ReadsAllFaceFormsAndNegativeIndices) {
  const std::string text =
      "# a quad and a triangle\n"
      "mtllib x.mtl\n"
      "o thing\n"
      "v 0 0 0\nv 1 0 1e-999\nv 1 1 0 1.0\nv +0 1 0 0.5 0.5 0.5\n"
      "vt 0 0\nvn 0 0 1\ns off\n"
      "usemtl brick\n"
      "f 1/1/1 2/1/1 3//1 4/1\n"
      "usemtl RoofSurface\n"
      "f -4 -3 -1   # trailing comment\r\n"
      "l 1 2\n";
  const base::Result<ObjModel> model = parse_obj(text, "forms.obj");
  ASSERT_TRUE(model.ok());
  EXPECT_TRUE(model.diagnostics().empty());
  ASSERT_EQ(model->mesh.face_count(), 2U);
  EXPECT_EQ(std::vector<std::uint32_t>(model->mesh.face(0).begin(), model->mesh.face(0).end()),
            (std::vector<std::uint32_t>{0, 1, 2, 3}));
  EXPECT_EQ(std::vector<std::uint32_t>(model->mesh.face(1).begin(), model->mesh.face(1).end()),
            (std::vector<std::uint32_t>{0, 1, 3}));
  EXPECT_EQ(model->materials, (std::vector<std::string>{"brick", "RoofSurface"}));
  EXPECT_EQ(model->mesh.tag(0).material, 1);
  EXPECT_EQ(model->mesh.tag(0).semantic, SemanticClass::kNone);
  EXPECT_EQ(model->mesh.tag(1).material, 2);
  EXPECT_EQ(model->mesh.tag(1).semantic, SemanticClass::kRoofSurface);
  EXPECT_EQ(model->mesh.tag(1).face_id, 1U);
}

TEST(ObjReader, ReadsTheBundledAssets) {
  for (const char* name : {"chimney.obj", "dormer.obj"}) {
    const auto path = std::filesystem::path(INSULA_TEST_DATA) / "assets" / name;
    const base::Result<kernel::Mesh> mesh = read_obj(testing::read_file(path), name);
    ASSERT_TRUE(mesh.ok()) << name;
    EXPECT_TRUE(kernel::is_watertight(mesh.value())) << name;
  }
}

struct BadObj {
  const char* text;
  const char* message;
};

class ObjReaderBadInput : public ::testing::TestWithParam<BadObj> {};

TEST_P(ObjReaderBadInput, ReportsTheExactDiagnostic) {
  const base::Result<ObjModel> model = parse_obj(GetParam().text, "bad.obj");
  EXPECT_FALSE(model.ok());
  ASSERT_FALSE(model.diagnostics().empty());
  EXPECT_EQ(base::render(model.diagnostics().front()), GetParam().message);
}

INSTANTIATE_TEST_SUITE_P(
    Catalog, ObjReaderBadInput,
    ::testing::Values(
        BadObj{"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n",
               "bad.obj:4:7: error[OBJ005]: vertex index 9 is out of range (3 vertices defined so "
               "far)"},
        BadObj{"v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n",
               "bad.obj:4:9: error[OBJ005]: vertex index -4 is out of range (3 vertices defined "
               "so far)"},
        BadObj{"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n",
               "bad.obj:4:3: error[OBJ005]: vertex index 0 is invalid (OBJ indices start at 1)"},
        BadObj{"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99999999999999999999\n",
               "bad.obj:4:7: error[OBJ005]: vertex index 99999999999999999999 is out of range (3 "
               "vertices defined so far)"},
        BadObj{"v 0 zero 0\n", "bad.obj:1:5: error[OBJ002]: 'zero' is not a number"},
        BadObj{"v 1 2\n", "bad.obj:1:1: error[OBJ001]: a vertex needs 3 coordinates, found 2"},
        BadObj{"v 1 nan 2\n", "bad.obj:1:5: error[OBJ003]: coordinate 'nan' is not finite"},
        BadObj{"v 1 1e999 2\n", "bad.obj:1:5: error[OBJ003]: coordinate '1e999' is not finite"},
        BadObj{"v 0 0 0\nv 1 0 0\nf 1 2\n",
               "bad.obj:3:1: error[OBJ004]: a face needs at least 3 vertices, found 2"},
        BadObj{"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x3\n",
               "bad.obj:4:7: error[OBJ006]: 'x3' is not a vertex reference"},
        BadObj{"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3/a/1\n",
               "bad.obj:4:7: error[OBJ006]: '3/a/1' is not a vertex reference"},
        BadObj{"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3/1/1/1\n",
               "bad.obj:4:7: error[OBJ006]: '3/1/1/1' is not a vertex reference"},
        BadObj{"v 0 0 0\n# nothing else\n", "bad.obj: error[OBJ007]: the file has no faces"},
        BadObj{"", "bad.obj: error[OBJ007]: the file has no faces"},
        BadObj{"f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n",
               "bad.obj:1:3: error[OBJ005]: vertex index 1 is out of range (0 vertices defined so "
               "far)"}));

// Found by obj_fuzz: every face dropped (warning OBJ101) left a model without faces.
TEST(ObjReader, FileWhoseEveryFaceWasDroppedIsAnError) {
  const base::Result<ObjModel> model = parse_obj("v 0 0 0\nv 1 0 0\nf 1 1 2\nf 2 2 2\n", "bad.obj");
  ASSERT_FALSE(model.ok());
  ASSERT_EQ(model.diagnostics().size(), 3U);  // two OBJ101 warnings, then the error
  EXPECT_EQ(base::render(model.diagnostics().back()),
            "bad.obj: error[OBJ007]: the file has no face with 3 distinct vertices");
}

TEST(ObjReader, WarnsAboutUnsupportedStatementsAndDegenerateFaces) {
  const base::Result<ObjModel> model =
      parse_obj("curv 0 1 1 2\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 1 2\n", "w.obj");
  ASSERT_TRUE(model.ok());
  ASSERT_EQ(model.diagnostics().size(), 2U);
  EXPECT_EQ(base::render(model.diagnostics()[0]),
            "w.obj:1:1: warning[OBJ100]: unsupported statement 'curv' ignored");
  EXPECT_EQ(base::render(model.diagnostics()[1]),
            "w.obj:6:1: warning[OBJ101]: face repeats its vertices and has fewer than 3 distinct "
            "ones; dropped");
  EXPECT_EQ(model->mesh.face_count(), 1U);
}

TEST(ObjReader, StopsAfterTooManyErrors) {
  std::string text;
  for (int i = 0; i < 500; ++i) text += "v x y z\n";
  const base::Result<ObjModel> model = parse_obj(text, "many.obj");
  EXPECT_FALSE(model.ok());
  EXPECT_EQ(model.diagnostics().size(), 50U);
  EXPECT_EQ(model.diagnostics().back().notes.front(),
            "too many errors; reading stopped at line 50");
}

TEST(ObjReader, SurvivesGarbage) {
  std::string text;
  for (int i = 0; i < 2000; ++i) text += static_cast<char>((i * 7919) % 256);
  const base::Result<ObjModel> model = parse_obj(text, "garbage.obj");
  EXPECT_FALSE(model.ok());
}

}  // namespace
}  // namespace insula::io
