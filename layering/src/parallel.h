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
#include <utility>
#include <vector>

namespace hair25d::layering::detail {

// Helper threads kept for one layering: parallel_for hands its items to
// them instead of starting a thread per call (starting one costs the caller
// tens of microseconds, and a layering has about ten parallel steps). Jobs
// run in the order posted, each on whichever helper is free. The helpers
// are detached: the pool's end does not wait for them to wake up and end,
// so a job must not refer to anything that may end before it runs
// (parallel_for's jobs refer only to what they share with the call).
class Pool {
 public:
  // `helpers` threads (default: one fewer than the cores); fewer where no
  // more threads can be made.
  explicit Pool(int helpers = -1) : state_(std::make_shared<State>()) {
    if (helpers < 0)
      helpers = static_cast<int>(std::max(1u, std::thread::hardware_concurrency())) - 1;
    for (int t = 0; t < helpers; ++t) {
      try {
        std::thread([state = state_] { run(*state); }).detach();
        ++helpers_;
      } catch (const std::system_error&) {
        break;  // the ones made take every job
      }
    }
  }
  // Helpers end once the jobs still queued are done.
  ~Pool() {
    {
      const std::lock_guard lock(state_->mutex);
      state_->stop = true;
    }
    state_->ready.notify_all();
  }
  Pool(const Pool&) = delete;
  Pool& operator=(const Pool&) = delete;

  int helpers() const { return helpers_; }
  // Queues `job` for a helper (there must be one: helpers() > 0).
  void post(std::function<void()> job) {
    {
      const std::lock_guard lock(state_->mutex);
      state_->jobs.push_back(std::move(job));
    }
    state_->ready.notify_one();
  }

 private:
  struct State {
    std::mutex mutex;
    std::condition_variable ready;
    std::deque<std::function<void()>> jobs;
    bool stop = false;
  };
  static void run(State& s) {
    for (;;) {
      std::function<void()> job;
      {
        std::unique_lock lock(s.mutex);
        s.ready.wait(lock, [&s] { return s.stop || !s.jobs.empty(); });
        if (s.jobs.empty()) return;  // stopped, nothing left
        job = std::move(s.jobs.front());
        s.jobs.pop_front();
      }
      job();  // parallel_for's helpers catch what their items throw
    }
  }
  std::shared_ptr<State> state_;  // shared with the helpers, which may outlive the pool
  int helpers_ = 0;
};

// A parallel_for started now and finished later: helpers take items while
// the caller does other work (one helper job per thread, queued behind the
// pool's earlier jobs), and finish() takes the items still left on the
// calling thread, waits for those under way on helpers and rethrows the
// first exception an item threw. Items not taken before finish() all run on
// the caller. The loop must outlive its items: it is neither copied nor
// moved, and its end (without finish(), e.g. while an exception unwinds)
// skips the items not yet taken and waits for those under way. Threads as
// parallel_for: up to max_threads, one per `items_per_thread` items.
template <class F>
class ParallelLoop {
 public:
  ParallelLoop(Pool* pool, int n, F f, int max_threads = 0, int items_per_thread = 8)
      : f_(std::move(f)), shared_(std::make_shared<Shared>(n)) {
    const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    // Threads cost tens of microseconds to start: not worth it for a handful
    // of small items.
    const int per = std::max(1, items_per_thread);
    int threads = std::min({max_threads > 0 ? max_threads : cores, cores, (n + per - 1) / per});
    if (pool != nullptr) threads = std::min(threads, pool->helpers() + 1);
    auto helper = [shared = shared_, body = &f_] {
      for (;;) {
        // Announced before an item is taken, so the caller, once every item
        // is taken, waits for this one.
        ++shared->busy;
        const int i = shared->next++;
        const bool take = i < shared->n && !shared->failed;
        if (take) run(*shared, i, *body);
        --shared->busy;
        shared->busy.notify_all();
        if (!take) return;
      }
    };
    try {
      for (int t = 1; t < threads; ++t) {
        if (pool != nullptr) {
          pool->post(helper);
          continue;
        }
        try {
          std::thread(helper).detach();
        } catch (const std::system_error&) {
          break;  // no more threads to be had: the ones running take every item
        }
      }
    } catch (...) {
      // No destructor runs for a loop not made: stop the helpers posted.
      shared_->failed = true;
      wait();
      throw;
    }
  }
  ParallelLoop(const ParallelLoop&) = delete;
  ParallelLoop& operator=(const ParallelLoop&) = delete;
  ~ParallelLoop() {
    if (finished_) return;
    shared_->failed = true;  // no item starts from here on
    wait();
  }

