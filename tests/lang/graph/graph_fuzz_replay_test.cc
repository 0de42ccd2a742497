// Replays the graph fuzz target's contract (fuzz/graph_fuzz.cc) over the examples, the test
// graphs and the bad-input catalog, plus deterministic truncations and byte mutations of each:
// the GCC build's stand-in for libFuzzer.
#define INSULA_FUZZ_NO_ENTRY
#include "../../../fuzz/graph_fuzz.cc"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "../../common/test_util.h"

namespace {

using insula::test::read_file;

std::vector<std::filesystem::path> replay_files() {
  return insula::test::corpus_files(
      {INSULA_TEST_DATA "/graph", INSULA_SOURCE_DIR "/examples/graph"}, /*recursive=*/true,
      [](const std::filesystem::path& path) { return path.extension() == ".json"; });
}

TEST(GraphFuzzReplay, CorpusKeepsTheContract) {
  const std::vector<std::filesystem::path> files = replay_files();
  ASSERT_GE(files.size(), 40U);
  for (const auto& file : files) EXPECT_EQ(insula::fuzz::check_graph(read_file(file)), "") << file;
}

TEST(GraphFuzzReplay, TruncationsAndMutationsKeepTheContract) {
  const std::string replacements = std::string("{}[]:,\"\\.->#=@ 0aT\xC3\xA9\xFF") + '\0';
  std::uint64_t state = 0x2545F4914F6CDD1DULL;  // fixed seed: deterministic
  std::size_t inputs = 0;
  for (const auto& file : replay_files()) {
    const std::string text = read_file(file);
    if (text.empty()) continue;
    const std::size_t step = std::max<std::size_t>(1, text.size() / 40);
    for (std::size_t length = 0; length < text.size(); length += step) {
      ASSERT_EQ(insula::fuzz::check_graph(text.substr(0, length)), "") << file << " cut " << length;
      ++inputs;
    }
    for (int round = 0; round < 60; ++round) {
      std::string mutated = text;
      for (int k = 0; k < 2; ++k) {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        const std::size_t at = (state >> 33) % mutated.size();
        mutated[at] = replacements[(state >> 17) % replacements.size()];
      }
      ASSERT_EQ(insula::fuzz::check_graph(mutated), "") << file << " mutation " << round;
      ++inputs;
    }
  }
  EXPECT_GT(inputs, 3000U);
}

}  // namespace
