// Replays the OBJ fuzz corpus (fuzz/corpus/obj, examples/lua/assets, tests/data/assets) through the
// fuzz target's contract check (fuzz/obj_fuzz.cc), plus every truncation point on a grid and seeded
// single-byte substitutions: the GCC build's stand-in for libFuzzer.
#define INSULA_FUZZ_NO_ENTRY
#include "../../fuzz/obj_fuzz.cc"

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
      {INSULA_SOURCE_DIR "/fuzz/corpus/obj", INSULA_SOURCE_DIR "/examples/lua/assets",
       INSULA_TEST_DATA "/assets"},
      /*recursive=*/false,
      [](const std::filesystem::path& path) { return path.extension() == ".obj"; });
}

TEST(ObjReplay, CorpusKeepsTheContract) {
  const std::vector<std::filesystem::path> files = replay_files();
  ASSERT_GE(files.size(), 12u);
  for (const auto& file : files) EXPECT_EQ(insula::fuzz::check_obj(read_file(file)), "") << file;
}

TEST(ObjReplay, TruncationsAndSubstitutionsKeepTheContract) {
  const std::string interesting = "vf/-+.eE019 \n#gou\t";
  std::mt19937 rng(20261125);  // fixed: a failure reproduces
  for (const auto& file : replay_files()) {
    const std::string text = read_file(file);
    const std::size_t step = std::max<std::size_t>(1, text.size() / 48);
    for (std::size_t n = 0; n < text.size(); n += step) {
      ASSERT_EQ(insula::fuzz::check_obj(std::string_view(text).substr(0, n)), "")
          << file << " cut at " << n;
    }
    for (int round = 0; round < 64 && !text.empty(); ++round) {
      std::string mutated = text;
      const std::size_t at = rng() % mutated.size();
      mutated[at] = interesting[rng() % interesting.size()];
      ASSERT_EQ(insula::fuzz::check_obj(mutated), "") << file << " byte " << at;
    }
  }
}

}  // namespace
