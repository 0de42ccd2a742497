// The geometry bindings of the Lua front-end (bind_geometry*.cc) on small programs with exact
// counts, sizes and volumes, their errors with file:line, the examples' goldens and glTF
// instancing of placed furniture.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "io/gltf_writer.h"
#include "io/obj_reader.h"
#include "lang/lua/runtime.h"
#include "shape/collect.h"
#include "shape/component_ops.h"
#include "shape/query.h"

namespace insula::lua {
namespace {

using shape::ShapeId;

std::string read(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The example assets, read with io's OBJ reader.
class Assets : public shape::AssetProvider {
 public:
  std::shared_ptr<const kernel::Mesh> find(std::string_view name,
                                           std::string& error) const override {
    if (auto it = cache_.find(name); it != cache_.end()) return it->second;
    const std::filesystem::path path = std::filesystem::path(INSULA_SOURCE_DIR) /
                                       "examples/lua/assets" / (std::string(name) + ".obj");
    if (!std::filesystem::exists(path)) {
      error = "asset '" + std::string(name) + "' not found";
      return nullptr;
    }
    auto mesh = io::read_obj(read(path), path.filename().string());
    if (!mesh) return nullptr;
    auto shared = std::make_shared<const kernel::Mesh>(std::move(mesh.value()));
    cache_.emplace(std::string(name), shared);
    return shared;
  }

 private:
  mutable std::map<std::string, std::shared_ptr<const kernel::Mesh>, std::less<>> cache_;
};

struct Outcome {
  std::unique_ptr<Runtime> runtime;
  std::vector<base::Diagnostic> diagnostics;
  const shape::ShapeTree& tree() const { return runtime->tree(); }
  std::vector<ShapeId> labelled(std::string_view label) const {
    std::vector<ShapeId> out;
    for (ShapeId id = 0; id < tree().size(); ++id) {
      if (tree().has_label(id, label)) out.push_back(id);
    }
    return out;
  }
};

const Assets& assets() {
  static const Assets kAssets;
  return kAssets;
}

Outcome run_program(const std::string& text, const std::string& name = "test.lua") {
  RunOptions options;
  options.assets = &assets();
  Outcome r;
  r.runtime = std::make_unique<Runtime>(options);
  r.diagnostics = r.runtime->run(base::Source(name, text));
  return r;
}

double world_volume(const shape::ShapeTree& tree, ShapeId id) {
  return kernel::volume(shape::mesh_to_world(*tree[id].mesh, tree[id].scope));
}

std::vector<double> sizes_x(const Outcome& r, std::string_view label) {
  std::vector<double> out;
  for (ShapeId id : r.labelled(label)) out.push_back(r.tree()[id].scope.size.x);
  return out;
}

TEST(LuaGeometry, SlicePolicies) {
  const Outcome r = run_program(R"(
    local b = component { size = { 10, 3, 6 } }
    slice(b, "x", 3, { leftover = "first", label = "first" })
    slice(b, "x", 3, { leftover = "last", label = "last" })
    slice(b, "x", 3, { leftover = "both", label = "both" })
    slice(b, "x", 3, { leftover = "spread", label = "spread" })
  )");
  ASSERT_TRUE(r.diagnostics.empty()) << r.diagnostics[0].message;
  EXPECT_EQ(sizes_x(r, "first"), (std::vector<double>{4, 3, 3}));
  EXPECT_EQ(sizes_x(r, "last"), (std::vector<double>{3, 3, 4}));
  EXPECT_EQ(sizes_x(r, "both"), (std::vector<double>{3.5, 3, 3.5}));
  for (double s : sizes_x(r, "spread")) EXPECT_NEAR(s, 10.0 / 3, 1e-12);
}

TEST(LuaGeometry, SnapAndRepelMoveBoundariesExactly) {
  const Outcome r = run_program(R"(
    local b = component { size = { 12, 3, 6 } }
    local pillar = component { size = { 0.4, 3, 0.4 }, position = { 4.3, 0, 2 } }
    slice(b, "x", 4, { constraints = snap(pillar, 0.5), label = "snapped" })
    constrainedSplit(b, "x", repel(pillar, 0.2), { abs = 4.6, label = "repelled" }, { rel = 1, label = "rest" })
  )");
  ASSERT_TRUE(r.diagnostics.empty()) << r.diagnostics[0].message;
  // The pillar covers [4.3, 4.7]: the boundary at 4 snaps onto 4.3; the one at 8 stays.
  const auto snapped = sizes_x(r, "snapped");
  ASSERT_EQ(snapped.size(), 3U);
  EXPECT_NEAR(snapped[0], 4.3, 1e-12);
  EXPECT_NEAR(snapped[2], 4, 1e-12);
  // 4.6 lies in [4.1, 4.9] (pillar plus 0.2 m): pushed to 4.9, the nearer end.
  const auto repelled = sizes_x(r, "repelled");
  ASSERT_EQ(repelled.size(), 1U);
  EXPECT_NEAR(repelled[0], 4.9, 1e-12);
}

TEST(LuaGeometry, BooleansPlaceResultsAsThePaperSays) {
  const Outcome r = run_program(R"(
    local apt = component { size = { 5, 2.5, 4 }, label = "apartment" }
    local shaft = component { size = { 2, 6, 1 }, position = { 4, -1, 2 }, label = "elevator" }
    subtract(apt, query("elevator"), { label = "room" })
    local a = component { size = { 4, 3, 4 }, label = "a" }
    local b = component { size = { 4, 3, 4 }, position = { 2, 0, 2 }, label = "b" }
    union({ a, b }, { label = "merged" })
    intersection({ a, b }, { label = "common" })
  )");
  ASSERT_TRUE(r.diagnostics.empty()) << r.diagnostics[0].message;
  const auto room = r.labelled("room");
  ASSERT_EQ(room.size(), 1U);
  EXPECT_EQ(r.tree()[r.tree().parent(room[0])].labels.size(), 1U);
  EXPECT_TRUE(r.tree().has_label(r.tree().parent(room[0]), "apartment"));
  EXPECT_NEAR(world_volume(r.tree(), room[0]), 50 - 2.5, 1e-9);
  const auto merged = r.labelled("merged");
  ASSERT_EQ(merged.size(), 1U);
  EXPECT_EQ(r.tree().parent(merged[0]), shape::kNoShape);  // a root (§3.4.3)
  EXPECT_NEAR(world_volume(r.tree(), merged[0]), 3 * 28, 1e-9);
  EXPECT_NEAR(world_volume(r.tree(), r.labelled("common").at(0)), 12, 1e-9);
}

TEST(LuaGeometry, Figure3WallsDoorsAndSolids) {
  // Seed 001 Fig. 3, transcribed: floor, corridors, apartments, elevator, walls, doors.
  const Outcome r = run_program(R"(
    component { size = { 10, 2.5, 10 }, label = "floor" }
    for c in query("floor") do
      split(c, "z", { label = "living space", rel = 1 }, { label = "corridor", abs = 2 },
        { label = "corridor", abs = 2 }, { label = "living space", rel = 1 })
    end
    for c in query("'living space'") do
      split(c, "x", { label = "apartment", rel = 1 }, { label = "apartment", rel = 1 })
    end
    component { size = { 2, 2.5, 2 }, position = { 4, 0, 2 }, label = "elevator" }
    for c in query("apartment or corridor") do
      subtract(c, query("elevator"), { label = "room" })
    end
    local i = 0
    for c in query("room") do
      local faces = {}
      for _, f in ipairs(fquery(c, "SIDE or BOTTOM")) do
        faces[#faces + 1] = component(c, { boundary = f, label = "wall" })
      end
      extrude(faces, -0.05, { label = "iwall", color = i })
      i = i + 1
    end
    for c in query("wall and not parent(corridor) and occlusion(corridor) > 0") do
      local r = region(c, { label = "door", min = { 0.5, 0, 0 }, max = { c.size[1] - 1.5, 0, 0 } })
      door(r)
    end
    for c in query("iwall") do solidGeometry(c, c.color) end
  )");
  ASSERT_TRUE(r.diagnostics.empty()) << r.diagnostics[0].message;
  EXPECT_EQ(r.labelled("room").size(), 6U);
  // Each apartment touches one corridor with one wall: four doors.
  EXPECT_EQ(r.labelled("door").size(), 4U);
  const auto solids = r.labelled("solid");
  EXPECT_EQ(solids.size(), r.labelled("iwall").size());
  std::size_t jambs = 0;
  for (ShapeId s : solids) {
    const kernel::Mesh& m = *r.tree()[s].mesh;
    for (std::size_t f = 0; f < m.face_count(); ++f) {
      jambs += m.tag(f).semantic == kernel::SemanticClass::kJamb ? 1 : 0;
    }
  }
  // Each door (kept 1.5 m from the elevator's corner) cuts the apartment's wall and the
  // corridor's wall behind it: 8 cuts of two jambs each (the long wall of the second corridor
  // carries two of them).
  EXPECT_EQ(jambs, 16U);
}

TEST(LuaGeometry, PlaceSharesMeshesAndGltfInstancesThem) {
  const Outcome r = run_program(R"(
    local room = component { size = { 6, 3, 6 }, label = "room" }
    local r = region(room, { label = "floor", min = { 1, 0, 1 }, max = { 5, 0, 5 } })
    for k = 1, 4 do place(r, "chair", { label = "chair" }) end
    local none = place(region(room, { label = "tiny", min = { 0, 0, 0 }, max = { 0, 0, 0 } }),
      "chair", { avoid = query("room"), attempts = 3 })
    assert(none == nil)
  )");
  ASSERT_TRUE(r.diagnostics.empty()) << r.diagnostics[0].message;
  const auto chairs = r.labelled("chair");
  ASSERT_EQ(chairs.size(), 4U);
  for (ShapeId c : chairs) EXPECT_EQ(r.tree()[c].mesh, r.tree()[chairs[0]].mesh);
  shape::CollectOptions options;
  options.labels = {"chair"};
  options.instances = true;
  const shape::Scene scene = shape::collect(r.tree(), options);
  const auto json = nlohmann::json::parse(io::gltf_text(scene));
  EXPECT_EQ(json["meshes"].size(), 1U);  // one shared mesh
  int placed = 0;
  for (const auto& node : json["nodes"]) {
    if (node.contains("matrix")) {
      ++placed;
      EXPECT_EQ(node["mesh"], 0);
      EXPECT_EQ(node["matrix"][15], 1.0);
    }
  }
  EXPECT_EQ(placed, 4);
}

TEST(LuaGeometry, ErrorsNameTheOperationAndLine) {
  const Outcome bad = run_program(
      "local b = component { size = { 10, 3, 6 } }\nslice(b, 'x', 3, { leftover = 'middle' })\n",
      "bad.lua");
  ASSERT_EQ(bad.diagnostics.size(), 1U);
  EXPECT_EQ(bad.diagnostics[0].span.line, 2U);
  EXPECT_NE(bad.diagnostics[0].message.find("in slice: argument 4: field 'leftover' must be one of "
                                            "first, last, both, spread; got 'middle'"),
            std::string::npos)
      << bad.diagnostics[0].message;
  const Outcome flat =
      run_program("local b = component { size = { 1, 1, 1 } }\nextrude({ b }, -0.1)\n");
  ASSERT_EQ(flat.diagnostics.size(), 1U);
  EXPECT_NE(flat.diagnostics[0].message.find("in extrude: component 0 is not flat"),
            std::string::npos)
      << flat.diagnostics[0].message;
  const Outcome outside = run_program(
      "local b = component { size = { 1, 1, 1 } }\ninstance(b, { position = { 5, 0, 0 }, size "
      "= { 1, 1, 1 } })\n");
  ASSERT_EQ(outside.diagnostics.size(), 1U);
  EXPECT_NE(
      outside.diagnostics[0].message.find("in instance: the component lies outside its parent"),
      std::string::npos);
}

// Hostile arguments stop with a message instead of exhausting memory or time.
TEST(LuaGeometry, HostileArgumentsAreBounded) {
  const struct {
    const char* program;
    const char* message;
  } cases[] = {
      {"slice(component { size = { 10, 3, 6 } }, 'x', 1e-9)", "in slice: more than 1000000 pieces"},
      {"slice(component { size = { 10, 3, 6 } }, 'x', 0/0)",
       "in slice: argument 3: expected a finite number"},
      {"local c = component { size = { 2, 2, 2 } }\nplace(region(c, { label = 'f' }), c, { "
       "attempts = 1e9 })",
       "in place: argument 3: field 'attempts' must be in [1, 10000]"},
      {"door(component { size = { 2, 2, 2 } })",
       "in door: the wall must be a flat component (a face)"},
      {"extrude({ component { size = { 2, 2, 2 } } }, 0/0)",
       "in extrude: argument 2: expected a finite number"},
      {"slice(component { size = { 10, 3, 6 } }, 'x', -1)", "in slice: size must be > 0"},
      {"subtract(component { size = { 2, 2, 2 } }, 'x')", "in subtract: argument 2:"},
  };
  for (const auto& c : cases) {
    const Outcome r = run_program(c.program, "hostile.lua");
    ASSERT_EQ(r.diagnostics.size(), 1U) << c.program;
    EXPECT_NE(r.diagnostics[0].message.find(c.message), std::string::npos)
        << c.program << " -> " << r.diagnostics[0].message;
  }
}

// Goldens of the examples: components, collected parts and triangles (INSULA_UPDATE_GOLDEN=1
// rewrites tests/data/lua/geometry/examples.json).
TEST(LuaGeometry, ExampleGoldens) {
  nlohmann::json counts;
  for (const char* name : {"hotel", "loft_office", "apartment_building"}) {
    const std::filesystem::path path =
        std::filesystem::path(INSULA_SOURCE_DIR) / "examples/lua" / (std::string(name) + ".lua");
    const Outcome r = run_program(read(path), path.string());
    ASSERT_TRUE(r.diagnostics.empty()) << name << ": " << r.diagnostics[0].message;
    const shape::Scene scene = collect_program(r.runtime->program());
    std::size_t parts = 0;
    std::size_t triangles = 0;
    for (const auto& b : scene.buildings) {
      for (const auto& p : b.parts) {
        ++parts;
        triangles += p.instance_of ? p.instance_of->triangle_count() : p.mesh.triangle_count();
      }
    }
    // Every (opening, wall it pierces) pair, and the openings actually cut (the solids'
    // "openings_cut").
    std::vector<ShapeId> openings = r.labelled("opening");
    std::size_t pairs = 0;
    std::size_t cuts = 0;
    for (ShapeId solid : r.labelled("solid")) {
      const ShapeId wall = r.tree().parent(solid);
      for (ShapeId o : openings) pairs += shape::opening_in_wall(r.tree(), wall, o) ? 1 : 0;
      if (const shape::Value* v = r.tree().attribute(solid, "openings_cut")) {
        cuts += static_cast<std::size_t>(std::get<double>(*v));
      }
    }
    counts[name] = {
        {"components", r.tree().size()},         {"cuts", cuts},   {"pierced_walls", pairs},
        {"doors", r.labelled("door").size()},    {"parts", parts}, {"triangles", triangles},
        {"windows", r.labelled("window").size()}};
  }
  const std::filesystem::path golden =
      std::filesystem::path(INSULA_TEST_DATA) / "lua/geometry/examples.json";
  if (std::getenv("INSULA_UPDATE_GOLDEN") != nullptr) {
    std::ofstream(golden) << counts.dump(2) << "\n";
  }
  EXPECT_EQ(counts, nlohmann::json::parse(read(golden)));
  EXPECT_GE(counts["apartment_building"]["triangles"].get<std::size_t>(), 500000U);
  // Every door and window is cut through every wall it pierces.
  for (const char* name : {"hotel", "loft_office", "apartment_building"}) {
    EXPECT_EQ(counts[name]["cuts"], counts[name]["pierced_walls"]) << name;
  }
}

}  // namespace
}  // namespace insula::lua
