// eval's batched metrics against the per-sample ones, and its reference built once per clip.
#include "pose_pass.h"

#include "rotinterp/eval/batch.h"
#include "rotinterp/eval/evaluate_clip.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <random>

#include <unistd.h>

namespace rotinterp {
namespace {

namespace fs = std::filesystem;

// A random tree of `joints` joints (parents before children, two feet among them)
// with an End Site per leaf, moving at random for `frames` frames at 30 Hz.
Clip random_clip(std::mt19937& rng, std::size_t joints, std::size_t frames) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Clip c;
  c.name = "random";
  c.frame_time = 1.0 / 30.0;
  for (std::size_t j = 0; j < joints; ++j) {
    const int parent = j == 0 ? -1 : static_cast<int>(rng() % j);
    const std::string name = j == joints - 1 ? "LeftToe" : j == joints - 2 ? "RightToe" : "j" + std::to_string(j);
    c.skeleton.joints.push_back({name, parent, Vec3(u(rng), 5.0 + u(rng), u(rng)), Quat::Identity()});
    RotationTrack r;
    const RotVec w(u(rng), u(rng), u(rng)), a(u(rng), u(rng), u(rng));
    for (std::size_t k = 0; k < frames; ++k) {
      const double t = static_cast<double>(k) * c.frame_time;
      r.times.push_back(t);
      r.keys.push_back(exp(RotVec(2.0 * w * t + a * std::sin(3.0 * t) + 0.05 * RotVec(u(rng), u(rng), u(rng)))));
    }
    r.make_sign_continuous();
    c.rotations.push_back(r);
    c.translations.emplace_back();
  }
  TranslationTrack root;
  for (std::size_t k = 0; k < frames; ++k) {
    root.times.push_back(static_cast<double>(k) * c.frame_time);
    root.keys.push_back(Vec3(u(rng), 10.0 + u(rng), u(rng)));
  }
  c.translations[0] = root;
  for (std::size_t j = 0; j < joints; ++j) {
    bool leaf = true;
    for (const Joint& other : c.skeleton.joints) leaf = leaf && other.parent != static_cast<int>(j);
    if (leaf) c.skeleton.end_sites.push_back({static_cast<int>(j), Vec3(0.0, 2.0 + u(rng), 0.0), ""});
  }
  return c;
}

void expect_same(const RunningError& batched, const RunningError& one_by_one, const std::string& what) {
  EXPECT_EQ(batched.count, one_by_one.count) << what;
  EXPECT_EQ(batched.sum, one_by_one.sum) << what;  // bit for bit: the same operations in the same order
  EXPECT_EQ(batched.sum_sq, one_by_one.sum_sq) << what;
  EXPECT_EQ(batched.max, one_by_one.max) << what;
}

// PosePass over whole blocks gives, per joint and End Site, exactly what forward
// kinematics and accumulate_pose_error give sample by sample (accumulate_equal_poses
// where every joint is the reference's), and the same rebuilt feet: on random trees
// and motion, with and without subframes, blocks longer and shorter than a chunk, a
// third of the samples reproducing the reference bit for bit and some single joints too.
TEST(BatchedMetrics, PosePassEqualsForwardKinematicsAndPoseErrorSampleBySample) {
  std::mt19937 rng(20261203);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 12; ++trial) {
    const Clip clip = random_clip(rng, 2 + rng() % 30, 3 + rng() % 200);
    ClipEvalOptions o;
    o.subframe = trial % 3 == 0 ? 2 : 0;
    auto ref = prepare_reference(clip, "random", o);
    ASSERT_TRUE(ref.ok()) << ref.error();
    const ClipReference& R = *ref;
    ASSERT_EQ(R.feet.size(), 2u);
    const std::size_t nj = R.skeleton.joints.size(), ns = R.samples, nf = R.frames.size();
    detail::Block block;
    block.fill(R, 0, ns, true);
    std::vector<std::vector<Quat>> test(nj, std::vector<Quat>(ns));
    std::vector<const Quat*> test_at(nj);
    for (std::size_t j = 0; j < nj; ++j) {
      for (std::size_t m = 0; m < ns; ++m)
        test[j][m] = m % 3 == 0 || rng() % 7 == 0 ? block.rotation(R, j)[m]
                                                  : block.rotation(R, j)[m] * exp(RotVec(0.1 * u(rng), 0.1 * u(rng), 0.1 * u(rng)));
      test_at[j] = test[j].data();
    }
    PoseError batched = make_pose_error(R.skeleton), one_by_one = make_pose_error(R.skeleton);
    std::vector<std::vector<Vec3>> feet_batched(2, std::vector<Vec3>(nf)), feet_one_by_one = feet_batched;
    detail::PosePass pass;
    pass.add(R, block, 0, ns, test_at.data(), batched, feet_batched);

    std::vector<Quat> r(nj);
    std::vector<Vec3> t(nj);
    WorldPose world;
    for (std::size_t m = 0; m < ns; ++m) {
      bool equal = true;
      for (std::size_t j = 0; j < nj; ++j) {
        r[j] = test[j][m], t[j] = block.translation(R, j)[m];
        equal = equal && r[j].coeffs() == block.rotation(R, j)[m].coeffs();
      }
      forward_kinematics(R.skeleton, r, t, world);
      if (equal)
        accumulate_equal_poses(one_by_one);
      else
        accumulate_pose_error(block.world(R, m), world, R.shell_distance, one_by_one);
      if (m % R.per_frame == 0)
        for (std::size_t f = 0; f < 2; ++f)
          feet_one_by_one[f][m / R.per_frame] = equal ? block.world(R, m).position[R.feet[f]] : world.position[R.feet[f]];
    }
    const std::string at = "trial " + std::to_string(trial);
    for (std::size_t j = 0; j < nj; ++j) {
      expect_same(batched.joint_position[j], one_by_one.joint_position[j], at + " position of joint " + std::to_string(j));
      expect_same(batched.joint_shell[j], one_by_one.joint_shell[j], at + " shell of joint " + std::to_string(j));
    }
    for (std::size_t e = 0; e < R.skeleton.end_sites.size(); ++e)
      expect_same(batched.end_site_position[e], one_by_one.end_site_position[e], at + " End Site " + std::to_string(e));
    EXPECT_EQ(feet_batched, feet_one_by_one) << at;
  }
}

