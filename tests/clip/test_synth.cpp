#include "rotinterp/clip/synth.h"

#include "rotinterp/io/files/file_record.h"

#include <gtest/gtest.h>

#include <set>

using namespace rotinterp;

namespace {

SynthOptions options(SynthKind kind, std::uint64_t seed = 1, double seconds = 2.0, Rate fps = {30, 1}) {
  SynthOptions o;
  o.kind = kind;
  o.seed = seed;
  o.seconds = seconds;
  o.fps = fps;
  return o;
}

const SynthKind kAllKinds[] = {SynthKind::constant, SynthKind::smooth, SynthKind::spin, SynthKind::walk};

}  // namespace

TEST(Synth, SampledKeysAreTheAnalyticTruthAtFrameTimes) {
  for (SynthKind kind : kAllKinds) {
    const SynthOptions o = options(kind, 4, 3.0, Rate{50, 1});
    auto motion = make_synth_motion(o);
    ASSERT_TRUE(motion.ok()) << motion.error();
    auto clip = make_synth_clip(o);
    ASSERT_TRUE(clip.ok()) << clip.error();
    ASSERT_TRUE(clip->validate().ok()) << clip->validate().error();
    EXPECT_EQ(clip->frame_count(), 151u);
    EXPECT_DOUBLE_EQ(clip->frame_time, 0.02);
    std::vector<Quat> q;
    std::vector<Vec3> p;
    for (std::size_t k = 0; k < 151; k += 7) {
      const double t = k / 50.0;
      motion->truth(t, q, p);
      for (std::size_t j = 0; j < q.size(); ++j) {
        ASSERT_EQ(clip->rotations[j].times[k], t);
        EXPECT_LT(angular_distance(clip->rotations[j].keys[k], q[j]), 1e-12) << synth_kind_name(kind) << " joint " << j;
        if (clip->translations[j]) {
          EXPECT_LT((clip->translations[j]->keys[k] - p[j]).norm(), 1e-12);
        }
      }
    }
  }
}

TEST(Synth, ConstantKindHasConstantFixedFrameAngularVelocityPerJoint) {
  auto motion = make_synth_motion(options(SynthKind::constant, 9));
  ASSERT_TRUE(motion.ok());
  for (std::size_t j = 0; j < motion->skeleton().joints.size(); ++j) {
    const double dt = 0.013;
    const Vec3 w0 = angular_velocity(motion->rotation(j, 0.0), motion->rotation(j, dt), dt);
    EXPECT_GT(w0.norm(), 0.4);
    for (double t : {0.3, 0.77, 1.9, 3.5}) {
      const Vec3 w = angular_velocity(motion->rotation(j, t), motion->rotation(j, t + dt), dt);
      EXPECT_LT((w - w0).norm(), 1e-10) << "joint " << j << " t=" << t;
    }
  }
}

TEST(Synth, SpinsTurnPastTwoPiAndStayBelowPiPerFrame) {
  auto clip = make_synth_clip(options(SynthKind::spin, 2, 4.0));
  ASSERT_TRUE(clip.ok());
  for (const RotationTrack& tr : clip->rotations) {
    double total = 0.0, largest = 0.0;
    for (std::size_t k = 1; k < tr.keys.size(); ++k) {
      const double a = angular_distance(tr.keys[k - 1], tr.keys[k]);
      total += a;
      largest = std::max(largest, a);
    }
    EXPECT_GT(total, 4 * kTwoPi);  // ≥ 1 turn/s for 4 s, minus the ±30 % modulation
    EXPECT_LT(largest, 1.0);       // at 30 Hz: well below π per frame
  }
}

