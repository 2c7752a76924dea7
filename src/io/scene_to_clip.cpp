// aiScene → Clip (scene_to_clip.h), as the steps of scene_to_clip(): fold the
// helper nodes, select the joints, gather the key times, sample each joint's keys,
// bake its static scale, build the tracks, detect the frame rate.
#include "scene_to_clip.h"

#include "mesh_end_sites.h"
#include "rotinterp/clip/sampling.h"

#include <assimp/scene.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <cstdio>
#include <string_view>
#include <utility>
#include <vector>

namespace rotinterp {

namespace {

constexpr const char* kHelperTag = "_$AssimpFbx$_";
constexpr const char* kGeometricTag = "_$AssimpFbx$_Geometric";

// Key times (in ticks) closer than this are one key: assimp's FBX importer merges
// curve times in float, and ticks are at least 1e-3 s apart in every format we know.
constexpr double kSameTickTolerance = 1e-6;
// Keys within this many ticks of whole ticks count as "on whole ticks". Where the
// tick rate is a frame rate (FBX, .x: at most kMaxFrameRate ticks per second), the
// clip then gets frame_time = 1/ticks-per-second; finer ticks (glTF and Collada
// read at 1000 per second) give the step of the keys' uniform grid instead.
constexpr double kWholeTickTolerance = 1e-4;
constexpr double kMaxFrameRate = 240.0;
// A node scale within this of 1 is no scale (assimp decomposes float matrices).
constexpr double kUnitScaleTolerance = 1e-5;
// uniform_grid_step(): every time within this many steps of the grid; a step
// within this of an integer or NTSC (n·1000/1001) rate is that rate.
constexpr double kGridTolerance = 1e-3;
constexpr double kRateSnapTolerance = 1e-5;

Eigen::Matrix4d to_eigen(const aiMatrix4x4& m) {
  Eigen::Matrix4d e;
  e << m.a1, m.a2, m.a3, m.a4, m.b1, m.b2, m.b3, m.b4, m.c1, m.c2, m.c3, m.c4, m.d1, m.d2, m.d3, m.d4;
  return e;
}

Quat to_quat(const aiQuaternion& q) { return Quat(q.w, q.x, q.y, q.z); }
Vec3 to_vec(const aiVector3D& v) { return Vec3(v.x, v.y, v.z); }

// Translation, rotation, scale of an affine matrix (no shear assumed).
struct Trs {
  Vec3 t = Vec3::Zero();
  Quat r = Quat::Identity();
  Vec3 s = Vec3::Ones();
};

Trs decompose(const Eigen::Matrix4d& m) {
  Trs out;
  out.t = m.block<3, 1>(0, 3);
  Mat3 a = m.block<3, 3>(0, 0);
  for (int c = 0; c < 3; ++c) out.s[c] = a.col(c).norm();
  if (a.determinant() < 0) out.s[0] = -out.s[0];
  for (int c = 0; c < 3; ++c)
    if (out.s[c] != 0.0) a.col(c) /= out.s[c];
  out.r = normalized_or_identity(Quat(a));
  return out;
}

Eigen::Matrix4d compose(const Trs& x) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<3, 3>(0, 0) = x.r.toRotationMatrix() * x.s.asDiagonal();
  m.block<3, 1>(0, 3) = x.t;
  return m;
}

// Value of a key array at time t (ticks): clamped, linear between keys.
template <class Key, class Lerp>
auto sample_keys(const Key* keys, unsigned n, double t, Lerp lerp) {
  if (t <= keys[0].mTime || n == 1) return lerp(keys[0], keys[0], 0.0);
  if (t >= keys[n - 1].mTime) return lerp(keys[n - 1], keys[n - 1], 0.0);
  const Key* hi = std::upper_bound(keys, keys + n, t, [](double x, const Key& k) { return x < k.mTime; });
  const Key* lo = hi - 1;
  const double span = hi->mTime - lo->mTime;
  return lerp(*lo, *hi, span > 0 ? (t - lo->mTime) / span : 0.0);
}

// A node's local transform at time t: its channel where it has one (each missing
// component from the static transform), else its static transform.
Eigen::Matrix4d node_local(const aiNode* node, const aiNodeAnim* ch, double t) {
  const Eigen::Matrix4d fixed = to_eigen(node->mTransformation);
  if (!ch) return fixed;
  Trs x = decompose(fixed);
  if (ch->mNumPositionKeys > 0)
    x.t = sample_keys(ch->mPositionKeys, ch->mNumPositionKeys, t, [](const aiVectorKey& a, const aiVectorKey& b, double u) {
      return Vec3((1 - u) * to_vec(a.mValue) + u * to_vec(b.mValue));
    });
  if (ch->mNumRotationKeys > 0)
    x.r = sample_keys(ch->mRotationKeys, ch->mNumRotationKeys, t, [](const aiQuatKey& a, const aiQuatKey& b, double u) {
      const Quat qa = normalized_or_identity(to_quat(a.mValue));
      return u == 0.0 ? qa : qa.slerp(u, normalized_or_identity(to_quat(b.mValue)));
    });
  if (ch->mNumScalingKeys > 0)
    x.s = sample_keys(ch->mScalingKeys, ch->mNumScalingKeys, t, [](const aiVectorKey& a, const aiVectorKey& b, double u) {
      return Vec3((1 - u) * to_vec(a.mValue) + u * to_vec(b.mValue));
    });
  return compose(x);
}

void add_times(const aiNodeAnim* ch, std::vector<double>& times) {
  for (unsigned k = 0; k < ch->mNumPositionKeys; ++k) times.push_back(ch->mPositionKeys[k].mTime);
  for (unsigned k = 0; k < ch->mNumRotationKeys; ++k) times.push_back(ch->mRotationKeys[k].mTime);
  for (unsigned k = 0; k < ch->mNumScalingKeys; ++k) times.push_back(ch->mScalingKeys[k].mTime);
}

// Sorted times with those within kSameTickTolerance of the previous one dropped.
std::vector<double> distinct_ticks(std::vector<double> ticks) {
  std::sort(ticks.begin(), ticks.end());
  std::vector<double> unique;
  for (double t : ticks)
    if (unique.empty() || t - unique.back() > kSameTickTolerance) unique.push_back(t);
  return unique;
}

// The step d when every time is t₀ + k·d (within kGridTolerance of d), d the
// smallest gap; 0 otherwise. Formats that store seconds in float (glTF) or at a
// fixed tick rate (Collada: 1000/s) keep their frame rate this way.
double uniform_grid_step(std::vector<double> ticks) {
  const std::vector<double> unique = distinct_ticks(std::move(ticks));
  if (unique.size() < 2) return 0.0;
  double gap = INFINITY;
  for (std::size_t k = 1; k < unique.size(); ++k) gap = std::min(gap, unique[k] - unique[k - 1]);
  // The step from the whole span: one float gap is too noisy over thousands of frames.
  const double span = unique.back() - unique.front();
  const double d = span / std::round(span / gap);
  for (double t : unique) {
    const double steps = (t - unique.front()) / d;
    if (std::abs(steps - std::round(steps)) > kGridTolerance) return 0.0;
  }
  return d;
}

// The animation's channels by node name (the first where names repeat).
class Channels {
 public:
  explicit Channels(const aiAnimation* anim) {
    for (unsigned c = 0; c < anim->mNumChannels; ++c) by_name_.emplace(anim->mChannels[c]->mNodeName.C_Str(), anim->mChannels[c]);
  }
  const aiNodeAnim* of(const aiNode* n) const {
    const auto it = by_name_.find(n->mName.C_Str());
    return it == by_name_.end() ? nullptr : it->second;
  }

