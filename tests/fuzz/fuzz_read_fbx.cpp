// Fuzz target (4): any bytes through our own FBX reader — the node tree (binary
// or ASCII, chosen by the magic), the animation curves read from it (7.x objects
// or 6.1 takes), each curve evaluated across its keys and beyond, and each model's
// transform with its layers blended. It must give a document or one error line:
// never crash, read past the buffer, hang or give a non-finite value.
#include "rotinterp/io/fbx/fbx_curve_eval.h"
#include "rotinterp/io/fbx/fbx_curves.h"
#include "rotinterp/io/fbx/fbx_nodes.h"
#include "rotinterp/io/fbx/fbx_transform.h"

#include <cmath>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  auto doc = rotinterp::parse_fbx_nodes(bytes, "fuzz.fbx");
  if (!doc.ok()) {
    if (doc.error().find('\n') != std::string::npos) __builtin_trap();
    return 0;
  }
  auto anim = rotinterp::read_fbx_animation(*doc, "fuzz.fbx");
  if (!anim.ok()) return 0;
  for (const rotinterp::FbxTake& take : anim->takes)
    for (const rotinterp::FbxCurve& curve : take.curves) {
      if (curve.keys.empty()) continue;
      const double first = static_cast<double>(curve.keys.front().ticks);
      const double last = static_cast<double>(curve.keys.back().ticks);
      // Inside, between and beyond the keys (extrapolation), at 17 points.
      for (int k = -4; k <= 12; ++k) {
        const double t = first + (last - first) * k / 8.0 + (k == 0 ? 0.0 : 1.0);
        if (!std::isfinite(rotinterp::evaluate_fbx_curve(curve, t))) __builtin_trap();
      }
    }
  for (const rotinterp::FbxTake& take : anim->takes) {
    const auto nodes = rotinterp::fbx_node_layers(take);
    for (const rotinterp::FbxModel& model : anim->models) {
      const auto node = nodes.find(model.name);
      for (int k = -1; k <= 3; ++k) {
        const double t = static_cast<double>(take.start) + static_cast<double>(take.stop - take.start) * k / 2.0;
        const auto values = rotinterp::fbx_lcl_values(take, model, node == nodes.end() ? nullptr : &node->second, t);
        if (!rotinterp::fbx_node_rotation(model, values.rotation).coeffs().allFinite()) __builtin_trap();
      }
    }
  }
  return 0;
}
