// core/work_queue.h: jobs run on the workers, results and exceptions come back
// through their futures in submission order, and the destructor finishes the queue.
#include "rotinterp/core/work_queue.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <new>
#include <set>
#include <stdexcept>
#include <thread>

using namespace rotinterp;

TEST(WorkQueue, ResultsComeBackInSubmissionOrderFromSeveralThreads) {
  WorkQueue queue(4);
  ASSERT_EQ(queue.threads(), 4u);
  std::vector<std::future<std::pair<int, std::thread::id>>> results;
  for (int i = 0; i < 200; ++i)
    results.push_back(queue.submit([i] {
      std::this_thread::sleep_for(std::chrono::microseconds((i * 37) % 200));  // finish out of order
      return std::make_pair(i * i, std::this_thread::get_id());
    }));
  std::set<std::thread::id> threads;
  for (int i = 0; i < 200; ++i) {
    const auto [value, thread] = results[static_cast<std::size_t>(i)].get();
    EXPECT_EQ(value, i * i);
    threads.insert(thread);
  }
  EXPECT_GT(threads.size(), 1u);
  EXPECT_EQ(threads.count(std::this_thread::get_id()), 0u);  // the caller only waits
}

TEST(WorkQueue, AJobsExceptionReachesItsFutureAndTheOthersStillRun) {
  WorkQueue queue(2);
  auto bad = queue.submit([]() -> int { throw std::bad_alloc(); });
  auto good = queue.submit([] { return 7; });
  EXPECT_THROW(bad.get(), std::bad_alloc);
  EXPECT_EQ(good.get(), 7);
}

TEST(WorkQueue, TheDestructorFinishesEveryQueuedJob) {
  std::atomic<int> ran{0};
  {
    WorkQueue queue(2);
    for (int i = 0; i < 50; ++i)
      (void)queue.submit([&ran] {
        std::this_thread::sleep_for(std::chrono::microseconds(100));
        ++ran;
      });
  }
  EXPECT_EQ(ran.load(), 50);
}
