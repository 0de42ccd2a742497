#include "io/png_renderer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <vector>

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

namespace insula::io {
namespace {

using kernel::MaterialId;
using kernel::Mesh;
using kernel::SemanticClass;
using kernel::Vec2;
using Rgba = std::array<std::uint8_t, 4>;

// A closed prism over a counter-clockwise ring: ground face, top face tagged as roof, walls.
Mesh prism(const std::vector<Vec2>& ring, double z0, double z1, MaterialId wall = 0,
           MaterialId roof = 0, SemanticClass wall_class = SemanticClass::kWallSurface) {
  Mesh mesh;
  const auto n = static_cast<std::uint32_t>(ring.size());
  for (Vec2 p : ring) mesh.add_vertex({p.x, p.y, z0});
  for (Vec2 p : ring) mesh.add_vertex({p.x, p.y, z1});
  std::vector<std::uint32_t> bottom, top;
  for (std::uint32_t i = 0; i < n; ++i) {
    bottom.push_back(n - 1 - i);
    top.push_back(n + i);
  }
  mesh.add_face(bottom, {SemanticClass::kGroundSurface, 0, 0});
  mesh.add_face(top, {SemanticClass::kRoofSurface, roof, 1});
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t j = (i + 1) % n;
    mesh.add_face({i, j, n + j, n + i}, {wall_class, wall, 2 + i});
  }
  return mesh;
}

std::vector<Vec2> rect(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

void add_part(shape::Scene& scene, Mesh mesh,
              shape::PartKind kind = shape::PartKind::kBuildingPart) {
  if (scene.buildings.empty()) scene.buildings.push_back({"b0", {}, {}});
  scene.buildings.back().parts.push_back({"part", kind, {}, std::move(mesh)});
}

shape::Scene unit_cube() {
  shape::Scene scene;
  add_part(scene, prism(rect(0, 0, 1, 1), 0, 1));
  return scene;
}

// Vivid materials so tests can tell surfaces apart by colour: 1 red, 2 green, 3 blue, 4 grey.
shape::Scene with_materials() {
  shape::Scene scene;
  scene.materials.push_back({"red", {0.9F, 0.0F, 0.0F, 1.0F}});
  scene.materials.push_back({"green", {0.0F, 0.8F, 0.0F, 1.0F}});
  scene.materials.push_back({"blue", {0.0F, 0.0F, 0.9F, 1.0F}});
  scene.materials.push_back({"grey", {0.6F, 0.6F, 0.6F, 1.0F}});
  return scene;
}

bool is_red(Rgba p) {
  return p[0] > 90 && p[1] < 50 && p[2] < 50;
}
bool is_green(Rgba p) {
  return p[1] > 90 && p[0] < 50 && p[2] < 50;
}
bool is_blue(Rgba p) {
  return p[2] > 90 && p[0] < 50 && p[1] < 50;
}
bool is_ink(Rgba p) {
  return p[0] < 60 && p[1] < 60 && p[2] < 60;
}

template <typename Predicate>
int count(const Image& image, Predicate predicate) {
  int n = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) n += predicate(image.pixel(x, y)) ? 1 : 0;
  }
  return n;
}

Rgba background_pixel(const RenderOptions& options) {
  shape::Scene empty;
  RenderOptions small = options;
  small.width = small.height = 4;
  return render(empty, small).pixel(0, 0);
}

// Options for an exact plan view: camera from the south looking straight down, so image x is
// world x and image up is world y (docs/renderer.md, "Camera").
RenderOptions plan_view(int size) {
  RenderOptions options;
  options.width = options.height = size;
  options.azimuth_deg = 270;
  options.elevation_deg = 90;
  options.shadows = false;
  return options;
}

std::string read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(PngRenderer, CubeCornersShowTheBackground) {
  const RenderOptions options;
  const Image image = render(unit_cube(), options);
  ASSERT_EQ(image.width, 1024);
  ASSERT_EQ(image.height, 768);
  const Rgba background = background_pixel(options);
  EXPECT_EQ(background[3], 255);
  for (auto [x, y] : {std::array{0, 0}, {1023, 0}, {0, 767}, {1023, 767}}) {
    EXPECT_EQ(image.pixel(x, y), background) << x << "," << y;
  }
}

