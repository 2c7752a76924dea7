// Cycle detection: the closure of every joint in the closed and open forms, the root's per-cycle offset.
#include "rotinterp/clip/loop.h"

#include "rotinterp/clip/frames.h"
#include "rotinterp/clip/sampling.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace rotinterp {

namespace {

constexpr double kDegrees = 180.0 / 3.14159265358979323846;

// Angular velocity from key a to key b (rad/s, fixed frame).
Vec3 rate(const Quat& a, const Quat& b, double dt) { return displacement_fixed(a, b).vec() / dt; }

// How far a track misses closing in `form`, as an angle. Closed: the last key's angle
// from the first. Open: the seam's change of angular velocity (last → first one
// frame later) beyond the largest change between keys inside, times one frame — the
// angle by which the step across the seam breaks the motion's own smoothness.
double closure_miss(const RotationTrack& r, LoopForm form, double clip_end, double frame) {
  const std::size_t n = r.keys.size();
  if (n < 2) return 0.0;
  if (form == LoopForm::closed) return angular_distance(r.keys.back(), r.keys.front());
  if (n < 3) return angular_distance(r.keys.back(), r.keys.front());
  const Vec3 seam = rate(r.keys[n - 1], r.keys[0], std::max(clip_end + frame - r.times[n - 1], frame));
  const Vec3 before = rate(r.keys[n - 2], r.keys[n - 1], r.times[n - 1] - r.times[n - 2]);
  const Vec3 after = rate(r.keys[0], r.keys[1], r.times[1] - r.times[0]);
  double inside = 0.0;
  for (std::size_t k = 1; k + 1 < n; ++k)
    inside = std::max(inside, (rate(r.keys[k], r.keys[k + 1], r.times[k + 1] - r.times[k]) -
                               rate(r.keys[k - 1], r.keys[k], r.times[k] - r.times[k - 1]))
                                  .norm());
  const double jump = std::max((seam - before).norm(), (after - seam).norm());
  return std::max(0.0, jump - inside) * frame;
}

// Index of the longest side of the rest pose's bounding box: the up axis of a standing figure.
int up_axis(const Skeleton& skeleton) {
  const WorldPose pose = rest_pose(skeleton);
  Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
  for (const Vec3& p : pose.position) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  for (const Vec3& p : pose.end_site_position) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  int axis = 1;
  // A figure with no extent (one joint, a box) has no tallest axis: Y, as BVH and glTF.
  if (!(lo.allFinite() && hi.allFinite()) || (hi - lo).maxCoeff() <= 0.0) return 1;
  (hi - lo).maxCoeff(&axis);
  return axis;
}

struct FormClosure {
  double sum = 0.0;
  std::vector<double> miss;  // per joint, rad; 0 for a joint with fewer than 2 keys
};

FormClosure closure(const Clip& clip, LoopForm form, double frame) {
  FormClosure c;
  const double end = clip.end_time();  // once: it visits every track (20 000 joints happen)
  for (const RotationTrack& r : clip.rotations) {
    const double a = closure_miss(r, form, end, frame);
    c.miss.push_back(a);
    c.sum += a;
  }
  return c;
}

}  // namespace

Vec3 per_cycle_offset(const TranslationTrack& tr, LoopForm form, double frame) {
  const std::size_t n = tr.keys.size();
  if (n < 2) return Vec3::Zero();
  if (form == LoopForm::closed) return tr.keys.back() - tr.keys.front();
  // The parabola through the last three keys (the line through two), one frame on.
  const double x = tr.times[n - 1] + frame;
  Vec3 next = Vec3::Zero();
  const std::size_t m = std::min<std::size_t>(n, 3);
  for (std::size_t i = n - m; i < n; ++i) {
    double w = 1.0;
    for (std::size_t k = n - m; k < n; ++k)
      if (k != i) w *= (x - tr.times[k]) / (tr.times[i] - tr.times[k]);
    next += w * tr.keys[i];
  }
  return next - tr.keys.front();
}

const char* loop_form_name(LoopForm form) { return form == LoopForm::closed ? "closed" : "open"; }

Result<std::optional<LoopForm>> parse_loop_form(std::string_view text) {
  if (text == "auto" || text.empty()) return std::optional<LoopForm>();
  if (text == "closed") return std::optional<LoopForm>(LoopForm::closed);
  if (text == "open") return std::optional<LoopForm>(LoopForm::open);
  return make_error("--loop '" + std::string(text) + "': expected auto, closed or open");
}

