// Golden files of the derivation stage: every tests/data/cga/derive/NAME.cga is derived (seed 0;
// lots from NAME.geojson when present, else the default lot) and its dump_derivation() compared
// with NAME.derive. Regenerate with INSULA_UPDATE_GOLDEN=1.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "derive_util.h"
#include "io/geojson_reader.h"
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
    lots.push_back({f.id, f.polygons, f.properties});
  }
  return lots;
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
    golden.replace_extension(".derive");
    if (update) {
      std::ofstream(golden, std::ios::binary) << dump;
      continue;
    }
    EXPECT_EQ(dump, testing::read_file(golden));
  }
}

}  // namespace
}  // namespace insula::lang::cga
