#include "rotinterp/clip/resample.h"

#include "rotinterp/clip/synth.h"
#include "rotinterp/interp/interpolator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

using namespace rotinterp;

namespace {

constexpr double kDeg = 180.0 / kPi;

Clip synth(SynthKind kind, Rate fps, double seconds, std::uint64_t seed = 1) {
  SynthOptions o;
  o.kind = kind;
  o.fps = fps;
  o.seconds = seconds;
  o.seed = seed;
  auto c = make_synth_clip(o);
  EXPECT_TRUE(c.ok());
  return std::move(c).value();
}

SynthMotion motion(SynthKind kind, std::uint64_t seed = 1) {
  SynthOptions o;
  o.kind = kind;
  o.seed = seed;
  return make_synth_motion(o).value();
}

double max_angle_deg(const Clip& a, const Clip& b, std::size_t frame_a_step = 1, std::size_t frames = 0) {
  double worst = 0.0;
  for (std::size_t j = 0; j < a.rotations.size(); ++j) {
    const std::size_t n = frames ? frames : b.rotations[j].keys.size();
    for (std::size_t k = 0; k < n; ++k)
      worst = std::max(worst, angular_distance(a.rotations[j].keys[k * frame_a_step], b.rotations[j].keys[k]) * kDeg);
  }
  return worst;
}

ResampleOptions at(const char* fps, const char* method = "slerp") {
  ResampleOptions o;
  o.fps = parse_rate(fps).value();
  o.method = method;
  return o;
}

}  // namespace

TEST(Resample, FrameCountsAndTimesForEveryRatio) {
  struct Case {
    const char* src;
    const char* dst;
    double seconds;
  };
  const Case cases[] = {{"120", "30", 3.0},       {"120", "50", 2.991},     {"30", "24", 2.0},
                        {"24", "60", 2.0},        {"60", "59.94", 3.0},     {"60", "30000/1001", 3.0},
                        {"30000/1001", "30", 2.0}, {"30", "120", 1.5}};
  for (const Case& c : cases) {
    const Rate src = parse_rate(c.src).value(), dst = parse_rate(c.dst).value();
    const Clip in = synth(SynthKind::smooth, src, c.seconds);
    auto out = resample_clip(in, at(c.dst));
    ASSERT_TRUE(out.ok()) << out.error();
    ASSERT_TRUE(out->validate().ok());
    const std::size_t frames = in.frame_count();
    const std::size_t expected = sample_count(frames, src, dst);
    const double duration = src.time_of(static_cast<std::int64_t>(frames) - 1);
    EXPECT_EQ(expected, static_cast<std::size_t>(std::floor(duration * dst.hz() + 1e-9)) + 1);
    EXPECT_EQ(out->frame_count(), expected) << c.src << " → " << c.dst;
    EXPECT_DOUBLE_EQ(out->frame_time, 1.0 / dst.hz());
    for (const RotationTrack& tr : out->rotations) {
      ASSERT_EQ(tr.times.size(), expected);
      for (std::size_t k = 0; k < expected; ++k) ASSERT_EQ(tr.times[k], dst.time_of(static_cast<std::int64_t>(k)));
      EXPECT_LE(tr.times.back(), in.end_time());  // never past the clip
    }
  }
}

TEST(Resample, DownsamplingByAnIntegerFactorLandsExactlyOnSourceFrames) {
  ASSERT_GE(methods().size(), 5u) << "the interpolators are not registered";
  Clip in = synth(SynthKind::walk, Rate{120, 1}, 3.0);
  in.frame_time = 0.008333;  // as a BVH header prints it
  for (const MethodInfo& m : methods()) {
    auto out = resample_clip(in, at("30", m.name.c_str()));
    ASSERT_TRUE(out.ok()) << out.error();
    ASSERT_EQ(out->frame_count(), 91u);
    EXPECT_LT(max_angle_deg(in, *out, 4), 1e-9) << m.name;
    for (std::size_t k = 0; k < 91; ++k)
      EXPECT_LT((out->translations[0]->keys[k] - in.translations[0]->keys[4 * k]).norm(), 1e-9);
  }
}

TEST(Resample, SameRateReproducesTheInput) {
  ASSERT_GE(methods().size(), 5u) << "the interpolators are not registered";
  const Clip in = synth(SynthKind::spin, Rate{30, 1}, 2.0);
  for (const MethodInfo& m : methods()) {
    ResampleOptions o;
    o.method = m.name;
    auto out = resample_clip(in, o);
    ASSERT_TRUE(out.ok()) << out.error();
    EXPECT_EQ(out->frame_count(), in.frame_count());
    EXPECT_EQ(out->frame_time, in.frame_time);
    // The output frames are the keys: copied, not rebuilt (bf and expmap only come
    // back to 1e-9 rad at their keys), so the same bits up to sign.
    for (std::size_t j = 0; j < in.rotations.size(); ++j)
      for (std::size_t k = 0; k < in.frame_count(); ++k) {
        const Quat a = normalized_or_identity(in.rotations[j].keys[k]), b = out->rotations[j].keys[k];
        EXPECT_TRUE(a.coeffs() == b.coeffs() || a.coeffs() == -b.coeffs()) << m.name << " joint " << j << " frame " << k;
        if (in.translations[j]) {
          EXPECT_EQ(in.translations[j]->keys[k], out->translations[j]->keys[k]);
        }
      }
  }
}

