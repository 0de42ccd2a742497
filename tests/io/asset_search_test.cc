#include "io/asset_search.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>

namespace insula::io {
namespace {

namespace fs = std::filesystem;

// A CityEngine workspace in a fresh temporary folder:
//   ws/City/assets/, ws/City/rules/sub/rule.cga, ws/Lib/assets/
class AssetSearchTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ws_ = fs::temp_directory_path() /
          ("insula_asset_search_" + std::to_string(::getpid()) + "_" +
           ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(ws_);
    fs::create_directories(ws_ / "City" / "assets");
    fs::create_directories(ws_ / "City" / "rules" / "sub");
    fs::create_directories(ws_ / "Lib" / "assets");
    rule_ = ws_ / "City" / "rules" / "sub" / "rule.cga";
    touch(rule_);
  }
  void TearDown() override { fs::remove_all(ws_); }

  static void touch(const fs::path& p) {
    fs::create_directories(p.parent_path());
    std::ofstream(p) << "x";
  }

  fs::path ws_;
  fs::path rule_;
};

TEST_F(AssetSearchTest, FindsTheProjectAndTheDefaultWorkspace) {
  const AssetSearch search(rule_);
  EXPECT_EQ(search.folder(), ws_ / "City" / "rules" / "sub");
  ASSERT_TRUE(search.project());
  EXPECT_EQ(*search.project(), ws_ / "City");
  EXPECT_EQ(search.workspace(), ws_);
}

// The rule's folder, then assets/, rules/ and the project root: each file found while the ones
// before it exist, the next one once it is removed.
TEST_F(AssetSearchTest, SearchOrderRuleFolderAssetsRulesProject) {
  const std::vector<fs::path> places = {
      ws_ / "City" / "rules" / "sub" / "d" / "x.obj", ws_ / "City" / "assets" / "d" / "x.obj",
      ws_ / "City" / "rules" / "d" / "x.obj", ws_ / "City" / "d" / "x.obj"};
  for (const fs::path& p : places) touch(p);
  const AssetSearch search(rule_);
  EXPECT_EQ(search.candidates("d/x.obj"), places);
  for (const fs::path& p : places) {
    ASSERT_EQ(search.resolve("d/x.obj"), p);
    fs::remove(p);
  }
  EXPECT_EQ(search.resolve("d/x.obj"), std::nullopt);
}

TEST_F(AssetSearchTest, AnUnpackedRulePackagesWorkspaceCopy) {
  // An .rpk keeps the workspace files its rules name under .ws/ at its root.
  const fs::path package = ws_ / "pkg.rpk!";
  const fs::path rule = package / "rules" / "typology" / "main.cga";
  touch(rule);
  touch(package / ".ws" / "ESRI.lib" / "rules" / "Plants" / "Loader.cga");
  const AssetSearch search(rule);
  EXPECT_EQ(search.resolve("/ESRI.lib/rules/Plants/Loader.cga"),
            package / ".ws" / "ESRI.lib" / "rules" / "Plants" / "Loader.cga");
  EXPECT_EQ(search.resolve("/ESRI.lib/rules/Plants/Other.cga"), std::nullopt);
}

TEST_F(AssetSearchTest, BackslashesAndDotDot) {
  touch(ws_ / "City" / "assets" / "facade" / "win.obj");
  const AssetSearch search(rule_);
  EXPECT_EQ(search.resolve("facade\\win.obj"), ws_ / "City" / "assets" / "facade" / "win.obj");
  // Relative to the rule's folder: rules/sub/../../assets/facade/win.obj.
  EXPECT_EQ(search.resolve("../../assets/facade/win.obj"),
            ws_ / "City" / "assets" / "facade" / "win.obj");
  EXPECT_EQ(search.resolve(""), std::nullopt);
  EXPECT_EQ(search.resolve("facade"), std::nullopt);  // a folder is not a file
}

// CityEngine runs on Windows: "Facade/Win.OBJ" finds facade/win.obj when nothing has the exact
// spelling, in every place of the search; the exact spelling wins.
TEST_F(AssetSearchTest, LetterCaseIsIgnoredWhenNothingMatchesExactly) {
  touch(ws_ / "City" / "assets" / "facade" / "win.obj");
  touch(ws_ / "Lib" / "assets" / "Tree.glb");
  const AssetSearch search(rule_);
  EXPECT_EQ(search.resolve("Facade/Win.OBJ"), ws_ / "City" / "assets" / "facade" / "win.obj");
  EXPECT_EQ(search.resolve("/lib/ASSETS/tree.glb"), ws_ / "Lib" / "assets" / "Tree.glb");
  touch(ws_ / "City" / "assets" / "Facade" / "Win.OBJ");
  EXPECT_EQ(search.resolve("Facade/Win.OBJ"), ws_ / "City" / "assets" / "Facade" / "Win.OBJ");
  EXPECT_EQ(search.resolve("FACADE/WIN.OBJ"), ws_ / "City" / "assets" / "Facade" / "Win.OBJ");
  EXPECT_EQ(search.resolve("facade/door.obj"), std::nullopt);
}

TEST_F(AssetSearchTest, WorkspacePaths) {
  touch(ws_ / "Lib" / "assets" / "tree.glb");
  touch(ws_ / "City" / "assets" / "door.obj");
  const AssetSearch search(rule_);
  EXPECT_EQ(search.resolve("/Lib/assets/tree.glb"), ws_ / "Lib" / "assets" / "tree.glb");
  EXPECT_EQ(search.resolve("/City/assets/door.obj"), ws_ / "City" / "assets" / "door.obj");
  // A workspace path is never searched elsewhere.
  EXPECT_EQ(search.resolve("/assets/door.obj"), std::nullopt);
  EXPECT_EQ(search.resolve("/door.obj"), std::nullopt);
}

TEST_F(AssetSearchTest, WorkspaceGivenElsewhereStillFindsTheOwnProject) {
  const fs::path other = ws_ / "elsewhere";
  fs::create_directories(other / "ESRI.lib" / "assets");
  touch(other / "ESRI.lib" / "assets" / "bush.obj");
  touch(ws_ / "City" / "assets" / "door.obj");
  const AssetSearch search(rule_, other);
  EXPECT_EQ(search.workspace(), other);
  EXPECT_EQ(search.resolve("/ESRI.lib/assets/bush.obj"),
            other / "ESRI.lib" / "assets" / "bush.obj");
  EXPECT_EQ(search.resolve("/City/assets/door.obj"), ws_ / "City" / "assets" / "door.obj");
  EXPECT_EQ(search.resolve("/Lib/assets/tree.glb"), std::nullopt);
}

TEST_F(AssetSearchTest, WorkspaceNamesResolveBack) {
  const fs::path door = ws_ / "City" / "assets" / "door.obj";
  touch(door);
  const AssetSearch search(rule_);
  EXPECT_EQ(search.workspace_name(door), "/City/assets/door.obj");
  EXPECT_EQ(search.resolve(search.workspace_name(door)), door);
  const AssetSearch outside(rule_, ws_ / "Lib");
  EXPECT_EQ(outside.workspace_name(door), "assets/door.obj");
  EXPECT_EQ(outside.resolve(outside.workspace_name(door)), door);
}

TEST_F(AssetSearchTest, NoProjectMeansTheRuleFolderOnly) {
  const fs::path loose = ws_ / "loose";
  touch(loose / "a.cga");
  touch(loose / "x.obj");
  const AssetSearch search(loose / "a.cga");
  EXPECT_EQ(search.project(), std::nullopt);
  EXPECT_EQ(search.workspace(), ws_);
  EXPECT_EQ(search.candidates("x.obj"), std::vector<fs::path>{loose / "x.obj"});
  EXPECT_EQ(search.resolve("x.obj"), loose / "x.obj");
}

TEST_F(AssetSearchTest, DotProjectMarksAProject) {
  const fs::path project = ws_ / "Eclipse";
  touch(project / ".project");
  touch(project / "models" / "m.cga");
  touch(project / "car.obj");
  const AssetSearch search(project / "models" / "m.cga");
  ASSERT_TRUE(search.project());
  EXPECT_EQ(*search.project(), project);
  EXPECT_EQ(search.resolve("car.obj"), project / "car.obj");
}

}  // namespace
}  // namespace insula::io
