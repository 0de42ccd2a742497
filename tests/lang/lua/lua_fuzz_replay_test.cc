// Replays the Lua fuzz corpus (fuzz/corpus/lua, examples/lua) and the bad-input catalog
// (tests/data/lua/bad) through the fuzz target's contract check (fuzz/lua_fuzz.cc), plus
// truncations of each example: the GCC build's stand-in for libFuzzer. A truncated example is
// mostly a syntax error, sometimes a shorter program that runs.
#define INSULA_FUZZ_NO_ENTRY
#include "../../../fuzz/lua_fuzz.cc"

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
      {INSULA_SOURCE_DIR "/fuzz/corpus/lua", INSULA_SOURCE_DIR "/examples/lua",
       INSULA_TEST_DATA "/lua/bad"},
      /*recursive=*/false,
      [](const std::filesystem::path& path) { return path.extension() == ".lua"; });
}

TEST(LuaFuzzReplay, CorpusAndCatalogKeepTheContract) {
  const std::vector<std::filesystem::path> files = replay_files();
  ASSERT_GE(files.size(), 25u);
  for (const auto& file : files) EXPECT_EQ(insula::fuzz::check_lua(read_file(file)), "") << file;
}

TEST(LuaFuzzReplay, TruncationsKeepTheContract) {
  for (const auto& file : insula::test::files_in(INSULA_SOURCE_DIR "/examples/lua", ".lua")) {
    const std::string text = read_file(file);
    const std::size_t step = std::max<std::size_t>(1, text.size() / 16);
    for (std::size_t n = 0; n < text.size(); n += step) {
      ASSERT_EQ(insula::fuzz::check_lua(std::string_view(text).substr(0, n)), "")
          << file << " cut at " << n;
    }
  }
}

}  // namespace
