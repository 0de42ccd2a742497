// `insula check FILE.bldg`: the rules' moderator of seed 000 §3.3 without any geometry. Prints
// every diagnostic (`file:line:col: error[BLDnnn]: ...`) and, on success, what the building holds.
#include <optional>
#include <string>

#include "apps/cli/front_ends.h"
#include "lang/bldg/parser.h"

namespace insula::cli {
namespace {

struct Counts {
  int parts = 0;
  int disposable = 0;
  int floors = 0;
  int rooms = 0;
};

void count_divisions(const lang::bldg::Division& division, Counts& counts) {
  if (division.room) ++counts.rooms;
  for (const auto& child : division.children) count_divisions(child, counts);
}

void count_parts(const lang::bldg::PartNode& node, Counts& counts) {
  if (node.part) {
    ++counts.parts;
    if (node.part->disposable) ++counts.disposable;
    for (const auto& floor : node.part->floors) {
      ++counts.floors;
      count_divisions(floor.layout, counts);
    }
  }
  for (const auto& child : node.children) count_parts(child, counts);
}

std::string plural(int n, const std::string& word) {
  return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
}

}  // namespace

std::optional<std::string> check_bldg(const base::Source& source, bool quiet) {
  base::Result<lang::bldg::Building> building = lang::bldg::parse_building(source);
  print_diagnostics(building.diagnostics(), source, quiet);
  if (!building.ok()) return std::nullopt;
  Counts counts;
  count_parts(building->layout, counts);
  std::string summary = "building '" + building->name + "': " + plural(counts.parts, "part");
  if (counts.disposable > 0) summary += " (" + std::to_string(counts.disposable) + " disposable)";
  summary += ", " + plural(counts.floors, "floor") + ", " + plural(counts.rooms, "room") + ", " +
             plural(static_cast<int>(building->transitions.size()), "transition");
  if (!building->outline_file.empty()) {
    summary +=
        ", outline from " + building->outline_file + " feature '" + building->outline_feature + "'";
  }
  return summary;
}

}  // namespace insula::cli
