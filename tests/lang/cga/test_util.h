// Helpers shared by the CGA front-end tests.
#pragma once

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "base/diagnostic.h"
#include "lang/cga/parser.h"

namespace insula::lang::cga::testing {

inline std::filesystem::path data_dir() {
  return std::filesystem::path(INSULA_TEST_DATA) / "cga";
}

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

// The first diagnostic of parsing `text` as `name`, rendered without source lines; empty when
// the parse succeeded.
inline std::string first_error(const std::string& text, const std::string& name = "t.cga") {
  const base::Source source(name, text);
  const auto result = parse(source);
  if (result.ok() || result.diagnostics().empty()) return {};
  return base::render(result.diagnostics().front());
}

}  // namespace insula::lang::cga::testing
