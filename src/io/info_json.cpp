// clip_info_json: `rotinterp info --json` for one file, shared by the CLI and the
// Python module (rotinterp.info), so that both give the same document.
#include "rotinterp/io/files/file_record.h"
#include "rotinterp/io/files/json_text.h"
#include "rotinterp/io/files/written_names.h"
#include "rotinterp/clip/frames.h"
#include "rotinterp/clip/loop.h"
#include "rotinterp/clip/units.h"
#include "rotinterp/io/info.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace rotinterp {

namespace {

nlohmann::json unit_object(const ClipUnit& u) {
  return {{"name", unit_name(u.metres_per_unit)},
          {"metres_per_unit", u.metres_per_unit},
          {"origin", unit_origin_name(u.origin)},
          {"reason", u.reason}};
}

}  // namespace

std::string unit_info_json(const ClipUnit& unit) { return json_text(unit_object(unit)); }

std::string clip_info_json(const std::string& path, const ClipFileInfo& info) {
  const Clip& clip = info.clip;
  const Skeleton& sk = clip.skeleton;
  const std::vector<std::string> odd = clip_oddities(clip);
  const double duration = clip.end_time() - clip.start_time();
  // The rate every command uses (resample too): BVH ".0333330" is 30 Hz, NTSC 30000/1001.
  const std::optional<Rate> rate = clip_rate(clip);
  const double size_m = first_pose_size(clip) * clip.unit.metres_per_unit;
  nlohmann::json out;
  out["file"] = path;  // json_text prints a path that is not UTF-8
  out["format"] = info.format;
  out["animations"] = nlohmann::json::array();
  for (std::size_t a = 0; a < info.animations.size(); ++a) {
    const AnimationSummary& s = info.animations[a];
    out["animations"].push_back({{"index", a}, {"name", readable_text(s.name)}, {"duration_s", s.duration},
                                 {"ticks_per_second", s.ticks_per_second}, {"default_rate", s.default_rate},
                                 {"channels", s.channels}, {"selected", a == info.selected},
                                 {"start_s", std::isfinite(s.start) ? nlohmann::json(s.start) : nlohmann::json(nullptr)},
                                 {"frames", take_frames(s)}, {"keys", s.keys},
                                 {"frame_rate_hz", s.frame_rate_hz > 0.0 ? nlohmann::json(s.frame_rate_hz) : nlohmann::json(nullptr)},
                                 {"rate_stated", s.rate_stated}});
  }
  out["frames"] = clip.frame_count();
  out["frame_time_s"] = clip.frame_time;
  out["frame_rate_hz"] = rate ? rate->hz() : 0.0;
  out["frame_rate"] = rate ? nlohmann::json(rate->to_string()) : nlohmann::json(nullptr);
  out["file_frame_rate_hz"] = stated_rate_hz(clip.source_record) > 0 ? nlohmann::json(stated_rate_hz(clip.source_record)) : nlohmann::json(nullptr);
  out["start_s"] = clip.start_time();
  out["end_s"] = clip.end_time();
  out["duration_s"] = duration;
  // The same shape as --summary's rows give (cmd_info.cpp).
  out["unit"] = unit_object(clip.unit);
  out["figure_size_m"] = size_m;
  out["folded_helpers"] = info.folded_helpers;
  nlohmann::json joints = nlohmann::json::array();
  nlohmann::json translated = nlohmann::json::array();
  const std::vector<std::string> names = written_joint_names(sk, NameForm::text);  // as a glTF or FBX writes them
  for (std::size_t j = 0; j < sk.joints.size(); ++j) {
    const Joint& jt = sk.joints[j];
    nlohmann::json channels = nlohmann::json::array();
    for (Channel c : bvh_channels(clip, j)) channels.push_back(channel_name(c));
    joints.push_back({{"name", names[j]},
                      {"parent", jt.parent >= 0 ? nlohmann::json(names[static_cast<std::size_t>(jt.parent)])
                                                : nlohmann::json(nullptr)},
                      {"channels", channels},
                      {"rotation_keys", clip.rotations[j].keys.size()},
                      {"translation_keys", clip.translations[j] ? clip.translations[j]->keys.size() : 0}});
    if (clip.translations[j]) translated.push_back(names[j]);
  }
  out["joints"] = joints;
  out["end_sites"] = sk.end_sites.size();
  out["translation_tracks"] = translated;
  // The cycle check (clip/loop.h); null where it cannot run (no frame rate, < 3 frames).
  if (const Result<LoopCheck> c = check_loop(clip)) {
    nlohmann::json misses = nlohmann::json::array();
    for (const ClosureMiss& m : c->misses) misses.push_back({{"joint", names[m.joint]}, {"angle_deg", m.angle * 180.0 / kPi}});
    out["cycle"] = {{"looks_like_cycle", c->looks_like_cycle},
                    {"form", loop_form_name(c->form)},
                    {"period_frames", c->period_frames},
                    {"period_s", c->period},
                    {"worst_closing_angle_deg", c->worst_closing_angle * 180.0 / kPi},
                    {"joints_missing_closure", misses},
                    {"moving_joints", c->moving_joints},
                    {"root_vertical_offset_m", c->root_vertical_offset},
                    {"root_advance", {c->root_advance.x(), c->root_advance.y(), c->root_advance.z()}},
                    {"text", loop_check_text(*c)}};
  } else {
    out["cycle"] = nullptr;
  }
  out["oddities"] = odd;
  out["warnings"] = info.warnings;
  return json_text(out, 2);
}

}  // namespace rotinterp
