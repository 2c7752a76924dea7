// The one thread pool of the library: eval's (clip, method) tasks, resample's
// joints and render's PNG writes all run on it.
//
// Jobs start in the order they are submitted; each submit gives a std::future of
// the job's result (or of the exception it threw, e.g. std::bad_alloc), so a
// caller consumes results in submission order and bounds the work in flight by
// the futures it holds. The destructor lets queued jobs finish and joins.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <future>
#include <memory>
#include <mutex>
#include <thread>
#include <type_traits>
#include <vector>

namespace rotinterp {

// The threads a caller's request stands for: `requested`, or with 0 one per hardware
// thread. Every library call that runs work in parallel takes its count from its
// caller this way, so a caller that runs files side by side (a folder run) gives
// each call its share instead of pools starting inside pools.
unsigned thread_count(unsigned requested);

class WorkQueue {
 public:
  // `threads` workers (0: one per hardware thread); fewer when the system gives no
  // more, and with none at all, submit runs each job itself.
  explicit WorkQueue(unsigned threads);
  ~WorkQueue();
  WorkQueue(const WorkQueue&) = delete;
  WorkQueue& operator=(const WorkQueue&) = delete;

  unsigned threads() const { return static_cast<unsigned>(workers_.size()); }

  template <class F>
  std::future<std::invoke_result_t<F&>> submit(F job) {
    auto task = std::make_shared<std::packaged_task<std::invoke_result_t<F&>()>>(std::move(job));
    auto future = task->get_future();
    if (workers_.empty()) {
      (*task)();
      return future;
    }
    {
      std::lock_guard<std::mutex> lock(mutex_);
      jobs_.emplace_back([task] { (*task)(); });
    }
    ready_.notify_one();
    return future;
  }

 private:
  void run();

  std::mutex mutex_;
  std::condition_variable ready_;
  std::deque<std::function<void()>> jobs_;
  bool closing_ = false;
  std::vector<std::thread> workers_;
};

}  // namespace rotinterp
