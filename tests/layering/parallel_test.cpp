// The layering's threads (layering/src/parallel.h): parallel_for against a
// plain loop, on threads started for the call and on a pool kept for many
// calls; loops and jobs started now and finished later; exceptions; the
// pool's and the worker's ends; the worker's job order.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <future>
#include <memory>
#include <optional>
#include <stdexcept>
#include <thread>
#include <utility>
#include <vector>

#include "parallel.h"

namespace hair25d::layering {
namespace {

// Every item once, on any number of threads started for the call or taken
// from a pool (one pool for many calls, as in a layering); the call returns
// only when every item has ended (items of uneven cost, some slow).
TEST(ParallelFor, CallsEveryItemOnceAndWaitsForThem) {
  for (const int helpers : {-1, 0, 1, 3}) {
    std::optional<detail::Pool> pool;
    if (helpers >= 0) pool.emplace(helpers);
    if (pool) {
      ASSERT_EQ(pool->helpers(), helpers);
    }
    detail::Pool* p = pool ? &*pool : nullptr;
    for (const int n : {0, 1, 2, 7, 8, 9, 64, 257})
      for (const auto& [threads, per] :
           {std::pair{0, 8}, std::pair{0, 1}, std::pair{2, 1}, std::pair{1, 1}, std::pair{16, 1}}) {
        std::vector<std::atomic<int>> calls(n);
        std::vector<int> done(n, 0);
        detail::parallel_for(
            p, n,
            [&](int i) {
              if (i % 5 == 0) std::this_thread::sleep_for(std::chrono::microseconds(200));
              ++calls[i];
              done[i] = i + 1;
            },
            threads, per);
        for (int i = 0; i < n; ++i) {
          ASSERT_EQ(calls[i].load(), 1) << "n " << n << ", item " << i << ", pool " << helpers;
          ASSERT_EQ(done[i], i + 1) << "n " << n << ", item " << i << ", pool " << helpers;
        }
      }
  }
}

// A pool's helpers really take items: with one helper, an item that waits
// until another item has run on a second thread ends (on the caller alone
// it would wait for ever; the wait is bounded so a failure does not hang).
TEST(ParallelFor, PoolHelpersTakeItems) {
  detail::Pool pool(1);
  ASSERT_EQ(pool.helpers(), 1);
  for (int trial = 0; trial < 5; ++trial) {
    std::atomic<int> arrived{0};
    std::atomic<bool> met{false};
    detail::parallel_for(
        &pool, 2,
        [&](int) {
          ++arrived;
          const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(5);
          while (arrived.load() < 2 && std::chrono::steady_clock::now() < until)
            std::this_thread::yield();
          if (arrived.load() == 2) met = true;
        },
        2, 1);
    EXPECT_TRUE(met.load()) << "trial " << trial;
  }
}

// Jobs still queued when a pool ends are run by its helpers, which end on
// their own afterwards (the pool does not wait for them).
TEST(Pool, RunsJobsQueuedBeforeItsEnd) {
  auto count = std::make_shared<std::atomic<int>>(0);
  {
    detail::Pool pool(2);
    ASSERT_EQ(pool.helpers(), 2);
    for (int k = 0; k < 50; ++k)
      pool.post([count] {
        std::this_thread::sleep_for(std::chrono::microseconds(100));
        ++*count;
      });
  }
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (count->load() < 50 && std::chrono::steady_clock::now() < until)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  EXPECT_EQ(count->load(), 50);
}

// The first exception is rethrown after the items under way end; no item
// runs once the call has returned (threads started for the call, or a
// pool's, the pool then used again).
TEST(ParallelFor, RethrowsAndStopsTakingItems) {
  detail::Pool pool;
  for (int trial = 0; trial < 20; ++trial) {
    std::atomic<int> started{0}, running{0};
    EXPECT_THROW(detail::parallel_for(
                     trial % 2 == 0 ? nullptr : &pool, 200,
                     [&](int i) {
                       ++started;
                       ++running;
                       std::this_thread::sleep_for(std::chrono::microseconds(50));
                       --running;
                       if (i == 3) throw std::runtime_error("item 3");
                     },
                     0, 1),
                 std::runtime_error);
    EXPECT_EQ(running.load(), 0);
    const int after = started.load();
    EXPECT_LT(after, 200);
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    EXPECT_EQ(started.load(), after);
  }
}

// A loop started and finished later: every item once, on pools of 0–3
// helpers and on threads started for it; the helpers take items while the
// caller is busy elsewhere (with one helper and the caller away, the helper
// ends up doing every item).
TEST(ParallelLoop, CallsEveryItemOnceAcrossTheGap) {
  for (const int helpers : {-1, 0, 1, 3}) {
    std::optional<detail::Pool> pool;
    if (helpers >= 0) pool.emplace(helpers);
    detail::Pool* p = pool ? &*pool : nullptr;
    for (const int n : {0, 1, 2, 9, 64}) {
      std::vector<std::atomic<int>> calls(n);
      std::vector<int> done(n, 0);
      detail::ParallelLoop loop(
          p, n,
          [&](int i) {
            ++calls[i];
            done[i] = i + 1;
          },
          0, 1);
      std::this_thread::sleep_for(std::chrono::microseconds(300));  // the caller's other work
      loop.finish();
      loop.finish();  // a second finish does nothing
      for (int i = 0; i < n; ++i) {
        ASSERT_EQ(calls[i].load(), 1) << "n " << n << ", item " << i << ", pool " << helpers;
        ASSERT_EQ(done[i], i + 1) << "n " << n << ", item " << i << ", pool " << helpers;
      }
    }
  }
  // One helper, items of 50 µs, the caller away for up to 5 s: the helper
  // takes them all (it would wait for ever if nothing ran before finish()).
  detail::Pool pool(1);
  std::atomic<int> left{40};
  std::vector<std::thread::id> by(40);
  detail::ParallelLoop loop(
      &pool, 40,
      [&](int i) {
        std::this_thread::sleep_for(std::chrono::microseconds(50));
        by[i] = std::this_thread::get_id();
        --left;
      },
      2, 1);
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  while (left.load() > 0 && std::chrono::steady_clock::now() < until)
    std::this_thread::sleep_for(std::chrono::microseconds(100));
  EXPECT_EQ(left.load(), 0);
  loop.finish();
  for (int i = 0; i < 40; ++i) EXPECT_NE(by[i], std::this_thread::get_id()) << "item " << i;
}

// The first exception is rethrown by finish(); a loop ended without
// finish() (as when an exception unwinds past it) starts no item after its
// end and waits for those under way.
TEST(ParallelLoop, RethrowsAndStopsAtItsEnd) {
  detail::Pool pool(1);
  {
    detail::ParallelLoop loop(
        &pool, 50,
        [](int i) {
          if (i == 7) throw std::runtime_error("item 7");
        },
        0, 1);
    EXPECT_THROW(loop.finish(), std::runtime_error);
  }
  for (int trial = 0; trial < 10; ++trial) {
    std::atomic<int> started{0}, running{0};
    {
      detail::ParallelLoop loop(
          &pool, 1000,
          [&](int) {
            ++started;
            ++running;
            std::this_thread::sleep_for(std::chrono::microseconds(100));
            --running;
          },
          0, 1);
      std::this_thread::sleep_for(std::chrono::microseconds(500));
    }
    EXPECT_EQ(running.load(), 0) << "trial " << trial;
    const int after = started.load();
    EXPECT_LT(after, 1000) << "trial " << trial;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    EXPECT_EQ(started.load(), after) << "trial " << trial;
  }
}

// A background job runs once: on the pool's helper when it is free (the
// caller away), on the caller when the pool has no helper or its helper is
// busy, and finish() returns after it; its exception comes out of finish().
TEST(BackgroundTask, RunsOnceWhereverItIsTaken) {
  {
    detail::Pool pool(1);
    std::atomic<int> runs{0};
    std::thread::id on;
    detail::BackgroundTask task(&pool, [&] {
      on = std::this_thread::get_id();
      ++runs;
    });
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    while (runs.load() == 0 && std::chrono::steady_clock::now() < until)
      std::this_thread::sleep_for(std::chrono::microseconds(100));
    task.finish();
    task.finish();
    EXPECT_EQ(runs.load(), 1);
    EXPECT_NE(on, std::this_thread::get_id());
  }
  {
    detail::Pool pool(0);
    int runs = 0;
    std::thread::id on;
    detail::BackgroundTask task(&pool, [&] {
      on = std::this_thread::get_id();
      ++runs;
    });
    task.finish();
    EXPECT_EQ(runs, 1);
    EXPECT_EQ(on, std::this_thread::get_id());
  }
  {
    // The helper is held by an earlier job until the task has been finished
    // here: the caller runs it, and the helper, once free, does not.
    detail::Pool pool(1);
    std::promise<void> release;
    std::shared_future<void> released = release.get_future().share();
    pool.post([released] { released.wait(); });
    auto runs = std::make_shared<std::atomic<int>>(0);
    {
      detail::BackgroundTask task(&pool, [runs] { ++*runs; });
      task.finish();
      EXPECT_EQ(runs->load(), 1);
    }
    release.set_value();
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    EXPECT_EQ(runs->load(), 1);
  }
  {
    detail::Pool pool(1);
    detail::BackgroundTask task(&pool, [] { throw std::runtime_error("job"); });
    EXPECT_THROW(task.finish(), std::runtime_error);
  }
  {
    // Ended without finish() while the helper is held: the job never runs.
    detail::Pool pool(1);
    std::promise<void> release;
    std::shared_future<void> released = release.get_future().share();
    pool.post([released] { released.wait(); });
    auto runs = std::make_shared<std::atomic<int>>(0);
    {
      detail::BackgroundTask task(&pool, [runs] { ++*runs; });
    }
    release.set_value();
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    EXPECT_EQ(runs->load(), 0);
  }
}

// The worker runs its jobs one after another in the order given, hands
// back results and exceptions through the futures, and its end waits for
// the jobs still queued.
TEST(Worker, RunsJobsInOrderWithResultsAndExceptions) {
  std::vector<int> order;
  std::future<void> last;
  {
    detail::Worker worker;
    auto slow = worker.submit([&] {
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
      order.push_back(1);
      return 7;
    });
    auto failing = worker.submit([&]() -> double {
      order.push_back(2);
      throw std::runtime_error("job failed");
    });
    for (int k = 3; k <= 40; ++k) last = worker.submit([&order, k] { order.push_back(k); });
    EXPECT_EQ(slow.get(), 7);
    EXPECT_THROW(failing.get(), std::runtime_error);
  }  // jobs still queued run before the worker goes
  EXPECT_EQ(last.wait_for(std::chrono::seconds(0)), std::future_status::ready);
  ASSERT_EQ(order.size(), 40u);
  for (int k = 0; k < 40; ++k) EXPECT_EQ(order[k], k + 1);
}

}  // namespace
}  // namespace hair25d::layering
