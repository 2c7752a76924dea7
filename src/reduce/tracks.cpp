// One joint's tracks: the translation keys, the rotation keys, and the curve rebuilt through them.
#include "reducer.h"
#include "slerp_window.h"

#include "rotinterp/clip/metrics.h"
#include "rotinterp/core/rotation.h"
#include "rotinterp/interp/interpolator.h"
#include "rotinterp/interp/periodic.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <utility>

namespace rotinterp::detail {

// The translation track of j: keys, then its rebuilt values at every frame.
Status Reducer::select_translation(std::size_t j, bool removal, std::vector<double>& e) {
  if (!clip_.translations[j]) return Ok{};
  const double tol = budget_[j].translation;
  const std::vector<Vec3>& src = dense_.translation[j];
  // The curve through the keys `keys`: in a cycle, periodic with the track's per-cycle offset.
  auto evaluator = [&](const std::vector<std::size_t>& keys) -> std::function<Vec3(double)> {
    if (!looped(j)) {
      auto curve = std::make_shared<TranslationCurve>(translation_keys(times(), src, keys), o_.translation);
      return [curve](double t) { return curve->evaluate(t); };
    }
    auto curve = std::make_shared<PeriodicTranslationCurve>(translation_keys(times(), src, in_period(keys)),
                                                            cycle_->offset[j], times()[0], cycle_->period, o_.translation);
    return [curve](double t) { return curve->evaluate(t); };
  };
  ErrorFn err = [&](const std::vector<std::size_t>& keys, std::size_t lo, std::size_t hi, double* out) -> Status {
    const auto curve = evaluator(keys);
    for (std::size_t f = lo; f <= hi; ++f) out[f - lo] = (curve(times()[f]) - src[f]).norm() / tol;
    return Ok{};
  };
  if (Status s = select_track_keys(j, tkeys_[j], err, nullptr, removal, e); !s) return s;
  const auto curve = evaluator(tkeys_[j]);
  std::vector<Vec3>& t = test_translation_[j];
  t.resize(n_);
  double worst = 0.0;
  for (std::size_t f = 0; f < n_; ++f) {
    t[f] = curve(times()[f]);
    worst = std::max(worst, (t[f] - src[f]).norm());
  }
  out_[j].max_translation_error = worst;
  return Ok{};
}

Result<std::unique_ptr<Interpolator>> Reducer::curve(std::size_t j, const std::vector<std::size_t>& keys) const {
  return looped(j) ? make_joint_curve(o_.method, decimated_track(times(), value_[j], in_period(keys)), cycle_->period)
                   : make_joint_curve(o_.method, decimated_track(times(), value_[j], keys), std::nullopt);
}

Status Reducer::rebuild(std::size_t j, const std::vector<std::size_t>& keys, std::size_t lo, std::size_t hi,
                        std::vector<Quat>& q) const {
  q.resize(hi - lo + 1);
  if (slerp_ && !looped(j) && keys.size() >= 2) {
    slerp_window(times(), value_[j], keys, lo, hi, q.data());
    return Ok{};
  }
  auto c = curve(j, keys);
  if (!c) return c.failure();
  (*c)->evaluate(times().data() + lo, q.size(), q.data());
  return Ok{};
}

// The rotation keys of j (its translation chosen, its ancestors rebuilt).
Status Reducer::select_rotation(std::size_t j, bool removal, std::vector<double>& e) {
  const ReduceBudget& b = budget_[j];
  const double tol_rot = b.rotation_deg * kPi / 180.0, d = o_.shell_distance;
  const std::vector<Quat>& src = dense_.rotation[j];
  const bool shell = b.shell > 0.0;
  // The children's share of their budget, for the headroom below (looked up once, not per frame).
  std::vector<std::pair<std::size_t, double>> headroom;
  for (std::size_t c : children_[j])
    if (const double limit = kChildShare * budget_[c].shell; limit > 0.0) headroom.emplace_back(c, limit);
  auto frame_error = [&](std::size_t f, const Quat& q) {
    double v = 0.0;
    if (tol_rot > 0.0) v = angular_distance(src[f], q) / tol_rot;
    if (shell) {
      Quat r;
      Vec3 p;
      test_world(j, f, q, r, p);
      v = std::max(v, shell_error_above(ref_rot_[j][f], ref_pos_[j][f], r, p, d, b.shell) / b.shell);
      // Headroom for the children: their positions (their own translation exact)
      // within a share of their budget.
      for (const auto& [c, limit] : headroom) {
        const Vec3 pc = p + r * dense_.translation[c][f];
        v = std::max(v, (ref_pos_[c][f] - pc).norm() / limit);
      }
    }
    return v;
  };
  std::vector<Quat> rebuilt;  // reused by every measure of this track
  ErrorFn err = [&](const std::vector<std::size_t>& keys, std::size_t lo, std::size_t hi, double* out) -> Status {
    if (Status s = rebuild(j, keys, lo, hi, rebuilt); !s) return s;
    for (std::size_t f = lo; f <= hi; ++f) out[f - lo] = frame_error(f, rebuilt[f - lo]);
    frames_measured_ += hi - lo + 1;
    return Ok{};
  };
  // The residuals behind frame_error, each block normalized by its budget (the
  // error is the largest block norm): the local rotation error vector; the three
  // shell vertices' displacements; each child's displacement.
  std::vector<std::size_t> kids;
  for (std::size_t c : children_[j])
    if (budget_[c].shell > 0.0) kids.push_back(c);
  const int blocks = (tol_rot > 0.0 ? 1 : 0) + (shell ? 3 + static_cast<int>(kids.size()) : 0);
  auto residual = [&](std::size_t f, const Quat& q, double* out) {
    double worst = 0.0;
    auto put = [&](const Vec3& v) {
      std::copy(v.data(), v.data() + 3, out);
      out += 3;
      worst = std::max(worst, v.squaredNorm());
    };
    if (tol_rot > 0.0) put(displacement_moving(src[f], q).vec() / tol_rot);
    if (shell) {
      Quat r;
      Vec3 p;
      test_world(j, f, q, r, p);
      const Mat3 dr = (d / b.shell) * (ref_rot_[j][f].toRotationMatrix() - r.toRotationMatrix());
      const Vec3 dp = (ref_pos_[j][f] - p) / b.shell;
      for (int a = 0; a < 3; ++a) put(dp + dr.col(a));
      for (std::size_t c : kids)
        put((ref_pos_[c][f] - (p + r * dense_.translation[c][f])) / (kChildShare * budget_[c].shell));
    }
    return std::sqrt(worst);
  };
  KeyValues values;
  values.start = [&](std::size_t f) { value_[j][f] = start_[j][f]; };
  values.reset = [&](std::size_t f) {
    if (value_[j][f].coeffs() == src[f].coeffs()) return false;
    value_[j][f] = src[f];
    return true;
  };
  values.refit = [&](const std::vector<std::size_t>& keys, const std::vector<std::size_t>& free, std::size_t lo,
                     std::size_t hi) -> Result<bool> {
    return refit_values(j, keys, free, lo, hi, blocks, residual);
  };
  // A later pass of a hierarchical run: every frame's error is the last pass's, measured
  // again only where the curve or its inputs moved since.
  const bool again = shell_ && measured_[j].done, known = again && !looped(j) && n_ >= 3;
  if (known) {
    e = measured_[j].error;
    const Status s = for_each_rebuilt_run(j, to_measure(j), false, [&](std::size_t lo, std::size_t hi, const std::vector<Quat>& q) {
      for (std::size_t f = lo; f <= hi; ++f) e[f] = frame_error(f, q[f - lo]);
    });
    if (!s) return s;
  }
  if (Status s = select_track_keys(j, rkeys_[j], err, &values, removal, e, known, static_cast<std::size_t>(support(j))); !s)
    return s;
  if (shell_) {
    out_[j].budget = b;
    if (!looped(j) && n_ >= 3) measured_[j].error = e;
    return settle_rotation(j, again ? to_measure(j) : std::vector<char>(n_, 1));
  }
  if (Status s = rebuild(j, rkeys_[j], 0, n_ - 1, rebuilt); !s) return s;
  ReducedJoint& out = out_[j];
  out.budget = b;
  out.max_rotation_error = out.max_shell_error = 0.0;
  for (std::size_t f = 0; f < n_; ++f) out.max_rotation_error = std::max(out.max_rotation_error, angular_distance(src[f], rebuilt[f]));
  return Ok{};
}

}  // namespace rotinterp::detail
