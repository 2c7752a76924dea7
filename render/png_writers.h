// PNG files written on a work queue while the GL thread draws the next frame (private to render/).
#pragma once

#include "rotinterp/core/progress.h"
#include "rotinterp/core/result.h"
#include "rotinterp/core/work_queue.h"
#include "rotinterp/render/image.h"

#include <atomic>
#include <cstddef>
#include <deque>
#include <filesystem>
#include <future>
#include <string>

namespace rotinterp::render {

// At most kInFlight images wait at a time (bounded memory); the first failure stops it.
class PngWriters {
 public:
  PngWriters(ProgressFn progress, std::size_t total);

  // Blocks while kInFlight images wait. False once a write has failed.
  bool push(std::filesystem::path path, Image image);
  // Waits for every image; the first error, if any.
  Status finish();

 private:
  static constexpr std::size_t kInFlight = 4;
  void collect_one();

  ProgressFn progress_;
  std::size_t total_;
  std::atomic<std::size_t> done_{0};
  std::atomic<bool> failed_{false};
  std::deque<std::future<Status>> writes_;
  Status error_ = Ok{};
  WorkQueue queue_;  // last: destroyed first, so its jobs finish while the members they use live
};

}  // namespace rotinterp::render
