// The clip reader: assimp for every format, our own BVH pass on top.
#include "rotinterp/io/read.h"

#include "assimp_text.h"
#include "clip_wire.h"
#include "rotinterp/clip/sampling.h"
#include "rotinterp/io/bvh.h"
#include "rotinterp/io/info.h"

#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/scene.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <csignal>
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

// assimp 5.2.5 as Debian ships it is built with its internal assertions on
// (ASSIMP_BUILD_DEBUG), and a failed one aborts the whole process: its FBX
// converter asserts on an animation curve without keys (fuzz_read_any
// crash-3197eb88, tests/io/test_assimp_guard.cpp). One bad file must not end a batch of
// thousands, so this definition takes the place of assimp's own: assimp calls it
// through its PLT, and the link exports it from every executable that uses this
// library (CMakeLists.txt: --export-dynamic-symbol). It throws instead of
// aborting; the importer's own catch, or ours around ReadFile, turns that into
// an ordinary "cannot read" error naming the file.
namespace Assimp {
[[noreturn]] void aiAssertViolation(const char* expression, const char* file, int line);
void aiAssertViolation(const char* expression, const char* file, int line) {
  throw std::runtime_error(std::string("assimp's internal check '") + expression + "' failed (" + file + ":" +
                           std::to_string(line) + ")");
}
}  // namespace Assimp

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
  if (ec || !fs::exists(st)) return make_error(label + ": no such file");
  if (fs::is_directory(st)) return make_error(label + ": is a directory, not a clip file");
  if (!fs::is_regular_file(st)) return make_error(label + ": not a regular file");
  const auto size = fs::file_size(path, ec);
  if (ec) return make_error(label + ": cannot read: " + ec.message());
  if (size == 0) return make_error(label + ": the file is empty");
  std::ifstream f(path, std::ios::binary);
  if (!f) return make_error(label + ": cannot open for reading");
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

// Files assimp 5.2.5 crashes on (a segfault, which no handler can catch), refused
// before it sees them. An FBX animation curve without keys ("KeyTime: *0" in the
// ASCII form) makes its FBX converter read past an empty key list. Only the ASCII
// form is recognized here; a binary file with such a curve is not.
Status check_fbx_before_assimp(std::string_view text, const std::string& label) {
  if (text.substr(0, 18) == "Kaydara FBX Binary") return Ok{};
  for (std::size_t at = text.find("KeyTime:"); at != std::string_view::npos; at = text.find("KeyTime:", at + 8)) {
    std::size_t i = at + 8;
    while (i < text.size() && (text[i] == ' ' || text[i] == '\t')) ++i;
    if (text.substr(i, 2) == "*0" && (i + 2 == text.size() || !std::isdigit(static_cast<unsigned char>(text[i + 2]))))
      return make_error(label + ": an animation curve has no keys (line " +
                        std::to_string(1 + std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n')) +
                        "); refused because assimp 5.2 crashes on such files");
  }
  return Ok{};
}

// The importer as load() configures it.
void configure(Assimp::Importer& importer, const ReadOptions& options) {
  importer.SetPropertyBool(AI_CONFIG_IMPORT_NO_SKELETON_MESHES, true);
  importer.SetPropertyBool(AI_CONFIG_IMPORT_FBX_PRESERVE_PIVOTS, options.fold_fbx_helpers);
}

// importer.ReadFile, with its failures (an error string, out of memory, our throwing
// assertion handler) as one line in `error`; nullptr then.
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

// The part of load() that assimp does: the import, the animations and the clip
// built from the scene. `info` comes with its format set.
Status read_with_assimp(const fs::path& path, const ReadOptions& options, const std::string& ext, ClipFileInfo& info,
                        const Warnings& warn) {
  const std::string label = path.string();
  Assimp::Importer importer;
  configure(importer, options);
  std::string assimp_error;
  const aiScene* scene = import_scene(importer, path, assimp_error);
  if (!scene) {
    if (assimp_error.find("No suitable reader") != std::string::npos || assimp_error.empty())
      return make_error(label + ": unknown or unsupported file format" + (ext.empty() ? "" : " ('." + ext + "')"));
    return make_error(label + ": cannot read: " + assimp_error);
  }
  if (scene->mNumAnimations == 0) return make_error(label + ": the file has no animation");
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
    return make_error(label + ": animation '" + summary.name + "' has an invalid tick rate");
  if (summary.default_rate)
    warn(label + ": animation '" + summary.name + "' gives 0 ticks per second; assuming " +
         std::to_string(static_cast<int>(kDefaultTicksPerSecond)));
  info.clip.name = summary.name.empty() ? path.stem().string() : summary.name;
  return fill_scene(scene, anim, summary.ticks_per_second, info.clip, info.folded_helpers, warn, label);
}

bool write_all(int fd, std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t put = ::write(fd, bytes.data(), bytes.size());
    if (put < 0 && errno == EINTR) continue;
    if (put <= 0) return false;
    bytes.remove_prefix(static_cast<std::size_t>(put));
  }
  return true;
}

