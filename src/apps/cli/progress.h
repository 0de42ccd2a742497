// Progress of a long run on stderr (docs/cli.md, "Progress"): on a terminal a bar redrawn in place
// with the count and the rate; otherwise (a log, a pipe) a plain line every few seconds. Nothing
// for runs shorter than one interval, nothing with --quiet. The interval is 0.1 s on a terminal and
// 2 s otherwise; INSULA_PROGRESS_SECONDS overrides it (tests set 0 to see every update).
#pragma once

#include <atomic>
#include <cstddef>
#include <mutex>
#include <string>

#include "apps/cli/stopwatch.h"

namespace insula::cli {

class Progress {
 public:
  // `noun` counts the work ("buildings", "lots"); `total` is how many there are.
  Progress(std::string noun, std::size_t total, bool quiet);
  ~Progress();  // finish()
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  // `n` more done; any thread.
  void advance(std::size_t n = 1);
  // `done` done in all, as counted elsewhere (every rank's work under mpirun); any thread. A
  // count below one already shown changes nothing.
  void reach(std::size_t done);
  // Ends a terminal bar with a line break (when one was drawn).
  void finish();

 private:
  // Draws `done` when the interval has passed.
  void show(std::size_t done);
  void draw(std::size_t done, double seconds);

  std::string noun_;
  std::size_t total_;
  bool enabled_;
  bool terminal_;
  double interval_;
  Stopwatch clock_;
  std::atomic<std::size_t> done_{0};
  std::atomic<double> next_draw_;
  std::mutex draw_mutex_;
  bool drawn_ = false;
};

// Clears a terminal bar before another line goes to stderr (warnings.cc); no-op otherwise.
void clear_progress_line();

}  // namespace insula::cli