TEST(Resample, UpThenDownReturnsTheInputFramesForEveryMethod) {
  ASSERT_GE(methods().size(), 5u) << "the interpolators are not registered";
  const Clip in = synth(SynthKind::smooth, Rate{30, 1}, 2.0, 5);
  for (const MethodInfo& m : methods()) {
    auto up = resample_clip(in, at("120", m.name.c_str()));
    ASSERT_TRUE(up.ok()) << up.error();
    EXPECT_EQ(up->frame_count(), 241u);
    auto down = resample_clip(*up, at("30", m.name.c_str()));
    ASSERT_TRUE(down.ok()) << down.error();
    ASSERT_EQ(down->frame_count(), in.frame_count());
    EXPECT_LT(max_angle_deg(in, *down), 1e-6) << m.name;
    for (std::size_t k = 0; k < in.frame_count(); ++k)
      EXPECT_LT((down->translations[0]->keys[k] - in.translations[0]->keys[k]).norm(), 1e-9);
  }
}

TEST(Resample, ConstantAngularVelocityWithRandomOrdersMatchesTheAnalyticMotionAt50Hz) {
  const SynthMotion truth = motion(SynthKind::constant, 21);
  const Clip in = truth.sample(3.0, Rate{30, 1}, "cav");
  for (const char* method : {"slerp", "squad", "bf"}) {
    ASSERT_NE(find_method(method), nullptr) << method;
    auto out = resample_clip(in, at("50", method));
    ASSERT_TRUE(out.ok()) << out.error();
    double worst = 0.0;
    for (std::size_t j = 0; j < in.rotations.size(); ++j)
      for (std::size_t k = 0; k < out->rotations[j].keys.size(); ++k) {
        const double t = out->rotations[j].times[k];
        worst = std::max(worst, angular_distance(out->rotations[j].keys[k], truth.rotation(j, t)) * kDeg);
      }
    EXPECT_LT(worst, 1e-3) << method;
  }
}

TEST(Resample, StraightRootPathIsReproducedExactlyAndCubicIsSmooth) {
  const SynthMotion truth = motion(SynthKind::constant, 8);  // root on a straight line
  const Clip in = truth.sample(2.0, Rate{30, 1}, "line");
  for (TranslationInterp tm : {TranslationInterp::linear, TranslationInterp::cubic}) {
    ResampleOptions o = at("97");
    o.translation = tm;
    auto out = resample_clip(in, o);
    ASSERT_TRUE(out.ok());
    for (std::size_t k = 0; k < out->frame_count(); ++k) {
      const double t = out->translations[0]->times[k];
      EXPECT_LT((out->translations[0]->keys[k] - truth.translation(0, t)).norm(), 1e-10);
    }
  }
  // On a curved path the cubic's velocity is continuous at the source keys.
  const Clip curved = synth(SynthKind::smooth, Rate{10, 1}, 2.0, 4);
  ResampleOptions o = at("10000");
  o.translation = TranslationInterp::cubic;
  auto fine = resample_clip(curved, o);
  ASSERT_TRUE(fine.ok());
  const auto& p = fine->translations[0]->keys;
  double jump = 0.0, speed = 0.0;
  for (std::size_t key = 1000; key + 1000 < p.size(); key += 1000) {  // source key every 1000 samples
    const Vec3 before = (p[key] - p[key - 1]) * 10000.0, after = (p[key + 1] - p[key]) * 10000.0;
    jump = std::max(jump, (after - before).norm());
    speed = std::max(speed, before.norm());
  }
  EXPECT_LT(jump, 1e-2 * speed);
}