// A child's message: an 8-byte length, then that many bytes of clip_wire.h.
// Read up to the announced length, not to end of file: a child forked meanwhile by
// another thread holds a copy of the pipe's write end until it exits. Returns
// false where the child stopped short (it crashed while writing).
bool read_message(int fd, std::string& payload) {
  std::string got;
  std::uint64_t want = 0;
  char chunk[1 << 16];
  while (got.size() < sizeof want || got.size() - sizeof want < want) {
    const ssize_t n = ::read(fd, chunk, sizeof chunk);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    got.append(chunk, static_cast<std::size_t>(n));
    if (got.size() >= sizeof want) std::memcpy(&want, got.data(), sizeof want);
  }
  got.erase(0, sizeof want);
  got.resize(static_cast<std::size_t>(want));
  payload = std::move(got);
  return true;
}

// ReadOptions::isolate_assimp: read_with_assimp runs in a forked child, which
// sends what it read (clip_wire.h) through a pipe; this process never calls
// assimp. assimp's double free is in the scene's destruction, which the child
// finishes before it writes. The child takes the default action for the signals
// the CLI handles (so it never cleans up the parent's temporary files), writes
// nothing to stderr, keeps warnings for the parent to pass on, and leaves with
// _exit (no atexit handlers, no flushing of inherited stdio buffers). A child that
// dies, exits non-zero (a sanitizer's report) or sends a garbled message makes the
// file refused. nullopt: no pipe or no fork; the caller reads in-process.
std::optional<Result<wire::ReadOutcome>> read_in_child(const fs::path& path, const ReadOptions& options,
                                                       const std::string& ext, const ClipFileInfo& info) {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) return std::nullopt;
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    return std::nullopt;
  }
  const std::string label = path.string();
  if (pid == 0) {
    ::close(fds[0]);
    for (int sig : {SIGINT, SIGTERM, SIGHUP}) std::signal(sig, SIG_DFL);
    // Quiet: what the crash prints (glibc's "double free detected", a sanitizer's
    // report) is not the user's error message; the parent's one line is.
    if (const int null = ::open("/dev/null", O_WRONLY); null >= 0) ::dup2(null, STDERR_FILENO);
    wire::ReadOutcome out;
    out.info = info;
    const Warnings keep{nullptr, &out.info.warnings};
    // The texts inspect_clip gives these in-process.
    try {
      if (Status st = read_with_assimp(path, options, ext, out.info, keep); !st) out.error = st.error();
    } catch (const std::bad_alloc&) {
      out.error = label + ": out of memory while reading";
    } catch (const std::exception& e) {
      out.error = label + ": " + one_line(e.what());
    }
    if (out.error) {
      ClipFileInfo warnings_only;
      warnings_only.warnings = std::move(out.info.warnings);
      out.info = std::move(warnings_only);
    }
    const std::string payload = wire::encode(out);
    const std::uint64_t size = payload.size();
    const bool sent = write_all(fds[1], std::string_view(reinterpret_cast<const char*>(&size), sizeof size)) &&
                      write_all(fds[1], payload);
    ::_exit(sent ? 0 : 1);
  }
  ::close(fds[1]);
  std::string payload;
  bool whole = false;
  bool out_of_memory = false;  // rethrown once the child is reaped
  try {
    whole = read_message(fds[0], payload);  // before waitpid: a big clip fills the pipe
  } catch (const std::bad_alloc&) {
    out_of_memory = true;
  }
  ::close(fds[0]);
  int status = 0;
  bool waited = true;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) {
      waited = false;
      break;
    }
  }
  if (out_of_memory) throw std::bad_alloc();
  std::string how;
  if (waited && WIFSIGNALED(status))
    how = std::string("signal ") + std::to_string(WTERMSIG(status)) + ", " + ::strsignal(WTERMSIG(status));
  else if (waited && WIFEXITED(status) && WEXITSTATUS(status) != 0)
    how = "exit status " + std::to_string(WEXITSTATUS(status));
  if (how.empty() && whole)
    if (Result<wire::ReadOutcome> got = wire::decode(payload)) return got;
  if (how.empty()) how = "its report was cut short or garbled";
  return Result<wire::ReadOutcome>(make_error(label + ": assimp crashed importing this file (" + how + "); refused"));
}

