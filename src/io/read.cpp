// The clip reader: our own BVH pass, and assimp for every other format (in the
// importer process: import.h).
#include "rotinterp/io/read.h"

#include "assimp_text.h"
#include "clip_wire.h"
#include "import.h"
#include "rotinterp/clip/sampling.h"
#include "rotinterp/io/bvh.h"
#include "rotinterp/io/info.h"

#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/scene.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <memory>
#include <new>
#include <optional>
#include <set>
#include <stdexcept>
#include <sstream>
#include <string_view>

namespace rotinterp {

namespace {

namespace fs = std::filesystem;

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

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

struct Warnings {
  const WarningFn* fn = nullptr;
  std::vector<std::string>* list = nullptr;
  void operator()(const std::string& w) const {
    if (list) list->push_back(w);
    if (fn && *fn) (*fn)(w);
  }
};

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

// The step d when every time is t₀ + k·d (within kGridTolerance of d), d the
// smallest gap; 0 otherwise. Formats that store seconds in float (glTF) or at a
// fixed tick rate (Collada: 1000/s) keep their frame rate this way. A step within
// 1e-5 of an integer or NTSC (n·1000/1001) rate is that rate (recognize_rate).
constexpr double kGridTolerance = 1e-3;
constexpr double kRateSnapTolerance = 1e-5;
double uniform_grid_step(std::vector<double> ticks) {
  std::sort(ticks.begin(), ticks.end());
  std::vector<double> unique;
  for (double t : ticks)
    if (unique.empty() || t - unique.back() > kSameTickTolerance) unique.push_back(t);
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

bool is_helper(const aiNode* n) { return std::string_view(n->mName.C_Str()).find(kHelperTag) != std::string_view::npos; }

struct Loaded {
  ClipFileInfo info;
};

// ---- checks before any parser runs --------------------------------------------

Status check_file(const fs::path& path, const std::string& label) {
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (ec == std::errc::too_many_symbolic_link_levels)
    return make_error(label + ": a loop of symbolic links (too many levels of symbolic links)", ErrorKind::no_file);
  if (ec || !fs::exists(st)) {
    std::error_code lec;
    if (fs::is_symlink(fs::symlink_status(path, lec)))
      return make_error(label + ": a symbolic link to a missing file", ErrorKind::no_file);
    if (ec && ec != std::errc::no_such_file_or_directory)
      return make_error(label + ": cannot read: " + ec.message(), ErrorKind::cannot_open);
    return make_error(label + ": no such file", ErrorKind::no_file);
  }
  if (fs::is_directory(st)) return make_error(label + ": is a directory, not a clip file", ErrorKind::directory);
  if (!fs::is_regular_file(st)) return make_error(label + ": not a regular file", ErrorKind::cannot_open);
  const auto size = fs::file_size(path, ec);
  if (ec) return make_error(label + ": cannot read: " + ec.message(), ErrorKind::cannot_open);
  if (size == 0) return make_error(label + ": the file is empty", ErrorKind::unreadable);
  std::ifstream f(path, std::ios::binary);
  if (!f) return make_error(label + ": cannot open for reading", ErrorKind::cannot_open);
  return Ok{};
}

// A file's bytes, read with read(2) into one buffer sized from fstat. Not
// memory-mapped: a file truncated while it is parsed (an exporter still writing it)
// would raise SIGBUS in a mapping, while a read just ends early and the parser
// reports the file as truncated.
class FileText {
 public:
  Status open(const fs::path& path, const std::string& label) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return make_error(label + ": cannot open for reading: " + std::strerror(errno));
    struct stat st {};
    std::size_t capacity = (::fstat(fd, &st) == 0 && st.st_size > 0) ? static_cast<std::size_t>(st.st_size) : 0;
    buffer_.reset(new char[capacity + 1]);  // uninitialized: read(2) fills it
    ++capacity;  // one byte more than fstat said, so a full buffer means the file grew
    for (;;) {
      if (size_ == capacity) {
        std::unique_ptr<char[]> bigger(new char[2 * capacity]);
        std::memcpy(bigger.get(), buffer_.get(), size_);
        buffer_ = std::move(bigger);
        capacity *= 2;
      }
      const ssize_t got = ::read(fd, buffer_.get() + size_, capacity - size_);
      if (got < 0 && errno == EINTR) continue;
      if (got < 0) {
        const std::string why = std::strerror(errno);
        ::close(fd);
        return make_error(label + ": read failed: " + why);
      }
      if (got == 0) break;
      size_ += static_cast<std::size_t>(got);
    }
    ::close(fd);
    return Ok{};
  }
  std::string_view text() const { return std::string_view(buffer_.get(), size_); }

 private:
  std::unique_ptr<char[]> buffer_;
  std::size_t size_ = 0;
};

bool looks_like_bvh(const std::string& text) {
  std::size_t i = 0;
  if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) i = 3;  // UTF-8 BOM
  while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
  return text.compare(i, 9, "HIERARCHY") == 0;
}

// ---- animation selection ----------------------------------------------------------

Result<std::size_t> select_animation(const aiScene* scene, const std::string& want, const std::string& label) {
  const std::size_t n = scene->mNumAnimations;
  if (want.empty()) return std::size_t{0};
  for (std::size_t a = 0; a < n; ++a)
    if (want == scene->mAnimations[a]->mName.C_Str()) return a;
  if (std::all_of(want.begin(), want.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); })) {
    const std::size_t index = want.size() > 9 ? n : static_cast<std::size_t>(std::stoul(want));
    if (index < n) return index;
    return make_error(label + ": there is no animation " + want + " (the file has " + std::to_string(n) + ", numbered from 0)");
  }
  std::string names;
  for (std::size_t a = 0; a < n; ++a) names += (a ? ", '" : "'") + std::string(scene->mAnimations[a]->mName.C_Str()) + "'";
  return make_error(label + ": no animation named '" + want + "' (the file has " + names + ")");
}

