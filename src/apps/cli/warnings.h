// Warnings of one run, capped per code (docs/cli.md, "Warnings"): the first kWarningsPerCode of a
// code are printed, the rest counted, and finish_warnings() prints one line "and N more like it
// (code XXX)" per code that went over. Every warning is counted, printed or not (--quiet), so
// reports can give the full count per code. The state is per process: one process runs one
// command, and warnings come from every front-end and from worker threads.
#pragma once

#include <cstddef>
#include <map>
#include <string>

namespace insula::cli {

inline constexpr std::size_t kWarningsPerCode = 10;

// Counts a warning of `code` and prints `line` to stderr unless `quiet` or over the cap.
void emit_warning(const std::string& code, const std::string& line, bool quiet);
// Counts `count` warnings of `code` that a reader did not list (io::FootprintSet::
// unlisted_warnings): they show in the "and N more like it" line and the counts.
void count_unlisted_warnings(const std::string& code, std::size_t count);
// Prints the "and N more like it" lines (unless `quiet`), in code order; only the first call does
// (a command calls it before its closing line, main() after every command).
void finish_warnings(bool quiet);
// Every warning of the run so far, by code (an empty code counts as "none").
std::map<std::string, std::size_t> warning_counts();
std::size_t warning_total();

}  // namespace insula::cli
