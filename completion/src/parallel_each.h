// Independent jobs on several threads (private).
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <future>
#include <vector>

namespace hair25d::completion::detail {

// Runs fn(k) for every k in [0, n) on up to `threads` threads (this one
// and threads − 1 more), each taking the next k when it is free: a few
// large jobs take most of the time. Each fn(k) must write only its own
// answer, so that the answers do not depend on the threads. An exception
// of a job is thrown here once every thread has stopped.
template <typename Fn>
void parallel_each(std::size_t n, int threads, Fn&& fn) {
  std::atomic<std::size_t> next{0};
  auto work = [&] {
    for (std::size_t k = next++; k < n; k = next++) fn(k);
  };
  std::vector<std::future<void>> others;
  const std::size_t helpers = std::min<std::size_t>(std::max(threads, 1), n);
  for (std::size_t i = 1; i < helpers; ++i) others.push_back(std::async(std::launch::async, work));
  work();
  for (std::future<void>& f : others) f.get();
}

}  // namespace hair25d::completion::detail
