// encode_source_fbx: the source FBX's own curves (keys, tangents, rotation order, Pre/PostRotation) written back.
#include "rotinterp/io/fbx/fbx_source.h"

#include "fbx_rest.h"
#include "rotinterp/io/fbx/fbx_write.h"

#include <cmath>
#include <cstring>

namespace rotinterp {

namespace {

// Packed weights are 16-bit decimal fixed point (0.4 digits); velocities in
// hundredths (as io/fbx/fbx_curves.cpp reads them).
constexpr double kWeightScale = 10000.0, kVelocityScale = 100.0;

float bits_as_float(std::uint32_t u) {
  float f;
  std::memcpy(&f, &u, 4);
  return f;
}
std::uint32_t pack(double lo, double hi, double scale) {
  const auto l = static_cast<std::uint16_t>(static_cast<std::int16_t>(std::lround(lo * scale)));
  const auto h = static_cast<std::uint16_t>(static_cast<std::int16_t>(std::lround(hi * scale)));
  return static_cast<std::uint32_t>(l) | (static_cast<std::uint32_t>(h) << 16);
}
std::uint32_t pack_unsigned(double lo, double hi, double scale) {
  const auto l = static_cast<std::uint16_t>(std::lround(lo * scale)), h = static_cast<std::uint16_t>(std::lround(hi * scale));
  return static_cast<std::uint32_t>(l) | (static_cast<std::uint32_t>(h) << 16);
}

// A read key as written: its stored flags, and its data re-packed as stored.
FbxOutKey copied_key(const FbxKey& k) {
  FbxOutKey out;
  out.ticks = k.ticks;
  out.value = static_cast<float>(k.value);
  out.stored_flags = k.flags;
  const bool tcb = k.tangent == FbxTangent::tcb;
  out.stored_data = {static_cast<float>(tcb ? k.tension : k.right_slope),
                     static_cast<float>(tcb ? k.continuity : k.next_left_slope),
                     tcb ? static_cast<float>(k.bias) : bits_as_float(pack_unsigned(k.right_weight, k.next_left_weight, kWeightScale)),
                     bits_as_float(pack(k.right_velocity, k.next_left_velocity, kVelocityScale))};
  return out;
}

bool zero(const FbxVec3& v) { return v[0] == 0.0 && v[1] == 0.0 && v[2] == 0.0; }
Vec3 vec(const FbxVec3& v) { return {v[0], v[1], v[2]}; }

// The take's first-layer channels of one property, if it has a curve with keys.
const FbxLayerChannels* keyed_layer(const FbxNodeLayers& node, std::size_t property) {
  for (const FbxLayerChannels& l : node.properties[property])
    if (l.layer == 0)
      for (const FbxCurve* c : l.channels)
        if (c && !c->keys.empty()) return &l;
  return nullptr;
}

// Whether the joint's translation in the clip (its track, else its rest offset, at
// its rotation key times) is what the curves give.
bool same_translation(const Clip& clip, std::size_t j, const FbxTake& take, const FbxModel& model,
                      const FbxNodeLayers& node, const SourceClip& source) {
  const auto& track = clip.translations[j];
  const std::vector<double>& times = track ? track->times : clip.rotations[j].times;
  for (std::size_t k = 0; k < times.size(); ++k) {
    const Vec3 expected = track ? track->keys[k] : clip.skeleton.joints[j].offset;
    const FbxVec3 v = fbx_lcl_values(take, model, &node, fbx_source_ticks(source, times[k])).translation;
    if ((vec(v) - expected).norm() > 1e-5 * (1.0 + expected.norm())) return false;
  }
  return true;
}

}  // namespace

Result<SourceFbx> encode_source_fbx(const Clip& clip, const SourceClip& source, const std::vector<std::string>& keep,
                                    bool ascii, const std::string& label) {
  if (Status s = clip.validate(); !s) return s.failure("cannot write an invalid clip: ");
  std::vector<FbxOutJoint> curves = fbx_frame_curves(clip);
  const FbxTake& take = source.curves.takes.at(source.take);
  // The file's own time axis: clip time t is FBX time span start + t.
  const std::int64_t origin = fbx_take_span(take).start;
  for (FbxOutJoint& o : curves)
    for (auto* set : {&o.rotation, &o.translation})
      for (FbxOutCurve& c : *set)
        for (FbxOutKey& k : c) k.ticks += origin;
  SourceFbx out;
  if (take.layers.size() == 1) {
    auto joints = fbx_joint_curves(clip, source, keep, label);
    if (!joints) return joints.failure();
    const std::vector<Vec3> rest = fbx_rest_translations(clip);
    for (std::size_t j = 0; j < curves.size(); ++j) {
      const FbxJointCurves& jc = (*joints)[j];
      if (!jc.model) continue;
      const FbxModel& m = *jc.model;
      if (!zero(m.rotation_offset) || !zero(m.rotation_pivot) || !zero(m.scaling_offset) || !zero(m.scaling_pivot)) continue;
      const FbxLayerChannels* rotation = keyed_layer(jc.layers, kFbxRotation);
      if (!rotation) continue;
      FbxOutJoint& o = curves[j];
      o.axes = fbx_order_axes(m.rotation_order);
      o.node = FbxOutNode{rest[j], vec(m.rotation), vec(m.pre_rotation), vec(m.post_rotation)};
      for (std::size_t a = 0; a < 3; ++a) {
        o.rotation[a].clear();
        o.rotation_default[static_cast<Eigen::Index>(a)] = rotation->defaults[a];
        if (const FbxCurve* c = rotation->channels[a])
          for (const FbxKey& k : c->keys) o.rotation[a].push_back(copied_key(k));
      }
      ++out.copied;
      const FbxLayerChannels* translation = keyed_layer(jc.layers, kFbxTranslation);
      if (!translation || !same_translation(clip, j, take, m, jc.layers, source)) continue;
      o.has_translation = true;
      for (std::size_t a = 0; a < 3; ++a) {
        o.translation[a].clear();
        o.translation_default[static_cast<Eigen::Index>(a)] = translation->defaults[a];
        if (const FbxCurve* c = translation->channels[a])
          for (const FbxKey& k : c->keys) o.translation[a].push_back(copied_key(k));
      }
    }
  }
  auto bytes = encode_fbx_curves(clip, curves, ascii ? FbxEncoding::ascii : FbxEncoding::binary);
  if (!bytes) return bytes.failure();
  out.bytes = std::move(*bytes);
  return out;
}

}  // namespace rotinterp
