// render --loop: the cycle's frames laid out over two periods, and each method's curve on that timeline.
#include "rotinterp/render/loop_play.h"

#include "rotinterp/clip/frames.h"

#include <algorithm>
#include <cmath>

namespace rotinterp::render {

namespace {

// An ordinary curve over one period played again every period (a joint that
// misses closure: its pop at every seam).
class RepeatedCurve final : public Interpolator {
 public:
  RepeatedCurve(std::unique_ptr<Interpolator> one_period, double t0, double period)
      : curve_(std::move(one_period)), t0_(t0), period_(period) {}
  Quat evaluate(double t) const override {
    double x = std::isfinite(t) ? std::fmod(t - t0_, period_) : 0.0;
    if (x < 0.0) x += period_;
    return curve_->evaluate(t0_ + x);
  }

 private:
  std::unique_ptr<Interpolator> curve_;
  double t0_, period_;
};

}  // namespace

Result<CyclePlayedTwice> play_cycle_twice(const Clip& clip, const LoopPlay& loop, std::size_t keep_every) {
  auto cycle = cycle_frames(clip, loop.form);
  if (!cycle) return cycle.failure();
  const LoopCheck* check = &cycle->check;
  const DenseClip dense = dense_clip(clip);
  const std::vector<double>& times = dense.grid.times;
  const double t0 = times.front(), period = check->period;
  // The frames inside the period, by time: a clip without a frame time has its key times as frames.
  const double end = t0 + period - 0.5 * period / static_cast<double>(check->period_frames);
  const auto n = static_cast<std::size_t>(std::lower_bound(times.begin(), times.end(), end) - times.begin());
  if (n < 2) return make_error("--loop: fewer than 2 frames per period");
  const bool closed = check->form == LoopForm::closed;
  const std::size_t total = 2 * n + (closed ? 1 : 0);
  const std::size_t nj = clip.skeleton.joints.size();

  CyclePlayedTwice out;
  out.period_frames = n;
  out.keep_every = std::max<std::size_t>(keep_every, 1);
  Clip& c = out.clip;
  c = clip.without_tracks();
  c.frame_time = clip.frame_time;
  std::vector<double> played(total);
  for (std::size_t i = 0; i < total; ++i) played[i] = times[i % n] + static_cast<double>(i / n) * period;
  c.rotations.resize(nj);
  c.translations.resize(nj);
  const std::size_t kept = std::min(times.size(), n + (closed ? 1 : 0));  // one period, with the closed form's end
  out.period_times.assign(times.begin(), times.begin() + static_cast<std::ptrdiff_t>(kept));
  out.period_frames_rotation.resize(nj);
  for (std::size_t j = 0; j < nj; ++j) {
    const std::vector<Quat>& q = dense.rotation[j];
    out.period_frames_rotation[j].assign(q.begin(), q.begin() + static_cast<std::ptrdiff_t>(kept));
    RotationTrack& r = c.rotations[j];
    if (clip.rotations[j].keys.size() <= 1) {  // a still joint stays one key
      r = clip.rotations[j];
    } else {
      r.times = played;
      for (std::size_t i = 0; i < total; ++i) r.keys.push_back(q[i % n]);
      r.make_sign_continuous();
    }
    if (!clip.translations[j]) continue;
    const Vec3 offset = per_cycle_offset(*clip.translations[j], check->form, period / static_cast<double>(check->period_frames));
    TranslationTrack& p = c.translations[j].emplace();
    p.times = played;
    for (std::size_t i = 0; i < total; ++i)
      p.keys.push_back(dense.translation[j][i % n] + offset * static_cast<double>(i / n));
  }
  for (std::size_t m = 0; m < 2; ++m)
    for (std::size_t k = 0; k < n; k += out.keep_every) out.keys.push_back(m * n + k);
  if (closed) out.keys.push_back(2 * n);
  out.cycle = std::move(*cycle);
  if (Status s = c.validate(); !s) return make_error("internal: the cycle played twice is not valid: " + s.error());
  return out;
}

Result<std::unique_ptr<Interpolator>> CyclePlayedTwice::curve(const std::string& method, std::size_t joint) const {
  auto rebuilt = rebuild_joint(period_times, period_frames_rotation[joint], method, keep_every, &cycle, joint);
  if (!rebuilt) return rebuilt.failure();
  if (rebuilt->periodic) return std::move(rebuilt->curve);
  return std::unique_ptr<Interpolator>(new RepeatedCurve(std::move(rebuilt->curve), period_times.front(), cycle.check.period));
}

}  // namespace rotinterp::render