TEST(Synth, EveryJointGetsASeededRandomBvhRotationOrder) {
  auto a = make_synth_file_clip(options(SynthKind::walk, 1)), b = make_synth_file_clip(options(SynthKind::walk, 1)),
       c = make_synth_file_clip(options(SynthKind::walk, 2));
  ASSERT_TRUE(a.ok() && b.ok() && c.ok());
  std::set<std::vector<Channel>> orders;
  bool differs = false;
  for (std::size_t j = 0; j < a->skeleton.joints.size(); ++j) {
    const Joint& ja = a->skeleton.joints[j];
    const std::vector<Channel>& channels = bvh_channels(*a, j);
    ASSERT_EQ(channels.size(), ja.parent < 0 ? 6u : 3u);
    if (ja.parent < 0) {
      EXPECT_EQ(channels[0], Channel::Xposition);
      EXPECT_EQ(channels[2], Channel::Zposition);
    }
    std::vector<Channel> rot(channels.end() - 3, channels.end());
    EXPECT_EQ(std::set<Channel>(rot.begin(), rot.end()).size(), 3u);
    orders.insert(rot);
    EXPECT_EQ(channels, bvh_channels(*b, j));  // same seed, same file
    differs |= channels != bvh_channels(*c, j);
  }
  EXPECT_GE(orders.size(), 5u);  // 31 joints draw from 6 orders
  EXPECT_TRUE(differs);
}

TEST(Synth, SameOptionsGiveTheSameClip) {
  for (SynthKind kind : kAllKinds) {
    auto a = make_synth_clip(options(kind, 77)), b = make_synth_clip(options(kind, 77));
    ASSERT_TRUE(a.ok() && b.ok());
    for (std::size_t j = 0; j < a->rotations.size(); ++j)
      for (std::size_t k = 0; k < a->rotations[j].keys.size(); ++k)
        ASSERT_EQ(a->rotations[j].keys[k].coeffs(), b->rotations[j].keys[k].coeffs());
  }
}

TEST(Synth, WalkingFigureWalksForwardOnItsFeet) {
  auto clip = make_synth_clip(options(SynthKind::walk, 3, 4.0));
  ASSERT_TRUE(clip.ok());
  const Skeleton& s = clip->skeleton;
  ASSERT_EQ(s.joints.size(), 31u);
  ASSERT_EQ(s.end_sites.size(), 7u);
  EXPECT_EQ(s.find("Hips"), 0);
  EXPECT_GE(s.find("RThumb"), 0);
  ASSERT_TRUE(clip->translations[0].has_value());
  const auto& root = clip->translations[0]->keys;
  EXPECT_GT(root.back().z() - root.front().z(), 300.0);  // ~1.2 m/s for 4 s, in cm
  WorldPose pose;
  std::vector<Quat> q(31);
  std::vector<Vec3> p(31);
  for (std::size_t k = 0; k < root.size(); k += 5) {
    for (std::size_t j = 0; j < 31; ++j) {
      q[j] = clip->rotations[j].keys[k];
      p[j] = clip->translations[j] ? clip->translations[j]->keys[k] : s.joints[j].offset;
    }
    forward_kinematics(s, q, p, pose);
    const double head = pose.position[static_cast<std::size_t>(s.find("Head"))].y();
    const double lfoot = pose.position[static_cast<std::size_t>(s.find("LeftFoot"))].y();
    const double lhand = pose.position[static_cast<std::size_t>(s.find("LeftHand"))].y();
    EXPECT_GT(head, 130.0);
    EXPECT_LT(lfoot, 25.0);
    EXPECT_LT(lhand, pose.position[0].y() + 20.0);  // arms hang down, not in T-pose
    EXPECT_GT(lfoot, -5.0);
  }
}

TEST(Synth, BadOptionsAreRejected) {
  EXPECT_FALSE(parse_synth_kind("jog").ok());
  EXPECT_FALSE(make_synth_motion(options(SynthKind::walk, 1, 0.0)).ok());
  EXPECT_FALSE(make_synth_motion(options(SynthKind::walk, 1, -1.0)).ok());
  EXPECT_FALSE(make_synth_motion(options(SynthKind::walk, 1, 1e12)).ok());
  SynthOptions none = options(SynthKind::constant);
  none.joints = 0;
  EXPECT_FALSE(make_synth_motion(none).ok());
}
