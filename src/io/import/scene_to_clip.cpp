// aiScene → Clip (scene_to_clip.h): the joints (scene_joints.cpp) and their keys
// (scene_keys.cpp) as a skeleton and tracks, static scale baked into the offsets,
// and what the scene states beside its keys.
#include "scene_to_clip.h"

#include "rotinterp/io/fbx/fbx_bvh_layout.h"
#include "rotinterp/io/files/distinct_names.h"
#include "rotinterp/io/files/file_record.h"
#include "mesh_end_sites.h"
#include "scene_parts.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <optional>
#include <set>
#include <utility>
#include <vector>

namespace rotinterp {

namespace {

using namespace scene_parts;

// A node scale within this of 1 is no scale (assimp decomposes float matrices).
constexpr double kUnitScaleTolerance = 1e-5;

// ---- bake scale -------------------------------------------------------------------

// The uniform scale of a joint's frame to bake into its children's offsets and
// translations (a Clip has no scale); 1 where there is none. Only a static positive
// scale is kept (a non-uniform one as its mean); the rest is ignored with a warning.
double baked_scale(const std::vector<Trs>& keys, const std::string& name, const Warnings& warn, const std::string& label) {
  const Vec3 s0 = keys.front().s;
  bool varies = false;
  for (const Trs& k : keys) varies = varies || (k.s - s0).cwiseAbs().maxCoeff() > kUnitScaleTolerance * s0.cwiseAbs().maxCoeff();
  const bool uniform = (s0.cwiseAbs() - Vec3::Constant(std::abs(s0.x()))).cwiseAbs().maxCoeff() <= kUnitScaleTolerance * std::abs(s0.x());
  if (s0.minCoeff() <= 0.0)
    warn(label + ": joint '" + name + "' has a negative or zero scale; ignored");
  else if (varies)
    warn(label + ": joint '" + name + "' has animated scale; ignored (only its first key's scale is kept)");
  else if (!uniform)
    warn(label + ": joint '" + name + "' has a non-uniform scale; its mean is baked into its children's offsets");
  double s = std::cbrt(std::abs(s0.x() * s0.y() * s0.z()));
  if (!(s > 0.0) || !std::isfinite(s)) s = 1.0;
  if (std::abs(s - 1.0) < kUnitScaleTolerance) s = 1.0;
  return s;
}

// ---- tracks -----------------------------------------------------------------------

// Joint names are unique in a Clip; assimp's may be empty or repeat.
std::string unique_name(const aiNode* node, std::size_t node_index, DistinctNames& taken) {
  const std::string name = node->mName.C_Str();
  return taken.take(name.empty() ? "node" + std::to_string(node_index) : name);
}

RotationTrack rotation_track(const JointKeys& k, double tps) {
  RotationTrack rt;
  for (std::size_t i = 0; i < k.ticks.size(); ++i) {
    rt.times.push_back(k.ticks[i] / tps);
    rt.keys.push_back(k.keys[i].r);
  }
  rt.make_sign_continuous();
  return rt;
}

// Translation tracks only where an animated joint's translation moves from its
// offset by more than the float round-off of the source.
void add_translation_tracks(const Selection& sel, const std::vector<JointKeys>& keys,
                            const std::vector<double>& cum_scale, double tps, Clip& clip) {
  double size = 0.0;
  for (const Joint& j : clip.skeleton.joints) size = std::max(size, j.offset.norm());
  const double still = 1e-7 * std::max(size, 1e-9);
  for (std::size_t j = 0; j < sel.selected.size(); ++j) {
    if (!sel.animated[sel.selected[j]]) continue;
    const Joint& joint = clip.skeleton.joints[j];
    const double parent_scale = joint.parent >= 0 ? cum_scale[static_cast<std::size_t>(joint.parent)] : 1.0;
    TranslationTrack tt;
    bool moves = false;
    for (std::size_t k = 0; k < keys[j].keys.size(); ++k) {
      tt.times.push_back(keys[j].ticks[k] / tps);
      tt.keys.push_back(keys[j].keys[k].t * parent_scale);
      moves = moves || (tt.keys.back() - joint.offset).norm() > still;
    }
    if (moves) clip.translations[j] = std::move(tt);
  }
}

std::string short_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// What the scene states beside its keys: its meshes (no writer keeps them), FBX's
// frame rate (GlobalSettings: assimp's metadata FrameRate, the TimeMode, with ticks
// per second = that rate; TimeMode 0 states none) and FBX's unit (centimetres per
// unit).
void add_scene_facts(const aiScene* scene, const aiAnimation* anim, double tps, Clip& clip) {
  clip.source_meshes = scene->mNumMeshes;
  if (scene_states_rate(scene) && anim->mTicksPerSecond > 0.0) set_file_rate_hz(clip, tps);
  if (scene->mMetaData) {
    double f = 0.0;
    float ff = 0.0f;
    if (scene->mMetaData->Get("UnitScaleFactor", f) || (scene->mMetaData->Get("UnitScaleFactor", ff) && (f = ff, true)))
      if (f > 0.0 && std::isfinite(f))
        clip.unit = {f * 0.01, UnitOrigin::declared, "declared by the file: FBX UnitScaleFactor " + short_number(f)};
  }
}

// The BVH channel layout our FBX writer kept in its Models' user properties
// (fbx_bvh_layout.h), as assimp hands it on in node metadata; none where no joint has
// one, or where a joint's channels could not write its tracks (a translation track
// without position channels): a layout is taken whole or not at all.
std::optional<BvhLayout> kept_bvh_layout(const std::vector<NodeRec>& recs, const Selection& sel, const Clip& clip) {
  BvhLayout layout;
  bool any = false;
  for (std::size_t j = 0; j < sel.selected.size(); ++j) {
    std::vector<Channel>& channels = layout.channels.emplace_back();
    aiString text;
    const aiMetadata* meta = recs[sel.selected[j]].node->mMetaData;
    if (!meta || !meta->Get(kBvhChannelsProperty, text)) continue;
    const auto parsed = parse_bvh_channels_text(text.C_Str());
    if (!parsed) return std::nullopt;
    channels = *parsed;
    const bool positions = !std::all_of(channels.begin(), channels.end(), is_rotation);
    if (clip.translations[j] && !positions) return std::nullopt;
    any = true;
  }
  if (!any) return std::nullopt;
  return layout;
}

}  // namespace

bool scene_states_rate(const aiScene* scene) {
  std::int32_t mode = 0;
  return scene->mMetaData && scene->mMetaData->Get("FrameRate", mode) && mode != 0;
}

Status scene_to_clip(const aiScene* scene, const aiAnimation* anim, double tps, std::optional<double> take_ticks,
                     Clip& clip, std::size_t& folded, const Warnings& warn, const std::string& label) {
  const std::vector<NodeRec> recs = fold_helpers(scene->mRootNode, folded);
  const Channels channels(anim);
  Result<Selection> sel = select_joints(scene, recs, channels, label);
  if (!sel) return sel.failure();
  std::optional<TickSpan> span;
  if (take_ticks && *take_ticks >= 0.0 && std::isfinite(*take_ticks)) span = TickSpan{0.0, *take_ticks};
  Result<KeyTimes> times = key_times(anim, span, label);
  if (!times) return times.failure();

  const std::size_t n = sel->selected.size();
  clip.skeleton.joints.resize(n);
  clip.rotations.assign(n, RotationTrack{});
  clip.translations.assign(n, std::nullopt);
  std::vector<double> cum_scale(n, 1.0);  // uniform scale of the joint's frame (baked)
  DistinctNames names;
  std::vector<JointKeys> keys(n);
  for (std::size_t j = 0; j < n; ++j) {  // parents first
    const std::size_t node = sel->selected[j];
    const NodeRec& rec = recs[node];
    Joint& joint = clip.skeleton.joints[j];
    joint.name = unique_name(rec.node, node, names);
    joint.parent = rec.real_parent >= 0 ? sel->joint_of[static_cast<std::size_t>(rec.real_parent)] : -1;
    const double parent_scale = joint.parent >= 0 ? cum_scale[static_cast<std::size_t>(joint.parent)] : 1.0;
    keys[j] = sample_joint(rec, sel->animated[node], channels, *times);
    joint.offset = keys[j].rest.t * parent_scale;
    joint.rest_rotation = keys[j].rest.r;
    cum_scale[j] = parent_scale * baked_scale(keys[j].keys, joint.name, warn, label);
    clip.rotations[j] = rotation_track(keys[j], tps);
  }
  add_translation_tracks(*sel, keys, cum_scale, tps, clip);
  std::set<const aiNode*> joint_nodes;
  for (std::size_t node : sel->selected) joint_nodes.insert(recs[node].node);
  const auto is_joint = [&](const aiNode* x) { return joint_nodes.count(x) > 0; };
  for (std::size_t j = 0; j < n; ++j)
    if (sel->animated[sel->selected[j]])
      add_mesh_end_sites(scene, recs[sel->selected[j]].node, static_cast<int>(j), cum_scale[j], is_joint, clip.skeleton);
  set_bvh_layout(clip, kept_bvh_layout(recs, *sel, clip));
  add_scene_facts(scene, anim, tps, clip);
  // The file's own rate is the frames' rate, even where keys lie off its grid.
  if (const double stated = stated_rate_hz(clip.source_record),
      ft = stated > 0.0 ? 1.0 / stated : detect_frame_time(*times, tps);
      ft > 0.0)
    clip.frame_time = ft;
  return Ok{};
}

}  // namespace rotinterp
