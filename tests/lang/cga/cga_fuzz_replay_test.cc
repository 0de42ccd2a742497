// Replays the CGA fuzz target's contract (fuzz/cga_fuzz.cc) over every grammar and XML file under
// tests/data/cga (goldens, bad-input catalogs, transform data) and fuzz/corpus/cga, plus
// deterministic truncations and byte mutations of each: the GCC build's stand-in for libFuzzer.
#define INSULA_FUZZ_NO_ENTRY
#include "../../../fuzz/cga_fuzz.cc"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "../../common/fuzz_replay.h"
#include "../../common/test_util.h"

namespace {

using insula::test::read_file;

// Every file of the fuzz corpus, and the grammars and XML files of the test data.
std::vector<std::filesystem::path> replay_files() {
  return insula::test::corpus_files({INSULA_TEST_DATA "/cga", INSULA_SOURCE_DIR "/fuzz/corpus/cga"},
                                    /*recursive=*/true, [](const std::filesystem::path& path) {
                                      const std::string extension = path.extension().string();
                                      const bool corpus =
                                          path.string().find("/fuzz/corpus/") != std::string::npos;
                                      return corpus || extension == ".cga" || extension == ".xml";
                                    });
}

TEST(CgaFuzzReplay, CorpusKeepsTheContract) {
  const std::vector<std::filesystem::path> files = replay_files();
  ASSERT_GE(files.size(), 40U);
  for (const auto& file : files) {
    EXPECT_EQ(insula::fuzz::check_cga(read_file(file)), "") << file;
  }
}

TEST(CgaFuzzReplay, TruncationsAndMutationsKeepTheContract) {
  const std::string replacements = std::string("{}[]()|:;,\"~>-'*/#<>=&\xCE\xB5\xFF") + '\0';
  std::size_t inputs = 0;
  EXPECT_EQ(
      insula::test::replay_variants(replay_files(), insula::fuzz::check_cga, replacements, inputs),
      "");
  EXPECT_GT(inputs, 3000U);
}

}  // namespace
