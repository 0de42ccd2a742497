// What a finished `insula mass` run tells and keeps, for the whole-scene and the tile-by-tile
// jobs alike: the buildings' warnings and failures in input order, the checks that fail a run,
// the report and the commit point.
#pragma once

#include <cstddef>
#include <vector>

#include "apps/cli/mass_build.h"
#include "apps/cli/mass_command.h"
#include "apps/cli/mass_plan.h"
#include "apps/cli/mass_report.h"
#include "apps/cli/stopwatch.h"
#include "io/footprint_finish.h"
#include "io/output.h"

namespace insula::cli {

// Warnings (MAS004) of the built buildings and their failures (MAS005 or an error), in input
// order. Returns how many gave no closed building.
std::size_t account(const MassOptions& options, const io::FootprintSet& set,
                    const std::vector<BuildOutcome>& built, std::vector<Warning>& warnings);
// Fails the run when buildings failed without --keep-going or none was made; else 0.
int check_built(const MassOptions& options, std::size_t failed, std::size_t made,
                std::size_t total);
void emit_mass_warnings(const MassOptions& options, const std::vector<Warning>& warnings,
                        MassReport& report);
// The report, the commit point, and what a finished run prints.
int finish_mass(const MassOptions& options, MassReport& report, const Stopwatch& total,
                io::OutputTransaction& transaction);

}  // namespace insula::cli
