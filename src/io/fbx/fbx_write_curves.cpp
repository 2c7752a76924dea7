// The FBX writer's curves of a clip: key ticks, rotation orders, time modes, and a linear key at every key time.
#include "rotinterp/io/fbx/fbx_write.h"

#include "rotinterp/io/files/key_times.h"
#include "rotinterp/io/files/file_record.h"
#include "rotinterp/io/files/written_names.h"
#include "rotinterp/clip/frames.h"
#include "rotinterp/track/sample.h"

#include <cmath>

namespace rotinterp {

namespace {

using i128 = __int128;

constexpr int kTimeModeCustom = 14;
// Key times within this (s, relative to max(1, |t|)) of a grid time are on the grid.
constexpr double kOnGridTolerance = 1e-9;
constexpr double kDegrees = 180.0 / kPi;

// Tick k of a rate num/den after `start_tick`: start + round(k·den·TPS/num), exactly.
std::int64_t grid_tick(std::int64_t start_tick, std::int64_t k, const Rate& r) {
  const i128 n = static_cast<i128>(k) * r.den * kFbxTicksPerSecond;
  const i128 q = (2 * n + r.num) / (2 * static_cast<i128>(r.num));  // round half up (n ≥ 0)
  return start_tick + static_cast<std::int64_t>(q);
}

}  // namespace

std::vector<std::int64_t> fbx_ticks(const std::vector<double>& times, const std::optional<Rate>& rate) {
  std::vector<std::int64_t> ticks(times.size());
  if (times.empty()) return ticks;
  const double t0 = times.front();
  const auto start_tick = static_cast<std::int64_t>(std::llround(t0 * static_cast<double>(kFbxTicksPerSecond)));
  for (std::size_t i = 0; i < times.size(); ++i) {
    const double t = times[i];
    if (rate) {
      const double k = std::round((t - t0) * rate->hz());
      if (k >= 0 && k < 9e15 &&
          std::abs(t0 + rate->time_of(static_cast<std::int64_t>(k)) - t) <= kOnGridTolerance * std::max(1.0, std::abs(t))) {
        ticks[i] = grid_tick(start_tick, static_cast<std::int64_t>(k), *rate);
        continue;
      }
    }
    ticks[i] = static_cast<std::int64_t>(std::llround(t * static_cast<double>(kFbxTicksPerSecond)));
  }
  return ticks;
}

// The joint's BVH rotation channels when they are three different axes (FBX has
// only those six orders), else FBX's default XYZ (R = Rz·Ry·Rx: our outermost-first ZYX).
EulerAxes fbx_joint_axes(const Clip& clip, std::size_t joint) {
  EulerAxes axes{};
  int n = 0;
  for (Channel c : bvh_channels(clip, joint)) {
    if (c < Channel::Xrotation) continue;
    if (n == 3) return {2, 1, 0};
    axes[static_cast<std::size_t>(n++)] = static_cast<int>(c) - static_cast<int>(Channel::Xrotation);
  }
  if (n != 3 || axes[0] == axes[1] || axes[1] == axes[2] || axes[0] == axes[2]) return {2, 1, 0};
  return axes;
}

int fbx_time_mode(std::int64_t num, std::int64_t den) {
  struct Mode {
    std::int64_t num, den;
    int mode;
  };
  static constexpr Mode modes[] = {{120, 1, 1},    {100, 1, 2},       {60, 1, 3},         {50, 1, 4},
                                   {48, 1, 5},     {30, 1, 6},        {30000, 1001, 9},   {25, 1, 10},
                                   {24, 1, 11},    {24000, 1001, 13}, {96, 1, 15},        {72, 1, 16},
                                   {60000, 1001, 17}, {120000, 1001, 18}};
  for (const Mode& m : modes)
    if (m.num == num && m.den == den) return m.mode;
  return kTimeModeCustom;
}

std::vector<FbxOutJoint> fbx_frame_curves(const Clip& clip) {
  std::vector<EulerAxes> axes(clip.skeleton.joints.size());
  for (std::size_t j = 0; j < axes.size(); ++j) axes[j] = fbx_joint_axes(clip, j);
  return fbx_frame_curves(clip, axes);
}

std::vector<FbxOutJoint> fbx_frame_curves(const Clip& clip, const std::vector<EulerAxes>& axes) {
  const std::vector<double> times = all_key_times(clip);
  const std::vector<std::int64_t> ticks = fbx_ticks(times, clip_rate(clip));
  std::vector<FbxOutJoint> out(clip.skeleton.joints.size());
  for (std::size_t j = 0; j < out.size(); ++j) {
    FbxOutJoint& joint = out[j];
    joint.axes = axes[j];
    // Angle i of a sequence turns about axis axes[i]; FBX stores them by axis (X, Y, Z).
    Vec3 previous = Vec3::Zero();
    for (std::size_t k = 0; k < times.size(); ++k) {
      previous = euler_nearest(sample_rotation(clip.rotations[j], times[k]), joint.axes, previous);
      for (std::size_t i = 0; i < 3; ++i)
        joint.rotation[static_cast<std::size_t>(joint.axes[i])].push_back(
            {ticks[k], static_cast<float>(previous[static_cast<Eigen::Index>(i)] * kDegrees)});
    }
    joint.has_translation = clip.translations[j].has_value();
    if (const auto& tr = clip.translations[j])
      for (std::size_t k = 0; k < times.size(); ++k) {
        const Vec3 v = sample_translation(*tr, times[k]);
        for (std::size_t a = 0; a < 3; ++a)
          joint.translation[a].push_back({ticks[k], static_cast<float>(v[static_cast<Eigen::Index>(a)])});
      }
  }
  return out;
}

Result<std::string> encode_fbx(const Clip& clip, FbxEncoding encoding) {
  if (Status s = clip.validate(); !s) return s.failure("cannot write an invalid clip: ");
  return encode_fbx_curves(clip, fbx_frame_curves(clip), encoding);
}

Result<std::string> encode_fbx_clips(const std::vector<Clip>& takes, FbxEncoding encoding) {
  if (takes.empty()) return make_error("no takes to write");
  const Clip& first = takes.front();
  std::vector<EulerAxes> axes(first.skeleton.joints.size());
  for (std::size_t j = 0; j < axes.size(); ++j) axes[j] = fbx_joint_axes(first, j);
  std::optional<Rate> rate = clip_rate(first);
  std::vector<FbxOutTake> out;
  for (const Clip& take : takes) {
    if (Status s = take.validate(); !s) return s.failure("take '" + take.name + "': cannot write an invalid clip: ");
    if (clip_rate(take) != rate) rate.reset();  // TimeMode then states none: each take keeps its own grid
    out.push_back({readable_text(take.name), fbx_frame_curves(take, axes)});
  }
  // A joint's rest translation is shifted off its parent's axis only where it is keyed
  // in every take (fbx_rest.h): a take without its keys holds the rest value.
  Clip skeleton = first;
  for (const Clip& take : takes)
    for (std::size_t j = 0; j < take.translations.size(); ++j)
      if (!take.translations[j]) skeleton.translations[j].reset();
  return encode_fbx_takes(skeleton, out, rate, encoding);
}

}  // namespace rotinterp
