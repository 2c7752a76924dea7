// Translation tracks between keys: linear, or Steffen's monotone cubic; a cycle's, periodic with its per-cycle offset.
#include "rotinterp/clip/translation_curve.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace rotinterp {

namespace {

double sign(double x) { return x > 0.0 ? 1.0 : (x < 0.0 ? -1.0 : 0.0); }

// Steffen's interior tangent from the secants s0 (left, interval h0) and s1
// (right, interval h1).
double steffen_interior(double s0, double s1, double h0, double h1) {
  const double p = (s0 * h1 + s1 * h0) / (h0 + h1);
  return (sign(s0) + sign(s1)) * std::min({std::abs(s0), std::abs(s1), 0.5 * std::abs(p)});
}

// Steffen's end tangent: s_near is the secant of the end interval (h_near), s_far
// the next one (h_far).
double steffen_end(double s_near, double s_far, double h_near, double h_far) {
  const double p = s_near * (1.0 + h_near / (h_near + h_far)) - s_far * h_near / (h_near + h_far);
  if (p * s_near <= 0.0) return 0.0;
  if (std::abs(p) > 2.0 * std::abs(s_near)) return 2.0 * s_near;
  return p;
}

}  // namespace

const char* translation_interp_name(TranslationInterp m) {
  return m == TranslationInterp::linear ? "linear" : "cubic";
}

Result<TranslationInterp> parse_translation_interp(std::string_view name) {
  if (name == "linear") return TranslationInterp::linear;
  if (name == "cubic") return TranslationInterp::cubic;
  return make_error("unknown translation method '" + std::string(name) + "' (valid: linear, cubic)");
}

TranslationCurve::TranslationCurve(const TranslationTrack& track, TranslationInterp method)
    : method_(method), times_(track.times), keys_(track.keys) {
  ROTINTERP_ASSERT(!times_.empty() && times_.size() == keys_.size());
  const std::size_t n = keys_.size();
  if (method_ != TranslationInterp::cubic || n < 2) return;
  tangents_.assign(n, Vec3::Zero());
  std::vector<Vec3> secant(n - 1);
  std::vector<double> h(n - 1);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    h[i] = times_[i + 1] - times_[i];
    secant[i] = (keys_[i + 1] - keys_[i]) / h[i];
  }
  if (n == 2) {
    tangents_[0] = tangents_[1] = secant[0];
    return;
  }
  for (int c = 0; c < 3; ++c) {
    tangents_[0][c] = steffen_end(secant[0][c], secant[1][c], h[0], h[1]);
    tangents_[n - 1][c] = steffen_end(secant[n - 2][c], secant[n - 3][c], h[n - 2], h[n - 3]);
    for (std::size_t i = 1; i + 1 < n; ++i)
      tangents_[i][c] = steffen_interior(secant[i - 1][c], secant[i][c], h[i - 1], h[i]);
  }
}

std::size_t TranslationCurve::segment(double t) const {
  const auto it = std::upper_bound(times_.begin(), times_.end(), t);
  const std::size_t i = it == times_.begin() ? 0 : static_cast<std::size_t>(it - times_.begin()) - 1;
  return std::min(i, times_.size() - 2);
}

Vec3 TranslationCurve::evaluate(double t) const {
  const std::size_t n = times_.size();
  if (n == 1 || !(t > times_.front())) return keys_.front();
  if (t >= times_.back()) return keys_.back();
  const std::size_t i = segment(t);
  const double h = times_[i + 1] - times_[i];
  const double u = (t - times_[i]) / h;
  if (method_ == TranslationInterp::linear) return keys_[i] + u * (keys_[i + 1] - keys_[i]);
  // Cubic Hermite in the form p0 + u·(Δ + (1 − u)·(…)) so that a straight line
  // (m0 = m1 = Δ/h) reduces to p0 + u·Δ exactly, like the linear method.
  const Vec3 d = keys_[i + 1] - keys_[i];
  const Vec3 a = h * tangents_[i] - d;      // deviation of the start tangent from the secant
  const Vec3 b = h * tangents_[i + 1] - d;  // … of the end tangent
  return keys_[i] + u * d + (u * (1.0 - u)) * ((1.0 - u) * a - u * b);
}

Vec3 TranslationCurve::derivative(double t) const {
  const std::size_t n = times_.size();
  if (n == 1 || t < times_.front() || t > times_.back()) return Vec3::Zero();
  const std::size_t i = segment(t);
  const double h = times_[i + 1] - times_[i];
  const double u = (t - times_[i]) / h;
  const Vec3 d = keys_[i + 1] - keys_[i];
  if (method_ == TranslationInterp::linear) return d / h;
  const Vec3 a = h * tangents_[i] - d;
  const Vec3 b = h * tangents_[i + 1] - d;
  // d/du [u(1−u)²·a − u²(1−u)·b] = ((1−u)² − 2u(1−u))·a + (u² − 2u(1−u))·b
  const double w = 1.0 - u;
  const Vec3 dp_du = d + (w * w - 2.0 * u * w) * a + (u * u - 2.0 * u * w) * b;
  return dp_du / h;
}

// Keys of the residual unrolled on each side: Steffen's cubic looks two keys away.
constexpr long long kPeriodicPadding = 3;

PeriodicTranslationCurve::PeriodicTranslationCurve(const TranslationTrack& open, Vec3 offset, double t0, double period,
                                                   TranslationInterp method)
    : offset_(std::move(offset)), t0_(t0), period_(period) {
  const auto n = static_cast<long long>(open.times.size());
  TranslationTrack unrolled;
  for (long long k = -kPeriodicPadding; k <= n + kPeriodicPadding; ++k) {
    const long long cycles = k >= 0 ? k / n : -((-k + n - 1) / n);
    const auto i = static_cast<std::size_t>(k - cycles * n);
    const double t = open.times[i] + static_cast<double>(cycles) * period;
    unrolled.times.push_back(t);
    unrolled.keys.push_back(open.keys[i] - drift(open.times[i]));
  }
  curve_.emplace(unrolled, method);
}

Vec3 PeriodicTranslationCurve::evaluate(double t) const {
  double x = std::fmod(t - t0_, period_);
  if (x < 0.0) x += period_;
  return curve_->evaluate(t0_ + x) + drift(t);
}

}  // namespace rotinterp