// ---- BVH: our pass, optionally cross-checked against assimp ------------------------------------

// assimp parses BVH values and builds rotations in 32-bit float: its keys differ from
// the exact ones by up to ~5e-5° on the real clips (370° angles). More than this
// means the two parsers disagree about the file.
constexpr double kAssimpAgreementRadians = 1e-3 * kPi / 180.0;

// The clip comes from our pass: the file's values in double precision (assimp's
// float keys would use up half of the 1e-4° round-trip budget). With `anim`
// (ReadOptions::cross_check_with_assimp), assimp's reading of the same file must agree: same joints, one key per frame, same rotations
// within float precision, same positions where it keeps them.
Status fill_bvh(const BvhFile& bvh, const aiAnimation* anim, Clip& clip, const Warnings& warn, const std::string& label) {
  clip = bvh_to_clip(bvh, clip.name);
  if (!anim) return Ok{};
  std::map<std::string, const aiNodeAnim*> channels;
  for (unsigned c = 0; c < anim->mNumChannels; ++c) channels[anim->mChannels[c]->mNodeName.C_Str()] = anim->mChannels[c];
  for (std::size_t j = 0; j < bvh.joints.size(); ++j) {
    const std::string& name = bvh.joints[j].name;
    const auto it = channels.find(name);
    if (it == channels.end())
      return make_error(label + ": assimp and rotinterp disagree about the HIERARCHY: no animation channel for joint '" +
                        name + "'");
    const aiNodeAnim* ch = it->second;
    if (ch->mNumRotationKeys != bvh.frames)
      return make_error(label + ": assimp read " + std::to_string(ch->mNumRotationKeys) + " frames for joint '" + name +
                        "', rotinterp " + std::to_string(bvh.frames));
    double worst = 0.0;
    std::size_t worst_frame = 0;
    for (std::size_t f = 0; f < bvh.frames; ++f) {
      const double d = angular_distance(clip.rotations[j].keys[f], normalized_or_identity(to_quat(ch->mRotationKeys[f].mValue)));
      if (d > worst) worst = d, worst_frame = f;
    }
    if (worst > kAssimpAgreementRadians)
      warn(label + ": assimp reads joint '" + name + "' differently (" + std::to_string(worst * 180.0 / kPi) +
           " degrees at frame " + std::to_string(worst_frame) + "); rotinterp's reading is used");
  }
  return Ok{};
}

