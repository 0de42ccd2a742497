#include "apps/cli/mass_outcome.h"

#include <cstdio>

#include "apps/cli/exit_codes.h"
#include "apps/cli/interrupt.h"
#include "apps/cli/warnings.h"

namespace insula::cli {
namespace {

// A footprint that gave no closed shell: an error, or a warning with --keep-going.
void report_failed_building(const MassOptions& options, const io::Footprint& footprint,
                            const BuildOutcome& built) {
  std::string message = feature_name(footprint) + ": no closed building could be made";
  if (!built.messages.empty()) message += ": " + built.messages.front();
  if (options.keep_going) {
    emit_warning("MAS005", options.input + ": warning[MAS005]: " + message, options.quiet);
  } else {
    std::fprintf(stderr, "%s: error: %s\n", options.input.c_str(), message.c_str());
  }
}

}  // namespace

// Warnings and failures of the built buildings, in input order. Returns how many gave no closed
// building.
std::size_t account(const MassOptions& options, const io::FootprintSet& set,
                    const std::vector<BuildOutcome>& built, std::vector<Warning>& warnings) {
  std::size_t failed = 0;
  for (const BuildOutcome& b : built) {
    for (const std::string& m : b.messages)
      warnings.push_back({"MAS004", "building \"" + b.id + "\": " + m});
    if (!b.watertight) {
      ++failed;
      report_failed_building(options, set.footprints[b.feature], b);
    }
  }
  return failed;
}

// Fails the run when buildings failed without --keep-going or none was made; else 0.
int check_built(const MassOptions& options, std::size_t failed, std::size_t made,
                std::size_t total) {
  if (failed > 0 && !options.keep_going) {
    std::fprintf(
        stderr,
        "insula: %zu of %zu buildings failed; nothing written (--keep-going leaves them out)\n",
        failed, total);
    return kExitInput;
  }
  if (made == 0) {
    std::fprintf(stderr, "insula: error: no building could be made; nothing written\n");
    return kExitInput;
  }
  return 0;
}

void emit_mass_warnings(const MassOptions& options, const std::vector<Warning>& warnings,
                        MassReport& report) {
  for (const Warning& w : warnings) {
    emit_warning(w.code, options.input + ": warning[" + w.code + "]: " + w.text, options.quiet);
  }
  report.warnings = warning_total();
  report.warning_counts = warning_counts();
}

// The report, the commit point, and what a finished run prints.
int finish_mass(const MassOptions& options, MassReport& report, const Stopwatch& total,
                io::OutputTransaction& transaction) {
  report.total_seconds = total.seconds();
  if (!options.report.empty()) {
    if (const std::string error = transaction.write_text(options.report, report.json());
        !error.empty()) {
      return write_failure(error);
    }
  }
  if (const std::string error = transaction.commit(); !error.empty()) return write_failure(error);
  finish_warnings(options.quiet);
  if (!options.quiet) {
    std::fprintf(stderr, "insula: %zu buildings in %.2f s\n", report.buildings,
                 report.total_seconds);
  }
  for (const std::string& out : options.outputs) std::printf("%s\n", out.c_str());
  return kExitDone;
}

}  // namespace insula::cli
