// The reducer: the source at its frames, the world poses, the tracks' keys; the result.
#include "reducer.h"

#include "rotinterp/clip/metrics.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace rotinterp::detail {

TranslationTrack translation_keys(const std::vector<double>& times, const std::vector<Vec3>& source,
                                  const std::vector<std::size_t>& kept) {
  TranslationTrack t;
  for (std::size_t f : kept) {
    t.times.push_back(times[f]);
    t.keys.push_back(source[f]);
  }
  return t;
}

// Every joint's rotations smoothed by the kStartSmoothing Gaussian over the frames on
// either side, as many on each side (the first and last frames stay as they are),
// weights below 1e-4 left out: the normalized weighted sum of the sign-aligned
// quaternions, which keeps a constant angular velocity on its geodesic.
std::vector<std::vector<Quat>> smoothed(const DenseClip& d) {
  std::vector<std::vector<Quat>> out = d.rotation;
  const std::vector<double>& t = d.grid.times;
  const std::size_t n = t.size();
  for (std::size_t j = 0; j < out.size(); ++j)
    for (std::size_t f = 1; f + 1 < n; ++f) {
      const Quat& centre = d.rotation[j][f];
      Eigen::Vector4d sum = centre.coeffs();
      for (std::size_t k = 1; k <= std::min(f, n - 1 - f); ++k) {
        const double dt = 0.5 * (t[f + k] - t[f - k]);
        const double w = std::exp(-dt * dt / (2.0 * kStartSmoothing * kStartSmoothing));
        if (w < 1e-4) break;
        for (const Quat& q : {d.rotation[j][f - k], d.rotation[j][f + k]})
          sum += (q.dot(centre) < 0.0 ? -w : w) * q.coeffs();
      }
      out[j][f].coeffs() = sum.normalized();
    }
  return out;
}

Reducer::Reducer(const Clip& clip, const ReduceOptions& o, std::vector<ReduceBudget> budgets,
                 std::optional<LoopCheck> cycle)
    : clip_(clip), o_(o), budget_(std::move(budgets)), dense_(exact_dense_clip(clip)), value_(dense_.rotation),
      start_(smoothed(dense_)) {
  children_.resize(clip.skeleton.joints.size());
  for (std::size_t j = 0; j < clip.skeleton.joints.size(); ++j)
    if (clip.skeleton.joints[j].parent >= 0) children_[static_cast<std::size_t>(clip.skeleton.joints[j].parent)].push_back(j);
  n_ = dense_.grid.size();
  joints_ = clip.skeleton.joints.size();
  for (const ReduceBudget& b : budget_) shell_ = shell_ || b.shell > 0.0;
  const MethodInfo* method = find_method(o.method);
  slerp_ = method && method->name == "slerp" && n_ >= 2;
  for (std::size_t f = 1; slerp_ && f < n_; ++f) slerp_ = times()[f] > times()[f - 1];
  for (std::size_t f = 0; slerp_ && f < n_; ++f) slerp_ = std::isfinite(times()[f]);
  rkeys_.assign(joints_, ends(n_));
  tkeys_.assign(joints_, {});
  for (std::size_t j = 0; j < joints_; ++j)
    if (clip.translations[j]) tkeys_[j] = ends(n_);
  out_.assign(joints_, ReducedJoint{});
  test_translation_.resize(joints_);
  if (cycle) setup_ = set_cycle(std::move(*cycle));
  if (shell_) {
    measured_.assign(joints_, Measured{});
    for (Measured& m : measured_) m.moved.assign(n_, 0);
    ref_rot_.assign(joints_, std::vector<Quat>(n_));
    ref_pos_.assign(joints_, std::vector<Vec3>(n_));
    test_rot_ = ref_rot_;
    test_pos_ = ref_pos_;
    for (std::size_t j = 0; j < joints_; ++j) {
      const int p = clip.skeleton.joints[j].parent;
      for (std::size_t f = 0; f < n_; ++f) {
        const Quat& q = dense_.rotation[j][f];
        const Vec3& t = dense_.translation[j][f];
        if (p < 0) {
          ref_rot_[j][f] = q;
          ref_pos_[j][f] = t;
        } else {
          const auto pu = static_cast<std::size_t>(p);
          ref_rot_[j][f] = ref_rot_[pu][f] * q;
          ref_pos_[j][f] = ref_pos_[pu][f] + ref_rot_[pu][f] * t;
        }
      }
    }
  }
}

