// Periodic interpolators: any method built on the unrolled cycle, evaluated modulo the period.
#include "rotinterp/interp/periodic.h"

#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace rotinterp {

namespace {

class PeriodicInterpolator final : public Interpolator {
 public:
  PeriodicInterpolator(std::unique_ptr<Interpolator> unrolled, double t0, double period)
      : unrolled_(std::move(unrolled)), t0_(t0), period_(period) {}

  Quat evaluate(double t) const override { return unrolled_->evaluate(wrap(t)); }
  void evaluate(const double* t, std::size_t n, Quat* out) const override {
    std::vector<double> wrapped(t, t + n);
    for (double& x : wrapped) x = wrap(x);
    unrolled_->evaluate(wrapped.data(), n, out);
  }
  bool has_angular_velocity() const override { return unrolled_->has_angular_velocity(); }
  Vec3 angular_velocity(double t) const override { return unrolled_->angular_velocity(wrap(t)); }
  bool has_angular_acceleration() const override { return unrolled_->has_angular_acceleration(); }
  Vec3 angular_acceleration(double t) const override { return unrolled_->angular_acceleration(wrap(t)); }

 private:
  // t moved by whole periods into [t₀, t₀ + P); NaN and ±∞ to t₀.
  double wrap(double t) const {
    if (!std::isfinite(t)) return t0_;
    double x = std::fmod(t - t0_, period_);
    if (x < 0.0) x += period_;
    return t0_ + x;
  }

  std::unique_ptr<Interpolator> unrolled_;
  double t0_, period_;
};

}  // namespace

Result<std::unique_ptr<Interpolator>> make_periodic_interpolator(std::string_view method, const RotationTrack& track,
                                                                 double period) {
  const MethodInfo* m = find_method(method);
  if (!m) return make_error(unknown_method_message(method));
  // The method validates the unrolled keys (rules 1–3); the span needs matching, non-empty lists.
  if (track.times.empty() || track.times.size() != track.keys.size())
    return make_error("a cycle needs as many times as keys, at least one");
  const double span = track.times.back() - track.times.front();
  if (!std::isfinite(period) || !(period > span))
    return make_error("the period (" + std::to_string(period) + " s) must be finite and longer than the keys' span (" +
                      std::to_string(span) + " s)");
  // Unrolled: key index k ∈ [−pad, n + pad] is key k mod n, a whole number of periods later.
  const auto n = static_cast<long long>(track.times.size());
  const auto pad = static_cast<long long>(kPeriodicPadding);
  RotationTrack unrolled;
  for (long long k = -pad; k <= n + pad; ++k) {
    const long long cycles = k >= 0 ? k / n : -((-k + n - 1) / n);
    const auto i = static_cast<std::size_t>(k - cycles * n);
    unrolled.times.push_back(track.times[i] + static_cast<double>(cycles) * period);
    unrolled.keys.push_back(track.keys[i]);
  }
  auto made = m->make(std::move(unrolled));
  if (!made) return made.failure();
  return std::unique_ptr<Interpolator>(
      std::make_unique<PeriodicInterpolator>(std::move(made.value()), track.times.front(), period));
}

Result<std::unique_ptr<Interpolator>> make_joint_curve(std::string_view method, const RotationTrack& keys,
                                                       std::optional<double> period) {
  return period ? make_periodic_interpolator(method, keys, *period) : make_interpolator(method, keys);
}

}  // namespace rotinterp
