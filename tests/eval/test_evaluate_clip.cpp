// evaluate_clip on hand-made clips with known answers, and on real clips.
#include "rotinterp/eval/evaluate_clip.h"
#include "rotinterp/interp/slerp.h"

#include "rotinterp/interp/interpolator.h"
#include "rotinterp/io/read.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

namespace rotinterp {
namespace {

// A 4-joint chain with an End Site; every joint turns at its own constant
// fixed-frame angular velocity (≤ 3 rad/s), the root moves on a line.
Clip constant_velocity_clip(std::size_t frames, double fps) {
  Clip c;
  c.name = "cav";
  c.frame_time = 1.0 / fps;
  const Vec3 omegas[] = {{0.5, -1.0, 2.0}, {-2.5, 0.3, 1.0}, {0.0, 3.0, 0.0}, {1.2, 1.2, -1.2}};
  for (int j = 0; j < 4; ++j) {
    c.skeleton.joints.push_back({"j" + std::to_string(j), j - 1, j == 0 ? Vec3::Zero() : Vec3(0, 10, 0),
                                 Quat::Identity()});
    RotationTrack r;
    const Quat q0 = exp(RotVec(0.3 * j, -0.2, 0.1 * j));
    for (std::size_t k = 0; k < frames; ++k) {
      const double t = static_cast<double>(k) / fps;
      r.times.push_back(t);
      r.keys.push_back(exp(RotVec(omegas[j] * t)) * q0);
    }
    r.make_sign_continuous();
    c.rotations.push_back(r);
    c.translations.emplace_back();
  }
  TranslationTrack root;
  for (std::size_t k = 0; k < frames; ++k) {
    root.times.push_back(static_cast<double>(k) / fps);
    root.keys.push_back(Vec3(0.5 * static_cast<double>(k), 0, 0));
  }
  c.translations[0] = root;
  c.skeleton.end_sites.push_back({3, Vec3(0, 5, 0), "EndSite_j3"});
  return c;
}

TEST(EvaluateClip, ConstantAngularVelocityIsRebuiltExactlyBySlerpSquadAndBf) {
  const Clip clip = constant_velocity_clip(97, 30.0);
  ASSERT_TRUE(clip.validate().ok());
  ClipEvalOptions o;
  o.methods = {"slerp", "squad", "bf"};
  o.keep_every = {2, 4, 8, 16};
  auto rows = evaluate_clip(clip, "cav", o);
  ASSERT_TRUE(rows.ok()) << rows.error();
  ASSERT_EQ(rows->size(), 3u * 4u * 5u);
  for (const ErrorRow& r : *rows) {
    if (r.end_site) {
      EXPECT_LT(r.pos_max, 1e-9 * r.height) << r.method << " " << r.keep_every;
      continue;
    }
    EXPECT_LT(r.max_deg, 1e-3) << r.method << " keep " << r.keep_every << " " << r.joint;
    EXPECT_LT(r.pos_max_pct, 1e-6) << r.method << " " << r.joint;
    EXPECT_EQ(r.frames, 97u);
  }
}

TEST(EvaluateClip, KeepingEveryFrameGivesZeroErrorForEveryMethod) {
  const Clip clip = constant_velocity_clip(20, 30.0);
  ClipEvalOptions o;
  for (const MethodInfo& m : methods()) o.methods.push_back(m.name);
  ASSERT_FALSE(o.methods.empty());
  o.keep_every = {1};
  auto rows = evaluate_clip(clip, "cav", o);
  ASSERT_TRUE(rows.ok()) << rows.error();
  for (const ErrorRow& r : *rows) {
    EXPECT_LT(r.max_deg, 1e-9) << r.method;
    EXPECT_LT(r.pos_max, 1e-9) << r.method;
  }
}

TEST(EvaluateClip, SubframesCompareAgainstTheSlerpOfFramesOrTheTruth) {
  const Clip clip = constant_velocity_clip(31, 30.0);
  ClipEvalOptions o;
  o.methods = {"slerp"};
  o.keep_every = {1, 3};
  o.subframe = 4;
  auto rows = evaluate_clip(clip, "cav", o);
  ASSERT_TRUE(rows.ok()) << rows.error();
  for (const ErrorRow& r : *rows) {
    EXPECT_EQ(r.samples, 30u * 5u + 1u);
    if (!r.end_site) {
      EXPECT_LT(r.max_deg, 1e-6);
    }
  }
  // A truth that is off by a fixed 2° about z for joint 0 reads 2° there.
  o.truth = [&](double t, std::vector<Quat>& rot, std::vector<Vec3>& tr) {
    rot.resize(4);
    tr.resize(4);
    const Vec3 omegas[] = {{0.5, -1.0, 2.0}, {-2.5, 0.3, 1.0}, {0.0, 3.0, 0.0}, {1.2, 1.2, -1.2}};
    for (int j = 0; j < 4; ++j) {
      rot[j] = exp(RotVec(omegas[j] * t)) * exp(RotVec(0.3 * j, -0.2, 0.1 * j));
      tr[j] = j == 0 ? Vec3(0.5 * t * 30.0, 0, 0) : Vec3(0, 10, 0);
    }
    rot[0] = rot[0] * exp(RotVec(0, 0, 2.0 * kPi / 180.0));
  };
  rows = evaluate_clip(clip, "cav", o);
  ASSERT_TRUE(rows.ok()) << rows.error();
  for (const ErrorRow& r : *rows) {
    if (r.end_site) continue;
    if (r.joint == "j0") {
      EXPECT_NEAR(r.rms_deg, 2.0, 1e-6);
    } else {
      EXPECT_LT(r.max_deg, 1e-6);
    }
  }
}

TEST(EvaluateClip, SlerpKeysShowAVelocityJumpAndCubicMethodsDoNot) {
  // Smooth non-constant motion: angle = sin(2t) about a fixed axis.
  Clip c = constant_velocity_clip(61, 30.0);
  for (RotationTrack& r : c.rotations) {
    for (std::size_t k = 0; k < r.times.size(); ++k) r.keys[k] = exp(RotVec(Vec3(0, 0, 1.5 * std::sin(2 * r.times[k]))));
    r.make_sign_continuous();
  }
  ClipEvalOptions o;
  o.methods = {"slerp", "squad"};
  o.keep_every = {6};
  auto rows = evaluate_clip(c, "sine", o);
  ASSERT_TRUE(rows.ok()) << rows.error();
  std::map<std::string, double> jump;
  for (const ErrorRow& r : *rows)
    if (r.joint == "j1") jump[r.method] = r.vel_jump_max;
  EXPECT_GT(jump["slerp"], 10.0);  // deg/s
  EXPECT_LT(jump["squad"], 1e-2 * jump["slerp"]);
}

TEST(EvaluateClip, UnknownMethodIsAnErrorNamingIt) {
  ClipEvalOptions o;
  o.methods = {"nosuch"};
  o.keep_every = {2};
  auto rows = evaluate_clip(constant_velocity_clip(10, 30.0), "cav", o);
  ASSERT_FALSE(rows.ok());
  EXPECT_NE(rows.error().find("nosuch"), std::string::npos) << rows.error();
}

TEST(EvaluateClip, ErrorGrowsWithKeySpacingOnRealClipsForEveryMethod) {
  for (const char* file : {"/bvh/NC_bandai1_walk_normal_001.bvh", "/bvh/cmu_01_01.bvh"}) {
    auto clip = read_clip(std::string(ROTINTERP_SHARED_DATA) + file);
    ASSERT_TRUE(clip.ok()) << clip.error();
    // The first 400 frames are enough and keep the test short.
    for (RotationTrack& r : clip->rotations)
      if (r.times.size() > 400) r.times.resize(400), r.keys.resize(400);
    for (auto& t : clip->translations)
      if (t && t->times.size() > 400) t->times.resize(400), t->keys.resize(400);
    ClipEvalOptions o;
    for (const MethodInfo& m : methods()) o.methods.push_back(m.name);
    o.keep_every = {2, 4, 8, 16};
    auto rows = evaluate_clip(*clip, file, o);
    ASSERT_TRUE(rows.ok()) << rows.error();
    // Sample-weighted RMS over joints, per method × spacing.
    std::map<std::string, std::map<int, std::pair<double, double>>> acc;
    for (const ErrorRow& r : *rows) {
      if (r.end_site) continue;
      auto& a = acc[r.method][r.keep_every];
      a.first += r.rms_deg * r.rms_deg * static_cast<double>(r.samples);
      a.second += static_cast<double>(r.samples);
    }
    for (const auto& [method, by_keep] : acc) {
      double previous = 0;
      for (const auto& [keep, a] : by_keep) {
        const double rms = std::sqrt(a.first / a.second);
        EXPECT_GT(rms, previous) << file << " " << method << " keep " << keep;
        previous = rms;
      }
    }
  }
}

}  // namespace
}  // namespace rotinterp

