// reduce --loop: keys chosen on a cycle's periodic curve. The written clip, replayed as
// resample --loop replays it (resample_cycle), stays within the budget at every frame,
// across the seam too; a cycle needs fewer keys than the same clip with ends, and the
// count does not depend on the frame the cycle starts on.
#include "clip/cycle_clips.h"
#include "support/run_cli.h"

#include "rotinterp/clip/frames.h"
#include "rotinterp/clip/metrics.h"
#include "rotinterp/clip/resample_loop.h"
#include "rotinterp/clip/units.h"
#include "rotinterp/io/read.h"
#include "rotinterp/reduce/reduce.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

namespace rotinterp {
namespace {

namespace fs = std::filesystem;

constexpr double kDeg = kPi / 180.0;
const test::CycleTruth kTruth{1.0, Vec3(0.8, 0.0, 0.0)};  // 1 s per cycle, the root 0.8 m forward each

// The largest errors of a replay, at the seam (the first and last frames and their
// neighbours) and inside.
struct ReplayErrors {
  double angle_seam = 0, angle_inside = 0;  // rad, the largest local rotation error (normalized by the budget)
  double shell_seam = 0, shell_inside = 0;  // normalized by the budget
  double translation = 0;                   // normalized by the budget
  std::size_t frames = 0;                   // source frames compared
};

// Replays the written clip as resample --loop does (every written cycle closes) at
// `rate`, and measures each output frame that is a source frame against the source —
// a closed cycle's last frame, for the joints that loop, against its first: the cycle.
ReplayErrors replay_errors(const Clip& source, const ReduceResult& r, const ReduceOptions& o, Rate rate) {
  ResampleOptions ro;
  ro.fps = rate;
  ro.method = o.method;
  ro.translation = o.translation;
  auto replay = resample_cycle(r.reduced, ro, LoopForm::closed);
  EXPECT_TRUE(replay) << replay.error();
  ReplayErrors e;
  if (!replay) return e;
  DenseClip ref = dense_clip(source);
  if (ref.grid.rate)
    for (std::size_t k = 0; k < ref.grid.size(); ++k) ref.grid.times[k] = ref.grid.exact_time(k);
  const std::size_t n = ref.grid.size(), joints = source.skeleton.joints.size();
  const bool closed = r.cycle->form == LoopForm::closed;
  const Clip& out = replay->clip;
  for (std::size_t k = 0; k < out.rotations[0].times.size(); ++k) {
    const double t = out.rotations[0].times[k];
    const std::optional<std::size_t> at = ref.grid.frame_at(t);
    if (!at) continue;  // a replay frame between the source's (sparse FBX keys)
    const std::size_t f = *at;
    ++e.frames;
    const bool seam = f <= 1 || f + 2 >= n;
    std::vector<Quat> qr(joints), qt(joints);
    std::vector<Vec3> tr(joints), tt(joints);
    for (std::size_t j = 0; j < joints; ++j) {
      const std::size_t truth = closed && f + 1 == n && r.joints[j].looped ? 0 : f;
      qr[j] = ref.rotation[j][truth];
      tr[j] = ref.translation[j][f];
      qt[j] = out.rotations[j].keys[k];
      tt[j] = out.translations[j] ? out.translations[j]->keys[k] : ref.translation[j][f];
      const ReduceBudget& b = r.joints[j].budget;
      if (b.rotation_deg > 0.0) {
        const double a = angular_distance(qr[j], qt[j]) / (b.rotation_deg * kDeg);
        (seam ? e.angle_seam : e.angle_inside) = std::max(seam ? e.angle_seam : e.angle_inside, a);
      }
      if (out.translations[j]) e.translation = std::max(e.translation, (tr[j] - tt[j]).norm() / b.translation);
    }
    if (!(o.budget.shell > 0.0)) continue;
    WorldPose wr, wt;
    forward_kinematics(source.skeleton, qr, tr, wr);
    forward_kinematics(source.skeleton, qt, tt, wt);
    for (std::size_t j = 0; j < joints; ++j) {
      const double s = shell_error(wr.rotation[j], wr.position[j], wt.rotation[j], wt.position[j], o.shell_distance) /
                       r.joints[j].budget.shell;
      (seam ? e.shell_seam : e.shell_inside) = std::max(seam ? e.shell_seam : e.shell_inside, s);
    }
  }
  return e;
}

// Within budget: the written keys and values are floats nowhere here, so round-off only.
constexpr double kWithin = 1.0 + 1e-6;

ReduceOptions angle_budget(const std::string& method, bool loop) {
  ReduceOptions o;
  o.method = method;
  o.budget.rotation_deg = 0.5;
  o.budget.translation = 0.001;  // metres
  o.loop = loop;
  return o;
}

std::size_t rotation_keys(const ReduceResult& r, std::size_t j) {
  return r.joints[j].rotation_frames.size() - (r.joints[j].looped ? 1 : 0);
}

TEST(ReduceLoop, ACycleKeepsFewerKeysThanWithEndsAndNoneForTheLastFrame) {
  for (LoopForm form : {LoopForm::closed, LoopForm::open})
    for (const std::string method : {"slerp", "c2", "squad"}) {
      SCOPED_TRACE(std::string(loop_form_name(form)) + " " + method);
      const Clip clip = test::cycle_clip(kTruth, 60, form);
      auto ends = reduce_clip(clip, angle_budget(method, false));
      auto cycle = reduce_clip(clip, angle_budget(method, true));
      ASSERT_TRUE(ends) << ends.error();
      ASSERT_TRUE(cycle) << cycle.error();
      // Closed: the last frame's keys are the seam's. Open: slerp has no end conditions
      // to lose, and the cycle's one more segment (last frame to the seam) costs what the
      // last key saved; the cubics' one-sided ends cost keys that the cycle does not need.
      if (form == LoopForm::open && method == "slerp") {
        EXPECT_LE(cycle->kept_keys, ends->kept_keys);
      } else {
        EXPECT_LT(cycle->kept_keys, ends->kept_keys);
      }
      const std::size_t n = clip.rotations[1].times.size();
      for (std::size_t j = 0; j < 3; ++j) {
        ASSERT_TRUE(cycle->joints[j].looped);
        const std::vector<std::size_t>& f = cycle->joints[j].rotation_frames;
        // The seam is the one key both ends share; the last key written closes the cycle.
        EXPECT_EQ(f.front(), 0u);
        EXPECT_EQ(f.back(), form == LoopForm::closed ? n - 1 : n);
        EXPECT_LT(f[f.size() - 2], n - 1) << "a key of the last frame's own";
      }
      // A full turn at constant velocity: three slerp keys round the cycle.
      if (method == "slerp") {
        EXPECT_EQ(rotation_keys(*cycle, 1), 3u);
      }
    }
}

TEST(ReduceLoop, TheWrittenCycleReplayedAsACycleStaysWithinBudgetAtEveryFrameAcrossTheSeam) {
  for (LoopForm form : {LoopForm::closed, LoopForm::open})
    for (const std::string method : {"slerp", "c2", "squad", "expmap-c2"}) {
      SCOPED_TRACE(std::string(loop_form_name(form)) + " " + method);
      const Clip clip = test::cycle_clip(kTruth, 60, form);
      const ReduceOptions o = angle_budget(method, true);
      auto r = reduce_clip(clip, o);
      ASSERT_TRUE(r) << r.error();
      const ReplayErrors e = replay_errors(clip, *r, o, Rate{60, 1});
      EXPECT_EQ(e.frames, clip.rotations[0].times.size());
      EXPECT_LE(e.angle_seam, kWithin);
      EXPECT_LE(e.angle_inside, kWithin);
      EXPECT_LE(e.translation, kWithin);
      EXPECT_GT(e.angle_inside, 0.5) << "the budget is used, so the check can fail";
    }
}

// The same cycle started `shift` frames later: rotations moved round, the root's
// positions round too, each wrapped one moved by the per-cycle offset.
Clip started_later(const Clip& closed, std::size_t shift) {
  Clip c = closed;
  const std::size_t n = closed.rotations[0].times.size(), period = n - 1;
  for (std::size_t j = 0; j < c.rotations.size(); ++j) {
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t from = (k + shift) % period;
      c.rotations[j].keys[k] = closed.rotations[j].keys[from];
      if (closed.translations[j]) {
        const Vec3 drift = closed.translations[j]->keys[period] - closed.translations[j]->keys[0];
        c.translations[j]->keys[k] = closed.translations[j]->keys[from] + drift * double((k + shift) / period);
      }
    }
    c.rotations[j].make_sign_continuous();
  }
  return c;
}

TEST(ReduceLoop, StartingTheCycleOnAnotherFrameKeepsAsManyKeysWithinOnePerTrack) {
  const Clip clip = test::cycle_clip(kTruth, 60, LoopForm::closed);
  for (const std::string method : {"slerp", "c2"}) {
    auto base = reduce_clip(clip, angle_budget(method, true));
    ASSERT_TRUE(base) << base.error();
    for (std::size_t shift : {7u, 20u, 33u, 51u}) {
      SCOPED_TRACE(method + " shifted by " + std::to_string(shift));
      auto moved = reduce_clip(started_later(clip, shift), angle_budget(method, true));
      ASSERT_TRUE(moved) << moved.error();
      for (std::size_t j = 0; j < 3; ++j) {
        const auto a = static_cast<long>(rotation_keys(*base, j)), b = static_cast<long>(rotation_keys(*moved, j));
        EXPECT_LE(std::abs(a - b), 1) << clip.skeleton.joints[j].name;
      }
      const auto ta = static_cast<long>(base->joints[0].translation_frames.size());
      const auto tb = static_cast<long>(moved->joints[0].translation_frames.size());
      EXPECT_LE(std::abs(ta - tb), 1) << "root translation";
    }
  }
}

// The three real cycles of the shared data, at the command's default budget (1 mm at
// 10 cm, translations to 0.5 mm), for slerp and c2.
TEST(ReduceLoop, RealCyclesReplayWithinTheDefaultBudgetAcrossTheSeam) {
  for (const std::string name : {"digitalrune_Dude.fbx", "digitalrune_PlayerMarine_Idle.fbx", "digitalrune_Marine_Run.fbx"}) {
    auto clip = read_clip(fs::path(ROTINTERP_SHARED_DATA) / "fbx" / name);
    ASSERT_TRUE(clip) << clip.error();
    for (const std::string method : {"slerp", "c2"}) {
      SCOPED_TRACE(name + " " + method);
      ReduceOptions o;
      o.method = method;
      o.budget.shell = in_clip_units(*clip, 0.001);
      o.budget.translation = in_clip_units(*clip, 0.001);
      o.shell_distance = in_clip_units(*clip, 0.1);
      o.loop = true;
      auto r = reduce_clip(*clip, o);
      ASSERT_TRUE(r) << r.error();
      ASSERT_TRUE(r->cycle);
      EXPECT_EQ(r->cycle->form, LoopForm::closed);
      const ReplayErrors e = replay_errors(*clip, *r, o, Rate{30, 1});
      EXPECT_GE(e.frames, r->cycle->period_frames + 1);
      EXPECT_LE(e.shell_seam, kWithin);
      EXPECT_LE(e.shell_inside, kWithin);
      EXPECT_LE(e.translation, kWithin);
      EXPECT_GT(e.shell_inside, 0.5) << "the budget is used, so the check can fail";
    }
  }
}

// The file itself: the sparse GLB reduce --loop writes, resampled with resample --loop at
// the source's rate, stays within the angle budget at every frame, the seam's included
// (slerp: the LINEAR samplers; L_Arm, the source's pop, keeps its ends).
TEST(ReduceLoopCli, TheWrittenGlbResampledAsACycleReplaysWithinBudgetAtEveryFrame) {
  const fs::path dir = fs::temp_directory_path() / ("rotinterp_reduce_loop_glb_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string run = std::string(ROTINTERP_SHARED_DATA) + "/fbx/digitalrune_Marine_Run.fbx";
  const std::string keys = (dir / "run.glb").string(), replay = (dir / "replay.glb").string();
  auto reduced = test::run_cli("reduce " + run + " -o " + keys + " --loop --tolerance 0.5deg --quiet");
  ASSERT_EQ(reduced.exit_code, 0) << reduced.err;
  auto resampled = test::run_cli("resample " + keys + " -o " + replay + " --loop closed --fps 30 -m slerp --quiet");
  ASSERT_EQ(resampled.exit_code, 0) << resampled.err;
  auto source = read_clip(run);
  auto out = read_clip(replay);
  ASSERT_TRUE(source) << source.error();
  ASSERT_TRUE(out) << out.error();
  const DenseClip ref = dense_clip(*source);
  const std::size_t n = out->rotations[0].times.size();
  ASSERT_EQ(n, 41u);  // 1.333 s at its file's 30 Hz
  double seam = 0.0, inside = 0.0;
  for (std::size_t j = 0; j < source->skeleton.joints.size(); ++j) {
    ASSERT_EQ(out->rotations[j].keys.size(), n);
    for (std::size_t k = 0; k < n; ++k) {
      const std::optional<std::size_t> f = ref.grid.frame_at(out->rotations[j].times[k]);
      ASSERT_TRUE(f);
      const double a = angular_distance(ref.rotation[j][*f], out->rotations[j].keys[k]) / kDeg;
      (k <= 1 || k + 2 >= n ? seam : inside) = std::max(k <= 1 || k + 2 >= n ? seam : inside, a);
    }
  }
  EXPECT_LE(seam, 0.5 + 1e-4);  // the GLB's floats: ≤ 2e-6° (docs/reduce.md)
  EXPECT_LE(inside, 0.5 + 1e-4);
  EXPECT_GT(inside, 0.4) << "the budget is used, so the check can fail";
  fs::remove_all(dir);
}

TEST(ReduceLoopCli, ABadLoopWordOrAClipThatIsNoCycleIsOneLine) {
  const std::string walk = std::string(ROTINTERP_SOURCE_DIR) + "/samples/walk.bvh";
  const fs::path out = fs::temp_directory_path() / ("rotinterp_reduce_loop_" + std::to_string(::getpid()) + ".json");
  auto bad = test::run_cli("reduce " + walk + " -o " + out.string() + " --loop sideways");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
  EXPECT_NE(bad.err.find("expected auto, closed or open"), std::string::npos) << bad.err;
  auto not_cycle = test::run_cli("reduce " + walk + " -o " + out.string() + " --loop");
  EXPECT_EQ(not_cycle.exit_code, 1);
  EXPECT_EQ(std::count(not_cycle.err.begin(), not_cycle.err.end(), '\n'), 1) << not_cycle.err;
  EXPECT_NE(not_cycle.err.find("does not look like a cycle"), std::string::npos) << not_cycle.err;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace rotinterp