TEST(PngRenderer, CubeCoversAPlausibleShareOfTheImage) {
  RenderOptions options;
  options.shadows = false;
  const Image image = render(unit_cube(), options);
  const Rgba background = background_pixel(options);
  const double share = count(image, [&](Rgba p) { return p != background; }) / (1024.0 * 768.0);
  // A cube seen from 35 degrees fitted to 90 % of the height covers about half of a 4:3 frame.
  EXPECT_GT(share, 0.30);
  EXPECT_LT(share, 0.70);
}

TEST(PngRenderer, CubeShowsThreeDistinctShades) {
  RenderOptions options;
  options.shadows = false;
  options.outlines = false;
  const Image image = render(unit_cube(), options);
  const Rgba background = background_pixel(options);
  std::map<Rgba, int> histogram;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      if (image.pixel(x, y) != background) ++histogram[image.pixel(x, y)];
    }
  }
  std::vector<std::pair<int, Rgba>> by_count;
  for (const auto& [colour, n] : histogram) by_count.push_back({n, colour});
  std::sort(by_count.rbegin(), by_count.rend());
  ASSERT_GE(by_count.size(), 3U);
  // Three flat faces: three colours that each fill a large area, pairwise clearly different.
  for (int i = 0; i < 3; ++i) EXPECT_GT(by_count[static_cast<std::size_t>(i)].first, 40000);
  for (int i = 0; i < 3; ++i) {
    for (int j = i + 1; j < 3; ++j) {
      const Rgba a = by_count[static_cast<std::size_t>(i)].second;
      const Rgba b = by_count[static_cast<std::size_t>(j)].second;
      int difference = 0;
      for (int k = 0; k < 3; ++k)
        difference += std::abs(a[static_cast<std::size_t>(k)] - b[static_cast<std::size_t>(k)]);
      EXPECT_GT(difference, 30) << i << " vs " << j;
    }
  }
  // Exactly one of them is the terracotta roof (red dominant), the others plaster walls.
  int reddish = 0;
  for (int i = 0; i < 3; ++i) {
    const Rgba c = by_count[static_cast<std::size_t>(i)].second;
    reddish += c[0] > c[1] + 40 ? 1 : 0;
  }
  EXPECT_EQ(reddish, 1);
}

TEST(PngRenderer, OutlinesAppearOnlyWhenAskedFor) {
  RenderOptions options;
  options.shadows = false;
  // Darker than the darkest shaded face of the cube: outline pixels, anti-aliased or not.
  auto dark = [](Rgba p) { return p[0] < 110 && p[1] < 110 && p[2] < 110; };
  const int with = count(render(unit_cube(), options), dark);
  options.outlines = false;
  const int without = count(render(unit_cube(), options), dark);
  // Nine visible edges of about 300 pixels each, one pixel wide.
  EXPECT_GT(with, 1500);
  EXPECT_EQ(without, 0);
}

TEST(PngRenderer, BuildingsTinyOnScreenGetNoOutlines) {
  RenderOptions options;
  options.shadows = false;
  options.width = options.height = 20;  // the cube spans 18 pixels: below the 24-pixel minimum
  EXPECT_EQ(count(render(unit_cube(), options), is_ink), 0);
  options.width = options.height = 40;
  EXPECT_GT(count(render(unit_cube(), options), is_ink), 0);
}

TEST(PngRenderer, RenderingIsDeterministic) {
  const std::string a = encode_png(render(unit_cube()));
  const std::string b = encode_png(render(unit_cube()));
  ASSERT_FALSE(a.empty());
  EXPECT_EQ(a, b);
}

TEST(PngRenderer, WrittenFileDecodesToTheRenderedPixels) {
  const auto path = std::filesystem::temp_directory_path() / "insula_png_renderer_cube.png";
  std::filesystem::remove(path);
  RenderOptions options;
  options.width = 320;
  options.height = 200;
  ASSERT_EQ(write_png(unit_cube(), path, options), "");
  const std::string bytes = read_bytes(path);
  int width = 0, height = 0, channels = 0;
  stbi_uc* decoded =
      stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()),
                            static_cast<int>(bytes.size()), &width, &height, &channels, 4);
  ASSERT_NE(decoded, nullptr);
  EXPECT_EQ(width, 320);
  EXPECT_EQ(height, 200);
  EXPECT_EQ(channels, 4);
  const Image image = render(unit_cube(), options);
  EXPECT_TRUE(std::equal(image.pixels.begin(), image.pixels.end(), decoded));
  stbi_image_free(decoded);
  // Same scene, same options: the same bytes on disk.
  ASSERT_EQ(write_png(unit_cube(), path, options), "");
  EXPECT_EQ(read_bytes(path), bytes);
  std::filesystem::remove(path);
}

