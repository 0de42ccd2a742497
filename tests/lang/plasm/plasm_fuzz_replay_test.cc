// Replays the PLaSM fuzz target's contract (fuzz/plasm_fuzz.cc) over the examples, the test
// programs and the bad-input catalog, plus deterministic truncations and byte mutations of each:
// the GCC build's stand-in for libFuzzer.
#define INSULA_FUZZ_NO_ENTRY
#include "../../../fuzz/plasm_fuzz.cc"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "../../common/fuzz_replay.h"
#include "../../common/test_util.h"

namespace {

using insula::test::read_file;

std::vector<std::filesystem::path> replay_files() {
  return insula::test::corpus_files(
      {INSULA_TEST_DATA "/plasm", INSULA_SOURCE_DIR "/examples/plasm"}, /*recursive=*/true,
      [](const std::filesystem::path& path) { return path.extension() == ".psm"; });
}

TEST(PlasmFuzzReplay, CorpusKeepsTheContract) {
  const std::vector<std::filesystem::path> files = replay_files();
  ASSERT_GE(files.size(), 40U);
  for (const auto& file : files) EXPECT_EQ(insula::fuzz::check_plasm(read_file(file)), "") << file;
}

TEST(PlasmFuzzReplay, TruncationsAndMutationsKeepTheContract) {
  const std::string replacements = std::string("()[]<>:~,;=%\"#-*/+.\xCE\xB5\xFF") + '\0';
  std::size_t inputs = 0;
  EXPECT_EQ(insula::test::replay_variants(replay_files(), insula::fuzz::check_plasm, replacements,
                                          inputs),
            "");
  EXPECT_GT(inputs, 3000U);
}

}  // namespace
