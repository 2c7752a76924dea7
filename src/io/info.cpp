// What `rotinterp info` reads of a file, and says of a clip beside its data: its
// oddities and its facts (clip_facts), which the text and the JSON both print.
#include "rotinterp/io/info.h"
#include "rotinterp/clip/frames.h"
#include "rotinterp/clip/units.h"
#include "rotinterp/io/files/file_record.h"
#include "rotinterp/io/files/formats.h"

#include "rotinterp/io/record/read_parts.h"
#include "rotinterp/io/files/file_errors.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

namespace rotinterp {

namespace {

// Key spacing differing from the median spacing by more than this fraction of it
// counts as non-uniform.
constexpr double kUniformSpacingTolerance = 1e-3;

std::string seconds(double s) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g s", s);
  return buf;
}

bool uniform(const std::vector<double>& t) {
  if (t.size() < 3) return true;
  std::vector<double> d(t.size() - 1);
  for (std::size_t k = 1; k < t.size(); ++k) d[k - 1] = t[k] - t[k - 1];
  std::vector<double> sorted = d;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2), sorted.end());
  const double median = sorted[sorted.size() / 2];
  for (double x : d)
    if (std::abs(x - median) > kUniformSpacingTolerance * median) return false;
  return true;
}

}  // namespace


ReadOutcome inspect_clip_for_info(const std::filesystem::path& path, ReadOptions options) {
  if (options.read_curves || !is_format(extension_of(path), FormatId::fbx)) return inspect_clip_outcome(path, options);
  options.read_curves = true;
  ReadOutcome with_curves = inspect_clip_outcome(path, options);
  if (!with_curves.error || with_curves.kind == file_error::no_animation) return with_curves;
  options.read_curves = false;
  return inspect_clip_outcome(path, options);
}

std::vector<std::string> clip_oddities(const Clip& clip) {
  std::vector<std::string> out;
  const Skeleton& sk = clip.skeleton;
  std::vector<std::string> static_joints, uneven;
  std::size_t min_keys = SIZE_MAX, max_keys = 0;
  for (std::size_t j = 0; j < clip.rotations.size() && j < sk.joints.size(); ++j) {
    const RotationTrack& r = clip.rotations[j];
    if (r.times.size() == 1) static_joints.push_back(sk.joints[j].name);
    else {
      min_keys = std::min(min_keys, r.times.size());
      max_keys = std::max(max_keys, r.times.size());
    }
    if (!uniform(r.times)) uneven.push_back(sk.joints[j].name);
  }
  auto list = [](const std::vector<std::string>& names) {
    std::string s;
    for (std::size_t i = 0; i < names.size() && i < 8; ++i) s += (i ? ", " : "") + names[i];
    if (names.size() > 8) s += ", … (" + std::to_string(names.size()) + " in all)";
    return s;
  };
  if (!static_joints.empty())
    out.push_back(std::to_string(static_joints.size()) + " joint(s) without rotation keys (static): " + list(static_joints));
  if (!uneven.empty()) out.push_back("non-uniform key spacing in " + std::to_string(uneven.size()) + " joint(s): " + list(uneven));
  if (max_keys > 0 && min_keys != max_keys)
    out.push_back("rotation key counts differ between joints: " + std::to_string(min_keys) + " to " + std::to_string(max_keys));
  if (clip.start_time() < 0.0) out.push_back("keys before time 0 (first at " + seconds(clip.start_time()) + ")");
  if (clip.frame_time == 0.0) out.push_back("no uniform frame rate: resample before writing BVH");
  return out;
}

ClipFacts clip_facts(const ClipFileInfo& info) {
  const Clip& clip = info.clip;
  const Skeleton& sk = clip.skeleton;
  ClipFacts f;
  f.frames = clip.frame_count();
  f.frame_time = clip.frame_time;
  f.frame_time_written = frame_time_text(clip);
  f.rate = clip_rate(clip);
  f.rate_stated = info.selected < info.animations.size() && info.animations[info.selected].rate_stated;
  f.file_rate_hz = stated_rate_hz(clip.source_record);
  f.start = clip.start_time();
  f.end = clip.end_time();
  f.duration = f.end - f.start;
  f.size_m = first_pose_size(clip) * clip.unit.metres_per_unit;
  for (std::size_t j = 0; j < sk.joints.size(); ++j) {
    const Joint& jt = sk.joints[j];
    JointFacts joint{jt.name, std::nullopt, 0, bvh_channels(clip, j), clip.rotations[j].keys.size(), std::nullopt};
    if (jt.parent >= 0) {
      const auto parent = static_cast<std::size_t>(jt.parent);
      joint.parent = sk.joints[parent].name;
      joint.depth = f.joints[parent].depth + 1;  // parents come first (Skeleton::validate)
    }
    if (clip.translations[j]) {
      joint.translation_keys = clip.translations[j]->keys.size();
      f.translated.push_back(jt.name);
    }
    f.channels += joint.channels.size();
    f.joints.push_back(std::move(joint));
  }
  f.end_sites = sk.end_sites.size();
  if (Result<LoopCheck> cycle = check_loop(clip)) f.cycle = std::move(*cycle);
  f.oddities = clip_oddities(clip);
  return f;
}

}  // namespace rotinterp