// ---- other formats: the node tree ---------------------------------------------------

struct NodeRec {
  const aiNode* node = nullptr;
  int real_parent = -1;              // index in `recs` of the nearest non-helper ancestor
  std::vector<const aiNode*> chain;  // helper nodes between real_parent and node, top first
};

Status fill_scene(const aiScene* scene, const aiAnimation* anim, double tps, Clip& clip, std::size_t& folded,
                  const Warnings& warn, const std::string& label) {
  // Real nodes depth-first, with their helper chains.
  std::vector<NodeRec> recs;
  std::map<const aiNode*, int> index_of;
  std::function<void(const aiNode*, int, std::vector<const aiNode*>)> walk = [&](const aiNode* n, int parent,
                                                                               std::vector<const aiNode*> chain) {
    if (is_helper(n)) {
      // FBX geometric transforms apply to the node's geometry only: assimp puts
      // GeometricX above the node and GeometricXInverse below it, so they cancel
      // for the children. Dropping both gives the joint its own transform.
      if (std::string_view(n->mName.C_Str()).find(kGeometricTag) == std::string_view::npos) chain.push_back(n);
      ++folded;
      for (unsigned c = 0; c < n->mNumChildren; ++c) walk(n->mChildren[c], parent, chain);
      return;
    }
    const int me = static_cast<int>(recs.size());
    recs.push_back(NodeRec{n, parent, std::move(chain)});
    index_of[n] = me;
    for (unsigned c = 0; c < n->mNumChildren; ++c) walk(n->mChildren[c], me, {});
  };
  walk(scene->mRootNode, -1, {});

  std::map<std::string, const aiNodeAnim*> channels;
  for (unsigned c = 0; c < anim->mNumChannels; ++c) channels.emplace(anim->mChannels[c]->mNodeName.C_Str(), anim->mChannels[c]);
  auto channel_of = [&](const aiNode* n) -> const aiNodeAnim* {
    const auto it = channels.find(n->mName.C_Str());
    return it == channels.end() ? nullptr : it->second;
  };
  std::set<std::string> bones;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m)
    for (unsigned b = 0; b < scene->mMeshes[m]->mNumBones; ++b) bones.insert(scene->mMeshes[m]->mBones[b]->mName.C_Str());

  // Selection: animated nodes, bones, and their ancestors.
  // Also transform-only subtrees (no meshes, cameras or lights anywhere below):
  // end bones and static joints of a skeleton that nothing animates or skins.
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
  std::vector<bool> keep(recs.size(), false);
  std::vector<bool> animated(recs.size(), false);
  for (std::size_t i = 0; i < recs.size(); ++i) {
    bool a = channel_of(recs[i].node) != nullptr;
    for (const aiNode* h : recs[i].chain) a = a || channel_of(h) != nullptr;
    animated[i] = a;
    if (a || bones.count(recs[i].node->mName.C_Str()) || (bare[i] && i > 0))
      for (int k = static_cast<int>(i); k >= 0 && !keep[static_cast<std::size_t>(k)]; k = recs[static_cast<std::size_t>(k)].real_parent)
        keep[static_cast<std::size_t>(k)] = true;
  }
  // The scene root only when it transforms something.
  if (!recs.empty() && keep[0] && !animated[0] && recs[0].chain.empty() &&
      to_eigen(recs[0].node->mTransformation).isIdentity(1e-12) && !bones.count(recs[0].node->mName.C_Str()))
    keep[0] = false;
  std::vector<int> joint_of(recs.size(), -1);
  std::vector<std::size_t> selected;
  for (std::size_t i = 0; i < recs.size(); ++i)
    if (keep[i]) {
      joint_of[i] = static_cast<int>(selected.size());
      selected.push_back(i);
    }
  if (selected.empty()) return make_error(label + ": the animation moves no node of the scene");

  // Times: the union over all channels, and the animation's first key.
  double t0 = INFINITY;
  std::vector<double> all_ticks;
  for (unsigned c = 0; c < anim->mNumChannels; ++c) add_times(anim->mChannels[c], all_ticks);
  for (double t : all_ticks) t0 = std::min(t0, t);
  if (!std::isfinite(t0)) t0 = 0.0;
  bool whole_ticks = !all_ticks.empty();
  for (double t : all_ticks) whole_ticks = whole_ticks && std::abs(t - std::round(t)) < kWholeTickTolerance;
  for (double t : all_ticks)
    if (!std::isfinite(t)) return make_error(label + ": a key time is not finite");

  const std::size_t n = selected.size();
  clip.skeleton.joints.resize(n);
  clip.rotations.assign(n, RotationTrack{});
  clip.translations.assign(n, std::nullopt);
  std::vector<double> cum_scale(n, 1.0);  // uniform scale of the joint's frame (baked)
  std::set<std::string> names;
  std::vector<std::vector<Trs>> key_trs(n);
  std::vector<std::vector<double>> key_ticks(n);
  for (std::size_t j = 0; j < n; ++j) {
    const NodeRec& rec = recs[selected[j]];
    Joint& joint = clip.skeleton.joints[j];
    std::string name = rec.node->mName.C_Str();
    if (name.empty()) name = "node" + std::to_string(selected[j]);
    while (!names.insert(name).second) name += "#";
    joint.name = name;
    int p = rec.real_parent;
    joint.parent = p >= 0 ? joint_of[static_cast<std::size_t>(p)] : -1;
    const double parent_scale = joint.parent >= 0 ? cum_scale[static_cast<std::size_t>(joint.parent)] : 1.0;

    std::vector<const aiNode*> path = rec.chain;
    path.push_back(rec.node);
    auto local_at = [&](double tick) {
      Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
      for (const aiNode* x : path) m = m * node_local(x, channel_of(x), tick);
      return decompose(m);
    };
    Eigen::Matrix4d rest = Eigen::Matrix4d::Identity();
    for (const aiNode* x : path) rest = rest * to_eigen(x->mTransformation);
    const Trs rest_trs = decompose(rest);
    joint.offset = rest_trs.t * parent_scale;
    joint.rest_rotation = rest_trs.r;

    std::vector<double> ticks;
    for (const aiNode* x : path)
      if (const aiNodeAnim* ch = channel_of(x)) add_times(ch, ticks);
    std::sort(ticks.begin(), ticks.end());
    std::vector<double> unique;
    for (double t : ticks)
      if (unique.empty() || t - unique.back() > kSameTickTolerance) unique.push_back(t);
    if (unique.empty()) unique.push_back(t0);
    key_ticks[j] = unique;
    std::vector<Trs>& keys = key_trs[j];
    keys.reserve(unique.size());
    for (double t : unique) keys.push_back(animated[selected[j]] ? local_at(t) : rest_trs);

    // Scale: bake a uniform static one, ignore the rest with a warning.
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
    cum_scale[j] = parent_scale * s;

    RotationTrack& rt = clip.rotations[j];
    for (std::size_t k = 0; k < unique.size(); ++k) {
      rt.times.push_back(unique[k] / tps);
      rt.keys.push_back(keys[k].r);
    }
    rt.make_sign_continuous();
  }

  // Translation tracks where a joint's translation moves.
  double size = 0.0;
  for (const Joint& j : clip.skeleton.joints) size = std::max(size, j.offset.norm());
  const double still = 1e-7 * std::max(size, 1e-9);  // float round-off of the source
  for (std::size_t j = 0; j < n; ++j) {
    if (!animated[selected[j]]) continue;
    const Joint& joint = clip.skeleton.joints[j];
    const double parent_scale = joint.parent >= 0 ? cum_scale[static_cast<std::size_t>(joint.parent)] : 1.0;
    TranslationTrack tt;
    bool moves = false;
    for (std::size_t k = 0; k < key_trs[j].size(); ++k) {
      tt.times.push_back(key_ticks[j][k] / tps);
      tt.keys.push_back(key_trs[j][k].t * parent_scale);
      moves = moves || (tt.keys.back() - joint.offset).norm() > still;
    }
    if (moves) clip.translations[j] = std::move(tt);
  }
  if (whole_ticks && tps <= kMaxFrameRate) {
    clip.frame_time = 1.0 / tps;
  } else if (const double step = uniform_grid_step(all_ticks) / tps; step > 0.0) {
    // Float times: an integer or NTSC rate within the tolerance is that exact rate.
    const std::optional<Rate> exact = recognize_rate(1.0 / step, kRateSnapTolerance);
    clip.frame_time = exact ? exact->period() : step;
  }

  clip.source_meshes = scene->mNumMeshes;
  // FBX states its frame rate in GlobalSettings (assimp: metadata FrameRate, the
  // TimeMode, and ticks per second = that rate); TimeMode 0 states none.
  if (std::int32_t mode = 0; scene->mMetaData && scene->mMetaData->Get("FrameRate", mode) && mode != 0 &&
                             anim->mTicksPerSecond > 0.0)
    clip.file_rate_hz = tps;

  // Unit scale: FBX gives centimetres per unit.
  if (scene->mMetaData) {
    double f = 0.0;
    float ff = 0.0f;
    if (scene->mMetaData->Get("UnitScaleFactor", f) || (scene->mMetaData->Get("UnitScaleFactor", ff) && (f = ff, true)))
      if (f > 0.0 && std::isfinite(f)) clip.unit_scale = f * 0.01;
  }
  return Ok{};
}

