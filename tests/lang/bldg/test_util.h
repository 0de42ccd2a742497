// Helpers shared by the .bldg front-end tests.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "../../common/test_util.h"
#include "base/diagnostic.h"
#include "lang/bldg/parser.h"

namespace insula::lang::bldg::testing {

inline std::filesystem::path data_dir() {
  return std::filesystem::path(INSULA_TEST_DATA) / "bldg";
}

// Shared by every front-end (tests/common/test_util.h).
using insula::test::files_in;
using insula::test::read_file;

// prefix + i, built by appending: GCC 12 -O3 reports a false -Wrestrict on "x" + std::string.
inline std::string numbered(const char* prefix, int i) {
  std::string out(prefix);
  out += std::to_string(i);
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

namespace insula::lang::bldg::testing {

// Every field of a model except source locations, independent of the printer, so round-trip
// tests compare models and not just texts.
inline std::string dump(const Division& d, const std::string& indent) {
  std::string out =
      indent + "div " + d.symbol + " o" + std::to_string(static_cast<int>(d.orientation));
  if (d.room) {
    out += " room[" + d.room->type + " s" + std::to_string(static_cast<int>(d.room->size)) + " w" +
           std::to_string(d.room->walls) + " n" + std::to_string(d.room->windows) + " e" +
           std::to_string(d.room->entrance) + "]";
  }
  out += "\n";
  for (const Division& c : d.children) out += dump(c, indent + "  ");
  return out;
}

inline std::string dump(const PartNode& p, const std::string& indent) {
  std::string out =
      indent + "part " + p.symbol + " o" + std::to_string(static_cast<int>(p.orientation));
  if (p.part) {
    out += " roof" + std::to_string(static_cast<int>(p.part->roof)) + " h" +
           std::to_string(p.part->height) + " disp" + std::to_string(p.part->disposable) + "\n";
    for (const Floor& f : p.part->floors) {
      out += indent + " floor " + f.symbol + " h" + std::to_string(f.height) + "\n" +
             dump(f.layout, indent + "  ");
    }
  } else {
    out += "\n";
  }
  for (const PartNode& c : p.children) out += dump(c, indent + "  ");
  return out;
}

inline std::string dump(const Building& b) {
  char buffer[64];
  std::string out = "building " + b.symbol + " '" + b.name + "' file '" + b.outline_file +
                    "' feature '" + b.outline_feature + "'\n";
  for (std::size_t r = 0; r <= b.outline.holes.size(); ++r) {
    out += r == 0 ? " outer" : " hole";
    for (const kernel::Vec2& v : r == 0 ? b.outline.outer : b.outline.holes[r - 1]) {
      std::snprintf(buffer, sizeof buffer, " (%.17g %.17g)", v.x, v.y);
      out += buffer;
    }
    out += "\n";
  }
  out += dump(b.layout, " ");
  for (const Transition& t : b.transitions) {
    out += " transition " + t.symbol + " k" + std::to_string(static_cast<int>(t.kind)) + " " +
           t.from + " " + t.to + " w" + std::to_string(t.width) + "\n";
  }
  return out;
}

}  // namespace insula::lang::bldg::testing
