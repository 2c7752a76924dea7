// clip_info_json: `rotinterp info --json` for one file, its clip_facts as JSON, shared
// by the CLI and the Python module (rotinterp.info), so that both give the same document.
#include "rotinterp/clip/loop.h"
#include "rotinterp/clip/units.h"
#include "rotinterp/io/files/bvh_layout.h"
#include "rotinterp/io/files/json_text.h"
#include "rotinterp/io/files/written_names.h"
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
  const ClipFacts facts = clip_facts(info);
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
  out["frames"] = facts.frames;
  out["frame_time_s"] = facts.frame_time;
  out["frame_rate_hz"] = facts.rate ? facts.rate->hz() : 0.0;
  out["frame_rate"] = facts.rate ? nlohmann::json(facts.rate->to_string()) : nlohmann::json(nullptr);
  out["file_frame_rate_hz"] = facts.file_rate_hz > 0 ? nlohmann::json(facts.file_rate_hz) : nlohmann::json(nullptr);
  out["start_s"] = facts.start;
  out["end_s"] = facts.end;
  out["duration_s"] = facts.duration;
  // The same shape as --summary's rows give (cmd_info.cpp).
  out["unit"] = unit_object(info.clip.unit);
  out["figure_size_m"] = facts.size_m;
  out["folded_helpers"] = info.folded_helpers;
  nlohmann::json joints = nlohmann::json::array();
  nlohmann::json translated = nlohmann::json::array();
  // The names as a glTF or FBX writes them: valid UTF-8, no control characters.
  const Skeleton& sk = info.clip.skeleton;
  const std::vector<std::string> names = written_joint_names(sk, NameForm::text);
  for (std::size_t j = 0; j < facts.joints.size(); ++j) {
    const JointFacts& f = facts.joints[j];
    const int parent = sk.joints[j].parent;
    nlohmann::json channels = nlohmann::json::array();
    for (Channel c : f.channels) channels.push_back(channel_name(c));
    joints.push_back({{"name", names[j]},
                      {"parent", parent >= 0 ? nlohmann::json(names[static_cast<std::size_t>(parent)]) : nlohmann::json(nullptr)},
                      {"channels", channels},
                      {"rotation_keys", f.rotation_keys},
                      {"translation_keys", f.translation_keys.value_or(0)}});
    if (f.translation_keys) translated.push_back(names[j]);
  }
  out["joints"] = joints;
  out["end_sites"] = facts.end_sites;
  out["translation_tracks"] = translated;
  if (const std::optional<LoopCheck>& c = facts.cycle) {
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
  out["oddities"] = facts.oddities;
  out["warnings"] = info.warnings;
  return json_text(out, 2);
}

}  // namespace rotinterp
