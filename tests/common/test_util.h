// Helpers shared by the tests of every layer and front-end: reading files, listing data folders,
// comparing with golden files. Front-end specific helpers (parse_ok, first_error, data_dir) stay
// in tests/lang/<front-end>/test_util.h, which re-export these.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace insula::test {

// The bytes of `path`; empty when it cannot be read.
inline std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

// Files with `extension` directly in `dir`, sorted by name.
inline std::vector<std::filesystem::path> files_in(const std::filesystem::path& dir,
                                                   const std::string& extension) {
  std::vector<std::filesystem::path> out;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.is_regular_file() && entry.path().extension() == extension) {
      out.push_back(entry.path());
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Regular files of `folders` (and of their subfolders when `recursive`) that `keep` accepts,
// sorted: the corpus walker of the fuzz replay tests.
inline std::vector<std::filesystem::path> corpus_files(
    const std::vector<std::filesystem::path>& folders, bool recursive,
    const std::function<bool(const std::filesystem::path&)>& keep) {
  std::vector<std::filesystem::path> out;
  const auto visit = [&](const std::filesystem::directory_entry& entry) {
    if (entry.is_regular_file() && keep(entry.path())) out.push_back(entry.path());
  };
  for (const std::filesystem::path& folder : folders) {
    if (recursive) {
      for (const auto& entry : std::filesystem::recursive_directory_iterator(folder)) visit(entry);
    } else {
      for (const auto& entry : std::filesystem::directory_iterator(folder)) visit(entry);
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

// True when the run regenerates golden files (INSULA_UPDATE_GOLDEN set).
inline bool updating_goldens() {
  return std::getenv("INSULA_UPDATE_GOLDEN") != nullptr;
}

// Compares `actual` with the golden file byte for byte; with INSULA_UPDATE_GOLDEN set, writes it
// instead (creating its folder), so a change of output is a reviewed diff.
inline void expect_golden(const std::filesystem::path& golden, const std::string& actual) {
  if (updating_goldens()) {
    std::filesystem::create_directories(golden.parent_path());
    std::ofstream(golden, std::ios::binary) << actual;
    return;
  }
  ASSERT_TRUE(std::filesystem::exists(golden))
      << "missing golden " << golden << "; run with INSULA_UPDATE_GOLDEN=1";
  EXPECT_EQ(actual, read_file(golden)) << "golden " << golden;
}

// A bad-input catalog: every file of `files` has the first diagnostic `expected` lists for its
// stem (as `first_line` renders it), and every listed stem has its file.
inline void expect_catalog_first_lines(
    const std::vector<std::filesystem::path>& files,
    const std::map<std::string, std::string>& expected,
    const std::function<std::string(const std::filesystem::path&)>& first_line) {
  for (const auto& path : files) {
    const std::string stem = path.stem().string();
    SCOPED_TRACE(stem);
    const auto it = expected.find(stem);
    ASSERT_NE(it, expected.end()) << "add the expected diagnostic for " << stem;
    EXPECT_EQ(first_line(path), it->second);
  }
  EXPECT_EQ(files.size(), expected.size()) << "a listed file is missing";
}

}  // namespace insula::test
