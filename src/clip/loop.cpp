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

// The track's value one frame after the clip's last (`frame` seconds) in `form`:
// closed, the last key itself; open, the last key moved on by its last step's rate
// (held where the track ends before the clip does).
Quat next_after_last(const RotationTrack& r, LoopForm form, double clip_end, double frame) {
  const std::size_t n = r.keys.size();
  const Quat& last = r.keys.back();
  if (form == LoopForm::closed || r.times.back() < clip_end - 0.5 * frame) return last;
  const double step = frame / (r.times[n - 1] - r.times[n - 2]);
  return (exp(RotVec(displacement_fixed(r.keys[n - 2], last) * step)) * last).normalized();
}

// Index of the longest side of the rest pose's bounding box: the up axis of a standing figure.
int up_axis(const Skeleton& skeleton) {
  const WorldPose pose = rest_pose(skeleton);
  Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
  for (const Vec3& p : pose.position) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  for (const Vec3& p : pose.end_site_position) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  int axis = 1;
  (hi - lo).maxCoeff(&axis);
  return axis;
}

struct FormClosure {
  double sum = 0.0;
  std::vector<double> miss;  // per joint, rad; 0 for a joint with fewer than 2 keys
};

FormClosure closure(const Clip& clip, LoopForm form, double frame) {
  FormClosure c;
  for (const RotationTrack& r : clip.rotations) {
    const double a =
        r.keys.size() >= 2 ? angular_distance(next_after_last(r, form, clip.end_time(), frame), r.keys.front()) : 0.0;
    c.miss.push_back(a);
    c.sum += a;
  }
  return c;
}

}  // namespace

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
  if (!rate && clip.file_rate_hz > 0.0)
    if (const Result<Rate> r = rate_from_frame_time(1.0 / clip.file_rate_hz)) rate = r.value();
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
    const Vec3& last = tr->keys.back();
    const std::size_t n = tr->keys.size();
    const double step = frame / (tr->times[n - 1] - tr->times[n - 2]);
    const Vec3 next = check.form == LoopForm::closed ? last : Vec3(last + step * (last - tr->keys[n - 2]));
    check.root_advance = next - tr->keys.front();
    check.root_vertical_offset = std::abs(check.root_advance[up_axis(clip.skeleton)]) * clip.unit.metres_per_unit;
    break;
  }
  check.looks_like_cycle = check.moving_joints > 0 && check.misses.size() * 10 <= check.moving_joints &&
                           check.root_vertical_offset <= tolerance.root_offset;
  return check;
}

std::string loop_check_text(const LoopCheck& c) {
  char head[160];
  std::snprintf(head, sizeof head, "%s (%s form: %zu frames, %.4g s per period); joints close within %.4f°",
                c.looks_like_cycle ? "looks like a cycle" : "not a cycle", loop_form_name(c.form), c.period_frames,
                c.period, c.worst_closing_angle * kDegrees);
  std::string s = head;
  if (c.moving_joints == 0) s += "; nothing moves";
  if (c.root_vertical_offset >= 1e-4) {
    char root[96];
    std::snprintf(root, sizeof root, "; root rises %.4g m per cycle", c.root_vertical_offset);
    s += root;
  }
  if (!c.misses.empty()) {
    s += "; " + std::to_string(c.misses.size()) + (c.misses.size() == 1 ? " joint misses" : " joints miss") +
         " closure (a pop at the seam in the source):";
    for (std::size_t i = 0; i < c.misses.size() && i < 8; ++i) {
      char m[128];
      std::snprintf(m, sizeof m, "%s %s %.2f°", i ? "," : "", c.misses[i].name.c_str(), c.misses[i].angle * kDegrees);
      s += m;
    }
    if (c.misses.size() > 8) s += ", …";
  }
  return s;
}

}  // namespace rotinterp
