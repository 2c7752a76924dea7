// resample --loop on synthetic cycles: at seven rates (one NTSC, two that do not
// divide the period) the output is a whole period closing as the input, exact on
// constant velocity, seam-continuous for every method, with the root's forward motion kept.
#include "cycle_clips.h"
#include "seam_jumps.h"

#include "rotinterp/clip/resample_loop.h"
#include "rotinterp/interp/interpolator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace rotinterp {
namespace {

using test::cycle_clip;
using test::CycleTruth;
using test::seam_jump;

// 40 frames at 30 Hz: a period of 4/3 s. 25 Hz (33.3 frames) and 30000/1001 (39.96) do not divide it.
const CycleTruth kTruth{4.0 / 3.0, Vec3(1.5, 0.0, 0.0)};
const std::vector<Rate> kRates = {{15, 1}, {24, 1}, {25, 1}, {30000, 1001}, {48, 1}, {60, 1}, {120, 1}};

CycleResample resampled(const Clip& clip, const std::string& method, std::optional<Rate> fps,
                        std::optional<std::size_t> keep_every = std::nullopt) {
  ResampleOptions o;
  o.method = method;
  o.fps = fps;
  o.keep_every = keep_every;
  auto r = resample_cycle(clip, o);
  EXPECT_TRUE(r) << r.error();
  return r ? std::move(*r) : CycleResample{};
}

TEST(ResampleLoop, WholeFramesPerPeriodClosingAsTheInputAtSevenRates) {
  for (LoopForm form : {LoopForm::closed, LoopForm::open})
    for (const Rate& rate : kRates) {
      const CycleResample r = resampled(cycle_clip(kTruth, 40, form), "clamped", rate);
      const double exact = kTruth.period * rate.hz();
      const auto m = static_cast<std::size_t>(std::lround(exact));
      EXPECT_EQ(r.period_frames, m) << rate.to_string();
      EXPECT_EQ(r.clip.rotations[1].keys.size(), m + (form == LoopForm::closed ? 1 : 0));
      EXPECT_NEAR(r.period, static_cast<double>(m) / rate.hz(), 1e-12);
      EXPECT_LE(std::abs(r.period - kTruth.period), 0.5 / rate.hz() + 1e-12) << "stretched by under half a frame";
      EXPECT_EQ(r.stretch != 0.0, std::abs(exact - std::round(exact)) > 1e-9) << rate.to_string();
      auto again = check_loop(r.clip);
      ASSERT_TRUE(again);
      EXPECT_TRUE(again->looks_like_cycle) << rate.to_string() << ": " << loop_check_text(*again);
      EXPECT_EQ(again->form, form) << rate.to_string();
    }
}

TEST(ResampleLoop, ConstantVelocityTurnIsExactAtEveryRateForMethodsThatClaimIt) {
  for (const MethodInfo& m : methods()) {
    if (!m.exact_on_constant_velocity) continue;
    for (LoopForm form : {LoopForm::closed, LoopForm::open})
      for (const Rate& rate : kRates) {
        const CycleResample r = resampled(cycle_clip(kTruth, 40, form), m.name, rate);
        const RotationTrack& spin = r.clip.rotations[1];
        double worst = 0.0;
        for (std::size_t k = 0; k < spin.keys.size(); ++k)  // frame k is the source at k·P/M
          worst = std::max(worst, angular_distance(spin.keys[k], kTruth.spin(kTruth.period * static_cast<double>(k) /
                                                                               static_cast<double>(r.period_frames))));
        EXPECT_LT(worst, 1e-9) << m.name << " at " << rate.to_string() << " " << loop_form_name(form);
      }
  }
}

TEST(ResampleLoop, SeamIsNoRougherThanInsideForEveryMethodAndRate) {
  for (const MethodInfo& m : methods())
    for (LoopForm form : {LoopForm::closed, LoopForm::open})
      for (const Rate& rate : kRates) {
        const CycleResample r = resampled(cycle_clip(kTruth, 40, form), m.name, rate);
        for (std::size_t j : {1u, 2u}) {
          const test::SeamJump jump = seam_jump(r.clip.rotations[j], form, r.clip.frame_time);
          EXPECT_LE(jump.seam, jump.inside * 1.0001 + 1e-9)
              << m.name << " joint " << j << " at " << rate.to_string() << " " << loop_form_name(form);
        }
      }
}

TEST(ResampleLoop, KeepEveryUsesTheWrapAroundNeighbours) {
  const Clip clip = cycle_clip(kTruth, 40, LoopForm::closed);
  for (const MethodInfo& m : methods())
    for (std::size_t n : {2u, 4u, 8u, 3u}) {
      const CycleResample r = resampled(clip, m.name, std::nullopt, n);
      ASSERT_EQ(r.clip.rotations[2].keys.size(), 41u);
      const test::SeamJump looped = seam_jump(r.clip.rotations[2], LoopForm::closed, clip.frame_time);
      EXPECT_LE(looped.seam, looped.inside * 1.0001 + 1e-9) << m.name << " every " << n;
      EXPECT_LT(angular_distance(r.clip.rotations[2].keys.back(), r.clip.rotations[2].keys.front()), 1e-12);
    }
  // Without the loop the same keys give a seam rougher than anything inside (C¹ and C² methods).
  for (const MethodInfo& m : methods()) {
    if (m.continuity == 0) continue;
    ResampleOptions o;
    o.method = m.name;
    o.keep_every = 8;
    auto plain = resample_clip(clip, o);
    ASSERT_TRUE(plain);
    const test::SeamJump open_ends = seam_jump(plain->rotations[2], LoopForm::closed, clip.frame_time);
    EXPECT_GT(open_ends.seam, open_ends.inside) << m.name << " without --loop";
  }
}

TEST(ResampleLoop, RootKeepsItsForwardMotionAndClosesAroundIt) {
  for (LoopForm form : {LoopForm::closed, LoopForm::open})
    for (const Rate& rate : kRates) {
      const CycleResample r = resampled(cycle_clip(kTruth, 40, form), "clamped", rate);
      const TranslationTrack& root = *r.clip.translations[0];
      if (form == LoopForm::closed) {
        EXPECT_NEAR((root.keys.back() - root.keys.front() - kTruth.drift).norm(), 0.0, 1e-12) << rate.to_string();
      }
      double worst = 0.0;
      for (std::size_t k = 0; k < root.keys.size(); ++k)
        worst = std::max(worst, (root.keys[k] - kTruth.root(kTruth.period * static_cast<double>(k) /
                                                           static_cast<double>(r.period_frames)))
                                    .norm());
      EXPECT_LT(worst, form == LoopForm::closed ? 2e-3 : 0.03) << rate.to_string() << " " << loop_form_name(form);
    }
}

TEST(ResampleLoop, RefusesARangeAndAClipThatIsNotACycle) {
  ResampleOptions o;
  o.range = TimeRange{};
  EXPECT_FALSE(resample_cycle(cycle_clip(kTruth, 40, LoopForm::closed), o));
  Clip risen = cycle_clip(kTruth, 40, LoopForm::closed);
  risen.translations[0]->keys.back().y() += 0.5;
  auto r = resample_cycle(risen, ResampleOptions{});
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().find("does not look like a cycle"), std::string::npos) << r.error();
  EXPECT_TRUE(resample_cycle(risen, ResampleOptions{}, LoopForm::closed)) << "a forced form is taken as asked";
}

}  // namespace
}  // namespace rotinterp
