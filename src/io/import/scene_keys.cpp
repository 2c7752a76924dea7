// Each joint's keys in an assimp scene: its chain's channels sampled at the union
// of their key times, the animation's key times, and the frame rate they lie on.
#include "scene_parts.h"

#include "rotinterp/io/files/key_times.h"

#include "rotinterp/clip/sampling.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

namespace rotinterp::scene_parts {

namespace {


// Key times (in ticks) closer than this are one key: assimp's FBX importer merges
// curve times in float, and ticks are at least 1e-3 s apart in every format we know.
constexpr double kSameTickTolerance = 1e-6;
// Keys within this many ticks of whole ticks count as "on whole ticks". Where the
// tick rate is a frame rate (FBX, .x: at most kMaxFrameRate ticks per second), the
// clip then gets frame_time = 1/ticks-per-second; finer ticks (glTF and Collada
// read at 1000 per second) give the step of the keys' uniform grid instead.
constexpr double kWholeTickTolerance = 1e-4;
constexpr double kMaxFrameRate = 240.0;

Quat to_quat(const aiQuaternion& q) { return Quat(q.w, q.x, q.y, q.z); }
Vec3 to_vec(const aiVector3D& v) { return Vec3(v.x, v.y, v.z); }

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

// The times within `span` (kSameTickTolerance either side).
std::vector<double> within(const std::vector<double>& ticks, const TickSpan& span) {
  std::vector<double> out;
  for (double t : ticks)
    if (t >= span.lo - kSameTickTolerance && t <= span.hi + kSameTickTolerance) out.push_back(t);
  return out;
}

// Sorted times with those within kSameTickTolerance of the previous one dropped.
std::vector<double> distinct_ticks(std::vector<double> ticks) {
  std::sort(ticks.begin(), ticks.end());
  std::vector<double> unique;
  for (double t : ticks)
    if (unique.empty() || t - unique.back() > kSameTickTolerance) unique.push_back(t);
  return unique;
}


}  // namespace

// The union over all channels: unanimated joints and the frame rate need it.
Result<KeyTimes> key_times(const aiAnimation* anim, const std::optional<TickSpan>& span, const std::string& label) {
  KeyTimes out;
  out.span = span;
  for (unsigned c = 0; c < anim->mNumChannels; ++c) add_times(anim->mChannels[c], out.all);
  for (double t : out.all)
    if (!std::isfinite(t)) return make_error(label + ": a key time is not finite");
  if (span) out.all = within(out.all, *span);
  double t0 = INFINITY, t1 = -INFINITY;
  for (double t : out.all) t0 = std::min(t0, t), t1 = std::max(t1, t);
  out.first = span ? span->lo : std::isfinite(t0) ? t0 : 0.0;
  out.last = std::isfinite(t1) ? t1 : out.first;
  out.distinct = distinct_ticks(out.all).size();
  out.whole_ticks = !out.all.empty();
  for (double t : out.all) out.whole_ticks = out.whole_ticks && std::abs(t - std::round(t)) < kWholeTickTolerance;
  return out;
}

// A joint's keys at the union of its chain's key times: a helper and its bone may
// be keyed at different times, and the joint is their product at every one of them.
JointKeys sample_joint(const NodeRec& rec, bool animated, const Channels& channels, const KeyTimes& times) {
  std::vector<const aiNode*> path = rec.chain;
  path.push_back(rec.node);
  JointKeys out;
  Eigen::Matrix4d rest = Eigen::Matrix4d::Identity();
  for (const aiNode* x : path) rest = rest * to_eigen(x->mTransformation);
  out.rest = decompose(rest);
  std::vector<double> ticks;
  for (const aiNode* x : path)
    if (const aiNodeAnim* ch = channels.of(x)) add_times(ch, ticks);
  if (times.span && !ticks.empty()) {
    ticks = within(ticks, *times.span);
    ticks.push_back(times.span->lo);
    ticks.push_back(times.span->hi);
  }
  out.ticks = distinct_ticks(std::move(ticks));
  if (out.ticks.empty()) out.ticks.push_back(times.first);
  out.keys.reserve(out.ticks.size());
  // A channel on the node itself is assimp's simple FBX animation (only translation,
  // rotation, scaling and pre/post rotations): its keys are the node's whole local
  // transform, PreRotation multiplied in, while the helpers that keeping pivots
  // leaves above the node hold the same parts at rest. So the keys go alone
  // (composing both counted a PreRotation twice: 90° off on the Maya sausage).
  const std::vector<const aiNode*> keyed =
      channels.of(rec.node) ? std::vector<const aiNode*>{rec.node} : path;
  for (double t : out.ticks) {
    if (!animated) {
      out.keys.push_back(out.rest);
      continue;
    }
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    for (const aiNode* x : keyed) m = m * node_local(x, channels.of(x), t);
    out.keys.push_back(decompose(m));
  }
  return out;
}

// Seconds per frame, 0 if the keys lie on no grid. Ticks at a frame rate (FBX, .x)
// give it directly; float seconds (glTF) and fine ticks (Collada) the step of the
// keys' uniform grid, snapped to an integer or NTSC rate within the tolerance.
double detect_frame_time(const KeyTimes& times, double tps) {
  if (times.whole_ticks && tps <= kMaxFrameRate) return 1.0 / tps;
  std::vector<double> seconds = times.all;
  for (double& t : seconds) t /= tps;
  return uniform_frame_time(std::move(seconds));
}

}  // namespace rotinterp::scene_parts
