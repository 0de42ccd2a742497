// The GCC build's stand-in for libFuzzer, shared by the front-ends' *_fuzz_replay_test.cc: a fuzz
// target's contract (a function that returns "" when an input keeps it, else what broke) replayed
// over deterministic truncations and byte mutations of corpus files.
#pragma once

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "test_util.h"

namespace insula::test {

// Every file cut at about 40 lengths, then 60 times with two bytes replaced by characters of
// `replacements` (a fixed-seed generator: the same inputs every run). Returns the first broken
// contract ("FILE cut N: ..." or "FILE mutation R: ..."), or "" when all keep it; `inputs` counts
// the inputs tried.
inline std::string replay_variants(const std::vector<std::filesystem::path>& files,
                                   const std::function<std::string(const std::string&)>& check,
                                   const std::string& replacements, std::size_t& inputs) {
  std::uint64_t state = 0x2545F4914F6CDD1DULL;
  inputs = 0;
  for (const auto& file : files) {
    const std::string text = read_file(file);
    if (text.empty()) continue;
    const std::size_t step = std::max<std::size_t>(1, text.size() / 40);
    for (std::size_t length = 0; length < text.size(); length += step, ++inputs) {
      const std::string broken = check(text.substr(0, length));
      if (!broken.empty()) return file.string() + " cut " + std::to_string(length) + ": " + broken;
    }
    for (int round = 0; round < 60; ++round, ++inputs) {
      std::string mutated = text;
      for (int k = 0; k < 2; ++k) {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        const std::size_t at = (state >> 33) % mutated.size();
        mutated[at] = replacements[(state >> 17) % replacements.size()];
      }
      const std::string broken = check(mutated);
      if (!broken.empty())
        return file.string() + " mutation " + std::to_string(round) + ": " + broken;
    }
  }
  return {};
}

}  // namespace insula::test
