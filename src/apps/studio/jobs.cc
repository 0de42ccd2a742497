#include "apps/studio/jobs.h"

#include <fcntl.h>
#include <linux/close_range.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <random>
#include <sstream>
#include <thread>

namespace insula::studio {
namespace fs = std::filesystem;

namespace {

// A child's output, its head and tail only when it is long (a chatty runaway build could write
// gigabytes before its time limit; the diagnostics that matter come first and last).
std::string read_output(const fs::path& log) {
  constexpr std::uintmax_t kKept = std::uintmax_t{512} << 10;  // bytes from each end
  std::error_code error;
  const std::uintmax_t size = fs::file_size(log, error);
  std::ifstream in(log, std::ios::binary);
  if (error || !in) return {};
  if (size <= 2 * kKept) {
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }
  std::string head(kKept, '\0');
  std::string tail(kKept, '\0');
  in.read(head.data(), static_cast<std::streamsize>(kKept));
  in.seekg(static_cast<std::streamoff>(size - kKept));
  in.read(tail.data(), static_cast<std::streamsize>(kKept));
  return head + "\n... (" + std::to_string(size - 2 * kKept) + " bytes left out) ...\n" + tail;
}

}  // namespace

Jobs::Jobs(fs::path executable, JobLimits limits)
    : executable_(std::move(executable)), limits_(limits) {}

void Jobs::start(const std::string& key, pid_t pid) {
  std::lock_guard lock(mutex_);
  if (stopping_) kill(-pid, SIGKILL);
  const auto [it, added] = running_.try_emplace(key, pid);
  if (!added) {
    cancelled_.insert(it->second);
    kill(-it->second, SIGKILL);  // its process group: the build and anything it started
    it->second = pid;
  }
}

void Jobs::stop_all() {
  std::lock_guard lock(mutex_);
  stopping_ = true;
  for (const auto& [key, pid] : running_) {
    cancelled_.insert(pid);
    kill(-pid, SIGKILL);
  }
}

bool Jobs::finish(const std::string& key, pid_t pid) {
  std::lock_guard lock(mutex_);
  if (const auto it = running_.find(key); it != running_.end() && it->second == pid) {
    running_.erase(it);
  }
  return cancelled_.erase(pid) > 0;
}

JobResult Jobs::run(const std::string& key, const std::vector<std::string>& args,
                    const fs::path& folder, int niceness) {
  JobResult result;
  // Everything the child needs is made before fork: after it only async-signal-safe calls.
  std::vector<std::string> words{executable_.string()};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  std::random_device random;
  const fs::path log = fs::temp_directory_path() / ("insula-studio-" + std::to_string(random()) +
                                                    "-" + std::to_string(getpid()) + ".log");
  const std::string log_name = log.string();
  const std::string folder_name = folder.string();
  const rlimit memory{limits_.memory_bytes, limits_.memory_bytes};

  const pid_t pid = fork();
  if (pid < 0) {
    result.output = "cannot start a process";
    return result;
  }
  if (pid == 0) {
    setpgid(0, 0);
    prctl(PR_SET_PDEATHSIG, SIGKILL);  // the server gone, the build goes too
    if (getppid() == 1) _exit(126);
    const int fd = open(log_name.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    if (fd < 0 || chdir(folder_name.c_str()) != 0) _exit(126);
    dup2(fd, STDOUT_FILENO);
    dup2(fd, STDERR_FILENO);
    syscall(SYS_close_range, 3U, ~0U, 0U);  // not the server's sockets
    if (memory.rlim_cur > 0) setrlimit(RLIMIT_AS, &memory);
    if (niceness > 0) setpriority(PRIO_PROCESS, 0, niceness);
    execv(argv[0], argv.data());
    _exit(127);
  }
  setpgid(pid, pid);
  start(key, pid);
  const auto deadline = std::chrono::steady_clock::now() + limits_.timeout;
  int status = 0;
  while (true) {
    const pid_t done = waitpid(pid, &status, WNOHANG);
    if (done == pid) break;
    if (std::chrono::steady_clock::now() > deadline) {
      result.timed_out = true;
      kill(-pid, SIGKILL);
      waitpid(pid, &status, 0);
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  result.cancelled = finish(key, pid);
  if (WIFEXITED(status)) result.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) result.signal = WTERMSIG(status);
  result.output = read_output(log);
  std::error_code ignored;
  fs::remove(log, ignored);
  return result;
}

}  // namespace insula::studio
