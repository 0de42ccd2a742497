// Building the masses of `insula mass`: one unit per building of the output, a footprint or an
// OpenStreetMap outline with the building:part features that replace it (S3DB), built on its own
// so that the whole-scene job and the tile-by-tile job (mass_tiles.h) make the same buildings.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "apps/cli/mass_plan.h"
#include "io/footprint_finish.h"
#include "io/tile_tree.h"
#include "shape/scene.h"

namespace insula::cli {

struct BuiltBuilding {
  shape::Building building;
  std::vector<std::string> messages;  // fallbacks and failures, reported in input order
  bool watertight = true;
  double top = 0;           // highest point built
  std::size_t feature = 0;  // the footprint it stands for (the outline, for joined parts)
};

// What the warnings and the report need of a building once its meshes are written.
struct BuildOutcome {
  std::string id;
  std::size_t feature = 0;
  bool watertight = true;
  std::vector<std::string> messages;
  std::string entry;  // its report entry, with --report-buildings
};
BuildOutcome outcome_of(BuiltBuilding&& built);

// The footprints of one output building: the first is the one it is named after.
using MassUnit = std::vector<std::size_t>;

// Every building of the output, in input order: a footprint, or a replaced outline followed by its
// building:part features; the parts are not units of their own.
std::vector<MassUnit> mass_units(const MassPlan& plan);

BuiltBuilding build_unit(const io::FootprintSet& set, const MassPlan& plan, const MassUnit& unit);

// Where a unit will stand and what it will cost, before it is built: the plan box of its
// footprints widened by the roof overhang, and about as many faces as its mass will have.
io::TileItem unit_tile_item(const io::FootprintSet& set, const MassUnit& unit, double overhang);

}  // namespace insula::cli
