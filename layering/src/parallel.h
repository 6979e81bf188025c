// Independent per-item work of the layering (measuring lines along
// boundaries, the cues of each boundary and junction) spread over the
// machine's cores. Each item writes only its own
// output, so results do not depend on the number of threads.
#pragma once

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace hair25d::layering::detail {

// Calls f(i) once for every i in [0, n), on the calling thread and up to
// max_threads − 1 more (items handed out one at a time, as costs vary with
// boundary length), one thread per `items_per_thread` items at most. The first exception thrown by
// f is rethrown here after all threads have stopped; items not yet started are then skipped.
template <class F>
void parallel_for(int n, F&& f, int max_threads = 0, int items_per_thread = 8) {
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  // Threads cost tens of microseconds to start: not worth it for a handful
  // of small items.
  const int threads =
      std::min({max_threads > 0 ? max_threads : cores, cores,
                (n + std::max(1, items_per_thread) - 1) / std::max(1, items_per_thread)});
  if (threads <= 1) {
    for (int i = 0; i < n; ++i) f(i);
    return;
  }
  std::atomic<int> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr error;
  std::mutex error_mutex;
  auto work = [&] {
    for (int i = next++; i < n && !failed; i = next++) {
      try {
        f(i);
      } catch (...) {
        const std::lock_guard lock(error_mutex);
        if (!error) error = std::current_exception();
        failed = true;
      }
    }
  };
  std::vector<std::jthread> helpers;
  helpers.reserve(threads - 1);
  for (int t = 1; t < threads; ++t) {
    try {
      helpers.emplace_back(work);
    } catch (const std::system_error&) {
      break;  // no more threads to be had: the ones running take every item
    }
  }
  work();
  helpers.clear();  // joins
  if (error) std::rethrow_exception(error);
}

}  // namespace hair25d::layering::detail
