// `insula build FILE.cga --lot LOTS -o DIR/tileset.json` (issue 17): the lots are derived and
// written tile by tile (tile_job.h), so a city's terminal shapes and meshes are never held whole,
// and under mpirun the tiles are shared among the ranks. The report and the diagnostics are those
// of the whole-scene build (build_cga.cc), in lot order.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "apps/cli/build_command.h"
#include "apps/cli/stopwatch.h"
#include "base/diagnostic.h"
#include "io/asset_library.h"
#include "io/asset_search.h"
#include "lang/cga/derive.h"

namespace insula::cli {

// What a CGA build derives from, once the grammar is compiled and the lots are read.
struct CgaCity {
  const lang::cga::Program& program;
  const base::Source& source;
  const std::vector<lang::cga::Lot>& lots;
  kernel::Vec3 origin;
  std::string crs;
  const lang::cga::DeriveOptions& derive;
  const io::AssetSearch& search;
  const io::AssetLibrary& library;
};

// The derivation's part of a CGA build's report: lots, shapes, terminals, rule applications,
// symbols and report() sums.
nlohmann::json cga_report(const lang::cga::Program& program, const lang::cga::Totals& totals,
                          std::size_t lots);

// Derives, writes and reports, tile by tile; `report` comes with the build's earlier fields
// (seconds of the stages before, threads, seed, CRS). Every rank calls it and returns the exit
// code.
int build_cga_tiles(const BuildOptions& options, const CgaCity& city, nlohmann::json report,
                    const Stopwatch& total);

}  // namespace insula::cli