// The importer as the reads configure it.
void configure(Assimp::Importer& importer, const ReadOptions& options) {
  importer.SetPropertyBool(AI_CONFIG_IMPORT_NO_SKELETON_MESHES, true);
  importer.SetPropertyBool(AI_CONFIG_IMPORT_FBX_PRESERVE_PIVOTS, options.fold_fbx_helpers);
}

// importer.ReadFile, with its failures (an error string, out of memory, an
// exception) as one line in `error`; nullptr then.
const aiScene* import_scene(Assimp::Importer& importer, const fs::path& path, std::string& error) {
  try {
    const aiScene* scene = importer.ReadFile(path.string(), 0);
    if (!scene) error = one_line(importer.GetErrorString());
    return scene;
  } catch (const std::bad_alloc&) {
    error = "out of memory while importing";
  } catch (const std::exception& e) {
    error = one_line(e.what());
  }
  return nullptr;
}

// The part of a read that assimp does: the import, the animations and the clip
// built from the scene. `info` comes with its format set. Runs in the importer.
Status read_with_assimp(const fs::path& path, const ReadOptions& options, const std::string& ext, ClipFileInfo& info,
                        const Warnings& warn) {
  const std::string label = path.string();
  Assimp::Importer importer;
  configure(importer, options);
  std::string assimp_error;
  const aiScene* scene = import_scene(importer, path, assimp_error);
  if (!scene) {
    if (assimp_error.find("No suitable reader") != std::string::npos || assimp_error.empty())
      return make_error(label + ": unknown or unsupported file format" + (ext.empty() ? "" : " ('." + ext + "')"),
                        ErrorKind::unreadable);
    return make_error(label + ": cannot read: " + assimp_error, ErrorKind::unreadable);
  }
  if (scene->mNumAnimations == 0) return make_error(label + ": the file has no animation", ErrorKind::no_animation);
  for (unsigned a = 0; a < scene->mNumAnimations; ++a) {
    const aiAnimation* an = scene->mAnimations[a];
    AnimationSummary s;
    s.name = an->mName.C_Str();
    s.default_rate = !(an->mTicksPerSecond > 0.0);
    s.ticks_per_second = s.default_rate ? kDefaultTicksPerSecond : an->mTicksPerSecond;
    s.duration = an->mDuration / s.ticks_per_second;
    s.channels = an->mNumChannels;
    info.animations.push_back(s);
  }
  Result<std::size_t> sel = select_animation(scene, options.animation, label);
  if (!sel) return make_error(sel.error());
  info.selected = *sel;
  const aiAnimation* anim = scene->mAnimations[info.selected];
  const AnimationSummary& summary = info.animations[info.selected];
  if (!std::isfinite(anim->mTicksPerSecond) || anim->mTicksPerSecond < 0.0)
    return make_error(label + ": animation '" + summary.name + "' has an invalid tick rate", ErrorKind::unreadable);
  if (summary.default_rate)
    warn(label + ": animation '" + summary.name + "' gives 0 ticks per second; assuming " +
         std::to_string(static_cast<int>(kDefaultTicksPerSecond)));
  info.clip.name = summary.name.empty() ? path.stem().string() : summary.name;
  Status filled = fill_scene(scene, anim, summary.ticks_per_second, info.clip, info.folded_helpers, warn, label);
  if (!filled) return make_error(filled.error(), ErrorKind::unreadable);
  return Ok{};
}

