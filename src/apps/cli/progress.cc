#include "apps/cli/progress.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <string>

namespace insula::cli {
namespace {

// Set while a bar is drawn on the terminal, so other stderr lines can clear it first.
std::atomic<bool> bar_on_screen{false};

double interval_seconds(bool terminal) {
  if (const char* text = std::getenv("INSULA_PROGRESS_SECONDS")) {
    char* end = nullptr;
    const double seconds = std::strtod(text, &end);
    if (end != text && seconds >= 0) return seconds;
  }
  return terminal ? 0.1 : 2.0;
}

}  // namespace

Progress::Progress(std::string noun, std::size_t total, bool quiet)
    : noun_(std::move(noun)),
      total_(total),
      enabled_(!quiet && total > 1),
      terminal_(isatty(STDERR_FILENO) == 1),
      interval_(interval_seconds(terminal_)),
      next_draw_(interval_) {}

Progress::~Progress() {
  finish();
}

void Progress::advance(std::size_t n) {
  show(done_ += n);
}

void Progress::reach(std::size_t done) {
  std::size_t known = done_.load();
  // Raised to `done` unless another thread raised it as far meanwhile.
  while (known < done && !done_.compare_exchange_weak(known, done)) {
  }
  if (known < done) show(done);
}

void Progress::show(std::size_t done) {
  if (!enabled_) return;
  const double seconds = clock_.seconds();
  double next = next_draw_.load();
  // One thread per interval draws; the others go back to work at once.
  if (seconds < next || !next_draw_.compare_exchange_strong(next, seconds + interval_)) return;
  draw(done, seconds);
}

void Progress::draw(std::size_t done, double seconds) {
  const std::lock_guard<std::mutex> lock(draw_mutex_);
  const double rate = seconds > 0 ? static_cast<double>(done) / seconds : 0;
  const double fraction = total_ > 0 ? static_cast<double>(done) / static_cast<double>(total_) : 1;
  if (!terminal_) {
    std::fprintf(stderr, "insula: %zu of %zu %s (%.0f%%), %.1f/s\n", done, total_, noun_.c_str(),
                 100 * fraction, rate);
    return;
  }
  constexpr int kWidth = 30;
  const int filled = static_cast<int>(fraction * kWidth);
  std::string bar(static_cast<std::size_t>(filled), '#');
  bar.append(static_cast<std::size_t>(kWidth - filled), '.');
  std::fprintf(stderr, "\r\033[K[%s] %zu/%zu %s %.1f/s", bar.c_str(), done, total_, noun_.c_str(),
               rate);
  std::fflush(stderr);
  drawn_ = true;
  bar_on_screen = true;
}

void Progress::finish() {
  if (!drawn_) return;
  draw(done_.load(), clock_.seconds());  // the bar's last state: the final count
  const std::lock_guard<std::mutex> lock(draw_mutex_);
  std::fprintf(stderr, "\n");
  drawn_ = false;
  bar_on_screen = false;
}

void clear_progress_line() {
  if (bar_on_screen.exchange(false)) std::fprintf(stderr, "\r\033[K");
}

}  // namespace insula::cli