TEST(PngRenderer, FailedWriteReturnsAMessageAndLeavesNoFile) {
  const auto dir = std::filesystem::temp_directory_path() / "insula_no_such_dir_for_png";
  std::filesystem::remove_all(dir);
  const auto path = dir / "cube.png";
  const std::string error = write_png(unit_cube(), path);
  EXPECT_NE(error.find(path.string()), std::string::npos) << error;
  EXPECT_FALSE(std::filesystem::exists(path));
  EXPECT_FALSE(std::filesystem::exists(dir));
}

TEST(PngRenderer, BadOptionsAreRejectedWithTheirName) {
  RenderOptions options;
  options.width = 0;
  EXPECT_EQ(validate(options), "width must be in 1..8192");
  EXPECT_TRUE(render(unit_cube(), options).empty());
  const auto path = std::filesystem::temp_directory_path() / "insula_bad_options.png";
  const std::string error = write_png(unit_cube(), path, options);
  EXPECT_EQ(error, path.string() + ": cannot render: width must be in 1..8192");
  EXPECT_FALSE(std::filesystem::exists(path));
  options = {};
  options.supersample = 9;
  EXPECT_EQ(validate(options), "supersample must be in 1..4");
  options = {};
  options.elevation_deg = std::nan("");
  EXPECT_EQ(validate(options), "elevation must be a finite number of degrees");
  EXPECT_EQ(validate(RenderOptions{}), "");
}

TEST(PngRenderer, EmptySceneIsAllBackground) {
  const shape::Scene empty;
  RenderOptions options;
  options.width = 64;
  options.height = 48;
  const Image image = render(empty, options);
  const Rgba background = image.pixel(0, 0);
  EXPECT_EQ(count(image, [&](Rgba p) { return p == background; }), 64 * 48);
}

TEST(PngRenderer, TransparentBackgroundHasZeroAlpha) {
  RenderOptions options;
  options.transparent_background = true;
  options.shadows = false;
  const Image image = render(unit_cube(), options);
  EXPECT_EQ(image.pixel(0, 0)[3], 0);
  EXPECT_EQ(image.pixel(512, 384)[3], 255);
}

TEST(PngRenderer, NonFiniteFacesAreSkippedWithoutCrashing) {
  shape::Scene scene = unit_cube();
  Mesh bad;
  const double nan = std::nan("");
  bad.add_polygon(std::vector<kernel::Vec3>{{0, 0, 5}, {nan, 1, 5}, {1, 1, 5}},
                  {SemanticClass::kRoofSurface, 0, 0});
  add_part(scene, std::move(bad));
  RenderOptions options;
  options.shadows = false;
  const Image image = render(scene, options);
  // The NaN part neither crashes nor changes the fit: the picture equals the plain cube's.
  EXPECT_EQ(image.pixels, render(unit_cube(), options).pixels);
}

// Plan view of two overlapping boxes: the taller one hides the lower one's top and its edges.
TEST(PngRenderer, NearerSurfacesAndTheirEdgesHideFartherOnes) {
  for (bool tall_first : {false, true}) {
    shape::Scene scene = with_materials();
    Mesh low = prism(rect(0, 0, 2, 2), 0, 1, 4, 1);   // red roof
    Mesh tall = prism(rect(1, 1, 3, 3), 0, 2, 4, 3);  // blue roof
    if (tall_first) std::swap(low, tall);
    add_part(scene, std::move(low));
    add_part(scene, std::move(tall));
    RenderOptions options = plan_view(600);
    options.outline_width = 3;  // so the ink fully covers the pixels along the edge
    const Image image = render(scene, options);
    // 3 m span in 540 pixels: 180 px/m, world (x, y) at pixel (30 + 180 x, 570 - 180 y).
    auto at = [&](double x, double y) {
      return image.pixel(static_cast<int>(30 + 180 * x), static_cast<int>(570 - 180 * y));
    };
    EXPECT_TRUE(is_red(at(0.5, 0.5)));
    EXPECT_TRUE(is_blue(at(1.5, 1.5)));  // overlap: the taller roof is nearer
    EXPECT_TRUE(is_blue(at(2.5, 2.5)));
    // The low box's roof edge x = 2 is visible for y < 1 and hidden under the tall roof above.
    EXPECT_TRUE(is_ink(at(2.0, 0.5)));
    EXPECT_TRUE(is_blue(at(2.0, 1.5)));
  }
}