// BVH content: by extension, or a HIERARCHY first under another one.
bool is_bvh(const fs::path& path, const std::string& ext) {
  if (ext == "bvh") return true;
  std::ifstream f(path, std::ios::binary);
  std::string head(64, '\0');
  f.read(head.data(), 64);
  head.resize(static_cast<std::size_t>(f.gcount()));
  return looks_like_bvh(head);
}

// BVH by our own pass; with `cross_check` (ReadOptions::cross_check_with_assimp,
// only ever true in the importer) also assimp's reading, compared.
Status read_bvh(const fs::path& path, const ReadOptions& options, bool cross_check, ClipFileInfo& info,
                const Warnings& warn) {
  const std::string label = path.string();
  FileText text;
  if (Status st = text.open(path, label); !st) return make_error(st.error(), ErrorKind::unreadable);
  Result<BvhFile> bvh = parse_bvh(text.text(), label);
  if (!bvh) return make_error(bvh.error(), ErrorKind::unreadable);
  info.format = "bvh";
  if (bvh->extra_rows > 0)
    warn(label + ": " + std::to_string(bvh->extra_rows) + " data row(s) after the " + std::to_string(bvh->frames) +
         " declared frames ignored");
  Assimp::Importer importer;
  configure(importer, options);
  std::string assimp_error;
  const aiScene* scene = cross_check ? import_scene(importer, path, assimp_error) : nullptr;
  AnimationSummary s{"", static_cast<double>(bvh->frames - 1) * bvh->frame_time, 1.0 / bvh->frame_time, false,
                     bvh->joints.size()};
  const aiAnimation* anim = nullptr;
  if (!cross_check) {
    // No assimp: nothing to compare.
  } else if (scene && scene->mNumAnimations > 0) {
    anim = scene->mAnimations[0];
    s.name = anim->mName.C_Str();
  } else {
    warn(label + ": assimp could not read the motion (" + (assimp_error.empty() ? "no animation" : assimp_error) +
         "); read with rotinterp's own BVH pass");
  }
  info.animations.push_back(s);
  if (!options.animation.empty() && options.animation != "0" && options.animation != s.name)
    return make_error(label + ": a BVH file has one animation (0); there is no animation '" + options.animation + "'");
  info.clip.name = path.stem().string();
  if (Status st = fill_bvh(*bvh, anim, info.clip, warn, label); !st) return make_error(st.error(), ErrorKind::unreadable);
  info.clip.name = path.stem().string();
  return Ok{};
}

