// FBX node transforms from a take: layers blended per Lcl property, then the full
// local transform in FBX's order (io/fbx/fbx_transform.h).
#include "rotinterp/io/fbx/fbx_transform.h"

#include "rotinterp/io/files/euler.h"
#include "rotinterp/io/fbx/fbx_curve_eval.h"

#include <algorithm>
#include <cmath>

namespace rotinterp {

namespace {

constexpr double kRadiansPerDegree = kPi / 180.0;
// The Euler order rotations blend in "by layer", whatever the node's order: Maya
// (whose rotation-blend nodes default to XYZ) evaluates the frame-18 cubes of
// ufbx_maya_anim_layers_over_acc_orders this way, within 1e-5 cm.
constexpr int kLayerRotationOrder = 0;
// A layer weight above this is a full weight (the DCCs store 100 % as 99.99…).
constexpr double kFullWeight = 0.99999;

// Degrees (X, Y, Z) back from a rotation, nearest `near` (no 360° jumps).
FbxVec3 fbx_euler_angles(int order, const Quat& q, const FbxVec3& near) {
  const EulerAxes axes = fbx_order_axes(order);
  Vec3 previous;
  for (int i = 0; i < 3; ++i)
    previous[i] = near[static_cast<std::size_t>(axes[static_cast<std::size_t>(i)])] * kRadiansPerDegree;
  const Vec3 angles = euler_nearest(q, axes, previous);
  FbxVec3 out{};
  for (int i = 0; i < 3; ++i)
    out[static_cast<std::size_t>(axes[static_cast<std::size_t>(i)])] = angles[i] / kRadiansPerDegree;
  return out;
}

// v^w keeping v's sign (scale blends as powers; a mirrored scale stays mirrored).
double signed_power(double v, double w) {
  if (w <= 0.0) return 1.0;
  if (w >= 1.0) return v;
  return v < 0.0 ? -std::pow(-v, w) : std::pow(v, w);
}

FbxVec3 layer_value(const FbxLayerChannels& l, double ticks) {
  FbxVec3 v = l.defaults;
  for (std::size_t c = 0; c < 3; ++c)
    if (l.channels[c]) v[c] = evaluate_fbx_curve(*l.channels[c], ticks);
  return v;
}

// The layer's weight at `ticks` as a fraction in [0, 1].
double layer_weight(const FbxLayer& layer, double ticks) {
  const double percent = layer.weight_curve ? evaluate_fbx_curve(*layer.weight_curve, ticks) : layer.weight;
  const double w = std::isnan(percent) ? 1.0 : std::clamp(percent / 100.0, 0.0, 1.0);
  return w > kFullWeight ? 1.0 : w;
}

void blend(const FbxLayer& layer, double w, std::size_t property, int order, const FbxVec3& value, FbxVec3& result) {
  if (layer.blend == FbxBlendMode::override) {
    result = value;
    return;
  }
  const bool additive = layer.blend == FbxBlendMode::additive;
  if (property == kFbxScaling && layer.scale_accumulation == 0) {
    for (std::size_t c = 0; c < 3; ++c)
      result[c] = additive ? result[c] * signed_power(value[c], w)
                           : signed_power(result[c], 1.0 - w) * signed_power(value[c], w);
  } else if (property == kFbxRotation && layer.rotation_accumulation == 0) {
    const Quat a = fbx_euler_rotation(order, result), b = fbx_euler_rotation(order, value);
    const Quat q = additive ? a * Quat::Identity().slerp(w, b) : a.slerp(w, b);
    result = fbx_euler_angles(order, q.normalized(), result);
  } else {
    for (std::size_t c = 0; c < 3; ++c)
      result[c] = additive ? result[c] + value[c] * w : result[c] * (1.0 - w) + value[c] * w;
  }
}

Eigen::Matrix4d translation(const FbxVec3& v) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<3, 1>(0, 3) = Vec3(v[0], v[1], v[2]);
  return m;
}

}  // namespace

EulerAxes fbx_order_axes(int order) {
  static const char* names[] = {"XYZ", "XZY", "YZX", "YXZ", "ZXY", "ZYX"};
  const char* name = names[order >= 0 && order < 6 ? order : 0];
  return {name[2] - 'X', name[1] - 'X', name[0] - 'X'};
}

std::size_t fbx_lcl_index(const std::string& property) {
  if (property == "Lcl Translation") return kFbxTranslation;
  if (property == "Lcl Rotation") return kFbxRotation;
  if (property == "Lcl Scaling") return kFbxScaling;
  return 3;
}