// A concave (L-shaped) roof must not cover its notch: a fan from (10, 4) would.
TEST(PngRenderer, ConcaveFacesAreTriangulatedCorrectly) {
  shape::Scene scene = with_materials();
  add_part(scene, prism({{10, 4}, {4, 4}, {4, 10}, {0, 10}, {0, 0}, {10, 0}}, 0, 3, 4, 1));
  const Image image = render(scene, plan_view(1000));
  // 10 m span in 900 pixels: world (x, y) at pixel (50 + 90 x, 950 - 90 y).
  auto at = [&](double x, double y) {
    return image.pixel(static_cast<int>(50 + 90 * x), static_cast<int>(950 - 90 * y));
  };
  EXPECT_TRUE(is_red(at(2, 2)));
  EXPECT_TRUE(is_red(at(2, 8)));
  EXPECT_TRUE(is_red(at(8, 2)));
  EXPECT_EQ(at(7, 7), background_pixel(plan_view(1000)));  // the notch
  // Roof pixels: the L's 64 m2 of the 100 m2 square, at 90 px/m.
  const int red = count(image, is_red);
  EXPECT_NEAR(red, 64 * 90 * 90, 64 * 90 * 90 * 0.03);
}

// A box house (roof red, outer walls grey) with green inner walls.
shape::Scene box_with_inner_walls() {
  shape::Scene scene = with_materials();
  add_part(scene, prism(rect(0, 0, 10, 8), 0, 3, 4, 1));
  add_part(scene, prism(rect(4.9, 0.1, 5.1, 7.9), 0, 3, 2, 2, SemanticClass::kInteriorWallSurface),
           shape::PartKind::kOther);
  add_part(scene, prism(rect(0.1, 3.9, 4.9, 4.1), 0, 3, 2, 2, SemanticClass::kInteriorWallSurface),
           shape::PartKind::kOther);
  return scene;
}

TEST(PngRenderer, CutawayRemovesTheRoofAndShowsInnerWalls) {
  const shape::Scene scene = box_with_inner_walls();
  RenderOptions options;
  options.shadows = false;
  const Image closed = render(scene, options);
  EXPECT_GT(count(closed, is_red), 10000);
  EXPECT_EQ(count(closed, is_green), 0);  // inner walls hidden inside the box
  options.cutaway = true;
  options.cut_height = 1.5;
  const Image open = render(scene, options);
  EXPECT_EQ(count(open, is_red), 0);
  EXPECT_GT(count(open, is_green), 1000);
  // Cutting above the roof changes nothing.
  options.cut_height = 3.5;
  EXPECT_GT(count(render(scene, options), is_red), 10000);
}

TEST(PngRenderer, CutawayDrawsSectionLinesAlongTheCut) {
  const shape::Scene scene = box_with_inner_walls();
  RenderOptions options;
  options.shadows = false;
  options.outlines = false;
  options.cutaway = true;
  // With outlines off, every dark pixel is a section line where walls meet the cut.
  EXPECT_GT(count(render(scene, options), is_ink), 3000);
  options.cut_height = 3.5;
  EXPECT_EQ(count(render(scene, options), is_ink), 0);
}

