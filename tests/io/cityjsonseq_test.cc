// CityJSONSeq writer: golden file, the header line, one compact line per building with the
// building and its parts, line-local vertices, the same geometry and coordinates as the CityJSON
// writer, the streaming writer's translate and ids, expanded instances, atomic writes.
#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "io/cityjson_writer.h"
#include "io/cityjsonseq_writer.h"
#include "io/output.h"
#include "kernel/transform.h"
#include "writer_fixtures.h"

namespace insula::io {
namespace {

using nlohmann::json;
using testing::test_scene;

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t begin = 0;
  while (begin < text.size()) {
    const std::size_t end = text.find('\n', begin);
    if (end == std::string::npos) {
      lines.push_back(text.substr(begin));  // no final line feed: the test below notices
      break;
    }
    lines.push_back(text.substr(begin, end - begin));
    begin = end + 1;
  }
  return lines;
}

std::vector<json> parsed_lines(const std::string& text) {
  std::vector<json> result;
  for (const std::string& line : lines_of(text)) result.push_back(json::parse(line));
  return result;
}

// Every vertex index of a geometry's boundaries, in order.
void collect_indices(const json& boundaries, std::vector<std::int64_t>& out) {
  if (boundaries.is_array()) {
    for (const json& item : boundaries) collect_indices(item, out);
  } else {
    out.push_back(boundaries.get<std::int64_t>());
  }
}

// The world coordinates of every boundary vertex of `geometry`, in order, dequantised with
// `transform` from `vertices`.
std::vector<std::array<double, 3>> coordinates(const json& geometry, const json& vertices,
                                               const json& transform) {
  std::vector<std::int64_t> indices;
  collect_indices(geometry["boundaries"], indices);
  std::vector<std::array<double, 3>> points;
  for (std::int64_t index : indices) {
    const json& v = vertices.at(static_cast<std::size_t>(index));
    std::array<double, 3> p{};
    for (std::size_t k = 0; k < 3; ++k) {
      p[k] = transform["translate"][k].get<double>() +
             v[k].get<double>() * transform["scale"][k].get<double>();
    }
    points.push_back(p);
  }
  return points;
}

TEST(CityJsonSeqWriter, MatchesGoldenFile) {
  testing::expect_golden("scene.city.jsonl", cityjsonseq_text(test_scene()));
}

TEST(CityJsonSeqWriter, HeaderLine) {
  const json header = parsed_lines(cityjsonseq_text(test_scene())).at(0);
  EXPECT_EQ(header["type"], "CityJSON");
  EXPECT_EQ(header["version"], "2.0");
  EXPECT_EQ(header["transform"]["scale"], json::array({0.001, 0.001, 0.001}));
  // The fixture's local minimum corner is (0, 0, 0): translate is the origin.
  EXPECT_EQ(header["transform"]["translate"], json::array({500000.25, 5400000.5, 100.0}));
  EXPECT_EQ(header["metadata"]["referenceSystem"], "https://www.opengis.net/def/crs/EPSG/0/32633");
  EXPECT_EQ(header["CityObjects"], json::object());
  EXPECT_EQ(header["vertices"], json::array());
}

TEST(CityJsonSeqWriter, OneCompactLinePerBuilding) {
  const shape::Scene scene = test_scene();
  const std::string text = cityjsonseq_text(scene);
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.back(), '\n');
  EXPECT_EQ(text.find('\r'), std::string::npos);
  const std::vector<std::string> lines = lines_of(text);
  ASSERT_EQ(lines.size(), 1 + scene.buildings.size());
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const json feature = json::parse(lines[i]);
    EXPECT_EQ(feature.dump(), lines[i]);  // compact, sorted keys
    EXPECT_EQ(feature["type"], "CityJSONFeature");
    EXPECT_EQ(feature["id"], scene.buildings[i - 1].id);
    EXPECT_FALSE(feature.contains("transform"));
    EXPECT_FALSE(feature.contains("version"));
  }
}

