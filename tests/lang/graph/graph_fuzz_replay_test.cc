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

#include "../../common/fuzz_replay.h"
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
  std::size_t inputs = 0;
  EXPECT_EQ(insula::test::replay_variants(replay_files(), insula::fuzz::check_graph, replacements,
                                          inputs),
            "");
  EXPECT_GT(inputs, 3000U);
}

}  // namespace
