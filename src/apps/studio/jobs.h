// Checks and builds for the studio run as child processes of the insula binary itself, with the
// command line's own arguments: the same code as `insula check` and `insula build`, and a crashed,
// runaway or memory-hungry build ends its process only, never the server (docs/studio.md). A newer
// job under the same key (an edit of the same file) kills the one it supersedes.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <filesystem>
#include <map>
#include <mutex>
#include <set>
#include <string>
#include <vector>

namespace insula::studio {

struct JobLimits {
  std::chrono::milliseconds timeout{120'000};
  // The child's address space (0: unbounded; sanitizer builds reserve terabytes of it).
#if defined(INSULA_SANITIZED)
  std::size_t memory_bytes = 0;
#else
  std::size_t memory_bytes = std::size_t{8} << 30;
#endif
};

struct JobResult {
  int exit_code = -1;      // the child's, or -1 when it did not exit by itself
  bool cancelled = false;  // a newer job under the same key replaced it
  bool timed_out = false;  // killed at the time limit
  int signal = 0;          // the signal that ended it (crash, kill), else 0
  std::string output;      // stdout and stderr, in order
};

class Jobs {
 public:
  Jobs(std::filesystem::path executable, JobLimits limits);

  // Runs `executable args...` in `folder`, waiting for it; blocks the calling (worker) thread.
  // `niceness` > 0 lowers the child's CPU priority (a job that may wait behind another).
  JobResult run(const std::string& key, const std::vector<std::string>& args,
                const std::filesystem::path& folder, int niceness = 0);

  // Kills every running job and every job started from now on (the server is stopping).
  void stop_all();

 private:
  // Registers `pid` under `key`, killing the job it supersedes.
  void start(const std::string& key, pid_t pid);
  bool finish(const std::string& key, pid_t pid);  // true when it was cancelled

  std::filesystem::path executable_;
  JobLimits limits_;
  std::mutex mutex_;
  std::map<std::string, pid_t> running_;
  std::set<pid_t> cancelled_;
  bool stopping_ = false;
};

}  // namespace insula::studio
