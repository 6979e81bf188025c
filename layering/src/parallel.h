// Independent per-item work of the layering (measuring lines along
// boundaries, the cues of each boundary and junction) spread over the
// machine's cores. Each item writes only its own
// output, so results do not depend on the number of threads.
#pragma once

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <deque>
#include <exception>
#include <functional>
#include <future>
#include <memory>
#include <mutex>
#include <system_error>
#include <thread>
#include <type_traits>

namespace hair25d::layering::detail {

// Calls f(i) once for every i in [0, n), on the calling thread and up to
// max_threads − 1 more (items handed out one at a time, as costs vary with
// boundary length), one thread per `items_per_thread` items at most. The
// first exception thrown by f is rethrown here after all items under way
// have ended; items not yet started are then skipped.
//
// The caller waits only for items a helper has taken, never for a helper to
// start: on a busy machine a new thread may get a core late, and by then the
// caller has often done every item. Helpers are detached; one that starts
// after the call returned finds no item left and touches only the counters
// it shares (never f).
template <class F>
void parallel_for(int n, F&& f, int max_threads = 0, int items_per_thread = 8) {
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  // Threads cost tens of microseconds to start: not worth it for a handful
  // of small items.
  const int per = std::max(1, items_per_thread);
  const int threads = std::min({max_threads > 0 ? max_threads : cores, cores, (n + per - 1) / per});
  if (threads <= 1) {
    for (int i = 0; i < n; ++i) f(i);
    return;
  }
  struct Shared {
    explicit Shared(int count) : n(count) {}
    const int n;
    std::atomic<int> next{0};
    std::atomic<int> busy{0};  // helpers between announcing and ending an item
    std::atomic<bool> failed{false};
    std::mutex error_mutex;
    std::exception_ptr error;
  };
  auto run = [](Shared& s, int i, auto& body) {
    try {
      body(i);
    } catch (...) {
      const std::lock_guard lock(s.error_mutex);
      if (!s.error) s.error = std::current_exception();
      s.failed = true;
    }
  };
  auto shared = std::make_shared<Shared>(n);
  auto* body = &f;
  auto helper = [shared, body, run] {
    for (;;) {
      // Announced before an item is taken, so the caller, once every item is
      // taken, waits for this one.
      ++shared->busy;
      const int i = shared->next++;
      const bool take = i < shared->n && !shared->failed;
      if (take) run(*shared, i, *body);
      --shared->busy;
      shared->busy.notify_all();
      if (!take) return;
    }
  };
  for (int t = 1; t < threads; ++t) {
    try {
      std::thread(helper).detach();
    } catch (const std::system_error&) {
      break;  // no more threads to be had: the ones running take every item
    }
  }
  for (int i = shared->next++; i < n && !shared->failed; i = shared->next++) run(*shared, i, f);
  // Every item is taken: wait for those under way on helpers.
  for (int b = shared->busy.load(); b != 0; b = shared->busy.load()) shared->busy.wait(b);
  if (shared->error) std::rethrow_exception(shared->error);
}

// One helper thread that runs the jobs given to it one after another, in
// the order given: a chain of background steps (the line response's grey
// conversion, early blur and noise estimate) shares it instead of starting
// a thread each, which costs tens of microseconds. submit() returns the
// job's future (its result or exception). Jobs still queued when the worker
// is destroyed are run first. Where no thread can be made, jobs run in
// submit().
class Worker {
 public:
  Worker() {
    try {
      thread_ = std::thread([this] { run(); });
    } catch (const std::system_error&) {
      // No thread: submit() runs each job itself.
    }
  }
  ~Worker() {
    {
      const std::lock_guard lock(mutex_);
      stop_ = true;
    }
    ready_.notify_one();
    if (thread_.joinable()) thread_.join();
  }
  Worker(const Worker&) = delete;
  Worker& operator=(const Worker&) = delete;

  template <class F>
  std::future<std::invoke_result_t<F&>> submit(F f) {
    auto task = std::make_shared<std::packaged_task<std::invoke_result_t<F&>()>>(std::move(f));
    auto result = task->get_future();
    if (!thread_.joinable()) {
      (*task)();
      return result;
    }
    {
      const std::lock_guard lock(mutex_);
      jobs_.emplace_back([task] { (*task)(); });
    }
    ready_.notify_one();
    return result;
  }

 private:
  void run() {
    for (;;) {
      std::function<void()> job;
      {
        std::unique_lock lock(mutex_);
        ready_.wait(lock, [this] { return stop_ || !jobs_.empty(); });
        if (jobs_.empty()) return;  // stopped, nothing left
        job = std::move(jobs_.front());
        jobs_.pop_front();
      }
      job();  // a packaged_task: exceptions go to its future
    }
  }
  std::mutex mutex_;
  std::condition_variable ready_;
  std::deque<std::function<void()>> jobs_;
  bool stop_ = false;
  std::thread thread_;
};

}  // namespace hair25d::layering::detail