TEST(CityJsonSeqWriter, VerticesAreLocalToTheLine) {
  const std::vector<json> lines = parsed_lines(cityjsonseq_text(test_scene()));
  // b1: the 4 x 3 x 3 box, 8 corners; L-2: the L prism's 12 corners and the floor's 4.
  EXPECT_EQ(lines.at(1)["vertices"].size(), 8U);
  EXPECT_EQ(lines.at(2)["vertices"].size(), 16U);
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const json& feature = lines[i];
    std::set<std::int64_t> used;
    for (const auto& [id, object] : feature["CityObjects"].items()) {
      for (const json& geometry : object.value("geometry", json::array())) {
        std::vector<std::int64_t> indices;
        collect_indices(geometry["boundaries"], indices);
        for (std::int64_t index : indices) {
          EXPECT_GE(index, 0) << id;
          EXPECT_LT(index, static_cast<std::int64_t>(feature["vertices"].size())) << id;
          used.insert(index);
        }
      }
    }
    EXPECT_EQ(used.size(), feature["vertices"].size()) << "every vertex of line " << i << " used";
    EXPECT_EQ(*used.begin(), 0);  // numbered from 0 on every line
  }
}

// A line lists only the vertices its boundaries use and only the parts with a face left on the
// grid: a lot's border that an inward offset left a sliver 0.2 mm wide is no BuildingPart.
TEST(CityJsonSeqWriter, CollapsedFacesLeaveNoVertexAndCollapsedPartsNoObject) {
  kernel::Mesh sliver;
  sliver.add_polygon(std::vector<kernel::Vec3>{{5, 5, 0}, {6, 5, 0}, {6, 5.0002, 0}}, {});
  kernel::Mesh paving = sliver;
  paving.add_polygon(std::vector<kernel::Vec3>{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {});
  shape::Scene scene;
  scene.buildings.push_back({"lot",
                             {},
                             {{"Lawn", shape::PartKind::kBuildingPart, {}, sliver},
                              {"Paving", shape::PartKind::kBuildingPart, {}, paving}}});
  const json feature = parsed_lines(cityjsonseq_text(scene)).at(1);
  const json& objects = feature["CityObjects"];
  EXPECT_EQ(objects.size(), 2U);
  EXPECT_EQ(objects["lot"]["children"], json::array({"lot-Paving"}));
  std::vector<std::int64_t> indices;
  collect_indices(objects["lot-Paving"]["geometry"][0]["boundaries"], indices);
  EXPECT_EQ(std::set<std::int64_t>(indices.begin(), indices.end()).size(), 4U);
  EXPECT_EQ(feature["vertices"].size(), 4U);
}

TEST(CityJsonSeqWriter, BuildingWithItsPartsInOneLine) {
  const json feature = parsed_lines(cityjsonseq_text(test_scene())).at(2);
  const json& objects = feature["CityObjects"];
  ASSERT_EQ(objects.size(), 3U);
  EXPECT_EQ(objects["L-2"]["type"], "Building");
  EXPECT_EQ(objects["L-2"]["children"], json::array({"L-2-wing", "L-2-storey 0"}));
  EXPECT_EQ(objects["L-2-wing"]["parents"], json::array({"L-2"}));
  EXPECT_EQ(objects["L-2-wing"]["type"], "BuildingPart");
  EXPECT_EQ(objects["L-2-storey 0"]["type"], "BuildingStorey");
  EXPECT_EQ(objects["L-2"]["attributes"]["height"], 4.0);
}

// The same city objects as the .city.json file: types, attributes, geometry types, surfaces and
// semantics alike, and every boundary vertex at the same world coordinates.
TEST(CityJsonSeqWriter, SameGeometryAsTheCityJsonWriter) {
  const shape::Scene scene = test_scene();
  const json city = json::parse(cityjson_text(scene));
  const std::vector<json> lines = parsed_lines(cityjsonseq_text(scene));
  const json& transform = lines.at(0)["transform"];
  EXPECT_EQ(transform, city["transform"]);
  std::size_t objects = 0;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    for (const auto& [id, object] : lines[i]["CityObjects"].items()) {
      ++objects;
      ASSERT_TRUE(city["CityObjects"].contains(id)) << id;
      const json& expected = city["CityObjects"][id];
      json without_geometry = object;
      json expected_without_geometry = expected;
      without_geometry.erase("geometry");
      expected_without_geometry.erase("geometry");
      EXPECT_EQ(without_geometry, expected_without_geometry) << id;
      ASSERT_EQ(object.contains("geometry"), expected.contains("geometry")) << id;
      if (!object.contains("geometry")) continue;
      ASSERT_EQ(object["geometry"].size(), expected["geometry"].size()) << id;
      for (std::size_t g = 0; g < object["geometry"].size(); ++g) {
        const json& mine = object["geometry"][g];
        const json& theirs = expected["geometry"][g];
        EXPECT_EQ(mine["type"], theirs["type"]) << id;
        EXPECT_EQ(mine["semantics"], theirs["semantics"]) << id;
        const bool solid = mine["type"] == "Solid";
        const json& surfaces = solid ? mine["boundaries"][0] : mine["boundaries"];
        const json& expected_surfaces = solid ? theirs["boundaries"][0] : theirs["boundaries"];
        EXPECT_EQ(surfaces.size(), expected_surfaces.size()) << id;
        EXPECT_EQ(coordinates(mine, lines[i]["vertices"], transform),
                  coordinates(theirs, city["vertices"], city["transform"]))
            << id;
      }
    }
  }
  EXPECT_EQ(objects, city["CityObjects"].size());
}