std::string extension_of(const fs::path& path) {
  std::string ext = lower(path.extension().string());
  if (!ext.empty() && ext[0] == '.') ext.erase(0, 1);
  return ext;
}

// What both processes check last: a valid clip whose joints nest no deeper than
// BVH allows (fill_scene takes any depth assimp gives; callers may walk the tree).
Status check_clip(ClipFileInfo& info, const std::string& label) {
  info.clip.source_format = info.format;
  if (Status s = info.clip.validate(); !s) return make_error(label + ": " + s.error(), ErrorKind::unreadable);
  const std::vector<Joint>& joints = info.clip.skeleton.joints;
  std::vector<std::size_t> depth(joints.size(), 1);
  for (std::size_t j = 0; j < joints.size(); ++j) {
    if (joints[j].parent >= 0) depth[j] = depth[static_cast<std::size_t>(joints[j].parent)] + 1;
    if (depth[j] > kMaxJointDepth)
      return make_error(label + ": joints nested more than " + std::to_string(kMaxJointDepth) +
                            " levels deep (the most rotinterp reads)",
                        ErrorKind::unreadable);
  }
  return Ok{};
}

// The whole read in this process, assimp included (the importer's part).
Status read_here(const fs::path& path, const ReadOptions& options, ClipFileInfo& info, const Warnings& warn) {
  const std::string label = path.string();
  if (Status s = check_file(path, label); !s) return s.failure();
  const std::string ext = extension_of(path);
  info.format = ext;
  Status st = is_bvh(path, ext) ? read_bvh(path, options, options.cross_check_with_assimp, info, warn)
                                : read_with_assimp(path, options, ext, info, warn);
  if (!st) return st;
  return check_clip(info, label);
}

