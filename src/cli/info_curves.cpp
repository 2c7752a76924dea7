// print_info_curves: `info --curves` as text (one block per curve: its keys with
// interpolation, tangent and slopes, its extrapolation, optional samples) or JSON.
#include "info_curves.h"

#include "common.h"
#include "rotinterp/clip/key_limit.h"
#include "rotinterp/io/fbx/fbx_curve_eval.h"

#include <fmt/core.h>

namespace rotinterp::cli {

int print_info_curves(const std::string& path, const ClipFileInfo& info, double sample_hz, bool json) {
  if (!info.curves) return fail(path + ": --curves reads FBX files only (this is a '" + info.format + "' file)");
  // The samples' size, checked before they are made (clip/key_limit.h).
  if (const FbxTake* take = selected_take(info); take && sample_hz > 0.0) {
    const double samples = fbx_sample_count(sample_hz, fbx_take_span(*take).stop);
    const double total = samples * static_cast<double>(take->curves.size());
    if (too_many_keys(samples, take->curves.size()))
      return fail(fmt::format("{}: --sample {:g} would give {:.0f} samples over {} curve(s), more than {}; give a lower "
                              "--sample",
                              path, sample_hz, total, take->curves.size(), kMaxKeys));
  }
  if (json) {
    fmt::print("{}\n", curves_info_json(info, sample_hz));
    return kExitOk;
  }
  const FbxTake* take = selected_take(info);
  if (!take) {
    fmt::print("file:   {}\ncurves: none (the file has no animation stack)\n", path);
    return kExitOk;
  }
  const double ticks = static_cast<double>(kFbxTicksPerSecond);
  fmt::print("file:   {}\n", path);
  fmt::print("take:   '{}' ({:.6g} s to {:.6g} s), {} curve(s)\n", take->name, static_cast<double>(fbx_take_span(*take).start) / ticks,
             static_cast<double>(fbx_take_span(*take).stop) / ticks, take->curves.size());
  for (std::size_t l = 0; l < take->layers.size(); ++l) {
    const FbxLayer& layer = take->layers[l];
    fmt::print("layer {}: '{}' {} weight {:g}%{}{}\n", l, layer.name, fbx_blend_mode_name(layer.blend), layer.weight,
               layer.weight_curve ? fmt::format(" (keyed: {} key(s))", layer.weight_curve->keys.size()) : "",
               layer.mute ? " (muted)" : "");
  }
  for (const FbxCurve& c : take->curves) {
    fmt::print("\n{} {} {} layer {}: {} key(s), extrapolation {} before, {} after\n", c.node, c.property, c.channel,
               c.layer, c.keys.size(), fbx_extrapolation_name(c.pre.mode), fbx_extrapolation_name(c.post.mode));
    for (std::size_t i = 0; i < c.keys.size(); ++i) {
      const FbxKey& k = c.keys[i];
      const FbxKeyTangents t = fbx_key_tangents(c.keys, i);
      fmt::print("  t {:<10.6g} s  value {:<12.7g} {:<17} {:<7} slopes {:.6g} / {:.6g}  weights {:.4g} / {:.4g}\n",
                 static_cast<double>(k.ticks) / ticks, k.value, fbx_interpolation_name(k.interpolation),
                 fbx_tangent_name(k.tangent), t.left_slope, t.right_slope, t.left_weight, t.right_weight);
    }
    if (sample_hz > 0.0) {
      const std::vector<double> samples = sample_fbx_curve(c, sample_hz, fbx_take_span(*take).stop);
      fmt::print("  samples at {:g} Hz:", sample_hz);
      for (double v : samples) fmt::print(" {:.7g}", v);
      fmt::print("\n");
    }
  }
  return kExitOk;
}

}  // namespace rotinterp::cli
