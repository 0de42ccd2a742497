#include "apps/cli/warnings.h"

#include <cstdio>
#include <mutex>

#include "apps/cli/progress.h"

namespace insula::cli {
namespace {

std::mutex warnings_mutex;
// Per code: every warning of the run, and how many of them were printed.
struct Tally {
  std::size_t total = 0;
  std::size_t printed = 0;
};
std::map<std::string, Tally> tallies;
bool finished = false;  // the summary lines are printed once, by the first finish_warnings()

std::string code_name(const std::string& code) {
  return code.empty() ? "none" : code;
}

}  // namespace

void emit_warning(const std::string& code, const std::string& line, bool quiet) {
  const std::lock_guard<std::mutex> lock(warnings_mutex);
  Tally& tally = tallies[code_name(code)];
  ++tally.total;
  if (quiet || tally.printed >= kWarningsPerCode) return;
  ++tally.printed;
  clear_progress_line();
  std::fprintf(stderr, "%s\n", line.c_str());
}

void count_unlisted_warnings(const std::string& code, std::size_t count) {
  const std::lock_guard<std::mutex> lock(warnings_mutex);
  tallies[code_name(code)].total += count;
}

void finish_warnings(bool quiet) {
  const std::lock_guard<std::mutex> lock(warnings_mutex);
  if (quiet || finished) return;
  finished = true;
  for (const auto& [code, tally] : tallies) {
    if (tally.total <= tally.printed) continue;
    clear_progress_line();
    std::fprintf(stderr, "insula: and %zu more like it (code %s)\n", tally.total - tally.printed,
                 code.c_str());
  }
}

std::map<std::string, std::size_t> warning_counts() {
  const std::lock_guard<std::mutex> lock(warnings_mutex);
  std::map<std::string, std::size_t> counts;
  for (const auto& [code, tally] : tallies) counts[code] = tally.total;
  return counts;
}

std::size_t warning_total() {
  std::size_t total = 0;
  for (const auto& [code, count] : warning_counts()) total += count;
  return total;
}

}  // namespace insula::cli
