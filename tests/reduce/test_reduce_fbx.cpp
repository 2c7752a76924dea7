// reduce -o OUT.fbx (io/fbx/fbx_reduced.h): the written Euler curves, read back and
// replayed by our own FBX reader, stay within reduce's budget at every source frame
// with far fewer keys than frames; cubic methods write cubic keys with tangents,
// slerp linear keys; assimp reads the file.
#include "support/run_cli.h"
#include "rotinterp/clip/frames.h"
#include "rotinterp/io/fbx/fbx_curves.h"
#include "rotinterp/io/fbx/fbx_nodes.h"
#include "rotinterp/io/fbx/fbx_reduced.h"
#include "rotinterp/io/fbx/fbx_transform.h"
#include "rotinterp/io/read.h"
#include "rotinterp/reduce/reduce.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <unistd.h>
#include <string>

namespace rotinterp {
namespace {

const std::string kData = ROTINTERP_SHARED_DATA;
const std::string kWalk = std::string(ROTINTERP_SOURCE_DIR) + "/samples/walk.bvh";
constexpr double kDegrees = 180.0 / kPi;

FbxAnimation read_back(const std::string& bytes) {
  auto doc = parse_fbx_nodes(bytes, "written");
  EXPECT_TRUE(doc.ok()) << doc.error();
  if (!doc) return {};
  auto anim = read_fbx_animation(*doc, "written");
  EXPECT_TRUE(anim.ok()) << anim.error();
  return anim ? *anim : FbxAnimation{};
}

struct ReplayError {
  double rotation_deg = 0.0, shell = 0.0, translation = 0.0;  // worst over joints and frames
  double position = 0.0;                                      // every joint's position in object space
};

// The file's motion as our reader evaluates it at each source frame (FBX time =
// the frame's time in ticks), against the source: local rotation angle, local
// translation of the tracks, and the virtual vertices at `shell_distance` and the
// joints' positions in object space with every joint replayed.
ReplayError replay_error(const std::string& bytes, const Clip& source, double shell_distance) {
  const FbxAnimation anim = read_back(bytes);
  ReplayError worst;
  if (anim.takes.empty()) return {1e9, 1e9, 1e9, 1e9};
  const FbxTake& take = anim.takes.front();
  const auto layers = fbx_node_layers(take);
  const DenseClip dense = dense_clip(source);
  const Skeleton& sk = source.skeleton;
  const std::size_t n = sk.joints.size();
  std::vector<Quat> q(n);
  std::vector<Vec3> p(n);
  WorldPose a, b;
  for (std::size_t f = 0; f < dense.grid.size(); ++f) {
    const double ticks = std::round(dense.grid.times[f] * static_cast<double>(kFbxTicksPerSecond));
    std::vector<Quat> sq(n);
    std::vector<Vec3> sp(n);
    for (std::size_t j = 0; j < n; ++j) {
      const FbxModel* model = nullptr;
      for (const FbxModel& m : anim.models)
        if (m.name == sk.joints[j].name) model = &m;
      if (!model) return {1e9, 1e9, 1e9, 1e9};
      const auto it = layers.find(model->name);
      const FbxLclValues v = fbx_lcl_values(take, *model, it == layers.end() ? nullptr : &it->second, ticks);
      q[j] = fbx_node_rotation(*model, v.rotation);
      p[j] = Vec3(v.translation[0], v.translation[1], v.translation[2]);
      sq[j] = dense.rotation[j][f];
      sp[j] = dense.translation[j][f];
      worst.rotation_deg = std::max(worst.rotation_deg, angular_distance(q[j], sq[j]) * kDegrees);
      if (source.translations[j]) worst.translation = std::max(worst.translation, (p[j] - sp[j]).norm());
    }
    forward_kinematics(sk, q, p, a);
    forward_kinematics(sk, sq, sp, b);
    for (std::size_t j = 0; j < n; ++j) worst.position = std::max(worst.position, (a.position[j] - b.position[j]).norm());
    for (std::size_t j = 0; j < n; ++j)
      for (int axis = 0; axis < 3; ++axis) {
        const Vec3 d = Vec3::Unit(axis) * shell_distance;
        worst.shell = std::max(worst.shell, ((a.position[j] + a.rotation[j] * d) - (b.position[j] + b.rotation[j] * d)).norm());
      }
  }
  return worst;
}

Clip read(const std::string& path) {
  auto clip = read_clip(path);
  EXPECT_TRUE(clip.ok()) << clip.error();
  return clip ? *clip : Clip{};
}

struct Written {
  ReduceResult reduced;
  FbxReducedResult fbx;
};

Written reduce_to_fbx(const Clip& clip, const std::string& method, double deg, double mm) {
  ReduceOptions opt;
  opt.method = method;
  opt.budget.rotation_deg = deg;
  opt.budget.shell = in_clip_units(clip, mm / 1000.0);
  opt.budget.translation = in_clip_units(clip, (mm > 0.0 ? mm : 1.0) / 1000.0);
  opt.shell_distance = in_clip_units(clip, 0.1);
  auto r = reduce_clip(clip, opt);
  EXPECT_TRUE(r.ok()) << r.error();
  if (!r) return {};
  FbxReducedOptions o;
  o.method = method;
  o.shell_distance = opt.shell_distance;
  for (const ReducedJoint& j : r->joints) o.budgets.push_back({j.budget.rotation_deg, j.budget.shell, j.budget.translation});
  auto fbx = encode_reduced_fbx(r->reduced, clip, o);
  EXPECT_TRUE(fbx.ok()) << fbx.error();
  if (!fbx) return {};
  return {std::move(*r), std::move(*fbx)};
}

// The walk sample, a DigitalRune FBX (376 frames) and a Maya-keyed FBX; linear,
// C¹ and C² methods; an angle budget and the default 1 mm shell budget.
TEST(ReduceFbx, OurReaderReplaysTheWrittenCurvesWithinBudgetAtEveryFrameWithFarFewerKeysThanFrames) {
  const char* files[] = {"walk", "fbx/digitalrune_PlayerMarine_Idle.fbx", "fbx/ufbx_maya_game_sausage_7500_binary_wiggle.fbx"};
  for (const char* file : files) {
    const std::string path = std::string(file) == "walk" ? kWalk : kData + "/" + file;
    const Clip clip = read(path);
    const std::size_t frames = frame_grid(clip).size(), joints = clip.skeleton.joints.size();
    for (const char* method : {"slerp", "squad", "c2"})
      for (const auto& [deg, mm] : {std::pair{1.0, 0.0}, std::pair{0.0, 1.0}}) {
        SCOPED_TRACE(std::string(file) + " " + method + (deg > 0.0 ? " 1deg" : " 1mm"));
        const Written w = reduce_to_fbx(clip, method, deg, mm);
        ASSERT_FALSE(w.fbx.bytes.empty());
        EXPECT_TRUE(w.fbx.within_budget);
        const ReplayError e = replay_error(w.fbx.bytes, clip, in_clip_units(clip, 0.1));
        if (deg > 0.0) {
          EXPECT_LE(e.rotation_deg, deg * (1.0 + 1e-9));
        } else {
          EXPECT_LE(e.shell, in_clip_units(clip, mm / 1000.0) * (1.0 + 1e-9));
          EXPECT_LE(e.position, in_clip_units(clip, mm / 1000.0) * (1.0 + 1e-9));
        }
        EXPECT_LE(e.translation, in_clip_units(clip, (mm > 0.0 ? mm : 1.0) / 1000.0) * (1.0 + 1e-9));
        // Sparse: a quarter more keys than reduce kept at most, and with the angle
        // budget under 40 % of a key per frame (frames × joints) on the long clips (the
        // sausage's 20 frames wiggle all through).
        std::size_t kept = 0;
        for (const ReducedJoint& j : w.reduced.joints) kept += j.rotation_frames.size();
        EXPECT_GE(w.fbx.rotation_keys, kept);
        EXPECT_LE(w.fbx.rotation_keys, kept * 5 / 4);
        if (deg > 0.0 && frames > 100) {
          EXPECT_LT(w.fbx.rotation_keys, frames * joints * 2 / 5);
        }
      }
  }
}

// The keys replay the method: cubic keys with user tangents (the method's slopes)
// for squad, linear keys for slerp; translations cubic (Steffen's Hermite).
TEST(ReduceFbx, CubicMethodsWriteCubicKeysWithTangentsAndSlerpWritesLinearKeys) {
  const Clip clip = read(kWalk);
  for (const char* method : {"slerp", "squad"}) {
    const Written w = reduce_to_fbx(clip, method, 1.0, 0.0);
    const FbxAnimation anim = read_back(w.fbx.bytes);
    ASSERT_FALSE(anim.takes.empty());
    std::size_t cubic = 0, linear = 0, sloped = 0;
    for (const FbxCurve& c : anim.takes.front().curves) {
      if (c.property != "Lcl Rotation") continue;
      for (std::size_t k = 0; k + 1 < c.keys.size(); ++k) {
        const FbxKey& key = c.keys[k];
        if (key.interpolation == FbxInterpolation::cubic) {
          ++cubic;
          EXPECT_TRUE(key.tangent == FbxTangent::user || key.tangent == FbxTangent::broken);
          const double secant = (c.keys[k + 1].value - key.value) /
                                (static_cast<double>(c.keys[k + 1].ticks - key.ticks) / static_cast<double>(kFbxTicksPerSecond));
          if (std::abs(key.right_slope - secant) > 1e-3) ++sloped;
        } else if (key.interpolation == FbxInterpolation::linear) {
          ++linear;
        }
      }
    }
    if (std::string(method) == "slerp") {
      EXPECT_EQ(cubic, 0u);
      EXPECT_GT(linear, 0u);
    } else {
      EXPECT_EQ(linear, 0u);
      EXPECT_GT(cubic, 0u);
      EXPECT_GT(sloped, cubic / 2);  // tangents, not chords
    }
  }
}

// A joint turning once about Y (with a wobble about X) passes through XYZ's gimbal
// lock at Y = 90° twice: the Euler keys stay continuous (no key-to-key step near
// 180° or 360° on any axis), and the file still replays within budget.
TEST(ReduceFbx, EulerKeysStayContinuousThroughGimbalLockAndReplayWithinBudget) {
  Clip clip;
  clip.name = "gimbal";
  Joint root;
  root.name = "root";
  clip.skeleton.joints.push_back(root);
  RotationTrack track;
  for (int k = 0; k <= 60; ++k) {
    const double t = k / 30.0;
    track.times.push_back(t);
    track.keys.push_back(Quat(Eigen::AngleAxisd(kPi * t, Vec3::UnitY()) * Eigen::AngleAxisd(0.3 * std::sin(3.0 * t), Vec3::UnitX())));
  }
  track.make_sign_continuous();
  clip.rotations.push_back(track);
  clip.translations.emplace_back();
  clip.frame_time = 1.0 / 30.0;
  ASSERT_TRUE(clip.validate().ok());
  for (const char* method : {"slerp", "squad", "c2"}) {
    SCOPED_TRACE(method);
    const Written w = reduce_to_fbx(clip, method, 0.5, 0.0);
    ASSERT_FALSE(w.fbx.bytes.empty());
    EXPECT_TRUE(w.fbx.within_budget);
    EXPECT_LE(replay_error(w.fbx.bytes, clip, 0.1).rotation_deg, 0.5 * (1.0 + 1e-9));
    const FbxAnimation anim = read_back(w.fbx.bytes);
    ASSERT_FALSE(anim.takes.empty());
    for (const FbxCurve& c : anim.takes.front().curves)
      for (std::size_t k = 1; k < c.keys.size(); ++k)
        EXPECT_LT(std::abs(c.keys[k].value - c.keys[k - 1].value), 90.0) << c.channel << " key " << k;
  }
}

// The command writes the file, says what it wrote, and assimp reads it back with
// every joint and the clip's duration.
TEST(ReduceFbx, TheCommandWritesAnFbxThatAssimpReads) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("rotinterp_reduce_fbx_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string out = (dir / "walk.fbx").string();
  const test::CliResult r = test::run_cli("reduce " + kWalk + " -o " + out + " -m squad --tolerance 0.5deg");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("FBX curves:"), std::string::npos) << r.out;
  const Clip source = read(kWalk), back = read(out);
  EXPECT_EQ(back.skeleton.joints.size(), source.skeleton.joints.size());
  EXPECT_NEAR(back.end_time() - back.start_time(), source.end_time() - source.start_time(), 1e-6);
  EXPECT_EQ(test::run_cli("reduce " + kWalk + " -o " + out + " --loop").exit_code, 2);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace rotinterp