// A streaming pipeline: the transform chosen up front (here a translate away from the origin),
// lines written as buildings come; an unnamed building and a repeated id get unique ids.
TEST(CityJsonSeqWriter, StreamingWriterWithGivenTranslate) {
  const shape::Scene scene = test_scene();
  CityJsonSeqWriter writer(scene.origin, scene.crs, scene.origin + kernel::Vec3{-1.5, 2, 0.25});
  const json header = json::parse(writer.header_line());
  EXPECT_EQ(header["transform"]["translate"], json::array({499998.75, 5400002.5, 100.25}));

  const json box = json::parse(writer.feature_line(scene.buildings[0]));
  // The first vertex is where the ground face starts, local (0, 3, 0): (1.5, 1, -0.25) m from the
  // translate.
  EXPECT_EQ(box["vertices"][0], json::array({1500, 1000, -250}));
  const json city = json::parse(cityjson_text(scene));
  EXPECT_EQ(coordinates(box["CityObjects"]["b1-main"]["geometry"][0], box["vertices"],
                        header["transform"]),
            coordinates(city["CityObjects"]["b1-main"]["geometry"][0], city["vertices"],
                        city["transform"]));

  shape::Building unnamed = scene.buildings[1];
  unnamed.id.clear();
  const json second = json::parse(writer.feature_line(unnamed));
  EXPECT_EQ(second["id"], "building1");
  EXPECT_TRUE(second["CityObjects"].contains("building1-wing"));
  const json again = json::parse(writer.feature_line(scene.buildings[0]));
  EXPECT_EQ(again["id"], "b1-2");
  EXPECT_EQ(again["CityObjects"]["b1-2"]["children"], json::array({"b1-2-main"}));
}

TEST(CityJsonSeqWriter, InstancesAreExpanded) {
  shape::Scene scene = test_scene();
  auto cube =
      std::make_shared<const kernel::Mesh>(testing::prism({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0, 1));
  shape::Part instance;
  instance.name = "chimney";
  instance.instance_of = cube;
  instance.instance_transform = kernel::translation({1, 1, 3});
  scene.buildings[0].parts.push_back(instance);
  const json feature = parsed_lines(cityjsonseq_text(scene)).at(1);
  const json& chimney = feature["CityObjects"]["b1-chimney"]["geometry"][0];
  EXPECT_EQ(chimney["type"], "Solid");
  EXPECT_EQ(feature["vertices"].size(), 16U);
  const json city = json::parse(cityjson_text(scene));
  EXPECT_EQ(coordinates(chimney, feature["vertices"],
                        parsed_lines(cityjsonseq_text(scene))[0]["transform"]),
            coordinates(city["CityObjects"]["b1-chimney"]["geometry"][0], city["vertices"],
                        city["transform"]));
}

TEST(CityJsonSeqWriter, EmptySceneIsTheHeaderAlone) {
  const std::vector<std::string> lines = lines_of(cityjsonseq_text(shape::Scene{}));
  ASSERT_EQ(lines.size(), 1U);
  EXPECT_FALSE(json::parse(lines[0])["metadata"].contains("referenceSystem"));
}

TEST(CityJsonSeqWriter, WritesThroughTheOutputRegistry) {
  const std::filesystem::path dir = testing::temp_dir("cityjsonseq");
  const std::string path = (dir / "scene.City.JSONL").string();
  EXPECT_TRUE(is_supported_output(path));
  EXPECT_EQ(output_format_name(path), "cityjsonseq");
  EXPECT_EQ(output_format_name((dir / "scene.city.json").string()), "cityjson");
  EXPECT_EQ(files_of_output(path), std::vector<std::string>{path});
  ASSERT_EQ(write_scene(test_scene(), path), "");
  EXPECT_EQ(testing::read_file(path), cityjsonseq_text(test_scene()));
  const std::string error = write_cityjsonseq(test_scene(), dir / "missing" / "x.city.jsonl");
  EXPECT_NE(error.find("x.city.jsonl"), std::string::npos) << error;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace insula::io
