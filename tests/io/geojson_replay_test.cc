// Replays the fuzz corpus (fuzz/corpus/geojson) and the bad-input catalog (tests/data/bad)
// through the fuzz target's contract check, plus deterministic mutations of each file (every
// truncation point on a grid, single-byte substitutions): a GCC build's stand-in for libFuzzer,
// so every ctest run checks "no crash, no hang, an error or a usable result" on a few thousand
// inputs.
#define INSULA_FUZZ_NO_ENTRY
#include "../../fuzz/geojson_fuzz.cc"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "../common/test_util.h"

namespace {

using insula::test::read_file;

std::vector<std::filesystem::path> replay_files() {
  return insula::test::corpus_files(
      {INSULA_SOURCE_DIR "/fuzz/corpus/geojson", INSULA_TEST_DATA "/bad"}, /*recursive=*/false,
      [](const std::filesystem::path& path) { return path.extension() == ".geojson"; });
}

TEST(GeoJsonReplay, CorpusAndCatalogKeepTheContract) {
  const std::vector<std::filesystem::path> files = replay_files();
  ASSERT_GE(files.size(), 40u);  // 9 corpus seeds and the catalog
  for (const auto& file : files) {
    EXPECT_EQ(insula::fuzz::check_geojson(read_file(file)), "") << file;
  }
}

TEST(GeoJsonReplay, TruncationsKeepTheContract) {
  for (const auto& file : replay_files()) {
    const std::string text = read_file(file);
    const std::size_t step = std::max<std::size_t>(1, text.size() / 48);
    for (std::size_t n = 0; n < text.size(); n += step) {
      ASSERT_EQ(insula::fuzz::check_geojson(std::string_view(text).substr(0, n)), "")
          << file << " cut at " << n;
    }
  }
}

TEST(GeoJsonReplay, ByteSubstitutionsKeepTheContract) {
  // Bytes that change JSON structure or numbers: the mutations most likely to reach new paths.
  const std::string interesting = "[]{}\",:-+.eE019 \nnNtI\\";
  std::mt19937 rng(20240601);  // fixed: a failure reproduces
  for (const auto& file : replay_files()) {
    const std::string text = read_file(file);
    if (text.empty() || text.size() > 20000) continue;
    for (int round = 0; round < 64; ++round) {
      std::string mutated = text;
      const std::size_t at = rng() % mutated.size();
      mutated[at] = interesting[rng() % interesting.size()];
      ASSERT_EQ(insula::fuzz::check_geojson(mutated), "")
          << file << " byte " << at << " -> " << mutated[at];
    }
  }
}

}  // namespace
