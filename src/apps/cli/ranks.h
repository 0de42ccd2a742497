// The processes of one run: just this one, or the ranks of an `mpirun` (issue 17 item 5; docs/
// cluster.md). MPI (OpenMPI) is an optional build feature (INSULA_WITH_MPI); MPI is started only
// when the process was launched by mpirun, so a plain `insula` never touches it. Everything MPI is
// behind this header.
#pragma once

#include <cstddef>
#include <mutex>
#include <string>
#include <vector>

namespace insula::cli {

class Ranks {
 public:
  // Starts MPI when launched by mpirun (and the build has it); call once, first thing in main.
  static void start(int& argc, char**& argv);
  // Ends MPI (after the last collective call); nothing when it was not started.
  static void stop();
  static int rank();
  static int size();
  static bool leader() { return rank() == 0; }
  static bool shared() { return size() > 1; }

  // A work queue of `count` items shared by all ranks: next() hands each item to exactly one
  // rank, in the order ranks ask, until none is left (then it returns `count`). Collective: every
  // rank makes one, and destroys it together with the others.
  class Queue {
   public:
    explicit Queue(std::size_t count);
    ~Queue();
    Queue(const Queue&) = delete;
    Queue& operator=(const Queue&) = delete;
    // Thread-safe. `finished`: how much work (in any unit, e.g. lots) the caller finished since it
    // last asked, added to a sum at the leader with the same message, so the leader's progress
    // counts every rank's work.
    std::size_t next(std::size_t finished = 0);
    // The sum of every rank's `finished` so far. Thread-safe.
    std::size_t finished();

   private:
    std::size_t count_;
    std::mutex mutex_;       // MPI is started for one caller at a time (MPI_THREAD_SERIALIZED)
    std::size_t local_ = 0;  // without MPI
    std::size_t local_finished_ = 0;
    void* window_ = nullptr;
    long* counters_ = nullptr;  // at the leader: the next item, the finished sum
  };

  // Every rank's bytes, in rank order, at the leader (empty elsewhere). Collective.
  static std::vector<std::string> gather(const std::string& mine);
  // The leader's value, at every rank. Collective.
  static int broadcast(int value);
  static void barrier();
  // Ends every rank at once with `code` (an internal error on one rank must not leave the others
  // waiting in a collective call); nothing when MPI was not started.
  static void abort(int code);
};

}  // namespace insula::cli
