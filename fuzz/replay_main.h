// The replay main() of the fuzz targets for builds without libFuzzer (GCC): fuzz/<name>.cc
// defines LLVMFuzzerTestOneInput and, under INSULA_FUZZ_REPLAY, includes this header, which feeds
// it every file named on the command line and every file of every folder named there. A contract
// violation aborts inside LLVMFuzzerTestOneInput, as under libFuzzer.
//
// Before including, a target defines INSULA_FUZZ_REPLAY_NAME (the name printed in the summary)
// and may define INSULA_FUZZ_REPLAY_RECURSIVE to walk subfolders too (the CGA corpus nests its
// XML inputs).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#ifndef INSULA_FUZZ_REPLAY_NAME
#error "define INSULA_FUZZ_REPLAY_NAME before including fuzz/replay_main.h"
#endif

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace insula::fuzz {

// The files named by `argv`, folders expanded to their regular files.
inline std::vector<std::filesystem::path> replay_inputs(int argc, char** argv, bool recursive) {
  std::vector<std::filesystem::path> files;
  const auto visit = [&files](const std::filesystem::directory_entry& entry) {
    if (entry.is_regular_file()) files.push_back(entry.path());
  };
  for (int i = 1; i < argc; ++i) {
    if (!std::filesystem::is_directory(argv[i])) {
      files.emplace_back(argv[i]);
    } else if (recursive) {
      for (const auto& entry : std::filesystem::recursive_directory_iterator(argv[i])) visit(entry);
    } else {
      for (const auto& entry : std::filesystem::directory_iterator(argv[i])) visit(entry);
    }
  }
  return files;
}

}  // namespace insula::fuzz

int main(int argc, char** argv) {
#ifdef INSULA_FUZZ_REPLAY_RECURSIVE
  constexpr bool kRecursive = true;
#else
  constexpr bool kRecursive = false;
#endif
  const std::vector<std::filesystem::path> files =
      insula::fuzz::replay_inputs(argc, argv, kRecursive);
  for (const std::filesystem::path& file : files) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream bytes;
    bytes << in.rdbuf();
    const std::string text = bytes.str();
    LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
  }
  std::printf(INSULA_FUZZ_REPLAY_NAME ": %zu inputs, no contract violation\n", files.size());
  return 0;
}