 private:
  std::map<std::string, const aiNodeAnim*> by_name_;
};

// ---- fold helper nodes ----------------------------------------------------------

// A node that is not an assimp helper, with the helpers above it.
struct NodeRec {
  const aiNode* node = nullptr;
  int real_parent = -1;              // index in the list of the nearest non-helper ancestor
  std::vector<const aiNode*> chain;  // helper nodes between real_parent and node, top first
};

bool is_helper(const aiNode* n) { return std::string_view(n->mName.C_Str()).find(kHelperTag) != std::string_view::npos; }

void fold_below(const aiNode* n, int parent, std::vector<const aiNode*> chain, std::vector<NodeRec>& recs,
                std::size_t& folded) {
  if (is_helper(n)) {
    // FBX geometric transforms apply to the node's geometry only: assimp puts
    // GeometricX above the node and GeometricXInverse below it, so they cancel
    // for the children. Dropping both gives the joint its own transform.
    if (std::string_view(n->mName.C_Str()).find(kGeometricTag) == std::string_view::npos) chain.push_back(n);
    ++folded;
    for (unsigned c = 0; c < n->mNumChildren; ++c) fold_below(n->mChildren[c], parent, chain, recs, folded);
    return;
  }
  const int me = static_cast<int>(recs.size());
  recs.push_back(NodeRec{n, parent, std::move(chain)});
  for (unsigned c = 0; c < n->mNumChildren; ++c) fold_below(n->mChildren[c], me, {}, recs, folded);
}

// The real nodes depth-first, each with its chain of `$AssimpFbx$` helpers: assimp
// splits an FBX node's pivots and pre/post rotations into helper nodes above it,
// and the joint is all of them composed, so world poses stay exact.
std::vector<NodeRec> fold_helpers(const aiNode* root, std::size_t& folded) {
  std::vector<NodeRec> recs;
  fold_below(root, -1, {}, recs, folded);
  return recs;
}

// ---- select joints ----------------------------------------------------------------

struct Selection {
  std::vector<std::size_t> selected;  // the joints' indices among the nodes, in order
  std::vector<int> joint_of;          // per node: its joint, or −1
  std::vector<bool> animated;         // per node: a channel moves it or a helper of its chain
};

// Joints are the animated nodes, bones, and their ancestors: what moves a mesh or
// is moved. Also transform-only subtrees (no meshes, cameras or lights anywhere
// below): end bones and static joints of a skeleton that nothing animates or skins.
Result<Selection> select_joints(const aiScene* scene, const std::vector<NodeRec>& recs, const Channels& channels,
                                const std::string& label) {
  std::set<std::string> bones;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m)
    for (unsigned b = 0; b < scene->mMeshes[m]->mNumBones; ++b) bones.insert(scene->mMeshes[m]->mBones[b]->mName.C_Str());
  std::set<std::string> non_joints;
  for (unsigned c = 0; c < scene->mNumCameras; ++c) non_joints.insert(scene->mCameras[c]->mName.C_Str());
  for (unsigned l = 0; l < scene->mNumLights; ++l) non_joints.insert(scene->mLights[l]->mName.C_Str());
  std::vector<bool> bare(recs.size(), true);  // no mesh/camera/light in the subtree
  for (std::size_t i = recs.size(); i-- > 0;) {
    const aiNode* node = recs[i].node;
    if (node->mNumMeshes > 0 || non_joints.count(node->mName.C_Str())) bare[i] = false;
    for (const aiNode* h : recs[i].chain)
      if (h->mNumMeshes > 0) bare[i] = false;
    if (!bare[i] && recs[i].real_parent >= 0) bare[static_cast<std::size_t>(recs[i].real_parent)] = false;
  }
  Selection out;
  std::vector<bool> keep(recs.size(), false);
  out.animated.assign(recs.size(), false);
  for (std::size_t i = 0; i < recs.size(); ++i) {
    bool a = channels.of(recs[i].node) != nullptr;
    for (const aiNode* h : recs[i].chain) a = a || channels.of(h) != nullptr;
    out.animated[i] = a;
    if (a || bones.count(recs[i].node->mName.C_Str()) || (bare[i] && i > 0))
      for (int k = static_cast<int>(i); k >= 0 && !keep[static_cast<std::size_t>(k)]; k = recs[static_cast<std::size_t>(k)].real_parent)
        keep[static_cast<std::size_t>(k)] = true;
  }
  // The scene root only when it transforms something.
  if (!recs.empty() && keep[0] && !out.animated[0] && recs[0].chain.empty() &&
      to_eigen(recs[0].node->mTransformation).isIdentity(1e-12) && !bones.count(recs[0].node->mName.C_Str()))
    keep[0] = false;
  out.joint_of.assign(recs.size(), -1);
  for (std::size_t i = 0; i < recs.size(); ++i)
    if (keep[i]) {
      out.joint_of[i] = static_cast<int>(out.selected.size());
      out.selected.push_back(i);
    }
  if (out.selected.empty()) return make_error(label + ": the animation moves no node of the scene");
  return out;
}