TEST(Resample, KeepEveryRebuildsEveryFrameFromSparseKeys) {
  const Clip in = synth(SynthKind::constant, Rate{30, 1}, 2.0, 3);  // 61 frames
  ResampleOptions o;
  o.method = "slerp";
  o.keep_every = 8;  // keys 0, 8, …, 56 and 60
  auto out = resample_clip(in, o);
  ASSERT_TRUE(out.ok()) << out.error();
  EXPECT_EQ(out->frame_count(), 61u);
  EXPECT_EQ(out->frame_time, in.frame_time);
  EXPECT_LT(max_angle_deg(in, *out), 1e-6);  // slerp is exact on constant angular velocity
  // A smooth clip is not reproduced exactly, but the kept keys are.
  const Clip smooth = synth(SynthKind::smooth, Rate{30, 1}, 2.0, 3);
  auto rebuilt = resample_clip(smooth, o);
  ASSERT_TRUE(rebuilt.ok());
  EXPECT_GT(max_angle_deg(smooth, *rebuilt), 0.01);
  for (std::size_t k : {0, 8, 56, 60})
    for (std::size_t j = 0; j < smooth.rotations.size(); ++j)
      EXPECT_LT(angular_distance(smooth.rotations[j].keys[k], rebuilt->rotations[j].keys[k]), 1e-9);
}

TEST(Resample, PerJointMethodOverridesApplyOnlyToThatJoint) {
  const Clip in = synth(SynthKind::smooth, Rate{10, 1}, 2.0, 6);
  ResampleOptions a = at("60"), b = at("60");
  b.method_for = {{"J3", "nlerp"}};
  auto ra = resample_clip(in, a), rb = resample_clip(in, b);
  ASSERT_TRUE(ra.ok() && rb.ok());
  const std::size_t j3 = static_cast<std::size_t>(in.skeleton.find("J3"));
  for (std::size_t j = 0; j < in.rotations.size(); ++j) {
    double d = 0.0;
    for (std::size_t k = 0; k < ra->rotations[j].keys.size(); ++k)
      d = std::max(d, angular_distance(ra->rotations[j].keys[k], rb->rotations[j].keys[k]));
    if (j == j3) EXPECT_GT(d, 1e-6);
    else EXPECT_EQ(d, 0.0);
  }
}

TEST(Resample, RangeCutEqualsTheSameFramesOfAnUncutResample) {
  const Clip in = synth(SynthKind::walk, Rate{30, 1}, 4.0);
  ResampleOptions whole = at("50"), cut = at("50");
  cut.range = TimeRange{1.0, 2.5};
  auto rw = resample_clip(in, whole), rc = resample_clip(in, cut);
  ASSERT_TRUE(rw.ok() && rc.ok()) << (rc.ok() ? "" : rc.error());
  ASSERT_EQ(rc->frame_count(), 76u);  // 1.5 s · 50 + 1
  EXPECT_EQ(rc->rotations[0].times.front(), 0.0);
  for (std::size_t j = 0; j < in.rotations.size(); ++j)
    for (std::size_t k = 0; k < 76; ++k)
      ASSERT_LT(angular_distance(rc->rotations[j].keys[k], rw->rotations[j].keys[k + 50]), 1e-12);
  // keep-every within a range: frames 30 … 75 of the source.
  ResampleOptions ke;
  ke.method = "slerp";
  ke.keep_every = 4;
  ke.range = TimeRange{1.0, 2.5};
  auto rk = resample_clip(in, ke);
  ASSERT_TRUE(rk.ok()) << rk.error();
  ASSERT_EQ(rk->frame_count(), 46u);
  for (std::size_t j = 0; j < in.rotations.size(); ++j)
    EXPECT_LT(angular_distance(rk->rotations[j].keys[0], in.rotations[j].keys[30]), 1e-12);
}

TEST(Resample, ARangeInFramesCutsTheSameFramesAsInSeconds) {
  const Clip in = synth(SynthKind::walk, Rate{30, 1}, 3.0);
  for (const char* text : {"30f:75f", "1:75f", "30f:2.5", "1s:2.5s"}) {
    auto range = parse_time_range(text);
    ASSERT_TRUE(range) << text << ": " << range.error();
    ResampleOptions frames = at("50"), seconds = at("50");
    frames.range = *range;
    seconds.range = TimeRange{1.0, 2.5};
    auto a = resample_clip(in, frames), b = resample_clip(in, seconds);
    ASSERT_TRUE(a && b) << text;
    ASSERT_EQ(a->frame_count(), b->frame_count()) << text;
    for (std::size_t j = 0; j < in.rotations.size(); ++j)
      for (std::size_t k = 0; k < a->rotations[j].keys.size(); ++k)
        ASSERT_EQ(a->rotations[j].keys[k].coeffs(), b->rotations[j].keys[k].coeffs()) << text;
  }
  auto open = parse_time_range("120f:");
  ASSERT_TRUE(open);
  EXPECT_TRUE(open->start_in_frames);
  EXPECT_TRUE(std::isinf(open->end));
}

TEST(Resample, ARangePastTheEndSaysWhereTheClipEndsInSecondsAndFrames) {
  const Clip in = synth(SynthKind::walk, Rate{30, 1}, 2.0);
  ResampleOptions o = at("50");
  o.range = *parse_time_range("10f:90f");
  auto r = resample_clip(in, o);
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().find("range 10f:90f runs past the clip's end (ends at 2 s / frame 60)"), std::string::npos)
      << r.error();
}

