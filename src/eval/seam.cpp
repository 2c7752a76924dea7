// eval --loop: joints rebuilt on their periodic curves, and the figures of the seam.
#include "rotinterp/eval/seam.h"

#include "rotinterp/eval/error_row.h"
#include "rotinterp/eval/evaluate_clip.h"
#include "rotinterp/interp/periodic.h"

#include <algorithm>
#include <cmath>

namespace rotinterp {

namespace {
constexpr double kRadToDeg = 180.0 / kPi;
}  // namespace

Result<CycleFrames> cycle_frames(const Clip& clip, std::optional<LoopForm> form) {
  auto check = check_loop(clip, form);
  if (!check) return check.failure("--loop: ");
  if (!form && !check->looks_like_cycle)
    return make_error("--loop: the clip does not look like a cycle: " + loop_check_text(*check) +
                      " (give --loop closed or --loop open to treat it as one)");
  CycleFrames c;
  c.check = std::move(*check);
  c.looped.assign(clip.skeleton.joints.size(), true);
  for (const ClosureMiss& m : c.check.misses) c.looped[m.joint] = false;
  return c;
}

namespace {

// With a cycle: the key frames inside the period (0, N, 2N, … before t₀ + P), by
// time — a clip without a frame time has its key times as frames (clip/frames.h),
// not the cycle's period_frames — and whether the clip has a frame at t₀ + P.
std::vector<std::size_t> period_keys(const ClipReference& R, std::size_t n, bool& wrap_frame) {
  const LoopCheck& c = R.cycle->check;
  const double half_frame = 0.5 * c.period / static_cast<double>(c.period_frames);
  const double end = R.frames.front() + c.period - half_frame;
  std::vector<std::size_t> kf;
  std::size_t k = 0;
  for (; k < R.frames.size() && R.frames[k] < end; k += n) kf.push_back(k);
  wrap_frame = std::abs(R.frames.back() - (end + half_frame)) < half_frame;
  return kf;
}

}  // namespace

std::vector<std::size_t> key_frames(const ClipReference& R, int keep) {
  const std::size_t n = static_cast<std::size_t>(std::max(keep, 1));
  if (!R.cycle) return keep_every_indices(R.frames.size(), n);
  bool wrap_frame = false;
  std::vector<std::size_t> kf = period_keys(R, n, wrap_frame);
  if (wrap_frame && kf.back() != R.frames.size() - 1) kf.push_back(R.frames.size() - 1);
  return kf;
}

Result<RebuiltJoint> rebuild_joint(const ClipReference& R, std::size_t j, const std::string& method, int keep) {
  const std::size_t nf = R.frames.size(), n = static_cast<std::size_t>(std::max(keep, 1));
  RebuiltJoint out;
  out.periodic = R.cycle && R.cycle->looped[j];
  bool wrap_frame = false;
  const std::vector<std::size_t> kf = out.periodic ? period_keys(R, n, wrap_frame) : keep_every_indices(nf, n);
  out.keys = decimated_track(R.frames, R.original[j], kf);
  auto curve = out.periodic ? make_periodic_interpolator(method, out.keys, R.cycle->check.period)
                            : make_interpolator(method, out.keys);
  if (!curve) return curve.failure();
  out.curve = std::move(*curve);
  out.jump_times = out.keys.times;
  if (out.periodic) out.jump_times.push_back(R.frames.front() + R.cycle->check.period);
  return out;
}

SeamFigures seam_figures(const ClipReference& R, std::size_t j, const RebuiltJoint& rebuilt) {
  SeamFigures s;
  const std::vector<double>& t = rebuilt.jump_times;  // periodic: ends with the seam one period on
  if (t.size() < 2 || R.frames.empty()) return s;
  // The seam's two key intervals: [t₀, t₁] and the last one, [t_{n−2}, end].
  const double first_end = t[1], last_start = t[t.size() - 2];
  const double end = t.back(), start = t.front();
  std::vector<Quat> at(R.frames.size());
  rebuilt.curve->evaluate(R.frames.data(), R.frames.size(), at.data());
  const double snap = 1e-9 * std::max(1.0, std::abs(end));
  for (std::size_t k = 0; k < R.frames.size(); ++k) {
    const double e = angular_distance(R.reference[j][k], at[k]);
    const bool seam = R.frames[k] <= first_end + snap || R.frames[k] >= last_start - snap;
    double& worst = seam ? s.angle : s.inner_angle;
    worst = std::max(worst, e);
  }
  const double h = kKeyJumpStep * std::min(first_end - start, end - last_start);
  if (!(h > 0.0)) return s;
  // Played end to start: the period's end (periodic: its seam; otherwise the last key), then its start.
  const double after = rebuilt.periodic ? end : start;
  const double times[6] = {end - 2 * h, end - h, end, after, after + h, after + 2 * h};
  Quat q[6];
  rebuilt.curve->evaluate(times, 6, q);
  s.jumps = one_sided_jumps(q, q + 3, h);
  return s;
}

void fill_seam_columns(ErrorRow& r, const ClipReference& R, std::size_t j, const RebuiltJoint& rebuilt) {
  const SeamFigures s = seam_figures(R, j, rebuilt);
  r.seam = true;
  r.seam_angle_deg = s.angle * kRadToDeg;
  r.inner_angle_deg = s.inner_angle * kRadToDeg;
  r.seam_vel_jump = s.jumps.velocity * kRadToDeg;
  r.seam_acc_jump = s.jumps.acceleration * kRadToDeg;
  r.looped = rebuilt.periodic ? 1.0 : 0.0;
}

}  // namespace rotinterp