// ---- key times --------------------------------------------------------------------

struct KeyTimes {
  std::vector<double> all;   // every key of every channel, ticks
  double first = 0.0;        // the animation's first key: where unanimated joints get theirs
  bool whole_ticks = false;  // every key on a whole tick (within kWholeTickTolerance)
};

// The union over all channels: unanimated joints and the frame rate need it.
Result<KeyTimes> key_times(const aiAnimation* anim, const std::string& label) {
  KeyTimes out;
  double t0 = INFINITY;
  for (unsigned c = 0; c < anim->mNumChannels; ++c) add_times(anim->mChannels[c], out.all);
  for (double t : out.all) t0 = std::min(t0, t);
  out.first = std::isfinite(t0) ? t0 : 0.0;
  out.whole_ticks = !out.all.empty();
  for (double t : out.all) out.whole_ticks = out.whole_ticks && std::abs(t - std::round(t)) < kWholeTickTolerance;
  for (double t : out.all)
    if (!std::isfinite(t)) return make_error(label + ": a key time is not finite");
  return out;
}

// ---- sample keys ------------------------------------------------------------------

struct JointKeys {
  Trs rest;                   // the chain's static transforms composed
  std::vector<double> ticks;  // distinct key times of the chain's channels (or the first key)
  std::vector<Trs> keys;      // the chain's local transform at each tick
};

