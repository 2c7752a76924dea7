// evaluate_fbx_curve: one FBX curve at a time, as the DCC evaluates it (steps,
// lines, weighted Bezier segments solved for time, extrapolation).
#include "rotinterp/io/fbx/fbx_curve_eval.h"

#include <algorithm>
#include <cmath>

namespace rotinterp {

namespace {

constexpr double kTicks = static_cast<double>(kFbxTicksPerSecond);
// Newton on the Bezier's time polynomial stops when |x(u) − s| is below this
// (a fraction of the segment: 1e-12 of a 1-hour segment is 4 ns).
constexpr double kTimeSolveTolerance = 1e-12;
constexpr int kTimeSolveIterations = 64;

double bezier(double p0, double p1, double p2, double p3, double u) {
  const double v = 1.0 - u;
  return v * v * v * p0 + 3.0 * v * v * u * p1 + 3.0 * v * u * u * p2 + u * u * u * p3;
}

// The parameter u in [0, 1] where the time Bezier (0, x1, x2, 1) reaches s.
// Monotone for x1, x2 in [0, 1]: Newton from the linear guess, kept inside a
// bisection bracket so that it cannot leave it.
double solve_time(double x1, double x2, double s) {
  if (std::abs(x1 - 1.0 / 3.0) < 1e-12 && std::abs(x2 - 2.0 / 3.0) < 1e-12) return s;  // x(u) = u
  double lo = 0.0, hi = 1.0, u = s;
  for (int i = 0; i < kTimeSolveIterations; ++i) {
    const double x = bezier(0.0, x1, x2, 1.0, u) - s;
    if (std::abs(x) < kTimeSolveTolerance) break;
    (x < 0.0 ? lo : hi) = u;
    const double v = 1.0 - u;
    const double dx = 3.0 * (v * v * x1 + 2.0 * v * u * (x2 - x1) + u * u * (1.0 - x2));
    double next = dx > 0.0 ? u - x / dx : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    u = next;
  }
  return u;
}

// The segment from key i to key i + 1.
double segment(const std::vector<FbxKey>& keys, std::size_t i, double ticks) {
  const FbxKey& a = keys[i];
  const FbxKey& b = keys[i + 1];
  const double span = static_cast<double>(b.ticks - a.ticks);
  const double s = std::clamp((ticks - static_cast<double>(a.ticks)) / span, 0.0, 1.0);
  switch (a.interpolation) {
    case FbxInterpolation::constant_previous: return a.value;
    case FbxInterpolation::constant_next: return b.value;
    case FbxInterpolation::linear: return a.value + (b.value - a.value) * s;
    case FbxInterpolation::cubic: break;
  }
  const double seconds = span / kTicks;
  const FbxKeyTangents ta = fbx_key_tangents(keys, i), tb = fbx_key_tangents(keys, i + 1);
  const double w1 = std::clamp(ta.right_weight, 0.0, 1.0), w2 = std::clamp(tb.left_weight, 0.0, 1.0);
  const double y1 = a.value + ta.right_slope * w1 * seconds;
  const double y2 = b.value - tb.left_slope * w2 * seconds;
  const double v = bezier(a.value, y1, y2, b.value, solve_time(w1, 1.0 - w2, s));
  return std::isfinite(v) ? v : a.value;
}

// Inside the keys (first ≤ ticks ≤ last).
double inside(const std::vector<FbxKey>& keys, double ticks) {
  const auto after = std::upper_bound(keys.begin(), keys.end(), ticks,
                                      [](double t, const FbxKey& k) { return t < static_cast<double>(k.ticks); });
  if (after == keys.end()) return keys.back().value;
  if (after == keys.begin()) return keys.front().value;
  return segment(keys, static_cast<std::size_t>(after - keys.begin()) - 1, ticks);
}

// Slopes (value per tick) at the ends, for keep-slope extrapolation: the first
// key's outgoing tangent (its left one is not stored), the last key's incoming one.
double start_slope(const std::vector<FbxKey>& keys) {
  const FbxInterpolation i = keys[0].interpolation;
  if (i == FbxInterpolation::constant_previous || i == FbxInterpolation::constant_next) return 0.0;
  return fbx_key_tangents(keys, 0).right_slope / kTicks;
}
double end_slope(const std::vector<FbxKey>& keys) {
  if (keys.size() < 2) return 0.0;
  return fbx_key_tangents(keys, keys.size() - 1).left_slope / kTicks;
}

}  // namespace

namespace {

double evaluate_unguarded(const FbxCurve& curve, double ticks) {
  const std::vector<FbxKey>& keys = curve.keys;
  if (keys.empty()) return std::isfinite(curve.default_value) ? curve.default_value : 0.0;
  if (!std::isfinite(ticks)) ticks = 0.0;
  const double first = static_cast<double>(keys.front().ticks), last = static_cast<double>(keys.back().ticks);
  const double period = last - first;
  const bool before = ticks < first;
  if (!before && ticks <= last) return inside(keys, ticks);
  const FbxExtrapolationRule& rule = before ? curve.pre : curve.post;
  if (rule.mode == FbxExtrapolation::constant || period <= 0.0) return before ? keys.front().value : keys.back().value;
  if (rule.mode == FbxExtrapolation::keep_slope)
    return before ? keys.front().value + start_slope(keys) * (ticks - first)
                  : keys.back().value + end_slope(keys) * (ticks - last);
  // Repetition and mirror: cycles counted outward from the keyed span.
  const double outside = before ? first - ticks : ticks - last;
  const double cycle = std::ceil(outside / period);
  if (rule.repetitions >= 0 && cycle > rule.repetitions) {
    const bool ends_mirrored = rule.mode == FbxExtrapolation::mirror && static_cast<long long>(rule.repetitions) % 2 == 1;
    return (before != ends_mirrored) ? keys.front().value : keys.back().value;
  }
  double local = std::fmod(ticks - first, period);
  if (local < 0.0) local += period;
  const bool mirrored = rule.mode == FbxExtrapolation::mirror && std::fmod(cycle, 2.0) == 1.0;
  return inside(keys, mirrored ? last - local : first + local);
}

}  // namespace

double evaluate_fbx_curve(const FbxCurve& curve, double ticks) {
  const double v = evaluate_unguarded(curve, ticks);
  if (std::isfinite(v)) return v;
  // Keep-slope far out, or slopes near the float limit: the nearest end key.
  return ticks < static_cast<double>(curve.keys.front().ticks) ? curve.keys.front().value : curve.keys.back().value;
}

double fbx_sample_count(double hz, std::int64_t end_ticks) {
  if (!(hz > 0.0) || end_ticks < 0) return 0.0;
  return std::floor((static_cast<double>(end_ticks) + 1e-6) / kTicks * hz) + 1.0;
}

std::vector<double> sample_fbx_curve(const FbxCurve& curve, double hz, std::int64_t end_ticks) {
  std::vector<double> out;
  if (!(hz > 0.0) || end_ticks < 0) return out;
  // k/hz seconds as ticks, from k (never accumulated); a sample within a
  // millionth of a tick of the end belongs to the take.
  const double end = static_cast<double>(end_ticks) + 1e-6;
  for (std::size_t k = 0;; ++k) {
    const double ticks = static_cast<double>(k) * kTicks / hz;
    if (ticks > end) break;
    out.push_back(evaluate_fbx_curve(curve, ticks));
  }
  return out;
}

}  // namespace rotinterp
