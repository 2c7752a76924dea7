// A character's takes as curves in its models' own conventions, and the file of them (io/fbx/fbx_character.h).
#include "rotinterp/io/fbx/fbx_character.h"

#include "rotinterp/clip/frames.h"
#include "rotinterp/io/fbx/fbx_transform.h"
#include "rotinterp/io/files/key_times.h"
#include "rotinterp/track/sample.h"
#include "rotinterp/io/files/file_errors.h"

#include <set>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

namespace rotinterp {

namespace {

// First FBX version whose animation is objects (AnimationStack, …), not Takes.
constexpr std::uint32_t kFirstObjectVersion = 7000;
// A static Lcl Translation is the clip's rest offset within this, relative to max(1, |offset|).
constexpr double kSameTranslation = 1e-6;

// A scale within this of 1 is none (as the reader bakes it: io/import/scene_to_clip.cpp).
constexpr double kUnitScaleTolerance = 1e-5;

Vec3 vec(const FbxVec3& v) { return {v[0], v[1], v[2]}; }

// The uniform scale the reader baked into a joint's children's offsets and
// translations (the mean of a positive static scale, else 1): divided out again here.
double baked_scale(const FbxVec3& s) {
  double mean = std::cbrt(std::abs(s[0] * s[1] * s[2]));
  if (!(mean > 0.0) || !std::isfinite(mean) || std::abs(mean - 1.0) < kUnitScaleTolerance) mean = 1.0;
  return mean;
}

// The constant part C and the rotated part V of a node's local translation:
// translation(t) = T + C + Q(t)·V, from T·Roff·Rp·Rpre·R·Rpost⁻¹·Rp⁻¹·Soff·Sp·S·Sp⁻¹
// (io/fbx/fbx_transform.h) with S the node's static scaling.
struct PivotTerms {
  Vec3 constant = Vec3::Zero(), rotated = Vec3::Zero();
};
PivotTerms pivot_terms(const FbxModel& m) {
  const Vec3 scaled_pivot = vec(m.scaling).cwiseProduct(vec(m.scaling_pivot));
  return {vec(m.rotation_offset) + vec(m.rotation_pivot),
          vec(m.scaling_offset) + vec(m.scaling_pivot) - scaled_pivot - vec(m.rotation_pivot)};
}

// Each joint's model: the one of its name.
Result<std::vector<const FbxModel*>> joint_models(const Skeleton& skeleton, const FbxCharacter& source) {
  std::multimap<std::string, const FbxModel*> by_name;
  for (const FbxModel& m : source.animation.models) by_name.emplace(m.name, &m);
  std::vector<const FbxModel*> out;
  for (const Joint& joint : skeleton.joints) {
    const auto count = by_name.count(joint.name);
    if (count != 1)
      return make_error(source.label + ": joint '" + fbx_printable(joint.name) + "' has " +
                        (count == 0 ? std::string("no model") : std::to_string(count) + " models") + " of its name");
    out.push_back(by_name.find(joint.name)->second);
  }
  return out;
}

const FbxNodeLayers* layers_of(const std::map<std::string, FbxNodeLayers>& layers, const FbxModel& m) {
  const auto it = layers.find(m.name);
  return it == layers.end() ? nullptr : &it->second;
}

}  // namespace

Result<FbxCharacter> read_fbx_character(const std::filesystem::path& path) {
  FbxCharacter out;
  out.label = path.string();
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  if (!in || !(bytes << in.rdbuf())) return make_error(out.label + ": cannot read the file", file_error::cannot_open);
  auto doc = parse_fbx_nodes(bytes.str(), out.label);
  if (!doc) return doc.failure();
  if (doc->version < kFirstObjectVersion)
    return make_error(out.label + ": FBX " + std::to_string(doc->version) + " keeps its animation in Takes; only FBX 7 files are edited");
  auto animation = read_fbx_animation(*doc, out.label);
  if (!animation) return animation.failure();
  out.doc = std::move(*doc);
  out.animation = std::move(*animation);
  return out;
}

const FbxTake* fbx_character_source_take(const FbxCharacter& source, const std::string& name) {
  const std::vector<FbxTake>& takes = source.animation.takes;
  const auto same_name = std::find_if(takes.begin(), takes.end(), [&](const FbxTake& t) { return t.name == name; });
  return same_name != takes.end() ? &*same_name : takes.empty() ? nullptr : &takes.front();
}

Result<FbxCharacterJoints> fbx_character_joints(const Clip& clip, const FbxCharacter& source, const FbxTake* take) {
  auto models = joint_models(clip.skeleton, source);
  if (!models) return models.failure();
  const std::int64_t origin = take ? fbx_take_span(*take).start : 0;
  const std::map<std::string, FbxNodeLayers> layers = take ? fbx_node_layers(*take) : std::map<std::string, FbxNodeLayers>{};
  FbxCharacterJoints out;
  out.models = std::move(*models);
  std::vector<double> scale;  // the reader's baked scale of each joint's frame
  for (std::size_t j = 0; j < out.models.size(); ++j) {
    const FbxModel& m = *out.models[j];
    const int parent = clip.skeleton.joints[j].parent;
    FbxJointFrame f;
    f.parent_scale = parent >= 0 ? scale[static_cast<std::size_t>(parent)] : 1.0;
    const FbxVec3 s0 = take ? fbx_lcl_values(*take, m, layers_of(layers, m), static_cast<double>(origin)).scaling : m.scaling;
    scale.push_back(f.parent_scale * baked_scale(s0));
    f.axes = fbx_order_axes(m.rotation_order);
    f.pre = fbx_euler_rotation(0, m.pre_rotation);
    f.post = fbx_euler_rotation(0, m.post_rotation);
    const PivotTerms pivot = pivot_terms(m);
    f.constant = pivot.constant;
    f.rotated = pivot.rotated;
    const Vec3 offset = clip.skeleton.joints[j].offset / f.parent_scale;
    f.keyed_translation = !pivot.constant.isZero(0.0) || !pivot.rotated.isZero(0.0) ||
                          (offset - vec(m.translation)).norm() > kSameTranslation * std::max(1.0, offset.norm());
    out.frames.push_back(f);
  }
  return out;
}

void keep_source_scaling(std::vector<FbxOutJoint>& curves, const FbxCharacterJoints& joints, const FbxTake* take) {
  if (!take) return;
  const std::map<std::string, FbxNodeLayers> layers = fbx_node_layers(*take);
  for (std::size_t j = 0; j < curves.size(); ++j) {
    FbxOutJoint& joint = curves[j];
    const FbxModel& m = *joints.models[j];
    const FbxNodeLayers* node = layers_of(layers, m);
    if (!node || !node->keyed(kFbxScaling)) continue;
    joint.has_scaling = true;
    for (const FbxOutKey& key : joint.rotation[static_cast<std::size_t>(joint.axes[0])]) {
      const FbxVec3 s = fbx_lcl_values(*take, m, node, static_cast<double>(key.ticks)).scaling;
      for (std::size_t a = 0; a < 3; ++a) joint.scaling[a].push_back({key.ticks, static_cast<float>(s[a])});
    }
  }
}

FbxOutTake fbx_character_out_take(const std::string& name, std::vector<FbxOutJoint> curves, const FbxTake* replaced) {
  FbxOutTake out;
  out.name = name.empty() ? std::string("clip") : name;
  out.curves = std::move(curves);
  if (replaced && replaced->name == out.name && !replaced->layers.empty()) out.layer = replaced->layers.front().name;
  return out;
}

Result<FbxCharacterTake> fbx_character_take(const Clip& clip, const FbxCharacter& source, const FbxTake* take) {
  if (Status s = clip.validate(); !s) return s.failure("cannot write an invalid clip: ");
  auto joints = fbx_character_joints(clip, source, take);
  if (!joints) return joints.failure();
  const std::int64_t origin = take ? fbx_take_span(*take).start : 0;
  const std::vector<double> times = all_key_times(clip);
  // The clip with each joint's rotation and translation as its model's Lcl values.
  Clip local = clip;
  std::vector<EulerAxes> axes;
  FbxCharacterTake out;
  for (std::size_t j = 0; j < joints->models.size(); ++j) {
    const FbxJointFrame& f = joints->frames[j];
    out.model_ids.push_back(joints->models[j]->id);
    axes.push_back(f.axes);
    for (Quat& q : local.rotations[j].keys) q = f.lcl_rotation(q);
    const auto& track = clip.translations[j];
    if (!track && !f.keyed_translation) continue;  // the model's static value holds
    // A key at every key time of the clip.
    TranslationTrack keyed;
    for (double t : times) {
      const Vec3 value = track ? sample_translation(*track, t) : clip.skeleton.joints[j].offset;
      keyed.times.push_back(t);
      keyed.keys.push_back(f.lcl_translation(value, sample_rotation(clip.rotations[j], t)));
    }
    local.translations[j] = std::move(keyed);
  }
  out.take = fbx_character_out_take(clip.name, fbx_frame_curves(local, axes), take);
  for (FbxOutJoint& joint : out.take.curves)
    for (auto* set : {&joint.rotation, &joint.translation})
      for (FbxOutCurve& curve : *set)
        for (FbxOutKey& key : curve) key.ticks += origin;
  keep_source_scaling(out.take.curves, *joints, take);
  unkey_resting_joints(out, source, take);
  return out;
}

namespace {

// Every key of `curves` (else its default) within `tolerance` of `value`, per axis.
bool holds(const std::array<FbxOutCurve, 3>& curves, const Vec3& fallback, const FbxVec3& value, double tolerance) {
  for (std::size_t a = 0; a < 3; ++a) {
    const double v = value[a], tol = tolerance * std::max(1.0, std::abs(v));
    if (curves[a].empty() && std::abs(fallback[static_cast<int>(a)] - v) > tol) return false;
    for (const FbxOutKey& key : curves[a])
      if (std::abs(key.value - v) > tol) return false;
  }
  return true;
}

}  // namespace

void unkey_resting_joints(FbxCharacterTake& written, const FbxCharacter& source, const FbxTake* take) {
  // Float keys: degrees and file units within float precision of the model's values.
  constexpr double kRotationDegrees = 1e-4, kTranslationRelative = 1e-6;
  std::set<std::string> animated;
  if (take)
    for (const FbxAnimatedProperty& p : take->properties) animated.insert(p.node);
  std::vector<std::size_t> resting;
  std::vector<FbxOutJoint>& curves = written.take.curves;
  for (std::size_t j = 0; j < curves.size() && j < written.model_ids.size(); ++j) {
    const auto m = std::find_if(source.animation.models.begin(), source.animation.models.end(),
                                [&](const FbxModel& x) { return x.id == written.model_ids[j]; });
    if (m == source.animation.models.end() || animated.count(m->name) || curves[j].has_scaling) continue;
    if (!holds(curves[j].rotation, curves[j].rotation_default, m->rotation, kRotationDegrees)) continue;
    if (curves[j].has_translation &&
        !holds(curves[j].translation, curves[j].translation_default, m->translation, kTranslationRelative))
      continue;
    resting.push_back(j);
  }
  if (resting.size() == curves.size()) return;  // a take keys something
  for (std::size_t j : resting) {
    curves[j].has_rotation = curves[j].has_translation = false;
    curves[j].rotation = curves[j].translation = {};
  }
}

Result<FbxCharacterFile> fbx_character_file(const std::vector<Clip>& takes, const std::filesystem::path& source,
                                            bool ascii) {
  if (takes.empty()) return make_error(source.string() + ": no takes to write");
  auto character = read_fbx_character(source);
  if (!character) return character.failure();
  std::vector<FbxCharacterTake> written;
  std::optional<Rate> rate = clip_rate(takes.front());
  for (const Clip& clip : takes) {
    if (clip_rate(clip) != rate) rate.reset();  // TimeMode then keeps the source's
    auto one = fbx_character_take(clip, *character, fbx_character_source_take(*character, clip.name));
    if (!one) return one.failure();
    written.push_back(std::move(*one));
  }
  const bool as_ascii = ascii || !character->doc.binary;
  return encode_fbx_character(*character, written, rate, as_ascii ? FbxEncoding::ascii : FbxEncoding::binary);
}

}  // namespace rotinterp