Result<LoopCheck> check_loop(const Clip& clip, std::optional<LoopForm> form, const LoopTolerance& tolerance) {
  // The frame rate: the keys' grid, else the file's own (sparse keys, FBX).
  const FrameGrid grid = frame_grid(clip);
  std::optional<Rate> rate = grid.rate;
  if (const double stated = stated_rate_hz(clip.source_record); !rate && stated > 0.0)
    if (const Result<Rate> r = rate_from_frame_time(1.0 / stated)) rate = r.value();
  if (!rate) return make_error("the clip has no frame rate, so it cannot be checked as a cycle");
  const double frame = rate->period();
  const auto frames = static_cast<std::size_t>(std::llround((clip.end_time() - clip.start_time()) / frame)) + 1;
  if (frames < 3) return make_error("a cycle needs at least 3 frames (the clip has " + std::to_string(frames) + ")");
  LoopCheck check;
  const FormClosure closed = closure(clip, LoopForm::closed, frame), open = closure(clip, LoopForm::open, frame);
  check.form = form ? *form : (open.sum < closed.sum ? LoopForm::open : LoopForm::closed);
  const FormClosure& chosen = check.form == LoopForm::closed ? closed : open;
  check.period_frames = frames - (check.form == LoopForm::closed ? 1 : 0);
  check.period = rate->time_of(static_cast<std::int64_t>(check.period_frames));

  check.joints = clip.rotations.size();
  check.metres_per_unit = clip.unit.metres_per_unit;
  for (std::size_t j = 0; j < clip.rotations.size(); ++j) {
    const RotationTrack& r = clip.rotations[j];
    double travel = 0.0;
    for (const Quat& q : r.keys) travel = std::max(travel, angular_distance(q, r.keys.front()));
    if (travel > tolerance.angle) ++check.moving_joints;
    if (chosen.miss[j] > tolerance.angle)
      check.misses.push_back({j, clip.skeleton.joints[j].name, chosen.miss[j]});
    else
      check.worst_closing_angle = std::max(check.worst_closing_angle, chosen.miss[j]);
  }
  std::sort(check.misses.begin(), check.misses.end(),
            [](const ClosureMiss& a, const ClosureMiss& b) { return a.angle > b.angle; });

  for (std::size_t j = 0; j < clip.translations.size(); ++j) {
    const auto& tr = clip.translations[j];
    if (clip.skeleton.joints[j].parent >= 0 || !tr || tr->keys.size() < 2) continue;
    check.root_advance = per_cycle_offset(*tr, check.form, frame);
    check.root_vertical_offset = std::abs(check.root_advance[up_axis(clip.skeleton)]) * clip.unit.metres_per_unit;
    break;
  }
  check.looks_like_cycle = check.moving_joints > 0 && check.misses.size() * 10 <= check.moving_joints &&
                           check.root_vertical_offset <= tolerance.root_offset;
  return check;
}

std::string closure_misses_text(const std::vector<ClosureMiss>& misses) {
  if (misses.empty()) return "";
  std::string s = std::to_string(misses.size()) + (misses.size() == 1 ? " joint misses" : " joints miss") +
                  " closure (a pop at the seam in the source):";
  for (std::size_t i = 0; i < misses.size() && i < 8; ++i) {
    char m[128];
    std::snprintf(m, sizeof m, "%s %s %.2f°", i ? "," : "", misses[i].name.c_str(), misses[i].angle * kDegrees);
    s += m;
  }
  if (misses.size() > 8) s += ", …";
  return s;
}

std::string loop_check_text(const LoopCheck& c) {
  char part[160];
  std::snprintf(part, sizeof part, "%s (%s form: %zu frames, %.4g s per period)",
                c.looks_like_cycle ? "looks like a cycle" : "not a cycle", loop_form_name(c.form), c.period_frames,
                c.period);
  std::string s = part;
  // Which joints close, which miss: each counted once, so the parts cannot disagree.
  const std::size_t closing = c.joints - std::min(c.joints, c.misses.size());
  if (closing > 0) {
    std::snprintf(part, sizeof part, "; %s close within %.4f°",
                  c.misses.empty() ? "joints" : (std::to_string(closing) + (closing == 1 ? " joint" : " joints")).c_str(),
                  c.worst_closing_angle * kDegrees);
    s += part;
  }
  if (!c.misses.empty()) s += "; " + closure_misses_text(c.misses);
  // The root: rising (up, the figure's tallest axis) or translating (along the ground).
  const double advance = c.root_advance.norm() * c.metres_per_unit;
  if (c.moving_joints == 0) s += advance >= 1e-4 ? "; no joint turns" : "; nothing moves";
  if (c.root_vertical_offset >= 1e-4) {
    std::snprintf(part, sizeof part, "; root rises %.4g m per cycle", c.root_vertical_offset);
    s += part;
  } else if (advance >= 1e-4) {
    std::snprintf(part, sizeof part, "; root translates %.4g m per cycle", advance);
    s += part;
  }
  return s;
}

}  // namespace rotinterp
