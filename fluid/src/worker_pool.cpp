#include "worker_pool.h"

#include <algorithm>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#define HAIR25D_FLUID_PAUSE() _mm_pause()
#else
#define HAIR25D_FLUID_PAUSE() std::this_thread::yield()
#endif

namespace hair25d::fluid {
namespace {

constexpr std::uint64_t kMask = (std::uint64_t{1} << 20) - 1;
// Spins before sleeping: long enough to catch the next step of an animation loop (~0.1 ms),
// short enough not to burn a core when the solver is idle.
constexpr int kSpins = 20000;

}  // namespace

WorkerPool::WorkerPool(int threads) {
  for (int slot = 1; slot < std::max(1, threads); ++slot)
    workers_.emplace_back([this, slot] { worker_loop(slot); });
}

WorkerPool::~WorkerPool() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  for (std::thread& t : workers_) t.join();
}

bool WorkerPool::claim(std::uint64_t epoch, int* chunk) {
  std::uint64_t cur = next_.load(std::memory_order_acquire);
  for (;;) {
    if ((cur >> (2 * kChunkBits)) != epoch) return false;
    const std::uint64_t total = (cur >> kChunkBits) & kMask, c = cur & kMask;
    if (c >= total) return false;
    if (next_.compare_exchange_weak(cur, cur + 1, std::memory_order_acq_rel)) {
      *chunk = static_cast<int>(c);
      return true;
    }
  }
}

void WorkerPool::work(std::uint64_t epoch, int slot) {
  int chunk = 0;
  // A successful claim keeps the job (and fn_) alive: run() waits for every claimed chunk.
  while (claim(epoch, &chunk)) {
    (*fn_)(chunk, slot);
    done_.fetch_add(1, std::memory_order_acq_rel);
  }
}

void WorkerPool::run(int chunks, const std::function<void(int, int)>& fn) {
  if (chunks <= 0) return;
  if (workers_.empty() || chunks == 1) {
    for (int c = 0; c < chunks; ++c) fn(c, 0);
    return;
  }
  fn_ = &fn;
  done_.store(0, std::memory_order_relaxed);
  epoch_ = (epoch_ + 1) & ((std::uint64_t{1} << 24) - 1);
  next_.store((epoch_ << (2 * kChunkBits)) | (static_cast<std::uint64_t>(chunks) << kChunkBits),
              std::memory_order_release);
  {
    std::lock_guard<std::mutex> lock(mutex_);
    published_ = epoch_;
  }
  wake_.notify_all();
  work(epoch_, 0);
  for (int spins = 0; done_.load(std::memory_order_acquire) < chunks; ++spins) {
    if (spins < kSpins)
      HAIR25D_FLUID_PAUSE();
    else
      std::this_thread::yield();
  }
}

void WorkerPool::worker_loop(int slot) {
  std::uint64_t seen = 0;
  for (;;) {
    // Spin on the job counter first (cheap, no system call), then sleep until woken.
    std::uint64_t epoch = next_.load(std::memory_order_acquire) >> (2 * kChunkBits);
    for (int spins = 0; epoch == seen && spins < kSpins; ++spins) {
      HAIR25D_FLUID_PAUSE();
      epoch = next_.load(std::memory_order_acquire) >> (2 * kChunkBits);
    }
    if (epoch == seen) {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [&] { return stop_ || published_ != seen; });
      if (stop_) return;
      epoch = published_;
    }
    seen = epoch;
    work(epoch, slot);
  }
}

}  // namespace hair25d::fluid
