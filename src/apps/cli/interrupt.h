// SIGINT and SIGTERM during a run that writes files (docs/cli.md, "Interrupted runs"). The handler
// only records the signal (the one async-signal-safe thing to do); the workers stop taking new work
// when they see it, and the main thread rolls the output transaction back, so an interruption at
// any moment leaves either all the old files or all the new ones, never a mix, a backup or a
// temporary. The handlers stay until the process exits: a signal that arrives after the commit
// point, while the process returns from main and frees its scene, must not kill it either (the
// new files stay and the exit code is 0), and one that arrives before cannot kill it half-way
// through its rollback; the exit code is then 128 + the signal (130 for SIGINT, 143 for SIGTERM).
#pragma once

#include <string>

namespace insula::cli {

// Installs the handlers for the rest of the process (a signal the caller ignores stays ignored).
void install_interrupt_handlers();

// True once SIGINT or SIGTERM arrived after the handlers were installed; safe from any thread.
bool interrupted();
// 128 + the signal number, or 0 when no signal arrived.
int interrupt_exit_code();
// The exit code of a failed step that writes or commits outputs: after an interruption 128 + the
// signal (with one line saying so), else kExitInput with "insula: error: <error>".
int write_failure(const std::string& error);
// When interrupted: says so and gives 128 + the signal; else 0. For the checks between stages.
int stop_if_interrupted();

}  // namespace insula::cli
