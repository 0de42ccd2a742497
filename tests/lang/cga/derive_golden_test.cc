// Golden files of the derivation stage: every tests/data/cga/derive/NAME.cga is derived (seed 0;
// lots from NAME.geojson when present, else the default lot) and its dump_derivation() compared
// with NAME.derive (the derivation stage), and the scene's meshes summarised in NAME.mesh (the mesh
// stage: per part its name, face count, surface area and, for closed parts, volume). Regenerate
// with INSULA_UPDATE_GOLDEN=1.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "derive_util.h"
#include "io/geojson_reader.h"
#include "kernel/mesh.h"
#include "lang/cga/derive.h"
#include "test_util.h"

namespace insula::lang::cga {
namespace {

std::vector<Lot> lots_for(const std::filesystem::path& cga, const Program& program) {
  std::filesystem::path geojson = cga;
  geojson.replace_extension(".geojson");
  if (!std::filesystem::exists(geojson)) return {default_lot(program, {})};
  auto set = io::read_geojson(testing::read_file(geojson), geojson.string());
  EXPECT_TRUE(set.ok()) << geojson;
  std::vector<Lot> lots;
  if (!set.ok()) return lots;
  for (io::Footprint& f : set->footprints) {
    lots.push_back({f.id, f.polygons, f.properties.map(), {}});
  }
  return lots;
}

std::string fixed(double v) {
  char text[32];
  const double r = std::round(v * 1e4) / 1e4;
  std::snprintf(text, sizeof text, "%.4f", r == 0 ? 0.0 : r);
  return text;
}

std::string mesh_summary(const shape::Scene& scene) {
  std::string out;
  for (const shape::Building& b : scene.buildings) {
    out += "building " + b.id + " parts " + std::to_string(b.parts.size()) + "\n";
    for (const shape::Part& p : b.parts) {
      out += "  " + p.name + " faces " + std::to_string(p.mesh.face_count()) + " area " +
             fixed(kernel::surface_area(p.mesh));
      if (kernel::is_watertight(p.mesh)) out += " volume " + fixed(kernel::volume(p.mesh));
      out += "\n";
    }
  }
  return out;
}

void compare(const std::filesystem::path& golden, const std::string& text, bool update) {
  if (update) {
    std::ofstream(golden, std::ios::binary) << text;
    return;
  }
  EXPECT_EQ(text, testing::read_file(golden)) << golden;
}

TEST(DeriveGolden, EveryGrammarMatchesItsDump) {
  const auto files = testing::files_in(testing::data_dir() / "derive", ".cga");
  ASSERT_FALSE(files.empty());
  const bool update = std::getenv("INSULA_UPDATE_GOLDEN") != nullptr;
  for (const auto& path : files) {
    SCOPED_TRACE(path.string());
    auto program = testing::compile_text(testing::read_file(path), {}, path.filename().string());
    ASSERT_TRUE(program);
    const std::vector<LotResult> results = testing::derive_all(*program, lots_for(path, *program));
    for (const LotResult& r : results) EXPECT_TRUE(r.ok) << testing::diagnostics_text(r);
    const std::string dump = dump_derivation(*program, results);
    std::filesystem::path golden = path;
    compare(golden.replace_extension(".derive"), dump, update);
    const shape::Scene scene = to_scene(*program, lots_for(path, *program), results);
    compare(golden.replace_extension(".mesh"), mesh_summary(scene), update);
  }
}

}  // namespace
}  // namespace insula::lang::cga
