// The 3D Tiles job of `insula mass` (issue 17; docs/formats.md "3D Tiles", docs/cluster.md): the
// buildings are grouped into tiles by where they stand, and each tile is built (its buildings in
// parallel) and written before the next, so memory holds the footprints and the tiles in flight,
// never the city's meshes. Under mpirun the tiles are shared among the ranks through a work queue;
// the leader gathers what every rank built and writes the tileset, the report and the warnings.
#pragma once

#include <vector>

#include "apps/cli/mass_build.h"
#include "apps/cli/mass_command.h"
#include "apps/cli/mass_plan.h"
#include "apps/cli/mass_report.h"
#include "apps/cli/stopwatch.h"
#include "io/footprint_finish.h"

namespace insula::cli {

// Every rank calls it; every rank returns the run's exit code.
int run_mass_tiles(const MassOptions& options, const io::FootprintSet& set, const MassPlan& plan,
                   const std::vector<MassUnit>& units, std::vector<Warning>& warnings,
                   MassReport& report, const Stopwatch& total);

}  // namespace insula::cli