  void finish() {
    if (finished_) return;
    finished_ = true;
    Shared& s = *shared_;
    for (int i = s.next++; i < s.n && !s.failed; i = s.next++) run(s, i, f_);
    wait();
    if (s.error) std::rethrow_exception(s.error);
  }

 private:
  struct Shared {
    explicit Shared(int count) : n(count) {}
    const int n;
    std::atomic<int> next{0};
    std::atomic<int> busy{0};  // helpers between announcing and ending an item
    std::atomic<bool> failed{false};
    std::mutex error_mutex;
    std::exception_ptr error;
  };
  static void run(Shared& s, int i, F& body) {
    try {
      body(i);
    } catch (...) {
      const std::lock_guard lock(s.error_mutex);
      if (!s.error) s.error = std::current_exception();
      s.failed = true;
    }
  }
  // Every item is taken (or skipped): wait for those under way on helpers.
  void wait() {
    for (int b = shared_->busy.load(); b != 0; b = shared_->busy.load()) shared_->busy.wait(b);
  }
  F f_;
  std::shared_ptr<Shared> shared_;  // a helper starting late touches only this
  bool finished_ = false;
};

// One job started on `pool`'s helper (queued behind its earlier jobs) and
// finished by finish(): run there by the caller if no helper has taken it
// yet, else waited for; its exception is rethrown by finish(). Like
// ParallelLoop, it must outlive its job: its end (without finish(), e.g.
// while an exception unwinds) keeps a helper from starting the job, or
// waits for it where one has.
template <class F>
class BackgroundTask {
 public:
  BackgroundTask(Pool* pool, F f) : f_(std::move(f)), shared_(std::make_shared<Shared>()) {
    if (pool == nullptr || pool->helpers() == 0) return;
    pool->post([shared = shared_, body = &f_] {
      if (!shared->claim()) return;  // the caller has it
      shared->run(*body);
    });
  }
  BackgroundTask(const BackgroundTask&) = delete;
  BackgroundTask& operator=(const BackgroundTask&) = delete;
  ~BackgroundTask() {
    if (finished_) return;
    if (shared_->claim()) return;  // never started: nothing to wait for
    shared_->wait();
  }

  void finish() {
    if (finished_) return;
    finished_ = true;
    if (shared_->claim())
      shared_->run(f_);
    else
      shared_->wait();
    if (shared_->error) std::rethrow_exception(shared_->error);
  }

