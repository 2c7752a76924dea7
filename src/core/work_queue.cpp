// WorkQueue: the library's one thread pool.
#include "rotinterp/core/work_queue.h"

#include <algorithm>
#include <system_error>

namespace rotinterp {

unsigned thread_count(unsigned requested) {
  return requested ? requested : std::max(1u, std::thread::hardware_concurrency());
}

WorkQueue::WorkQueue(unsigned threads) {
  threads = thread_count(threads);
  for (unsigned i = 0; i < threads; ++i) {
    try {
      workers_.emplace_back([this] { run(); });
    } catch (const std::system_error&) {
      break;  // no more threads to be had: fewer do the work
    }
  }
}

WorkQueue::~WorkQueue() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    closing_ = true;
  }
  ready_.notify_all();
  for (std::thread& t : workers_) t.join();
}

void WorkQueue::run() {
  for (;;) {
    std::function<void()> job;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      ready_.wait(lock, [&] { return !jobs_.empty() || closing_; });
      if (jobs_.empty()) return;
      job = std::move(jobs_.front());
      jobs_.pop_front();
    }
    job();  // a packaged_task: what it throws goes to its future
  }
}

}  // namespace rotinterp
