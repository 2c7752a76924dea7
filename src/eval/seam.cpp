// eval --loop: the figures of the seam; and the rebuild of clip/rebuild.h on an evaluated clip's reference.
#include "rotinterp/eval/seam.h"

#include "rotinterp/eval/error_row.h"
#include "rotinterp/eval/evaluate_clip.h"

#include <algorithm>
#include <cmath>

namespace rotinterp {

namespace {
constexpr double kRadToDeg = 180.0 / kPi;
}  // namespace

std::vector<std::size_t> key_frames(const ClipReference& R, int keep) {
  return key_frames(R.frames, static_cast<std::size_t>(std::max(keep, 1)), R.cycle ? &*R.cycle : nullptr);
}

Result<RebuiltJoint> rebuild_joint(const ClipReference& R, std::size_t j, const std::string& method, int keep) {
  return rebuild_joint(R.frames, R.original[j], method, static_cast<std::size_t>(std::max(keep, 1)),
                       R.cycle ? &*R.cycle : nullptr, j);
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
