// Helpers shared by the .bldg front-end tests.
#pragma once

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "base/diagnostic.h"
#include "lang/bldg/parser.h"

namespace insula::lang::bldg::testing {

inline std::filesystem::path data_dir() {
  return std::filesystem::path(INSULA_TEST_DATA) / "bldg";
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

// Every diagnostic of parsing `text`, rendered without source lines, one per line.
inline std::string errors(const std::string& text, const std::string& name = "t.bldg") {
  const base::Source source(name, text);
  const auto result = parse_building(source);
  std::string out;
  for (const auto& d : result.diagnostics()) out += base::render(d) + "\n";
  return out;
}

// The first diagnostic of parsing `text`; empty when there is none.
inline std::string first_error(const std::string& text, const std::string& name = "t.bldg") {
  const base::Source source(name, text);
  const auto result = parse_building(source);
  if (result.diagnostics().empty()) return {};
  return base::render(result.diagnostics().front());
}

inline Building parse_ok(const std::string& text, const std::string& name = "t.bldg") {
  const base::Source source(name, text);
  auto result = parse_building(source);
  if (!result.ok()) {
    std::string all;
    for (const auto& d : result.diagnostics()) all += base::render(d, &source) + "\n";
    throw std::runtime_error("parse failed:\n" + all);
  }
  return std::move(result.value());
}

// Rooms of a division tree, depth first.
inline void for_each_room(const Division& division,
                          const std::function<void(const Division&)>& visit) {
  if (division.room) visit(division);
  for (const Division& child : division.children) for_each_room(child, visit);
}
inline void for_each_room(const PartNode& node, const std::function<void(const Division&)>& visit) {
  if (node.part) {
    for (const Floor& floor : node.part->floors) for_each_room(floor.layout, visit);
  }
  for (const PartNode& child : node.children) for_each_room(child, visit);
}

}  // namespace insula::lang::bldg::testing
