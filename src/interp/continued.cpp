// Curves continued at their end angular velocity (interp/continued.h).
#include "rotinterp/interp/continued.h"

#include <cmath>
#include <utility>

namespace rotinterp {

namespace {

class ContinuedInterpolator final : public Interpolator {
 public:
  ContinuedInterpolator(std::unique_ptr<Interpolator> curve, double t0, double tn)
      : curve_(std::move(curve)),
        t0_(t0),
        tn_(tn),
        q0_(curve_->evaluate(t0)),
        qn_(curve_->evaluate(tn)),
        w0_(curve_->angular_velocity(t0)),
        wn_(curve_->angular_velocity(tn)) {}

  Quat evaluate(double t) const override {
    if (t > tn_ && std::isfinite(t)) return integrate_angular_velocity(qn_, wn_, t - tn_);
    if (t < t0_ && std::isfinite(t)) return integrate_angular_velocity(q0_, w0_, t - t0_);
    return curve_->evaluate(t);
  }
  void evaluate(const double* t, std::size_t n, Quat* out) const override {
    curve_->evaluate(t, n, out);  // the batch path inside; the few times beyond are redone
    for (std::size_t i = 0; i < n; ++i)
      if (t[i] > tn_ || t[i] < t0_) out[i] = evaluate(t[i]);
  }
  bool has_angular_velocity() const override { return true; }
  Vec3 angular_velocity(double t) const override {
    if (t > tn_) return wn_;
    if (t < t0_) return w0_;
    return curve_->angular_velocity(t);
  }
  bool has_angular_acceleration() const override { return curve_->has_angular_acceleration(); }
  Vec3 angular_acceleration(double t) const override {
    if (t > tn_ || t < t0_) return Vec3::Zero();  // constant ω beyond the ends
    return curve_->angular_acceleration(t);
  }

 private:
  std::unique_ptr<Interpolator> curve_;
  double t0_, tn_;
  Quat q0_, qn_;
  Vec3 w0_, wn_;
};

}  // namespace

bool can_continue(const MethodInfo& m) { return m.continuity >= 1; }

std::string continued_method_names() {
  std::string names;
  for (const MethodInfo& m : methods())
    if (can_continue(m)) names += (names.empty() ? "" : ", ") + m.name;
  return names;
}

std::unique_ptr<Interpolator> continue_at_end_velocity(std::unique_ptr<Interpolator> curve, double t0, double tn) {
  return std::make_unique<ContinuedInterpolator>(std::move(curve), t0, tn);
}

}  // namespace rotinterp