namespace rotinterp {
namespace {

TEST(EvaluateClipSubframes, StreamedBlocksGiveTheStatisticsOfAllSamplesAtOnce) {
  // 97 frames × 1001 samples per interval: 96 097 samples, more than one block,
  // so the sums are combined and the 95th percentile is selected across blocks.
  // Here every sample is also kept at once, the way eval measured before it
  // streamed, and the two must agree (p95 and max exactly).
  const Clip clip = constant_velocity_clip(97, 30.0);
  ClipEvalOptions o;
  o.methods = {"squad"};
  o.keep_every = {4};
  o.subframe = 1000;
  auto ref = prepare_reference(clip, "cav", o);
  ASSERT_TRUE(ref.ok()) << ref.error();
  ASSERT_EQ(ref->samples, 96097u);
  auto rows = evaluate_method(*ref, "squad", o);
  ASSERT_TRUE(rows.ok()) << rows.error();
  std::vector<double> times(ref->samples);
  for (std::size_t m = 0; m < times.size(); ++m) times[m] = sample_time(*ref, m);
  std::vector<double> scratch;
  for (std::size_t j = 0; j < clip.skeleton.joints.size(); ++j) {
    SCOPED_TRACE(j);
    std::vector<Quat> reference(times.size()), test(times.size());
    for (std::size_t m = 0; m < times.size(); ++m) {
      const std::size_t k = m / ref->per_frame, i = m % ref->per_frame;
      const Quat& q0 = ref->original[j][k];
      reference[m] = i == 0 ? q0
                            : slerp(q0, ref->original[j][k + 1],
                                    static_cast<double>(i) / static_cast<double>(ref->per_frame));
    }
    const auto keys = keep_every_indices(ref->frames.size(), 4);
    auto curve = make_interpolator("squad", decimated_track(ref->frames, ref->original[j], keys));
    ASSERT_TRUE(curve.ok());
    (*curve)->evaluate(times.data(), times.size(), test.data());
    const RotationError all = rotation_error(reference.data(), test.data(), times.size(), ref->bone_axis[j], scratch);
    const ErrorRow& row = (*rows)[j];
    constexpr double kDeg = 180.0 / kPi;
    EXPECT_GT(all.angle.p95, 0.0);
    EXPECT_EQ(row.p95_deg, all.angle.p95 * kDeg);
    EXPECT_EQ(row.max_deg, all.angle.max * kDeg);
    EXPECT_NEAR(row.mean_deg, all.angle.mean * kDeg, 1e-12 * row.mean_deg);
    EXPECT_NEAR(row.rms_deg, all.angle.rms * kDeg, 1e-12 * row.rms_deg);
    EXPECT_NEAR(row.swing_rms_deg, all.swing.rms() * kDeg, 1e-12 * row.rms_deg);
    EXPECT_NEAR(row.twist_rms_deg, all.twist.rms() * kDeg, 1e-12 * row.rms_deg);
    const Smoothness smooth = sampled_smoothness(test.data(), test.size(), ref->sample_dt);
    EXPECT_NEAR(row.acc_rms, smooth.acceleration_rms * kDeg, 1e-9 * row.acc_rms);
    const Smoothness smooth_ref = sampled_smoothness(reference.data(), reference.size(), ref->sample_dt);
    EXPECT_NEAR(row.acc_rms_ref, smooth_ref.acceleration_rms * kDeg, 1e-9 * row.acc_rms_ref);
    EXPECT_EQ(row.samples, times.size());
  }
}

}  // namespace
}  // namespace rotinterp
