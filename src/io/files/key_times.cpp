// The union of a clip's key times, for the exporters.
#include "rotinterp/io/files/key_times.h"

#include "rotinterp/clip/sampling.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

namespace rotinterp {

namespace {

// Times closer than this are one (assimp merges curve times in float).
constexpr double kSameTimeSeconds = 1e-9;
constexpr double kGridTolerance = 1e-3;
constexpr double kRateSnapTolerance = 1e-5;

}  // namespace

std::vector<double> all_key_times(const Clip& clip) {
  std::vector<double> times;
  for (const RotationTrack& r : clip.rotations) times.insert(times.end(), r.times.begin(), r.times.end());
  for (const auto& tr : clip.translations)
    if (tr) times.insert(times.end(), tr->times.begin(), tr->times.end());
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  return times;
}

}  // namespace rotinterp

namespace rotinterp {

double uniform_frame_time(std::vector<double> seconds) {
  std::sort(seconds.begin(), seconds.end());
  std::vector<double> unique;
  for (double t : seconds)
    if (unique.empty() || t - unique.back() > kSameTimeSeconds) unique.push_back(t);
  if (unique.size() < 2) return 0.0;
  double gap = INFINITY;
  for (std::size_t k = 1; k < unique.size(); ++k) gap = std::min(gap, unique[k] - unique[k - 1]);
  // The step from the whole span: one float gap is too noisy over thousands of frames.
  const double span = unique.back() - unique.front();
  const double step = span / std::round(span / gap);
  for (double t : unique) {
    const double steps = (t - unique.front()) / step;
    if (std::abs(steps - std::round(steps)) > kGridTolerance) return 0.0;
  }
  const std::optional<Rate> exact = recognize_rate(1.0 / step, kRateSnapTolerance);
  return exact ? exact->period() : step;
}

}  // namespace rotinterp
