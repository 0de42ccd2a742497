// A village (seed 000, Fig. 12): `insula build FILE.bldg --lot LOTS` makes every feature of LOTS
// one building, from the grammar its "bldg" property names (relative to LOTS), else from FILE, on
// the feature's polygon as outline; buildings are named after the features. With only 3D Tiles
// out, the buildings are built and written tile by tile (tile_job.h) and, under mpirun, shared
// among the ranks; the report and the messages are the same either way, in lot order.
#pragma once

#include <nlohmann/json.hpp>

#include "apps/cli/bldg_pipeline.h"
#include "apps/cli/build_command.h"
#include "apps/cli/stopwatch.h"

namespace insula::cli {

// Every rank calls it and returns the exit code.
int build_village(const BuildOptions& options, const Parsed& input,
                  const lang::bldg::Restrictions& rules, nlohmann::json report,
                  const Stopwatch& total);

}  // namespace insula::cli