// GCC 12's AddressSanitizer allocator does not take its locks around fork: a child
// forked while another thread is inside it hangs at its first allocation (seen in
// CI: eval -j 2 on FBX files). glibc's malloc does, so release builds always
// isolate; sanitizer builds import in-process while other threads run.
bool fork_is_safe() {
#if defined(__SANITIZE_ADDRESS__)
  std::error_code ec;
  std::size_t threads = 0;
  for (fs::directory_iterator it("/proc/self/task", ec); !ec && it != fs::directory_iterator(); it.increment(ec))
    ++threads;
  return threads <= 1;
#else
  return true;
#endif
}

Result<ClipFileInfo> load(const fs::path& path, const ReadOptions& options) {
  const std::string label = path.string();
  if (Status s = check_file(path, label); !s) return make_error(s.error());
  ClipFileInfo info;
  Warnings warn{&options.on_warning, &info.warnings};
  std::string ext = lower(path.extension().string());
  if (!ext.empty() && ext[0] == '.') ext.erase(0, 1);
  info.format = ext;

  // BVH: our pass first (validation, layout, exact Frame Time).
  std::optional<BvhFile> bvh;
  bool bvh_content = ext == "bvh";
  if (!bvh_content) {  // BVH content under another extension
    std::ifstream f(path, std::ios::binary);
    std::string head(64, '\0');
    f.read(head.data(), 64);
    head.resize(static_cast<std::size_t>(f.gcount()));
    bvh_content = looks_like_bvh(head);
  }
  if (bvh_content) {
    FileText text;
    if (Status st = text.open(path, label); !st) return make_error(st.error());
    Result<BvhFile> parsed = parse_bvh(text.text(), label);
    if (!parsed) return make_error(parsed.error());
    bvh = std::move(*parsed);
    info.format = "bvh";
    if (bvh->extra_rows > 0)
      warn(label + ": " + std::to_string(bvh->extra_rows) + " data row(s) after the " + std::to_string(bvh->frames) +
           " declared frames ignored");
  }

  if (bvh) {
    // assimp for BVH only as the optional cross-check.
    Assimp::Importer importer;
    configure(importer, options);
    std::string assimp_error;
    const aiScene* scene = options.cross_check_with_assimp ? import_scene(importer, path, assimp_error) : nullptr;
    AnimationSummary s{"", static_cast<double>(bvh->frames - 1) * bvh->frame_time, 1.0 / bvh->frame_time, false,
                       bvh->joints.size()};
    const aiAnimation* anim = nullptr;
    if (!options.cross_check_with_assimp) {
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
    if (Status st = fill_bvh(*bvh, anim, info.clip, warn, label); !st) return make_error(st.error());
    info.clip.name = path.stem().string();
  } else {
    if (ext == "fbx") {  // only FBX has a pre-check: read it for that alone
      FileText text;
      if (Status s = text.open(path, label); !s) return make_error(s.error());
      if (Status s = check_fbx_before_assimp(text.text(), label); !s) return make_error(s.error());
    }
    std::optional<Result<wire::ReadOutcome>> child;
    if (options.isolate_assimp && fork_is_safe()) child = read_in_child(path, options, ext, info);
    if (!child) {
      if (Status st = read_with_assimp(path, options, ext, info, warn); !st) return make_error(st.error());
    } else {
      if (!*child) return make_error(child->error());
      info = std::move((*child)->info);
      for (const std::string& w : info.warnings)
        if (options.on_warning) options.on_warning(w);
      if ((*child)->error) return make_error(*(*child)->error);
    }
  }
  info.clip.source_format = info.format;
  if (Status s = info.clip.validate(); !s) return make_error(label + ": " + s.error());
  return info;
}

}  // namespace

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
  if (!info) return make_error(info.error());
  return std::move(info->clip);
}

}  // namespace rotinterp