TEST(Resample, ThreadCountDoesNotChangeTheResult) {
  const Clip in = synth(SynthKind::walk, Rate{120, 1}, 3.0);
  ResampleOptions one = at("50"), two = at("50");
  one.threads = 1;
  two.threads = 4;
  auto a = resample_clip(in, one), b = resample_clip(in, two);
  ASSERT_TRUE(a.ok() && b.ok());
  for (std::size_t j = 0; j < in.rotations.size(); ++j)
    for (std::size_t k = 0; k < a->rotations[j].keys.size(); ++k)
      ASSERT_EQ(a->rotations[j].keys[k].coeffs(), b->rotations[j].keys[k].coeffs());
}

TEST(Resample, BadRequestsAreOneLineErrors) {
  const Clip in = synth(SynthKind::walk, Rate{30, 1}, 2.0);
  auto expect_error = [&](const ResampleOptions& o, const char* needle) {
    auto r = resample_clip(in, o);
    ASSERT_FALSE(r.ok()) << needle;
    EXPECT_NE(r.error().find(needle), std::string::npos) << r.error();
    EXPECT_EQ(r.error().find('\n'), std::string::npos);
  };
  ResampleOptions o = at("50");
  o.keep_every = 2;
  expect_error(o, "not both");
  o = ResampleOptions{};
  o.keep_every = 0;
  expect_error(o, "at least 1");
  o = at("50", "cubicle");
  expect_error(o, "slerp");  // lists the valid names
  o = at("50");
  o.method_for = {{"Tail", "slerp"}};
  expect_error(o, "no joint 'Tail'");
  o.method_for = {{"Head", "nope"}};
  expect_error(o, "unknown method 'nope'");
  for (const auto& [r, why] : std::vector<std::pair<TimeRange, std::string>>{
           {TimeRange{-1.0, 1.0}, "starts before the clip's first frame"},
           {TimeRange{0.5, 3.0}, "runs past the clip's end (ends at 2 s / frame"},
           {TimeRange{1.5, 1.0}, "is empty"},
           {TimeRange{1.0, 1.0}, "is empty"}}) {
    o = at("50");
    o.range = r;
    expect_error(o, why.c_str());
  }
  Clip no_rate = in;
  no_rate.frame_time = 0.0;
  ResampleOptions same;
  same.method = "slerp";
  auto r = resample_clip(no_rate, same);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().find("--fps"), std::string::npos);
}

TEST(Resample, AbsurdOutputSizesAreRefusedBeforeAllocating) {
  const Clip in = synth(SynthKind::walk, Rate{30, 1}, 2.0);
  auto r = resample_clip(in, at("1000000000"));  // 2e9 frames × 31 joints
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().find("more than"), std::string::npos) << r.error();
}

// The command gives up the clip it read: the overload that takes it must give the
// same clip, and at the same rate keep the source's key arrays instead of copying.
TEST(Resample, AClipGivenUpResamplesAsACopyAndKeepsItsKeyArraysAtTheSameRate) {
  for (const std::optional<Rate> fps : {std::optional<Rate>{}, std::optional<Rate>{Rate{30, 1}}}) {
    for (const char* method : {"slerp", "c2"}) {
      ResampleOptions o;
      o.fps = fps;
      o.method = method;
      o.threads = 2;
      const Clip source = synth(SynthKind::walk, Rate{120, 1}, 2.0);
      Clip given = source;
      const Quat* root_keys = given.rotations[0].keys.data();
      const Vec3* root_positions = given.translations[0]->keys.data();
      const Result<Clip> copied = resample_clip(source, o);
      const Result<Clip> moved = resample_clip(std::move(given), o);
      ASSERT_TRUE(copied.ok() && moved.ok()) << method;
      ASSERT_EQ(copied->rotations.size(), moved->rotations.size());
      for (std::size_t j = 0; j < copied->rotations.size(); ++j) {
        EXPECT_EQ(copied->rotations[j].times, moved->rotations[j].times);
        ASSERT_EQ(copied->rotations[j].keys.size(), moved->rotations[j].keys.size());
        for (std::size_t k = 0; k < copied->rotations[j].keys.size(); ++k)
          ASSERT_EQ(copied->rotations[j].keys[k].coeffs(), moved->rotations[j].keys[k].coeffs()) << method << " " << j;
        ASSERT_EQ(copied->translations[j].has_value(), moved->translations[j].has_value());
        if (copied->translations[j]) {
          EXPECT_EQ(copied->translations[j]->keys, moved->translations[j]->keys);
        }
      }
      EXPECT_EQ(moved->rotations[0].keys.data() == root_keys, !fps) << method;
      EXPECT_EQ(moved->translations[0]->keys.data() == root_positions, !fps) << method;
    }
  }
}