 private:
  struct Shared {
    std::atomic<bool> taken{false};
    std::atomic<bool> done{false};
    std::exception_ptr error;  // written before done, read after it
    bool claim() { return !taken.exchange(true); }
    void run(F& body) {
      try {
        body();
      } catch (...) {
        error = std::current_exception();
      }
      done = true;
      done.notify_all();
    }
    void wait() {
      while (!done.load()) done.wait(false);
    }
  };
  F f_;
  std::shared_ptr<Shared> shared_;  // a helper starting late touches only this
  bool finished_ = false;
};

// Calls f(i) once for every i in [0, n), on the calling thread and up to
// max_threads − 1 more (items handed out one at a time, as costs vary with
// boundary length), one thread per `items_per_thread` items at most. The
// helpers are `pool`'s where one is given, else threads started for the
// call. The first exception thrown by f is rethrown here after all items
// under way have ended; items not yet started are then skipped.
//
// The caller waits only for items a helper has taken, never for a helper to
// start: on a busy machine a new thread may get a core late (a pool's helper
// may be busy with an earlier job), and by then the caller has often done
// every item. A helper that starts after the call returned finds no item
// left and touches only the counters it shares (never f).
template <class F>
void parallel_for(Pool* pool, int n, F&& f, int max_threads = 0, int items_per_thread = 8) {
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const int per = std::max(1, items_per_thread);
  int threads = std::min({max_threads > 0 ? max_threads : cores, cores, (n + per - 1) / per});
  if (pool != nullptr) threads = std::min(threads, pool->helpers() + 1);
  if (threads <= 1) {
    for (int i = 0; i < n; ++i) f(i);
    return;
  }
  ParallelLoop<std::reference_wrapper<std::remove_reference_t<F>>> loop(
      pool, n, std::ref(f), max_threads, items_per_thread);
  loop.finish();
}

// The same with threads started for the call.
template <class F>
void parallel_for(int n, F&& f, int max_threads = 0, int items_per_thread = 8) {
  parallel_for(nullptr, n, std::forward<F>(f), max_threads, items_per_thread);
}

// One helper thread that runs the jobs given to it one after another, in
// the order given: a chain of background steps (the line response's grey
// conversion, early blur and noise estimate) shares it instead of starting
// a thread each, which costs tens of microseconds. submit() returns the
// job's future (its result or exception). The worker's end waits for the
// jobs still queued or running, then leaves the thread to end on its own
// (detached: joining would wait for it to wake up). Where no thread can be
// made, jobs run in submit().
class Worker {
 public:
  Worker() : state_(std::make_shared<State>()) {
    try {
      std::thread([state = state_] { run(*state); }).detach();
      threaded_ = true;
    } catch (const std::system_error&) {
      // No thread: submit() runs each job itself.
    }
  }
  ~Worker() {
    std::unique_lock lock(state_->mutex);
    state_->idle.wait(lock, [this] { return state_->jobs.empty() && !state_->running; });
    state_->stop = true;
    lock.unlock();
    state_->ready.notify_one();
  }
  Worker(const Worker&) = delete;
  Worker& operator=(const Worker&) = delete;

  template <class F>
  std::future<std::invoke_result_t<F&>> submit(F f) {
    auto task = std::make_shared<std::packaged_task<std::invoke_result_t<F&>()>>(std::move(f));
    auto result = task->get_future();
    if (!threaded_) {
      (*task)();
      return result;
    }
    {
      const std::lock_guard lock(state_->mutex);
      state_->jobs.emplace_back([task] { (*task)(); });
    }
    state_->ready.notify_one();
    return result;
  }

 private:
  struct State {
    std::mutex mutex;
    std::condition_variable ready;  // a job queued, or stop
    std::condition_variable idle;   // a job ended
    std::deque<std::function<void()>> jobs;
    bool running = false;
    bool stop = false;
  };
  static void run(State& s) {
    std::unique_lock lock(s.mutex);
    for (;;) {
      s.ready.wait(lock, [&s] { return s.stop || !s.jobs.empty(); });
      if (s.jobs.empty()) return;  // stopped, nothing left
      std::function<void()> job = std::move(s.jobs.front());
      s.jobs.pop_front();
      s.running = true;
      lock.unlock();
      job();          // a packaged_task: exceptions go to its future
      job = nullptr;  // the task's state goes before the worker may end
      lock.lock();
      s.running = false;
      s.idle.notify_all();
    }
  }
  std::shared_ptr<State> state_;  // shared with the thread, which may outlive the worker
  bool threaded_ = false;
};

}  // namespace hair25d::layering::detail
