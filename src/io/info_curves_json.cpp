// curves_info_json: `rotinterp info --curves --json`, the FBX curves of the
// selected take as stored, with their tangents as evaluated and optional samples.
#include "rotinterp/io/fbx/fbx_curve_eval.h"
#include "rotinterp/io/files/json_text.h"
#include "rotinterp/io/files/written_names.h"
#include "rotinterp/io/info.h"

#include <nlohmann/json.hpp>

#include <algorithm>

namespace rotinterp {

namespace {

nlohmann::json extrapolation_json(const FbxExtrapolationRule& e) {
  return {{"mode", fbx_extrapolation_name(e.mode)}, {"repetitions", e.repetitions}};
}

nlohmann::json key_json(const std::vector<FbxKey>& keys, std::size_t i) {
  const FbxKey& k = keys[i];
  const FbxKeyTangents t = fbx_key_tangents(keys, i);
  nlohmann::json j = {{"t", static_cast<double>(k.ticks) / static_cast<double>(kFbxTicksPerSecond)},
                      {"ticks", k.ticks},
                      {"value", k.value},
                      {"interpolation", fbx_interpolation_name(k.interpolation)},
                      {"tangent", fbx_tangent_name(k.tangent)},
                      {"left_slope", t.left_slope},
                      {"right_slope", t.right_slope},
                      {"left_weight", t.left_weight},
                      {"right_weight", t.right_weight},
                      {"weighted", k.weighted_right || k.weighted_next_left},
                      {"flags", k.flags}};
  if (k.velocity_right || k.velocity_next_left)
    j["velocities"] = {k.right_velocity, k.next_left_velocity};
  if (k.tangent == FbxTangent::tcb) j["tcb"] = {k.tension, k.continuity, k.bias};
  return j;
}

}  // namespace

const FbxTake* selected_take(const ClipFileInfo& info) {
  if (!info.curves || info.curves->takes.empty()) return nullptr;
  const auto& takes = info.curves->takes;
  return &takes[info.selected < takes.size() ? info.selected : 0];
}

std::string curves_info_json(const ClipFileInfo& info, double sample_hz) {
  nlohmann::json curves = nlohmann::json::array();
  if (const FbxTake* take = selected_take(info))
    for (const FbxCurve& c : take->curves) {
      nlohmann::json keys = nlohmann::json::array();
      for (std::size_t i = 0; i < c.keys.size(); ++i) keys.push_back(key_json(c.keys, i));
      nlohmann::json entry = {{"node", readable_text(c.node)},
                              {"property", c.property},
                              {"channel", std::string(1, c.channel)},
                              {"layer", c.layer},
                              {"default", c.default_value},
                              {"pre_extrapolation", extrapolation_json(c.pre)},
                              {"post_extrapolation", extrapolation_json(c.post)},
                              {"keys", keys}};
      if (sample_hz > 0.0) entry["samples"] = sample_fbx_curve(c, sample_hz, fbx_take_span(*take).stop);
      curves.push_back(std::move(entry));
    }
  return json_text(nlohmann::json{{"curves", curves}}, 2);
}

}  // namespace rotinterp
