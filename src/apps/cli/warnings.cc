#include "apps/cli/warnings.h"

#include <cstdio>
#include <mutex>

#include "apps/cli/progress.h"

namespace insula::cli {
namespace {

std::mutex warnings_mutex;
std::map<std::string, std::size_t> counts;
bool finished = false;  // the summary lines are printed once, by the first finish_warnings()

std::string code_name(const std::string& code) {
  return code.empty() ? "none" : code;
}

}  // namespace

void emit_warning(const std::string& code, const std::string& line, bool quiet) {
  const std::lock_guard<std::mutex> lock(warnings_mutex);
  const std::size_t seen = ++counts[code_name(code)];
  if (quiet || seen > kWarningsPerCode) return;
  clear_progress_line();
  std::fprintf(stderr, "%s\n", line.c_str());
}

void finish_warnings(bool quiet) {
  const std::lock_guard<std::mutex> lock(warnings_mutex);
  if (quiet || finished) return;
  finished = true;
  for (const auto& [code, count] : counts) {
    if (count <= kWarningsPerCode) continue;
    clear_progress_line();
    std::fprintf(stderr, "insula: and %zu more like it (code %s)\n", count - kWarningsPerCode,
                 code.c_str());
  }
}

std::map<std::string, std::size_t> warning_counts() {
  const std::lock_guard<std::mutex> lock(warnings_mutex);
  return counts;
}

std::size_t warning_total() {
  std::size_t total = 0;
  for (const auto& [code, count] : warning_counts()) total += count;
  return total;
}

}  // namespace insula::cli
