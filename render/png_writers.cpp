// PNG files written on a work queue, a bounded number at a time, while the next frame is drawn.
#include "png_writers.h"

#include <utility>

namespace rotinterp::render {

PngWriters::PngWriters(ProgressFn progress, std::size_t total)
    : progress_(std::move(progress)), total_(total), queue_(2) {}

bool PngWriters::push(std::filesystem::path path, Image image) {
  while (writes_.size() >= kInFlight) collect_one();
  if (!error_) return false;
  writes_.push_back(queue_.submit([this, path = std::move(path), image = std::move(image)]() -> Status {
    if (failed_) return Ok{};
    Status s = write_png(image, path);
    if (!s) {
      failed_ = true;
      return s;
    }
    if (progress_) progress_(++done_, total_);
    return Ok{};
  }));
  return true;
}

Status PngWriters::finish() {
  while (!writes_.empty()) collect_one();
  return error_;
}

void PngWriters::collect_one() {
  Status s = writes_.front().get();
  writes_.pop_front();
  if (!s && error_) error_ = s;  // the first failure, its kind kept (an output's names the output)
}

}  // namespace rotinterp::render