// The cycle's period on the grid, which joints loop (those the check finds closing, as
// resample --loop and any reader of the output decide), their offsets and start keys:
// the seam and its image.
Status Reducer::set_cycle(LoopCheck check) {
  Cycle c;
  c.period = check.period;
  const double frame = check.period / static_cast<double>(check.period_frames);
  const double end = times()[0] + check.period - 0.5 * frame;
  c.frames = static_cast<std::size_t>(std::lower_bound(times().begin(), times().end(), end) - times().begin());
  const bool closed = check.form == LoopForm::closed;
  if (c.frames != (closed ? n_ - 1 : n_))
    return make_error(std::string("the clip's frames do not end ") + (closed ? "one period" : "one frame short of a period") +
                      " after the first (" + loop_form_name(check.form) + " cycle)");
  c.looped.assign(joints_, 1);
  for (const ClosureMiss& m : check.misses) c.looped[m.joint] = 0;
  c.offset.assign(joints_, Vec3::Zero());
  std::vector<std::size_t> all(n_);
  for (std::size_t f = 0; f < n_; ++f) all[f] = f;
  for (std::size_t j = 0; j < joints_; ++j) {
    if (!c.looped[j]) continue;
    // A closed cycle's last frame is its first again, as the curve replays it (the
    // source's own closure miss, within the check's tolerance, is not the curve's to meet).
    if (closed) {
      const std::size_t last = n_ - 1;
      dense_.rotation[j][last] = value_[j][last] = start_[j][last] = dense_.rotation[j][0];
    }
    rkeys_[j] = {0, c.frames};
    if (!clip_.translations[j]) continue;
    tkeys_[j] = {0, c.frames};
    c.offset[j] = per_cycle_offset(translation_keys(times(), dense_.translation[j], all), check.form, frame);
  }
  c.check = std::move(check);
  cycle_ = std::move(c);
  return Ok{};
}

Result<ReduceResult> Reducer::run() {
  if (!setup_) return setup_.failure();
  if (n_ >= 2) {
    if (Status s = shell_ ? run_hierarchical() : run_independent(); !s) return s.failure();
  } else {
    for (std::size_t j = 0; j < joints_; ++j) out_[j].budget = budget_[j];
  }
  ReduceResult r;
  r.reduced = clip_;
  r.source_keys = 0;
  for (std::size_t j = 0; j < joints_; ++j) {
    out_[j].rotation_frames = rkeys_[j];
    out_[j].translation_frames = tkeys_[j];
    // A looped joint's last key closes the cycle: the seam again, one period on, not a key of its own.
    const std::size_t closing = looped(j) ? 1 : 0;
    out_[j].looped = looped(j);
    if (closing) {
      RotationTrack& rot = r.reduced.rotations[j] = decimated_track(times(), value_[j], in_period(rkeys_[j]));
      rot.times.push_back(closing_time());
      rot.keys.push_back(value_[j][0]);
      rot.make_sign_continuous();
    } else {
      r.reduced.rotations[j] = decimated_track(times(), value_[j], rkeys_[j]);
    }
    r.source_keys += n_;
    r.kept_keys += rkeys_[j].size() - closing;
    if (clip_.translations[j]) {
      TranslationTrack& tr = r.reduced.translations[j].emplace(
          translation_keys(times(), dense_.translation[j], closing ? in_period(tkeys_[j]) : tkeys_[j]));
      if (closing) {
        tr.times.push_back(closing_time());
        tr.keys.push_back(dense_.translation[j][0] + cycle_->offset[j]);
      }
      r.source_keys += n_;
      r.kept_keys += tkeys_[j].size() - closing;
    }
  }
  if (cycle_) r.cycle = cycle_->check;
  r.joints = std::move(out_);
  r.grid = std::move(dense_.grid);
  return r;
}

}  // namespace rotinterp::detail