// A joint's keys at the union of its chain's key times: a helper and its bone may
// be keyed at different times, and the joint is their product at every one of them.
JointKeys sample_joint(const NodeRec& rec, bool animated, const Channels& channels, double first_tick) {
  std::vector<const aiNode*> path = rec.chain;
  path.push_back(rec.node);
  JointKeys out;
  Eigen::Matrix4d rest = Eigen::Matrix4d::Identity();
  for (const aiNode* x : path) rest = rest * to_eigen(x->mTransformation);
  out.rest = decompose(rest);
  std::vector<double> ticks;
  for (const aiNode* x : path)
    if (const aiNodeAnim* ch = channels.of(x)) add_times(ch, ticks);
  out.ticks = distinct_ticks(std::move(ticks));
  if (out.ticks.empty()) out.ticks.push_back(first_tick);
  out.keys.reserve(out.ticks.size());
  for (double t : out.ticks) {
    if (!animated) {
      out.keys.push_back(out.rest);
      continue;
    }
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    for (const aiNode* x : path) m = m * node_local(x, channels.of(x), t);
    out.keys.push_back(decompose(m));
  }
  return out;
}

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
std::string unique_name(const aiNode* node, std::size_t node_index, std::set<std::string>& taken) {
  std::string name = node->mName.C_Str();
  if (name.empty()) name = "node" + std::to_string(node_index);
  while (!taken.insert(name).second) name += "#";
  return name;
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

// ---- detect rate ------------------------------------------------------------------

// Seconds per frame, 0 if the keys lie on no grid. Ticks at a frame rate (FBX, .x)
// give it directly; float seconds (glTF) and fine ticks (Collada) the step of the
// keys' uniform grid, snapped to an integer or NTSC rate within the tolerance.
double detect_frame_time(const KeyTimes& times, double tps) {
  if (times.whole_ticks && tps <= kMaxFrameRate) return 1.0 / tps;
  if (const double step = uniform_grid_step(times.all) / tps; step > 0.0) {
    const std::optional<Rate> exact = recognize_rate(1.0 / step, kRateSnapTolerance);
    return exact ? exact->period() : step;
  }
  return 0.0;
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
  if (std::int32_t mode = 0; scene->mMetaData && scene->mMetaData->Get("FrameRate", mode) && mode != 0 &&
                             anim->mTicksPerSecond > 0.0)
    clip.file_rate_hz = tps;
  if (scene->mMetaData) {
    double f = 0.0;
    float ff = 0.0f;
    if (scene->mMetaData->Get("UnitScaleFactor", f) || (scene->mMetaData->Get("UnitScaleFactor", ff) && (f = ff, true)))
      if (f > 0.0 && std::isfinite(f))
        clip.unit = {f * 0.01, UnitOrigin::declared, "declared by the file: FBX UnitScaleFactor " + short_number(f)};
  }
}

}  // namespace

Status scene_to_clip(const aiScene* scene, const aiAnimation* anim, double tps, Clip& clip, std::size_t& folded,
                     const Warnings& warn, const std::string& label) {
  const std::vector<NodeRec> recs = fold_helpers(scene->mRootNode, folded);
  const Channels channels(anim);
  Result<Selection> sel = select_joints(scene, recs, channels, label);
  if (!sel) return sel.failure();
  Result<KeyTimes> times = key_times(anim, label);
  if (!times) return times.failure();

  const std::size_t n = sel->selected.size();
  clip.skeleton.joints.resize(n);
  clip.rotations.assign(n, RotationTrack{});
  clip.translations.assign(n, std::nullopt);
  std::vector<double> cum_scale(n, 1.0);  // uniform scale of the joint's frame (baked)
  std::set<std::string> names;
  std::vector<JointKeys> keys(n);
  for (std::size_t j = 0; j < n; ++j) {  // parents first
    const std::size_t node = sel->selected[j];
    const NodeRec& rec = recs[node];
    Joint& joint = clip.skeleton.joints[j];
    joint.name = unique_name(rec.node, node, names);
    joint.parent = rec.real_parent >= 0 ? sel->joint_of[static_cast<std::size_t>(rec.real_parent)] : -1;
    const double parent_scale = joint.parent >= 0 ? cum_scale[static_cast<std::size_t>(joint.parent)] : 1.0;
    keys[j] = sample_joint(rec, sel->animated[node], channels, times->first);
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
  if (const double ft = detect_frame_time(*times, tps); ft > 0.0) clip.frame_time = ft;
  add_scene_facts(scene, anim, tps, clip);
  return Ok{};
}

}  // namespace rotinterp
