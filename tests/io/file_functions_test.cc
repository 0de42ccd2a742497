// CGA's file functions on the workspace of CityEngine's fileSearch examples (two projects), with
// the results its reference gives for them.
#include "io/file_functions.h"

#include <gtest/gtest.h>

#include <array>

#include "asset_fixtures.h"
#include "io/png_renderer.h"

namespace insula::io {
namespace {

namespace fs = std::filesystem;
using testing::TempFolder;
using testing::write_file;

// ws/MyProject/{rules/rule.cga, assets/{textures/1.png, 2.png, 4.png, tower.png, tower.obj}},
// ws/OtherProject/assets/{glass.png, brick.obj}.
class FileFunctionsTest : public ::testing::Test {
 protected:
  FileFunctionsTest()
      : search_(make_workspace(ws_)),
        library_(search_, AssetLibrary::Missing::kNothing),
        files_(search_, library_) {}

  // The workspace's files (the search finds the project by its folders); the rule file's path.
  static fs::path make_workspace(const TempFolder& ws) {
    for (const char* f : {"MyProject/rules/rule.cga", "MyProject/assets/textures/1.png",
                          "MyProject/assets/textures/2.png", "MyProject/assets/textures/4.png",
                          "MyProject/assets/tower.png", "OtherProject/assets/glass.png",
                          "OtherProject/assets/brick.obj"}) {
      write_file(ws / f, "x");
    }
    // A 0.2 x 0.3 x 0.4 box at (0.5, 0.55, 0.6), as in CityEngine's assetInfo example.
    std::string obj = "o unitCube\n";
    for (int k = 0; k < 8; ++k) {
      obj += "v " + std::to_string(0.5 + (k & 1) * 0.2) + " " +
             std::to_string(0.55 + (k >> 1 & 1) * 0.3) + " " +
             std::to_string(0.6 + (k >> 2 & 1) * 0.4) + "\n";
    }
    obj += "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n";
    write_file(ws / "MyProject/assets/tower.obj", obj);
    return ws / "MyProject/rules/rule.cga";
  }

  std::string search(std::string_view query) {
    std::string error;
    std::string list = files_.file_search(query, error);
    EXPECT_EQ(error, "");
    return list;
  }

