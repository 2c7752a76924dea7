// rotinterp info CLIP [--json] [--anim NAME|INDEX]: what a clip file holds.
#include "common.h"
#include "rotinterp/clip/bvh_layout.h"
#include "rotinterp/clip/frames.h"
#include "rotinterp/io/info.h"

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <nlohmann/json.hpp>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace rotinterp::cli {

namespace {

struct InfoArgs {
  std::string path;
  std::string anim;
  bool json = false;
};

std::string layout_text(const std::vector<Channel>& channels) {
  std::string s;
  for (Channel c : channels) s += (s.empty() ? "" : " ") + std::string(channel_name(c));
  return s;
}

int run_info(const InfoArgs& args) {
  ReadOptions options;
  options.animation = args.anim;
  options.on_warning = warn;
  Result<ClipFileInfo> info = inspect_clip(args.path, options);
  if (!info) return fail(info.error());
  const Clip& clip = info->clip;
  const Skeleton& sk = clip.skeleton;
  const std::vector<std::string> odd = clip_oddities(clip);
  const double duration = clip.end_time() - clip.start_time();
  // The rate every command uses (resample too): BVH ".0333330" is 30 Hz, NTSC 30000/1001.
  const std::optional<Rate> rate = clip_rate(clip);
  // BVH has no unit.
  const bool has_unit = info->format != "bvh";
  std::vector<int> depth(sk.joints.size(), 0);
  for (std::size_t j = 0; j < sk.joints.size(); ++j)
    if (sk.joints[j].parent >= 0) depth[j] = depth[static_cast<std::size_t>(sk.joints[j].parent)] + 1;

  if (args.json) {
    nlohmann::json out;
    out["file"] = args.path;
    out["format"] = info->format;
    out["animations"] = nlohmann::json::array();
    for (std::size_t a = 0; a < info->animations.size(); ++a) {
      const AnimationSummary& s = info->animations[a];
      out["animations"].push_back({{"index", a}, {"name", s.name}, {"duration_s", s.duration},
                                   {"ticks_per_second", s.ticks_per_second}, {"default_rate", s.default_rate},
                                   {"channels", s.channels}, {"selected", a == info->selected}});
    }
    out["frames"] = clip.frame_count();
    out["frame_time_s"] = clip.frame_time;
    out["frame_rate_hz"] = rate ? rate->hz() : 0.0;
    out["frame_rate"] = rate ? nlohmann::json(rate->to_string()) : nlohmann::json(nullptr);
    out["file_frame_rate_hz"] = clip.file_rate_hz > 0 ? nlohmann::json(clip.file_rate_hz) : nlohmann::json(nullptr);
    out["start_s"] = clip.start_time();
    out["end_s"] = clip.end_time();
    out["duration_s"] = duration;
    out["unit_scale_m"] = has_unit ? nlohmann::json(clip.unit_scale) : nlohmann::json(nullptr);
    out["folded_helpers"] = info->folded_helpers;
    nlohmann::json joints = nlohmann::json::array();
    nlohmann::json translated = nlohmann::json::array();
    for (std::size_t j = 0; j < sk.joints.size(); ++j) {
      const Joint& jt = sk.joints[j];
      nlohmann::json channels = nlohmann::json::array();
      for (Channel c : bvh_channels(clip, j)) channels.push_back(channel_name(c));
      joints.push_back({{"name", jt.name},
                        {"parent", jt.parent >= 0 ? nlohmann::json(sk.joints[static_cast<std::size_t>(jt.parent)].name)
                                                  : nlohmann::json(nullptr)},
                        {"channels", channels},
                        {"rotation_keys", clip.rotations[j].keys.size()},
                        {"translation_keys", clip.translations[j] ? clip.translations[j]->keys.size() : 0}});
      if (clip.translations[j]) translated.push_back(jt.name);
    }
    out["joints"] = joints;
    out["end_sites"] = sk.end_sites.size();
    out["translation_tracks"] = translated;
    out["oddities"] = odd;
    out["warnings"] = info->warnings;
    fmt::print("{}\n", out.dump(2));
    return kExitOk;
  }

  fmt::print("file:        {}\n", args.path);
  fmt::print("format:      {}\n", info->format);
  fmt::print("animations:  {}\n", info->animations.size());
  for (std::size_t a = 0; a < info->animations.size(); ++a) {
    const AnimationSummary& s = info->animations[a];
    fmt::print("  {}{} '{}'  {:.6g} s  {:.9g} ticks/s{}  {} channels\n", a == info->selected ? "*" : " ", a, s.name,
               s.duration, s.ticks_per_second, s.default_rate ? " (default)" : "", s.channels);
  }
  fmt::print("frames:      {}\n", clip.frame_count());
  if (rate)
    fmt::print("frame rate:  {} Hz{} (frame time {} s)\n", rate->to_string(),
               rate->den == 1 ? std::string() : fmt::format(" = {:.9g} Hz", rate->hz()),
               frame_time_text(clip).empty() ? fmt::format("{:.9g}", clip.frame_time) : frame_time_text(clip));
  else
    fmt::print("frame rate:  none (keys not on a uniform grid){}\n",
               clip.file_rate_hz > 0 ? fmt::format("; the file's own: {:.9g} Hz (resample's default)", clip.file_rate_hz) : "");
  fmt::print("duration:    {:.6g} s (keys from {:.6g} s to {:.6g} s)\n", duration, clip.start_time(), clip.end_time());
  fmt::print("unit:        {}\n", has_unit ? fmt::format("{:.6g} m per unit", clip.unit_scale) : std::string("none (BVH has no unit)"));
  if (info->folded_helpers > 0) fmt::print("helpers:     {} $AssimpFbx$ helper nodes folded into their bones\n", info->folded_helpers);
  fmt::print("joints:      {} (+{} End Sites)\n", sk.joints.size(), sk.end_sites.size());
  for (std::size_t j = 0; j < sk.joints.size(); ++j) {
    const Joint& jt = sk.joints[j];
    std::string extra;
    if (!bvh_channels(clip, j).empty()) extra += "  [" + layout_text(bvh_channels(clip, j)) + "]";
    extra += "  " + std::to_string(clip.rotations[j].keys.size()) + " rotation keys";
    if (clip.translations[j]) extra += ", " + std::to_string(clip.translations[j]->keys.size()) + " translation keys";
    fmt::print("  {}{}{}\n", std::string(static_cast<std::size_t>(2 * depth[j]), ' '), jt.name, extra);
  }
  std::string translated;
  for (std::size_t j = 0; j < sk.joints.size(); ++j)
    if (clip.translations[j]) translated += (translated.empty() ? "" : ", ") + sk.joints[j].name;
  fmt::print("translation tracks: {}\n", translated.empty() ? "none" : translated);
  if (!odd.empty()) {
    fmt::print("oddities:\n");
    for (const std::string& o : odd) fmt::print("  - {}\n", o);
  }
  return kExitOk;
}

}  // namespace

void add_info_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<InfoArgs>();
  auto* sub = app.add_subcommand("info", "Describe a clip file: format, animations, joint tree and channel layout, "
                                         "frames, rate, duration, translation tracks, oddities");
  sub->add_option("clip", args->path, "Clip file (BVH, FBX, glTF/GLB, Collada, … anything assimp imports)")->required();
  sub->add_option("--anim", args->anim, "Animation to describe: name or 0-based index (default: the first)");
  sub->add_flag("--json", args->json, "Print JSON instead of text");
  sub->callback([args, &exit_code] { exit_code = run_info(*args); });
}

}  // namespace rotinterp::cli
