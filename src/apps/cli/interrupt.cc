#include "apps/cli/interrupt.h"

#include <atomic>
#include <csignal>
#include <cstdio>

#include "apps/cli/exit_codes.h"

namespace insula::cli {
namespace {

// Lock-free, so reading and writing it from a signal handler is defined behaviour.
std::atomic<int> received_signal{0};
static_assert(std::atomic<int>::is_always_lock_free);

extern "C" void on_signal(int signal) {
  received_signal.store(signal);
}

// A signal the caller ignores stays ignored (a background job of a script ignores SIGINT, so that
// the terminal's Ctrl-C stops the script only).
void install(int signal, const struct sigaction& action) {
  struct sigaction previous {};
  sigaction(signal, nullptr, &previous);
  if (previous.sa_handler != SIG_IGN) sigaction(signal, &action, nullptr);
}

}  // namespace

void install_interrupt_handlers() {
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  // Restarted system calls: a write or rename interrupted by the signal completes, and the
  // transaction decides what to keep.
  action.sa_flags = SA_RESTART;
  install(SIGINT, action);
  install(SIGTERM, action);
}

bool interrupted() {
  return received_signal.load() != 0;
}

int interrupt_exit_code() {
  const int signal = received_signal.load();
  return signal == 0 ? 0 : 128 + signal;
}

int stop_if_interrupted() {
  const int signal = received_signal.load();
  if (signal == 0) return 0;
  std::fprintf(stderr, "insula: interrupted (%s); nothing written, earlier files kept\n",
               signal == SIGTERM ? "SIGTERM" : "SIGINT");
  return 128 + signal;
}

int write_failure(const std::string& error) {
  if (const int code = stop_if_interrupted(); code != 0) return code;
  std::fprintf(stderr, "insula: error: %s\n", error.c_str());
  return kExitInput;
}

}  // namespace insula::cli
