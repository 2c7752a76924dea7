#include "common.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <mutex>

namespace rotinterp::cli {

int fail(std::string_view message) {
  std::fprintf(stderr, "rotinterp: %.*s\n", static_cast<int>(message.size()), message.data());
  return kExitFailure;
}

int fail_usage(std::string_view message) {
  fail(message);
  return kExitUsage;
}

std::vector<std::string> split_comma_list(std::string_view text) {
  std::vector<std::string> items;
  for (std::size_t begin = 0; begin <= text.size();) {
    const std::size_t comma = std::min(text.find(',', begin), text.size());
    if (comma > begin) items.emplace_back(text.substr(begin, comma - begin));
    begin = comma + 1;
  }
  return items;
}

static bool progress_visible(bool quiet) { return !quiet && ::isatty(STDERR_FILENO); }

ProgressFn make_progress(std::string label, bool quiet) {
  if (!progress_visible(quiet)) return {};
  struct State {
    std::mutex mutex;
    std::chrono::steady_clock::time_point last{};
  };
  auto state = std::make_shared<State>();
  return [label = std::move(label), state](std::size_t done, std::size_t total) {
    std::lock_guard<std::mutex> lock(state->mutex);
    const auto now = std::chrono::steady_clock::now();
    if (done < total && now - state->last < std::chrono::milliseconds(100)) return;  // at most 10 redraws/s
    state->last = now;
    const int pct = total ? static_cast<int>(100.0 * static_cast<double>(done) / static_cast<double>(total)) : 100;
    std::fprintf(stderr, "\r%s  %zu/%zu (%d%%)   ", label.c_str(), done, total, pct);
    std::fflush(stderr);
  };
}

void end_progress(bool quiet) {
  if (progress_visible(quiet)) std::fprintf(stderr, "\r\033[K");
}

}  // namespace rotinterp::cli