// Linear light of an sRGB channel (IEC 61966-2-1).
double linear(std::uint8_t s) {
  const double c = s / 255.0;
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

// Outline ink per building on screen. The regions are the connected areas of non-background
// pixels of the scene drawn without outlines; the same view with outlines gives each pixel's
// ink coverage, how far it is darkened towards the outline colour (0..1 in linear light). With
// one sample per pixel there is no anti-aliasing: a pixel is either untouched, fully inked
// (coverage 1) or inked with faded strength.
struct InkRegion {
  int size = 0;         // larger side of the region's bounding box, pixels
  double outlined = 0;  // share of its border pixels (next to the background) with full ink on
                        // them or on a background pixel beside them
  double faded = 0;     // share of its inked pixels whose ink is faded
};
std::vector<InkRegion> ink_regions(const shape::Scene& scene, RenderOptions options) {
  options.shadows = false;
  options.supersample = 1;
  options.outlines = true;
  const Image inked = render(scene, options);
  options.outlines = false;
  const Image plain = render(scene, options);
  const int w = plain.width, h = plain.height;
  const Rgba background = background_pixel(options);
  auto inside = [&](int x, int y) {
    return x >= 0 && y >= 0 && x < w && y < h && plain.pixel(x, y) != background;
  };
  auto coverage = [&](int x, int y) {
    if (x < 0 || y < 0 || x >= w || y >= h) return 0.0;
    const double under = linear(plain.pixel(x, y)[1]);
    return (under - linear(inked.pixel(x, y)[1])) / (under - options.outline_color[1]);
  };
  std::vector<int> label(static_cast<std::size_t>(w * h), -1);
  std::vector<InkRegion> result;
  for (int sy = 0; sy < h; ++sy) {
    for (int sx = 0; sx < w; ++sx) {
      if (!inside(sx, sy) || label[static_cast<std::size_t>(sy * w + sx)] >= 0) continue;
      const int id = static_cast<int>(result.size());
      int border = 0, outlined = 0, inked_pixels = 0, faded = 0;
      int x0 = sx, x1 = sx, y0 = sy, y1 = sy;
      std::vector<std::array<int, 2>> stack{{sx, sy}};
      label[static_cast<std::size_t>(sy * w + sx)] = id;
      while (!stack.empty()) {
        const auto [x, y] = stack.back();
        stack.pop_back();
        x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
        const double c = coverage(x, y);
        inked_pixels += c > 0.05 ? 1 : 0;
        faded += c > 0.05 && c < 0.95 ? 1 : 0;
        bool edge = false;
        for (auto [dx, dy] : {std::array{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
          const int nx = x + dx, ny = y + dy;
          if (!inside(nx, ny)) {
            edge = true;
            continue;
          }
          int& l = label[static_cast<std::size_t>(ny * w + nx)];
          if (l < 0) l = id, stack.push_back({nx, ny});
        }
        if (!edge) continue;
        bool full = c >= 0.95;
        for (int dy = -1; dy <= 1; ++dy) {
          for (int dx = -1; dx <= 1; ++dx) {
            if (!inside(x + dx, y + dy) && coverage(x + dx, y + dy) >= 0.95) full = true;
          }
        }
        ++border;
        outlined += full ? 1 : 0;
      }
      result.push_back({std::max(x1 - x0, y1 - y0) + 1, static_cast<double>(outlined) / border,
                        inked_pixels == 0 ? 0.0 : static_cast<double>(faded) / inked_pixels});
    }
  }
  return result;
}

// A closed gabled house over the rectangle [x0, x1] x [y0, y1]: walls to `eaves`, a ridge along x
// at `ridge`.
Mesh gabled_house(double x0, double y0, double x1, double y1, double eaves, double ridge) {
  Mesh mesh;
  const double ym = (y0 + y1) / 2;
  for (kernel::Vec3 p : std::vector<kernel::Vec3>{{x0, y0, 0},
                                                  {x1, y0, 0},
                                                  {x1, y1, 0},
                                                  {x0, y1, 0},
                                                  {x0, y0, eaves},
                                                  {x1, y0, eaves},
                                                  {x1, y1, eaves},
                                                  {x0, y1, eaves},
                                                  {x0, ym, ridge},
                                                  {x1, ym, ridge}}) {
    mesh.add_vertex(p);
  }
  const kernel::FaceTag wall{SemanticClass::kWallSurface, 0, 0};
  const kernel::FaceTag roof{SemanticClass::kRoofSurface, 0, 1};
  mesh.add_face({3, 2, 1, 0}, {SemanticClass::kGroundSurface, 0, 2});
  mesh.add_face({0, 1, 5, 4}, wall);
  mesh.add_face({1, 2, 6, 9, 5}, wall);
  mesh.add_face({2, 3, 7, 6}, wall);
  mesh.add_face({3, 0, 4, 8, 7}, wall);
  mesh.add_face({4, 5, 9, 8}, roof);
  mesh.add_face({6, 7, 8, 9}, roof);
  return mesh;
}

// Issue 12 item 8: on an OpenStreetMap city the crowded-line fading took most of the outline of
// small buildings with busy shapes (a few dozen pixels: their silhouette, roof and wall lines
// crowd the density window) while large ones kept theirs. A large house, small houses, a terrace
// of row houses sharing party walls and small blocks with a sawtooth front (wall corners about
// 3 pixels apart at 800 x 600): every silhouette is fully inked. Only the sawtooth's corner
// lines are crowded enough to fade; the other drawings have no faded ink at all.
TEST(PngRenderer, EveryOutlinedBuildingKeepsItsSilhouette) {
  for (bool sawtooth : {true, false}) {
    shape::Scene scene;
    auto add_building = [&](Mesh mesh) {
      scene.buildings.push_back({std::to_string(scene.buildings.size()), {}, {}});
      add_part(scene, std::move(mesh));
    };
    add_building(gabled_house(-70, -5, 10, 35, 12, 30));
    for (int i = 0; i < 4; ++i) {
      // Down the image's diagonal, so the buildings stand apart on screen.
      const double x = 25 + 12 * i, y = -12 * i;
      add_building(gabled_house(x, y, x + 7, y + 4, 3, 5));
      if (!sawtooth) continue;
      std::vector<Vec2> saw;
      for (int t = 0; t < 8; ++t) {
        saw.push_back({x + 12 + t, y + 12}), saw.push_back({x + 12.5 + t, y + 12.6});
      }
      for (Vec2 p : {Vec2{x + 20, y + 12}, {x + 20, y + 17}, {x + 12, y + 17}}) saw.push_back(p);
      add_building(prism(saw, 0, 3 + i));
    }
    for (int i = 0; i < 4; ++i) {
      add_building(gabled_house(75 + 5 * i, -40, 80 + 5 * i, -34, 3, 5));
    }
    for (auto [width, height] : {std::array{800, 600}, {1600, 1200}}) {
      RenderOptions options;
      options.width = width;
      options.height = height;
      const std::vector<InkRegion> regions = ink_regions(scene, options);
      ASSERT_EQ(regions.size(), sawtooth ? 10U : 6U);  // the terrace is one region
      for (const InkRegion& region : regions) {
        SCOPED_TRACE(std::to_string(width) + " px wide, a region of " +
                     std::to_string(region.size) + " px");
        EXPECT_GE(region.size, 30);  // all above the 24-pixel minimum for outlines
        EXPECT_GE(region.outlined, 0.99);
        if (!sawtooth) {
          EXPECT_LE(region.faded, 0.01);
        }
      }
    }
  }
}

// Issue 12 item 8: a 200-storey tower (a box per storey) at 320 x 240 has its floor lines about a
// pixel apart. Drawn at full strength they made a black bar; they fade to a light hatch, while
// the tower's silhouette and a lone box's outlines stay fully dark.
TEST(PngRenderer, LinesDenserThanPixelsFadeInsideTheSilhouette) {
  shape::Scene tower;
  for (int storey = 0; storey < 200; ++storey) {
    add_part(tower, prism(rect(0, 0, 20, 20), 3.0 * storey, 3.0 * (storey + 1)));
  }
  RenderOptions options;
  options.width = 320;
  options.height = 240;
  options.shadows = false;
  const Image image = render(tower, options);
  const Rgba background = background_pixel(options);
  // Pixels more than 3 pixels inside the tower's silhouette: the floor lines' hatch.
  auto inner = [&](int x, int y) {
    for (int dy = -3; dy <= 3; ++dy) {
      for (int dx = -3; dx <= 3; ++dx) {
        if (image.pixel(std::clamp(x + dx, 0, image.width - 1),
                        std::clamp(y + dy, 0, image.height - 1)) == background) {
          return false;
        }
      }
    }
    return true;
  };
  int hatch = 0, dark = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      if (!inner(x, y)) continue;
      ++hatch;
      dark += is_ink(image.pixel(x, y)) ? 1 : 0;
    }
  }
  ASSERT_GT(hatch, 1000);
  EXPECT_LT(dark, hatch / 20) << dark << " of " << hatch << " pixels inside the tower are ink";
  const std::vector<InkRegion> regions = ink_regions(tower, options);
  ASSERT_EQ(regions.size(), 1U);
  EXPECT_GE(regions[0].outlined, 0.99);
  EXPECT_GE(regions[0].faded, 0.2);
  const std::vector<InkRegion> cube = ink_regions(unit_cube(), options);
  ASSERT_EQ(cube.size(), 1U);
  EXPECT_GE(cube[0].outlined, 0.99);
  EXPECT_EQ(cube[0].faded, 0.0);
}

TEST(PngRenderer, AutomaticCutHeight) {
  // No storeys, no floors: eaves less 1.5 m, but at least min(1.2 m, half the height) up.
  shape::Scene box = unit_cube();
  EXPECT_DOUBLE_EQ(auto_cut_height(box.buildings[0]), 0.5);
  shape::Scene tower;
  add_part(tower, prism(rect(0, 0, 5, 5), 0, 30));
  EXPECT_DOUBLE_EQ(auto_cut_height(tower.buildings[0]), 28.5);
  // Storey parts: 1.2 m above the floor of the highest one.
  shape::Scene storeys;
  add_part(storeys, prism(rect(0, 0, 5, 5), 0, 3), shape::PartKind::kStorey);
  add_part(storeys, prism(rect(0, 0, 5, 5), 3, 6), shape::PartKind::kStorey);
  add_part(storeys, prism(rect(-1, -1, 6, 6), 6, 7));  // roof slab, not a storey
  EXPECT_DOUBLE_EQ(auto_cut_height(storeys.buildings[0]), 4.2);
  // Floor surfaces: 1.2 m above the highest floor below the eaves.
  shape::Scene floors;
  Mesh shell = prism(rect(0, 0, 8, 8), 0, 9);
  const auto floor =
      shell.add_polygon(std::vector<kernel::Vec3>{{0, 0, 6}, {8, 0, 6}, {8, 8, 6}, {0, 8, 6}}, {});
  shell.tag(floor).semantic = SemanticClass::kFloorSurface;
  add_part(floors, std::move(shell));
  EXPECT_DOUBLE_EQ(auto_cut_height(floors.buildings[0]), 7.2);
  EXPECT_TRUE(std::isnan(auto_cut_height(shape::Building{})));
}

// Issue 12 item 8: furniture and stair steps whose tops are tagged RoofSurface (a Lua hotel's beds
// at 0.2 m) lie under the floors above them: they are not the eaves, and the cut stays 1.2 m above
// the top floor instead of dropping to 0.1 m, where only the ground slab showed.
TEST(PngRenderer, AutomaticCutHeightIgnoresCoveredRoofFaces) {
  shape::Scene hotel;
  Mesh shell = prism(rect(0, 0, 8, 8), 0, 9);
  for (double z : {3.0, 6.0}) {
    const auto floor = shell.add_polygon(
        std::vector<kernel::Vec3>{{0, 0, z}, {8, 0, z}, {8, 8, z}, {0, 8, z}}, {});
    shell.tag(floor).semantic = SemanticClass::kFloorSurface;
  }
  add_part(hotel, std::move(shell));
  for (double z : {0.0, 3.0, 6.0}) add_part(hotel, prism(rect(1, 1, 3, 2), z, z + 0.2));  // beds
  EXPECT_DOUBLE_EQ(auto_cut_height(hotel.buildings[0]), 7.2);
  // A porch roof beside the house is open to the sky: it is the eaves of a mass model.
  shape::Scene porch;
  add_part(porch, prism(rect(0, 0, 5, 5), 0, 9));
  add_part(porch, prism(rect(5, 0, 7, 5), 0, 2.5));
  EXPECT_DOUBLE_EQ(auto_cut_height(porch.buildings[0]), 1.2);
}

}  // namespace
}  // namespace insula::io