// A read as callers see it: BVH by our pass here; anything for assimp through the
// importer process, whose warnings reach on_warning once it is done, in order.
Result<ClipFileInfo> load(const fs::path& path, const ReadOptions& options) {
  const std::string label = path.string();
  if (Status s = check_file(path, label); !s) return s.failure();
  const std::string ext = extension_of(path);
  ClipFileInfo info;
  info.format = ext;
  if (is_bvh(path, ext) && !options.cross_check_with_assimp) {
    Warnings warn{&options.on_warning, &info.warnings};
    if (Status st = read_bvh(path, options, false, info, warn); !st) return st.failure();
    if (Status st = check_clip(info, label); !st) return st.failure();
    return info;
  }
  Result<wire::ReadOutcome> got = detail::read_in_importer(path, options);
  if (!got) return got.failure();
  for (const std::string& w : got->info.warnings)
    if (options.on_warning) options.on_warning(w);
  if (got->error) return make_error(*got->error, got->kind);
  return std::move(got->info);
}

}  // namespace

namespace detail {

wire::ReadOutcome read_in_this_process(const fs::path& path, const ReadOptions& options) {
  wire::ReadOutcome out;
  const Warnings keep{nullptr, &out.info.warnings};
  try {
    if (Status st = read_here(path, options, out.info, keep); !st) {
      out.error = st.error();
      out.kind = st.error_kind();
    }
  } catch (const std::bad_alloc&) {
    out.error = path.string() + ": out of memory while reading";
  } catch (const std::exception& e) {
    out.error = path.string() + ": " + one_line(e.what());
  }
  if (out.error) {
    ClipFileInfo warnings_only;
    warnings_only.warnings = std::move(out.info.warnings);
    out.info = std::move(warnings_only);
  }
  return out;
}

}  // namespace detail

bool importable_extension(std::string extension) {
  extension = lower(std::move(extension));
  if (!extension.empty() && extension[0] == '.') extension.erase(0, 1);
  if (extension.empty()) return false;
  // assimp's list ("*.3ds;*.bvh;…"), asked once: only the table, no import.
  static const std::set<std::string> known = [] {
    std::string list;
    Assimp::Importer().GetExtensionList(list);
    std::set<std::string> out{"bvh"};
    std::stringstream items(list);
    for (std::string item; std::getline(items, item, ';');)
      if (item.size() > 2 && item.compare(0, 2, "*.") == 0) out.insert(lower(item.substr(2)));
    return out;
  }();
  return known.count(extension) > 0;
}

Result<ClipFileInfo> inspect_clip(const fs::path& path, const ReadOptions& options) {
  try {
    return load(path, options);
  } catch (const std::bad_alloc&) {
    return make_error(path.string() + ": out of memory while reading");
  } catch (const std::exception& e) {
    return make_error(path.string() + ": " + one_line(e.what()));
  }
}

Result<Clip> read_clip(const fs::path& path, const ReadOptions& options) {
  Result<ClipFileInfo> info = inspect_clip(path, options);
  if (!info) return info.failure();
  return std::move(info->clip);
}

}  // namespace rotinterp