bool FbxNodeLayers::keyed(std::size_t property) const {
  for (std::size_t p = 0; p < 3; ++p) {
    if (property < 3 && p != property) continue;
    for (const FbxLayerChannels& l : properties[p])
      for (const FbxCurve* c : l.channels)
        if (c && !c->keys.empty()) return true;
  }
  return false;
}

std::map<std::string, FbxNodeLayers> fbx_node_layers(const FbxTake& take) {
  std::map<std::string, FbxNodeLayers> out;
  auto entry = [&](const std::string& node, std::size_t property, std::size_t layer) -> FbxLayerChannels& {
    std::vector<FbxLayerChannels>& layers = out[node].properties[property];
    auto at = std::find_if(layers.begin(), layers.end(), [&](const FbxLayerChannels& l) { return l.layer >= layer; });
    if (at == layers.end() || at->layer != layer) at = layers.insert(at, FbxLayerChannels{layer, {}, {}});
    return *at;
  };
  for (const FbxAnimatedProperty& p : take.properties)
    if (const std::size_t i = fbx_lcl_index(p.property); i < 3) entry(p.node, i, p.layer).defaults = p.defaults;
  for (const FbxCurve& c : take.curves) {
    const std::size_t i = fbx_lcl_index(c.property);
    if (i >= 3 || c.channel < 'X' || c.channel > 'Z') continue;
    FbxLayerChannels& l = entry(c.node, i, c.layer);
    l.channels[static_cast<std::size_t>(c.channel - 'X')] = &c;
    l.defaults[static_cast<std::size_t>(c.channel - 'X')] = c.default_value;
  }
  return out;
}

FbxLclValues fbx_lcl_values(const FbxTake& take, const FbxModel& model, const FbxNodeLayers* node, double ticks) {
  FbxLclValues out{model.translation, model.rotation, model.scaling};
  FbxVec3* results[3] = {&out.translation, &out.rotation, &out.scaling};
  if (node)
    for (std::size_t p = 0; p < 3; ++p)
      for (const FbxLayerChannels& l : node->properties[p]) {
        if (l.layer >= take.layers.size() || take.layers[l.layer].mute) continue;
        const FbxVec3 value = layer_value(l, ticks);
        if (l.layer == 0)
          *results[p] = value;  // the take's first layer sets the property
        else
          blend(take.layers[l.layer], layer_weight(take.layers[l.layer], ticks), p, kLayerRotationOrder, value,
                *results[p]);
      }
  // A hostile file's non-finite static or default value: no NaN leaves the library.
  for (std::size_t p = 0; p < 3; ++p)
    for (double& v : *results[p])
      if (!std::isfinite(v)) v = p == kFbxScaling ? 1.0 : 0.0;
  return out;
}

Quat fbx_euler_rotation(int order, const FbxVec3& degrees) {
  const EulerAxes axes = fbx_order_axes(order);
  const Vec3 angles(degrees[static_cast<std::size_t>(axes[0])], degrees[static_cast<std::size_t>(axes[1])],
                    degrees[static_cast<std::size_t>(axes[2])]);
  return euler_to_quat(axes, angles * kRadiansPerDegree);
}

Quat fbx_node_rotation(const FbxModel& model, const FbxVec3& rotation_degrees) {
  const Quat q = fbx_euler_rotation(0, model.pre_rotation) *
                 fbx_euler_rotation(model.rotation_order, rotation_degrees) *
                 fbx_euler_rotation(0, model.post_rotation).conjugate();
  return q.normalized();
}

Eigen::Matrix4d fbx_node_matrix(const FbxModel& model, const FbxLclValues& v) {
  Eigen::Matrix4d rotation = Eigen::Matrix4d::Identity();
  rotation.block<3, 3>(0, 0) = fbx_node_rotation(model, v.rotation).toRotationMatrix();
  Eigen::Matrix4d scaling = Eigen::Matrix4d::Identity();
  for (int c = 0; c < 3; ++c) scaling(c, c) = v.scaling[static_cast<std::size_t>(c)];
  const FbxVec3& rp = model.rotation_pivot;
  const FbxVec3& sp = model.scaling_pivot;
  return translation(v.translation) * translation(model.rotation_offset) * translation(rp) * rotation *
         translation({-rp[0], -rp[1], -rp[2]}) * translation(model.scaling_offset) * translation(sp) * scaling *
         translation({-sp[0], -sp[1], -sp[2]});
}

}  // namespace rotinterp
