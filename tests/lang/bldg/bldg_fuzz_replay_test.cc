// Replays the fuzz contract (fuzz/bldg_fuzz.cc) over the fuzz corpus, the good grammars, the bad
// catalog, every truncation of each, byte mutations and pathological inputs: each input must keep
// the contract (no crash, errors positioned, printed grammars canonical).
#include <gtest/gtest.h>

#include <cstdint>

#define INSULA_FUZZ_NO_ENTRY
#include "../../../fuzz/bldg_fuzz.cc"
#include "test_util.h"

namespace insula::lang::bldg {
namespace {

using testing::files_in;
using testing::read_file;

std::vector<std::string> corpus() {
  std::vector<std::string> out;
  const std::filesystem::path fuzz_corpus =
      std::filesystem::path(INSULA_SOURCE_DIR) / "fuzz" / "corpus" / "bldg";
  for (const auto& dir : {testing::data_dir(), testing::data_dir() / "bad", fuzz_corpus}) {
    for (const char* ext : {".bldg", ".rules"}) {
      for (const auto& path : files_in(dir, ext)) out.push_back(read_file(path));
    }
  }
  return out;
}

TEST(BldgFuzzReplay, CorpusIsNotEmpty) {
  EXPECT_GE(corpus().size(), 50U);
}

TEST(BldgFuzzReplay, EveryTruncationKeepsTheContract) {
  for (const std::string& text : corpus()) {
    const std::size_t step = text.size() > 2000 ? 7 : 1;
    for (std::size_t length = 0; length <= text.size(); length += step) {
      const std::string problem = fuzz::check_bldg(text.substr(0, length));
      ASSERT_EQ(problem, "") << text.substr(0, length);
    }
  }
}

TEST(BldgFuzzReplay, ByteMutationsKeepTheContract) {
  const std::string replacements = std::string("{}[](),:;=.-\"#/*\n0aZ\xC3\xFF") + '\0';
  std::uint64_t state = 0x9E3779B97F4A7C15ULL;  // fixed seed: the test is deterministic
  for (const std::string& text : corpus()) {
    if (text.empty()) continue;
    for (int round = 0; round < 150; ++round) {
      std::string mutated = text;
      for (int k = 0; k < 3; ++k) {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        const std::size_t at = (state >> 33) % mutated.size();
        mutated[at] = replacements[(state >> 17) % replacements.size()];
      }
      const std::string problem = fuzz::check_bldg(mutated);
      ASSERT_EQ(problem, "") << mutated;
    }
  }
}

TEST(BldgFuzzReplay, PathologicalInputsStayBounded) {
  for (const std::string& text :
       {std::string(100000, '('), std::string(100000, '{'), std::string(50000, '-'),
        "a -> b(" + std::string(20000, '['),
        "a -> geojson(" +
            [] {
              std::string s;
              for (int i = 0; i < 5000; ++i) s += "g(";
              return s;
            }(),
        std::string(2000, '\xFF'), std::string("a -> b() : {") + std::string(100000, 'c'),
        [] {
          std::string s;
          for (int i = 0; i < 3000; ++i) {
            s += 'x';  // appended: GCC 12 -O3 reports a false -Wrestrict on "x" + std::string
            s += std::to_string(i);
            s += " -> room(a, small)\n";
          }
          return s;
        }()}) {
    EXPECT_EQ(fuzz::check_bldg(text), "");
  }
}

}  // namespace
}  // namespace insula::lang::bldg