// A folder run prepares each clip's reference once and shares it among every
// method × spacing and both worker threads: as many references for 3 methods × 4
// spacings as for 1 × 1.
TEST(BatchedMetrics, TheReferenceIsPreparedOncePerClipWhateverTheMethodsAndSpacings) {
  const fs::path out = fs::temp_directory_path() / ("rotinterp_reference_once_" + std::to_string(::getpid()));
  const fs::path data = fs::path(ROTINTERP_SHARED_DATA) / "bvh";
  auto prepared_by = [&](std::vector<std::string> methods, std::vector<int> keep_every) {
    EvalOptions o;
    o.inputs = {data / "cmu_01_01.bvh", data / "bvhio_example.bvh", data / "NC_bandai1_walk_normal_001.bvh"};
    o.output_dir = out;
    o.clip.methods = std::move(methods);
    o.clip.keep_every = std::move(keep_every);
    o.jobs = 2;
    o.plots = false;
    const std::size_t before = references_prepared();
    auto report = run_eval(o);
    EXPECT_TRUE(report.ok()) << report.error();
    return references_prepared() - before;
  };
  EXPECT_EQ(prepared_by({"slerp"}, {2}), 3u);
  EXPECT_EQ(prepared_by({"slerp", "squad", "c2"}, {2, 4, 8, 16}), 3u);
  fs::remove_all(out);
}

}  // namespace
}  // namespace rotinterp
