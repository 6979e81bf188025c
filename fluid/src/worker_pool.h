// A small pool of persistent threads that share out chunks of one job, used for the rows of a
// lattice step and for cutting filament links.
//
// Why not an OpenMP parallel region: its implicit barrier waits for every thread to arrive.
// On a busy machine (the studio renders, other jobs compile) a worker that is not scheduled
// costs the whole step a scheduler time slice; steps of 0.1 ms then took 10-30 ms with two
// threads. Here chunks are claimed from a shared counter and the caller only waits for
// chunks that were claimed: a worker that wakes up late finds nothing left and goes back to
// sleep, so two threads are never much slower than one.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace hair25d::fluid {

class WorkerPool {
 public:
  explicit WorkerPool(int threads);  // threads - 1 workers; the caller is the first thread
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  int size() const { return static_cast<int>(workers_.size()) + 1; }

  // Calls fn(chunk, slot) for every chunk in [0, chunks), each exactly once, and returns when
  // all are done. `slot` in [0, size()) names the thread running the chunk (0 = the caller),
  // for per-thread accumulators. chunks < 2^20.
  void run(int chunks, const std::function<void(int, int)>& fn);

 private:
  // next_ packs epoch (24 bits) | chunk count (20 bits) | next chunk (20 bits), so a worker
  // that claims a chunk knows it belongs to the current job without reading anything else.
  static constexpr int kChunkBits = 20;
  bool claim(std::uint64_t epoch, int* chunk);
  void work(std::uint64_t epoch, int slot);
  void worker_loop(int slot);

  std::vector<std::thread> workers_;
  std::atomic<std::uint64_t> next_{0};
  std::atomic<int> done_{0};
  const std::function<void(int, int)>* fn_ = nullptr;
  std::uint64_t epoch_ = 0;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::uint64_t published_ = 0;  // guarded by mutex_
  bool stop_ = false;            // guarded by mutex_
};

}  // namespace hair25d::fluid
