// CityJSON writer: golden file, structure (transform, metadata, parents and children, Solid vs
// MultiSurface, semantics), quantisation and deduplication of vertices, degenerate rings and the
// vertices and parts they leave unused.
#include <algorithm>
#include <cmath>
#include <functional>
#include <set>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "io/cityjson_writer.h"
#include "io/cityjsonseq_writer.h"
#include "writer_fixtures.h"

namespace insula::io {
namespace {

using nlohmann::json;
using testing::test_scene;

json written(const shape::Scene& scene) {
  return json::parse(cityjson_text(scene));
}

TEST(CityJsonWriter, MatchesGoldenFile) {
  testing::expect_golden("scene.city.json", cityjson_text(test_scene()));
}

TEST(CityJsonWriter, HeaderTransformAndMetadata) {
  const json city = written(test_scene());
  EXPECT_EQ(city["type"], "CityJSON");
  EXPECT_EQ(city["version"], "2.0");
  EXPECT_EQ(city["transform"]["scale"], json::array({0.001, 0.001, 0.001}));
  // The scene's local minimum corner is (0, 0, 0), so translate is the origin itself.
  EXPECT_EQ(city["transform"]["translate"], json::array({500000.25, 5400000.5, 100.0}));
  EXPECT_EQ(city["metadata"]["referenceSystem"], "https://www.opengis.net/def/crs/EPSG/0/32633");
  EXPECT_EQ(city["metadata"]["geographicalExtent"],
            json::array({500000.25, 5400000.5, 100.0, 500016.25, 5400005.5, 104.0}));
}

TEST(CityJsonWriter, BuildingsWithPartsStoreysAndAttributes) {
  const json objects = written(test_scene())["CityObjects"];
  ASSERT_EQ(objects.size(), 5U);
  EXPECT_EQ(objects["b1"]["type"], "Building");
  EXPECT_EQ(objects["b1"]["children"], json::array({"b1-main"}));
  EXPECT_EQ(objects["b1"]["attributes"]["height"], 3.0);
  EXPECT_EQ(objects["b1"]["attributes"]["listed"], true);
  EXPECT_EQ(objects["b1"]["attributes"]["name"], "Box & <Co> \"1\"");
  EXPECT_TRUE(objects["L-2"]["attributes"]["note"].is_null());
  EXPECT_EQ(objects["b1-main"]["type"], "BuildingPart");
  EXPECT_EQ(objects["b1-main"]["parents"], json::array({"b1"}));
  EXPECT_EQ(objects["b1-main"]["attributes"]["levels"], 1.0);
  EXPECT_EQ(objects["L-2"]["children"], json::array({"L-2-wing", "L-2-storey 0"}));
  EXPECT_EQ(objects["L-2-storey 0"]["type"], "BuildingStorey");
  EXPECT_FALSE(objects["b1"].contains("geometry"));
}

TEST(CityJsonWriter, ClosedPartsAreSolidsWithSemantics) {
  const json objects = written(test_scene())["CityObjects"];
  const json& box = objects["b1-main"]["geometry"][0];
  EXPECT_EQ(box["type"], "Solid");
  EXPECT_EQ(box["lod"], "2");
  ASSERT_EQ(box["boundaries"].size(), 1U);                         // one shell
  EXPECT_EQ(box["boundaries"][0].size(), 6U);                      // six surfaces of one ring each
  EXPECT_EQ(box["boundaries"][0][0], json::parse("[[0,1,2,3]]"));  // numbered by first use
  EXPECT_EQ(
      box["semantics"]["surfaces"],
      json::parse(R"([{"type":"GroundSurface"},{"type":"WallSurface"},{"type":"RoofSurface"}])"));
  EXPECT_EQ(box["semantics"]["values"], json::parse("[[0,1,1,1,1,2]]"));
  const json& wing = objects["L-2-wing"]["geometry"][0];
  EXPECT_EQ(wing["type"], "Solid");
  EXPECT_EQ(wing["boundaries"][0].size(), 8U);
  EXPECT_EQ(wing["boundaries"][0][7][0].size(), 6U);  // the concave roof stays one hexagon
}

TEST(CityJsonWriter, OpenPartsAreMultiSurfaces) {
  const json floor = written(test_scene())["CityObjects"]["L-2-storey 0"]["geometry"][0];
  EXPECT_EQ(floor["type"], "MultiSurface");
  EXPECT_EQ(floor["boundaries"].size(), 1U);
  EXPECT_EQ(floor["semantics"]["surfaces"], json::parse(R"([{"type":"FloorSurface"}])"));
  EXPECT_EQ(floor["semantics"]["values"], json::parse("[0]"));
}

TEST(CityJsonWriter, VerticesAreUniqueIntegersWithinHalfAMillimetre) {
  const shape::Scene scene = test_scene();
  const json city = written(scene);
  const json& vertices = city["vertices"];
  EXPECT_EQ(vertices.size(), 8U + 12U + 4U);
  std::set<std::vector<std::int64_t>> unique;
  for (const json& v : vertices) {
    ASSERT_TRUE(v[0].is_number_integer() && v[1].is_number_integer() && v[2].is_number_integer());
    unique.insert(v.get<std::vector<std::int64_t>>());
  }
  EXPECT_EQ(unique.size(), vertices.size());
  // The floor's corner (10, 2, 0.1) local is vertex 23 (first use order).
  const json& t = city["transform"]["translate"];
  const json& v = vertices[23];
  EXPECT_NEAR(t[0].get<double>() + v[0].get<double>() * 0.001, 500010.25, 5e-4);
  EXPECT_NEAR(t[1].get<double>() + v[1].get<double>() * 0.001, 5400002.5, 5e-4);
  EXPECT_NEAR(t[2].get<double>() + v[2].get<double>() * 0.001, 100.1, 5e-4);
}

TEST(CityJsonWriter, UnweldedFacesAreWeldedByQuantisationIntoASolid) {
  // Every face with its own vertices, jittered by 0.1 mm: one Solid after quantisation.
  const kernel::Mesh shared = testing::prism({{0, 0}, {4, 0}, {4, 3}, {0, 3}}, 0, 3);
  kernel::Mesh loose;
  for (std::size_t f = 0; f < shared.face_count(); ++f) {
    std::vector<kernel::Vec3> loop;
    for (std::uint32_t v : shared.face(f)) {
      loop.push_back(shared.position(v) + kernel::Vec3{1e-4 * static_cast<double>(f % 2), 0, 0});
    }
    loose.add_polygon(loop, shared.tag(f));
  }
  shape::Scene scene;
  scene.buildings.push_back({"b", {}, {{"p", shape::PartKind::kBuildingPart, {}, loose}}});
  const json city = written(scene);
  EXPECT_EQ(city["vertices"].size(), 8U);
  EXPECT_EQ(city["CityObjects"]["b-p"]["geometry"][0]["type"], "Solid");
  EXPECT_FALSE(city["metadata"].contains("referenceSystem"));
}

TEST(CityJsonWriter, DropsRingsThatCollapseAfterQuantisation) {
  kernel::Mesh mesh;
  // A sliver 0.2 mm wide collapses to a segment; a square with a doubled corner loses the repeat.
  mesh.add_polygon(std::vector<kernel::Vec3>{{0, 0, 0}, {1, 0, 0}, {1, 0.0002, 0}},
                   {kernel::SemanticClass::kRoofSurface, 0, 0});
  mesh.add_polygon(
      std::vector<kernel::Vec3>{{0, 0, 1}, {1, 0, 1}, {1, 0.0001, 1}, {1, 1, 1}, {0, 1, 1}},
      {kernel::SemanticClass::kNone, 0, 1});
  shape::Scene scene;
  scene.buildings.push_back({"b", {}, {{"p", shape::PartKind::kBuildingPart, {}, mesh}}});
  const json geometry = written(scene)["CityObjects"]["b-p"]["geometry"][0];
  EXPECT_EQ(geometry["type"], "MultiSurface");
  ASSERT_EQ(geometry["boundaries"].size(), 1U);
  EXPECT_EQ(geometry["boundaries"][0][0].size(), 4U);
  EXPECT_FALSE(geometry.contains("semantics"));  // the surviving face has no class
}

// Every vertex listed is one some boundary uses: the points of a face that collapsed on the grid
// are not listed (cjval warns about unused vertices).
std::set<std::int64_t> used_vertices(const json& boundaries) {
  std::set<std::int64_t> used;
  std::function<void(const json&)> walk = [&](const json& j) {
    if (j.is_number_integer()) {
      used.insert(j.get<std::int64_t>());
    } else {
      for (const json& element : j) walk(element);
    }
  };
  walk(boundaries);
  return used;
}

TEST(CityJsonWriter, ListsOnlyVerticesABoundaryUses) {
  kernel::Mesh mesh;
  // A sliver 0.2 mm wide (its own two points, a segment on the grid) beside a plain square.
  mesh.add_polygon(std::vector<kernel::Vec3>{{5, 5, 0}, {6, 5, 0}, {6, 5.0002, 0}}, {});
  mesh.add_polygon(std::vector<kernel::Vec3>{{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}, {});
  shape::Scene scene;
  scene.buildings.push_back({"b", {}, {{"p", shape::PartKind::kBuildingPart, {}, mesh}}});
  const json city = written(scene);
  const std::set<std::int64_t> used =
      used_vertices(city["CityObjects"]["b-p"]["geometry"][0]["boundaries"]);
  EXPECT_EQ(used, (std::set<std::int64_t>{0, 1, 2, 3}));
  EXPECT_EQ(city["vertices"].size(), 4U);
  // The extent is the square's: the sliver's points are no vertex.
  EXPECT_EQ(city["metadata"]["geographicalExtent"][3].get<double>(),
            city["transform"]["translate"][0].get<double>() + 1);
}

// A part all of whose faces collapse on the grid is no city object: not a child of its building,
// no id taken (a later part of the same name keeps its plain id). A building left with no part
// stays, with its attributes, as a building with no parts does.
TEST(CityJsonWriter, PartsWhoseFacesAllCollapseAreNoObjects) {
  kernel::Mesh sliver;
  sliver.add_polygon(std::vector<kernel::Vec3>{{5, 5, 0}, {6, 5, 0}, {6, 5.0002, 0}}, {});
  const kernel::Mesh square = testing::prism({{0, 0}, {4, 0}, {4, 3}, {0, 3}}, 0, 3);
  shape::Scene scene;
  scene.buildings.push_back({"b",
                             {},
                             {{"lawn", shape::PartKind::kBuildingPart, {}, sliver},
                              {"lawn", shape::PartKind::kBuildingPart, {}, square}}});
  scene.buildings.push_back({"c",
                             {{"name", std::string("nothing left")}},
                             {{"lawn", shape::PartKind::kRoom, {}, sliver}}});
  const json objects = written(scene)["CityObjects"];
  ASSERT_EQ(objects.size(), 3U);
  EXPECT_EQ(objects["b"]["children"], json::array({"b-lawn"}));
  EXPECT_EQ(objects["b-lawn"]["geometry"][0]["type"], "Solid");
  EXPECT_EQ(objects["c"]["attributes"]["name"], "nothing left");
  EXPECT_FALSE(objects["c"].contains("children"));
}

TEST(CityJsonWriter, NonFiniteFacesAreSkipped) {
  kernel::Mesh mesh;
  mesh.add_polygon(std::vector<kernel::Vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {});
  mesh.add_polygon(std::vector<kernel::Vec3>{{0, 0, NAN}, {1, 0, 0}, {0, 1, 0}}, {});
  shape::Scene scene;
  scene.buildings.push_back({"b", {}, {{"p", shape::PartKind::kRoom, {}, mesh}}});
  const json city = written(scene);
  EXPECT_EQ(city["CityObjects"]["b-p"]["type"], "BuildingRoom");
  EXPECT_EQ(city["CityObjects"]["b-p"]["geometry"][0]["boundaries"].size(), 1U);
}

// The solid test on the quantised rings: every edge used exactly once each way, one shell,
// positive volume; anything else is written as a MultiSurface.
TEST(CityJsonWriter, SolidsNeedOneClosedOrientedShell) {
  const auto box = [](double x, double y) {
    return testing::prism({{x, y}, {x + 1, y}, {x + 1, y + 1}, {x, y + 1}}, 0, 1);
  };
  const auto type = [](const kernel::Mesh& mesh) {
    shape::Scene scene;
    scene.buildings.push_back({"b", {}, {{"p", shape::PartKind::kBuildingPart, {}, mesh}}});
    return written(scene)["CityObjects"]["b-p"]["geometry"][0]["type"].get<std::string>();
  };
  EXPECT_EQ(type(box(0, 0)), "Solid");

  kernel::Mesh inside_out = box(0, 0);  // closed and oriented, negative volume
  inside_out.flip();
  EXPECT_EQ(type(inside_out), "MultiSurface");

  kernel::Mesh two_shells = box(0, 0);  // two components
  two_shells.append(box(3, 0));
  EXPECT_EQ(type(two_shells), "MultiSurface");

  kernel::Mesh edge_shared = box(0, 0);  // touching along one edge: used twice each way
  edge_shared.append(box(1, 1));
  EXPECT_EQ(type(edge_shared), "MultiSurface");

  const kernel::Mesh closed = box(0, 0);
  kernel::Mesh one_flipped;  // the roof turned: its edges used twice the same way
  kernel::Mesh roof_twice;   // the roof again: its edges used twice the same way too
  kernel::Mesh no_roof;      // open: the roof's edges used one way only
  for (const kernel::Vec3& p : closed.positions()) {
    one_flipped.add_vertex(p);
    roof_twice.add_vertex(p);
    no_roof.add_vertex(p);
  }
  for (std::size_t f = 0; f < closed.face_count(); ++f) {
    std::vector<std::uint32_t> loop(closed.face(f).begin(), closed.face(f).end());
    roof_twice.add_face(loop, closed.tag(f));
    const bool roof = f + 1 == closed.face_count();
    if (!roof) no_roof.add_face(loop, closed.tag(f));
    if (roof) {
      roof_twice.add_face(loop, closed.tag(f));
      std::reverse(loop.begin(), loop.end());
    }
    one_flipped.add_face(loop, closed.tag(f));
  }
  EXPECT_EQ(type(one_flipped), "MultiSurface");
  EXPECT_EQ(type(roof_twice), "MultiSurface");
  EXPECT_EQ(type(no_roof), "MultiSurface");
}

TEST(CityJsonWriter, IdsStayUnique) {
  kernel::Mesh face;  // a part without a face would be no object
  face.add_polygon(std::vector<kernel::Vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {});
  shape::Scene scene;
  scene.buildings.push_back({"a",
                             {},
                             {{"x", shape::PartKind::kBuildingPart, {}, face},
                              {"x", shape::PartKind::kBuildingPart, {}, face}}});
  scene.buildings.push_back({"a", {}, {}});
  const json objects = written(scene)["CityObjects"];
  EXPECT_EQ(objects.size(), 4U);
  EXPECT_EQ(objects["a"]["children"], json::array({"a-x", "a-x-2"}));
  EXPECT_EQ(objects["a-2"]["type"], "Building");
}

// With merge_alike_parts a building's parts alike in name, kind, attributes and uv map are one
// BuildingPart (a CGA scene made with a part per terminal); without, each is its own.
TEST(CityJsonWriter, MergesAlikePartsWhenAsked) {
  const auto face = [](double x) {
    kernel::Mesh mesh;
    mesh.add_polygon(std::vector<kernel::Vec3>{{x, 0, 0}, {x + 1, 0, 0}, {x, 1, 0}}, {});
    return mesh;
  };
  shape::Scene scene;
  const shape::AttributeMap plaster{{"color", std::string("#dccfb6")}};
  scene.buildings.push_back({"a",
                             {},
                             {{"Plaster", shape::PartKind::kBuildingPart, plaster, face(0)},
                              {"Pane", shape::PartKind::kBuildingPart, {}, face(2)},
                              {"Plaster", shape::PartKind::kBuildingPart, plaster, face(4)}}});
  const json apart = written(scene)["CityObjects"];
  EXPECT_EQ(apart["a"]["children"], json::array({"a-Plaster", "a-Pane", "a-Plaster-2"}));

  for (const std::string& text : {cityjson_text(scene, {.merge_alike_parts = true}),
                                  cityjsonseq_text(scene, {.merge_alike_parts = true})
                                      .substr(cityjsonseq_text(scene).find('\n') + 1)}) {
    const json objects = json::parse(text)["CityObjects"];
    EXPECT_EQ(objects["a"]["children"], json::array({"a-Plaster", "a-Pane"}));
    EXPECT_EQ(objects["a-Plaster"]["geometry"][0]["boundaries"].size(), 2U);
    EXPECT_EQ(objects["a-Plaster"]["attributes"]["color"], "#dccfb6");
    EXPECT_EQ(objects["a-Pane"]["geometry"][0]["boundaries"].size(), 1U);
  }
}

TEST(CityJsonWriter, ReferenceSystems) {
  EXPECT_EQ(cityjson_reference_system("EPSG:7415"), "https://www.opengis.net/def/crs/EPSG/0/7415");
  EXPECT_EQ(cityjson_reference_system("epsg::2056"), "https://www.opengis.net/def/crs/EPSG/0/2056");
  EXPECT_EQ(cityjson_reference_system("https://www.opengis.net/def/crs/EPSG/0/28992"),
            "https://www.opengis.net/def/crs/EPSG/0/28992");
  EXPECT_EQ(cityjson_reference_system("EPSG:"), "");
  EXPECT_EQ(cityjson_reference_system("EPSG:12a"), "");
  EXPECT_EQ(cityjson_reference_system("WGS84"), "");
  EXPECT_EQ(cityjson_reference_system(""), "");
}

TEST(CityJsonWriter, WritesAtomically) {
  const auto dir = testing::temp_dir("cityjson_write");
  ASSERT_EQ(write_cityjson(test_scene(), dir / "city.city.json"), "");
  EXPECT_EQ(testing::read_file(dir / "city.city.json"), cityjson_text(test_scene()));
  const std::string error = write_cityjson(test_scene(), dir / "no" / "city.city.json");
  EXPECT_NE(error.find("city.city.json"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir / "no"));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace insula::io
