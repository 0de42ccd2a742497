#include "apps/cli/ranks.h"

#include <algorithm>
#include <cstdlib>
#include <mutex>

#if defined(INSULA_WITH_MPI)
#include <mpi.h>
#endif

namespace insula::cli {
namespace {

#if defined(INSULA_WITH_MPI)
bool started = false;

// mpirun (OpenMPI's ORTE/PMIx, or a PMI launcher such as Slurm's srun) tells its processes so.
bool launched_by_mpirun() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"}) {
    if (std::getenv(name) != nullptr) return true;
  }
  return false;
}
#endif

}  // namespace

void Ranks::start(int& argc, char**& argv) {
#if defined(INSULA_WITH_MPI)
  if (!launched_by_mpirun()) return;
  int provided = 0;
  // Any thread may take the next tile from the queue, one at a time (Queue::next() locks).
  MPI_Init_thread(&argc, &argv, MPI_THREAD_SERIALIZED, &provided);
  started = true;
#else
  (void)argc;
  (void)argv;
#endif
}

void Ranks::stop() {
#if defined(INSULA_WITH_MPI)
  if (started) MPI_Finalize();
  started = false;
#endif
}

int Ranks::rank() {
#if defined(INSULA_WITH_MPI)
  if (started) {
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    return rank;
  }
#endif
  return 0;
}

int Ranks::size() {
#if defined(INSULA_WITH_MPI)
  if (started) {
    int size = 1;
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    return size;
  }
#endif
  return 1;
}

#if defined(INSULA_WITH_MPI)
namespace {
// The queue's counters at the leader, by displacement in its window.
constexpr MPI_Aint kNextItem = 0;
constexpr MPI_Aint kFinished = 1;
constexpr int kCounters = 2;
}  // namespace
#endif

// The queue is one counter at the leader that every rank increments atomically (one-sided
// MPI_Fetch_and_op): no rank waits for another to hand out work. A second counter sums the work
// the ranks finished, told with the same flush as they take the next item.
Ranks::Queue::Queue(std::size_t count) : count_(count) {
#if defined(INSULA_WITH_MPI)
  if (!started) return;
  MPI_Win window = MPI_WIN_NULL;
  const MPI_Aint bytes = leader() ? static_cast<MPI_Aint>(kCounters * sizeof(long)) : 0;
  MPI_Win_allocate(bytes, sizeof(long), MPI_INFO_NULL, MPI_COMM_WORLD, &counters_, &window);
  if (leader()) std::fill_n(counters_, kCounters, 0L);
  MPI_Barrier(MPI_COMM_WORLD);
  MPI_Win_lock_all(0, window);
  window_ = new MPI_Win(window);
#endif
}

Ranks::Queue::~Queue() {
#if defined(INSULA_WITH_MPI)
  if (window_ == nullptr) return;
  auto* window = static_cast<MPI_Win*>(window_);
  MPI_Win_unlock_all(*window);
  MPI_Win_free(window);
  delete window;
#endif
}

std::size_t Ranks::Queue::next(std::size_t finished) {
  const std::lock_guard<std::mutex> lock(mutex_);
#if defined(INSULA_WITH_MPI)
  if (window_ != nullptr) {
    auto* window = static_cast<MPI_Win*>(window_);
    const long one = 1;
    const auto done = static_cast<long>(finished);
    long taken = 0;
    if (done > 0) MPI_Accumulate(&done, 1, MPI_LONG, 0, kFinished, 1, MPI_LONG, MPI_SUM, *window);
    MPI_Fetch_and_op(&one, &taken, MPI_LONG, 0, kNextItem, MPI_SUM, *window);
    MPI_Win_flush(0, *window);
    return taken < 0 || static_cast<std::size_t>(taken) >= count_ ? count_
                                                                  : static_cast<std::size_t>(taken);
  }
#endif
  local_finished_ += finished;
  return local_ < count_ ? local_++ : count_;
}

std::size_t Ranks::Queue::finished() {
  const std::lock_guard<std::mutex> lock(mutex_);
#if defined(INSULA_WITH_MPI)
  if (window_ != nullptr) {
    auto* window = static_cast<MPI_Win*>(window_);
    long sum = 0;
    // An atomic read: the other ranks' sums may land at any time.
    MPI_Fetch_and_op(nullptr, &sum, MPI_LONG, 0, kFinished, MPI_NO_OP, *window);
    MPI_Win_flush(0, *window);
    return sum < 0 ? 0 : static_cast<std::size_t>(sum);
  }
#endif
  return local_finished_;
}

std::vector<std::string> Ranks::gather(const std::string& mine) {
#if defined(INSULA_WITH_MPI)
  if (started) {
    const int ranks = size();
    const int length = static_cast<int>(mine.size());
    std::vector<int> lengths(static_cast<std::size_t>(ranks));
    MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
    std::vector<int> offsets(static_cast<std::size_t>(ranks), 0);
    std::string all;
    if (leader()) {
      int total = 0;
      for (int r = 0; r < ranks; ++r) {
        offsets[static_cast<std::size_t>(r)] = total;
        total += lengths[static_cast<std::size_t>(r)];
      }
      all.resize(static_cast<std::size_t>(total));
    }
    MPI_Gatherv(mine.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(), MPI_CHAR,
                0, MPI_COMM_WORLD);
    std::vector<std::string> out;
    if (!leader()) return out;
    for (int r = 0; r < ranks; ++r) {
      out.push_back(all.substr(static_cast<std::size_t>(offsets[static_cast<std::size_t>(r)]),
                               static_cast<std::size_t>(lengths[static_cast<std::size_t>(r)])));
    }
    return out;
  }
#endif
  return {mine};
}

int Ranks::broadcast(int value) {
#if defined(INSULA_WITH_MPI)
  if (started) MPI_Bcast(&value, 1, MPI_INT, 0, MPI_COMM_WORLD);
#endif
  return value;
}

void Ranks::barrier() {
#if defined(INSULA_WITH_MPI)
  if (started) MPI_Barrier(MPI_COMM_WORLD);
#endif
}

void Ranks::abort([[maybe_unused]] int code) {
#if defined(INSULA_WITH_MPI)
  if (started && size() > 1) MPI_Abort(MPI_COMM_WORLD, code);
#endif
}

}  // namespace insula::cli
