// Terrain nodes (docs/graph-executor.md, "Terrain"): a noisy heightfield levelled under a row of
// lots and along a road, then lots, masses, a street and points placed on it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "kernel/heightfield.h"
#include "lang/graph/output.h"
#include "run_util.h"
#include "shape/scope.h"

namespace insula::lang::graph::testing {
namespace {

std::string graph(const std::string& body) {
  return R"({"format": "insula-graph", "version": 1, )" + body + "}";
}

// Five 15 x 20 lots 2 m apart (a sample lies under two neighbours: one terrace) along y = 40..60 on
// a 200 x 100 field with hills of up to 8 m; a road strip along y = 10..20.
const char* kTown = R"(
    "nodes": [
      { "id": "ground", "type": "terrain.create", "params": { "width": 200, "depth": 100 } },
      { "id": "hills", "type": "terrain.noise",
        "params": { "amplitude": 8, "wavelength": 80, "seed": 3 } },
      { "id": "lots", "type": "create.grid",
        "params": { "columns": 5, "rows": 1, "cell_width": 15, "cell_depth": 20, "gap": 2,
                    "origin": [40, 40, 0] } },
      { "id": "road", "type": "create.polygon",
        "params": { "vertices": [[0, 10], [200, 10], [200, 20], [0, 20]] } },
      { "id": "level", "type": "terrain.level", "params": { "margin": 6 } },
      { "id": "keep", "type": "attr.set" },
      { "id": "rough", "type": "attr.set" },
      { "id": "mass", "type": "shape.extrude", "params": { "height": 9 } },
      { "id": "street", "type": "path.create", "params": { "points": [[0, 15], [60, 15], [120, 15], [199, 15]] } },
      { "id": "lamps", "type": "create.points", "params": { "points": [[10, 90, 0], [150, 5, 0]] } },
      { "id": "place", "type": "terrain.place" },
      { "id": "place_mass", "type": "terrain.place" },
      { "id": "place_street", "type": "terrain.place" } ],
    "edges": [ "ground.out -> hills.in", "hills.out -> level.in", "hills.out -> rough.in",
               "lots.out -> level.shapes", "road.out -> level.roads",
               "level.out -> keep.in", "level.out -> place.terrain",
               "level.out -> place_mass.terrain", "level.out -> place_street.terrain",
               "lots.out -> place.in", "lots.out -> mass.in", "mass.out -> place_mass.in",
               "street.out -> place_street.in", "lamps.out -> place_street.in" ])";

TEST(Terrain, LotsSitOnTheirLevelledPlateauAndStreetsFollowTheSurface) {
  const TestRun t = run_text(graph(kTown));
  ASSERT_TRUE(t.ok()) << t.errors;
  ASSERT_EQ(t.at("keep.out").size(), 1U);
  ASSERT_EQ(t.at("rough.out").size(), 1U);
  const kernel::Heightfield& levelled = *t.run->entities[t.at("keep.out")[0]].terrain;
  const kernel::Heightfield& rough = *t.run->entities[t.at("rough.out")[0]].terrain;
  EXPECT_EQ(levelled.nx, 101);
  EXPECT_EQ(levelled.ny, 51);
  const auto [lo, hi] = std::minmax_element(rough.z.begin(), rough.z.end());
  EXPECT_GT(*hi - *lo, 4.0);  // hilly before levelling
  EXPECT_GE(*lo, -8.0);
  EXPECT_LE(*hi, 8.0);

  const std::vector<EntityId> lots = t.at("place.out");
  ASSERT_EQ(lots.size(), 5U);
  const double plateau = t.run->tree[t.run->entities[lots[0]].shape].scope.origin.z;
  for (EntityId lot : lots) {
    const shape::Shape& s = t.run->tree[t.run->entities[lot].shape];
    EXPECT_EQ(s.scope.origin.z, plateau);  // one terrace for the row
    EXPECT_DOUBLE_EQ(t.area(lot), 300.0);
    // The whole footprint lies on the plateau: corners, edge midpoints and centre.
    for (double u : {0.0, 0.5, 1.0}) {
      for (double v : {0.0, 0.5, 1.0}) {
        const kernel::Vec3 p = s.scope.to_world({u * s.scope.size.x, v * s.scope.size.y, 0});
        EXPECT_EQ(p.z, plateau);
        EXPECT_NEAR(kernel::height_at(levelled, p.x, p.y), plateau, 1e-12) << p.x << " " << p.y;
      }
    }
  }
  // Far from lots and road the noise is untouched.
  EXPECT_EQ(kernel::height_at(levelled, 180, 90), kernel::height_at(rough, 180, 90));

  // The masses stand on the plateau, 9 m tall.
  const std::vector<EntityId> masses = t.at("place_mass.out");
  ASSERT_EQ(masses.size(), 5U);
  for (EntityId m : masses) {
    const shape::Shape& s = t.run->tree[t.run->entities[m].shape];
    const kernel::Bounds3 b = shape::mesh_to_world(*s.mesh, s.scope).bounds();
    EXPECT_NEAR(b.min.z, plateau, 1e-9);
    EXPECT_NEAR(b.max.z, plateau + 9, 1e-9);
    EXPECT_NEAR(t.volume(m), 2700, 1e-6);
  }

  // The street gets the height under each vertex; the points sit on the surface.
  const std::vector<EntityId> placed = t.at("place_street.out");
  ASSERT_EQ(placed.size(), 3U);
  const PathGeometry& street = *t.run->entities[placed[0]].path;
  ASSERT_EQ(street.vertices.size(), 4U);
  for (const kernel::Vec3& v : street.vertices) {
    EXPECT_EQ(v.z, kernel::height_at(levelled, v.x, v.y)) << v.x;
  }
  EXPECT_NE(street.vertices[0].z, street.vertices[3].z);
  for (std::size_t i : {1U, 2U}) {
    const kernel::Vec3 p = t.run->entities[placed[i]].position;
    EXPECT_EQ(p.z, kernel::height_at(levelled, p.x, p.y));
  }
}

TEST(Terrain, ReportAndSceneShowTheSurface) {
  const TestRun t = run_text(graph(kTown));
  ASSERT_TRUE(t.ok()) << t.errors;
  const nlohmann::ordered_json report = graph_report(*t.run);
  const nlohmann::ordered_json* terrain = nullptr;
  for (const auto& e : report["entities"]) {
    if (e["port"] == "keep.out") terrain = &e;
  }
  ASSERT_NE(terrain, nullptr);
  EXPECT_EQ((*terrain)["type"], "terrain");
  EXPECT_EQ((*terrain)["cells"], 5000);
  EXPECT_EQ((*terrain)["size"], nlohmann::ordered_json({200.0, 100.0}));
  EXPECT_LT((*terrain)["min_height"].get<double>(), (*terrain)["max_height"].get<double>());
  EXPECT_GE((*terrain)["min_height"].get<double>(), -8.0);

  const shape::Scene scene = to_scene(*t.run);
  std::size_t terrains = 0;
  for (const shape::Building& b : scene.buildings) {
    if (b.id.rfind("terrain_", 0) != 0) continue;
    ++terrains;
    ASSERT_EQ(b.parts.size(), 1U);
    EXPECT_EQ(b.parts[0].name, "terrain");
    EXPECT_EQ(b.parts[0].mesh.face_count(), 10000U);
    EXPECT_EQ(scene.materials[b.parts[0].mesh.tag(0).material].name, "terrain");
  }
  EXPECT_EQ(terrains, 2U);  // keep.out and rough.out
  // The levelled terrain draws its road cells (centres 11..19 inside y 10..20: 5 rows of 100)
  // as road.
  std::size_t road_faces = 0;
  for (const shape::Building& b : scene.buildings) {
    if (b.id != "terrain_" + std::to_string(t.at("keep.out")[0])) continue;
    const kernel::Mesh& mesh = b.parts[0].mesh;
    for (std::size_t f = 0; f < mesh.face_count(); ++f) {
      road_faces += scene.materials[mesh.tag(f).material].name == "road" ? 1 : 0;
    }
  }
  EXPECT_EQ(road_faces, 1000U);
  // 5 lots + 5 masses; paths and points are not drawn.
  EXPECT_EQ(scene.buildings.size(), 12U);
}

TEST(Terrain, NoiseFollowsTheSeedsAndSmoothingFlattens) {
  const auto field = [](const std::string& noise, const std::string& extra = "") {
    const TestRun t = run_text(graph(R"(
      "nodes": [
        { "id": "ground", "type": "terrain.create",
          "params": { "width": 100, "depth": 100, "cell": 4, "origin": [-50, -50, 2] } },
        { "id": "hills", "type": "terrain.noise", "params": )" +
                                     noise + R"( }, )" + extra + R"(
        { "id": "end", "type": "attr.set" } ],
      "edges": [ "ground.out -> hills.in", )" +
                                     (extra.empty() ? std::string("\"hills.out -> end.in\"")
                                                    : std::string("\"hills.out -> soft.in\", "
                                                                  "\"soft.out -> end.in\"")) +
                                     "]"));
    EXPECT_TRUE(t.ok()) << t.errors;
    return *t.run->entities[t.at("end.out").at(0)].terrain;
  };
  const kernel::Heightfield a = field(R"({ "amplitude": 5, "wavelength": 30 })");
  const kernel::Heightfield b = field(R"({ "amplitude": 5, "wavelength": 30 })");
  const kernel::Heightfield c = field(R"({ "amplitude": 5, "wavelength": 30, "seed": 1 })");
  EXPECT_EQ(a.z, b.z);
  EXPECT_NE(a.z, c.z);
  EXPECT_EQ(a.origin.x, -50);
  for (double z : a.z) EXPECT_LE(std::abs(z - 2), 5.0);  // around the created height
  const kernel::Heightfield soft =
      field(R"({ "amplitude": 5, "wavelength": 30 })",
            R"({ "id": "soft", "type": "terrain.smooth", "params": { "iterations": 20 } },)");
  const auto spread = [](const kernel::Heightfield& f) {
    const auto [lo, hi] = std::minmax_element(f.z.begin(), f.z.end());
    return *hi - *lo;
  };
  EXPECT_LT(spread(soft), spread(a) * 0.8);
}

TEST(Terrain, BadInputStopsOrFailsWithAMessage) {
  const TestRun zero = run_text(graph(R"(
    "nodes": [ { "id": "ground", "type": "terrain.create",
                 "params": { "width": 100, "depth": 100, "cell": 0 } } ])"));
  EXPECT_FALSE(zero.ok());
  EXPECT_NE(zero.errors.find("error[G052]: a terrain's cell size must be finite and positive"),
            std::string::npos)
      << zero.errors;
  // A terrain is not placed on a terrain: that entity fails (W040), the point still goes.
  const TestRun self = run_text(graph(R"(
    "nodes": [
      { "id": "ground", "type": "terrain.create", "params": { "width": 10, "depth": 10, "height": 3 } },
      { "id": "p", "type": "create.points", "params": { "points": [[5, 5, 1]] } },
      { "id": "place", "type": "terrain.place" } ],
    "edges": [ "ground.out -> place.in", "p.out -> place.in", "ground.out -> place.terrain" ])"));
  ASSERT_TRUE(self.ok()) << self.errors;
  EXPECT_EQ(self.run->failed.at("place"), 1U);
  EXPECT_NE(
      self.errors.find("terrain.place places shapes, paths, points and lights; not a terrain"),
      std::string::npos)
      << self.errors;
  ASSERT_EQ(self.at("place.out").size(), 1U);
  EXPECT_EQ(self.run->entities[self.at("place.out")[0]].position.z, 3.0);
  // A checker error: a terrain port does not take a shape.
  const TestRun wrong = run_text(graph(R"(
    "nodes": [
      { "id": "lot", "type": "create.rectangle", "params": { "width": 10, "depth": 10 } },
      { "id": "soft", "type": "terrain.smooth" } ],
    "edges": [ "lot.out -> soft.in" ])"));
  EXPECT_FALSE(wrong.ok());
  EXPECT_NE(wrong.errors.find("error[G013]: edge 'lot.out -> soft.in': 'lot.out' carries shape "
                              "entities but 'soft.in' (terrain.smooth) accepts terrain entities"),
            std::string::npos)
      << wrong.errors;
}

TEST(Terrain, TranslateMovesATerrain) {
  const TestRun t = run_text(graph(R"(
    "nodes": [
      { "id": "ground", "type": "terrain.create", "params": { "width": 10, "depth": 10 } },
      { "id": "move", "type": "actor.translate", "params": { "x": 5, "y": -2, "z": 1.5 } } ],
    "edges": [ "ground.out -> move.in" ])"));
  ASSERT_TRUE(t.ok()) << t.errors;
  const kernel::Heightfield& f = *t.run->entities[t.at("move.out").at(0)].terrain;
  EXPECT_EQ(f.origin.x, 5);
  EXPECT_EQ(f.origin.y, -2);
  EXPECT_EQ(f.z.front(), 1.5);
}

}  // namespace
}  // namespace insula::lang::graph::testing
