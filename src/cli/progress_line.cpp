// The progress line: its text, and its drawing on a terminal at most 10 times a second.
#include "progress_line.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <mutex>

namespace rotinterp::cli {

static bool progress_visible(bool quiet) { return !quiet && ::isatty(STDERR_FILENO); }

std::string duration_text(double seconds) {
  const auto s = static_cast<long long>(std::llround(seconds));
  char text[48];
  if (s >= 3600) std::snprintf(text, sizeof text, "%lldh%02lldm", s / 3600, s / 60 % 60);
  else if (s >= 60) std::snprintf(text, sizeof text, "%lldm%02llds", s / 60, s % 60);
  else std::snprintf(text, sizeof text, "%llds", s);
  return text;
}

std::string progress_line(const std::string& label, const std::string& unit, std::size_t done, std::size_t total,
                          double seconds) {
  const int pct = total ? static_cast<int>(100.0 * static_cast<double>(done) / static_cast<double>(total)) : 100;
  const double rate = seconds > 0.0 ? static_cast<double>(done) / seconds : 0.0;
  const std::string per = unit.empty() ? "/s" : " " + unit + "/s";
  char text[256];
  std::snprintf(text, sizeof text, "%s  %zu/%zu%s%s (%d%%)  %.3g%s  ETA %s", label.c_str(), done, total,
                unit.empty() ? "" : " ", unit.c_str(), pct, rate, per.c_str(),
                rate > 0.0 ? duration_text(static_cast<double>(total - std::min(done, total)) / rate).c_str() : "?");
  return text;
}

ProgressFn make_progress(std::string label, bool quiet, std::string unit) {
  if (!progress_visible(quiet)) return {};
  struct State {
    std::mutex mutex;
    std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now();
    std::chrono::steady_clock::time_point last{};
  };
  auto state = std::make_shared<State>();
  return [label = std::move(label), unit = std::move(unit), state](std::size_t done, std::size_t total) {
    std::lock_guard<std::mutex> lock(state->mutex);
    const auto now = std::chrono::steady_clock::now();
    if (done < total && now - state->last < std::chrono::milliseconds(100)) return;  // at most 10 redraws/s
    state->last = now;
    const double seconds = std::chrono::duration<double>(now - state->started).count();
    std::fprintf(stderr, "\r\033[K%s", progress_line(label, unit, done, total, seconds).c_str());
    std::fflush(stderr);
  };
}

void end_progress(bool quiet) {
  if (progress_visible(quiet)) std::fprintf(stderr, "\r\033[K");
}

}  // namespace rotinterp::cli