  TempFolder ws_;
  AssetSearch search_;
  AssetLibrary library_;
  FileFunctions files_;
};

TEST_F(FileFunctionsTest, FileExistsFollowsTheAssetSearch) {
  EXPECT_TRUE(files_.file_exists("tower.obj"));
  EXPECT_TRUE(files_.file_exists("assets/tower.obj"));
  EXPECT_TRUE(files_.file_exists("textures/1.png"));
  EXPECT_TRUE(files_.file_exists("/OtherProject/assets/brick.obj"));
  EXPECT_TRUE(files_.file_exists("rule.cga"));
  EXPECT_FALSE(files_.file_exists("brick.obj"));  // another project's asset
  EXPECT_FALSE(files_.file_exists("textures"));   // a folder
  EXPECT_FALSE(files_.file_exists(""));
}

TEST_F(FileFunctionsTest, FileSearchAsCityEnginesExamples) {
  const std::string textures =
      "/MyProject/assets/textures/1.png;/MyProject/assets/textures/2.png;"
      "/MyProject/assets/textures/4.png;";
  EXPECT_EQ(search("*.png"),
            textures + "/MyProject/assets/tower.png;/OtherProject/assets/glass.png;");
  EXPECT_EQ(search("?.png"), "");
  EXPECT_EQ(search("*/?.png"), textures);
  EXPECT_EQ(search("textures/*"), textures);
  EXPECT_EQ(search("$[12].png"), "");
  EXPECT_EQ(search("$textures/[12].png"),
            "/MyProject/assets/textures/1.png;/MyProject/assets/textures/2.png;");
  EXPECT_EQ(search("$.*/[12].png"),
            "/MyProject/assets/textures/1.png;/MyProject/assets/textures/2.png;");
  EXPECT_EQ(search("$textures/[2-5].png"),
            "/MyProject/assets/textures/2.png;/MyProject/assets/textures/4.png;");
  EXPECT_EQ(search("$textures/[12].png|.*.obj"),
            "/MyProject/assets/textures/1.png;/MyProject/assets/textures/2.png;"
            "/MyProject/assets/tower.obj;/OtherProject/assets/brick.obj;");
  EXPECT_EQ(search("Name=1.png"), "/MyProject/assets/textures/1.png;");
  EXPECT_EQ(search("Project=OtherProject Ext=obj"), "/OtherProject/assets/brick.obj;");
  EXPECT_EQ(search("/OtherProject/*"),
            "/OtherProject/assets/brick.obj;/OtherProject/assets/glass.png;");
  EXPECT_EQ(search("assets/tower.*"), "/MyProject/assets/tower.obj;/MyProject/assets/tower.png;");
  EXPECT_EQ(search(""), "");
}

TEST_F(FileFunctionsTest, FileSearchBadRegex) {
  std::string error;
  EXPECT_EQ(files_.file_search("$[", error), "");
  EXPECT_EQ(error.rfind("fileSearch: invalid regular expression '[': ", 0), 0U) << error;
}

TEST_F(FileFunctionsTest, FileRandomPicksByTheRandomNumber) {
  std::string error;
  EXPECT_EQ(files_.file_random("textures/*.png", 0.0, error), "/MyProject/assets/textures/1.png");
  EXPECT_EQ(files_.file_random("textures/*.png", 0.34, error), "/MyProject/assets/textures/2.png");
  EXPECT_EQ(files_.file_random("textures/*.png", 0.999, error), "/MyProject/assets/textures/4.png");
  EXPECT_EQ(files_.file_random("textures/*.png", 1.0, error), "/MyProject/assets/textures/4.png");
  EXPECT_EQ(files_.file_random("*.fbx", 0.5, error), "");
  EXPECT_EQ(error, "");
  // What fileRandom returns, i() finds.
  EXPECT_TRUE(files_.file_exists(files_.file_random("*.obj", 0.9, error)));
}

TEST_F(FileFunctionsTest, AssetInfoIsTheBoundingBox) {
  const std::array<std::pair<const char*, double>, 6> expected = {
      {{"sx", 0.2}, {"sy", 0.3}, {"sz", 0.4}, {"tx", 0.5}, {"ty", 0.55}, {"tz", 0.6}}};
  for (const auto& [attribute, value] : expected) {
    std::string error;
    const std::optional<double> v = files_.asset_info("tower.obj", attribute, error);
    ASSERT_TRUE(v) << attribute << ": " << error;
    EXPECT_NEAR(*v, value, 1e-9) << attribute;
  }
  std::string error;
  EXPECT_FALSE(files_.asset_info("tower.obj", "volume", error));
  EXPECT_EQ(error, "assetInfo: unknown attribute 'volume' (expected sx, sy, sz, tx, ty or tz)");
  error.clear();
  EXPECT_FALSE(files_.asset_info("none.obj", "sx", error));
  EXPECT_EQ(error.rfind("asset 'none.obj' not found (looked in ", 0), 0U) << error;
}

TEST_F(FileFunctionsTest, ImageInfoReadsPngJpegBmpAndTiffHeaders) {
  Image png;
  png.width = 640;
  png.height = 480;
  png.pixels.assign(640 * 480 * 4, 128);
  write_file(ws_ / "MyProject/assets/wall.png", encode_png(png));
  // JPEG: SOI, an APP0 segment to skip, then SOF0 (precision 8, height 23, width 37, 3
  // components).
  write_file(ws_ / "MyProject/assets/roof.jpg",
             std::string("\xFF\xD8"
                         "\xFF\xE0\x00\x06JFIF"
                         "\xFF\xC0\x00\x11\x08\x00\x17\x00\x25\x03"
                         "\x01\x22\x00\x02\x11\x01\x03\x11\x01"
                         "\xFF\xD9",
                         2 + 8 + 19 + 2));
  // BMP: 300 wide, -200 high (rows top-down).
  std::string bmp(26, '\0');
  bmp[0] = 'B';
  bmp[1] = 'M';
  bmp[18] = static_cast<char>(300 & 0xFF);
  bmp[19] = static_cast<char>(300 >> 8);
  for (int k = 0; k < 4; ++k) bmp[22 + k] = static_cast<char>((-200 >> (8 * k)) & 0xFF);
  write_file(ws_ / "MyProject/assets/sign.bmp", bmp);
  // A little-endian TIFF whose first directory has ImageWidth 1024 (SHORT) and ImageLength 512
  // (LONG).
  const std::string tiff(
      "II\x2a\x00\x08\x00\x00\x00"
      "\x02\x00"
      "\x00\x01\x03\x00\x01\x00\x00\x00\x00\x04\x00\x00"
      "\x01\x01\x04\x00\x01\x00\x00\x00\x00\x02\x00\x00"
      "\x00\x00\x00\x00",
      8 + 2 + 24 + 4);
  write_file(ws_ / "MyProject/assets/door.tif", tiff);
  const std::array<std::tuple<const char*, double, double>, 4> expected = {
      {{"wall.png", 640, 480},
       {"roof.jpg", 37, 23},
       {"sign.bmp", 300, 200},
       {"door.tif", 1024, 512}}};
  for (const auto& [name, w, h] : expected) {
    std::string error;
    EXPECT_EQ(files_.image_info(name, "sx", error), w) << name << error;
    EXPECT_EQ(files_.image_info(name, "sy", error), h) << name << error;
  }
  std::string error;
  EXPECT_FALSE(files_.image_info("textures/1.png", "sx", error));  // "x" is no PNG
  EXPECT_EQ(error, "image 'textures/1.png': not an image this build reads");
  EXPECT_FALSE(files_.image_info("nothing.png", "sx", error));
  EXPECT_EQ(error, "image 'nothing.png' not found");
  EXPECT_FALSE(files_.image_info("wall.png", "bitsPerPixel", error));
  EXPECT_EQ(error, "imageInfo: unknown attribute 'bitsPerPixel' (expected sx or sy)");
}

}  // namespace
}  // namespace insula::io
