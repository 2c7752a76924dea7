// render --loop: the cycle played twice — time running on, the root moved on by its
// per-cycle offset — and every frame's error that of the periodic curves eval --loop measures.
#include "clip/cycle_clips.h"
#include "support/run_cli.h"

#include "rotinterp/eval/evaluate_clip.h"
#include "rotinterp/io/read.h"
#include "rotinterp/render/comparison.h"
#include "rotinterp/render/loop_play.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace rotinterp::render {
namespace {

namespace fs = std::filesystem;

Clip load(const std::string& rel) {
  auto c = read_clip(fs::path(ROTINTERP_SHARED_DATA) / rel);
  EXPECT_TRUE(c) << rel << ": " << (c ? "" : c.error());
  return c ? std::move(*c) : Clip{};
}

TEST(RenderLoop, PlaysTheCycleTwiceWithTimeRunningOnAndTheRootMovedOn) {
  const Clip clip = load("fbx/digitalrune_Marine_Run.fbx");
  auto twice = play_cycle_twice(clip, LoopPlay{}, 4);
  ASSERT_TRUE(twice) << twice.error();
  const std::size_t n = twice->period_frames;
  ASSERT_EQ(n, 40u);  // 1.333 s at its file's 30 Hz
  const Clip& c = twice->clip;
  EXPECT_EQ(frame_grid(c).size(), 2 * n + 1);  // closed: the first frame again two periods on
  const double dt = 1.0 / 30.0;
  for (std::size_t i = 0; i <= 2 * n; ++i) EXPECT_NEAR(frame_grid(c).times[i], clip.start_time() + dt * i, 1e-9) << i;
  std::vector<std::size_t> keys;
  for (std::size_t p = 0; p < 2; ++p)
    for (std::size_t k = 0; k < n; k += 4) keys.push_back(p * n + k);
  keys.push_back(2 * n);
  EXPECT_EQ(twice->keys, keys);
  // The root: the second period is the first moved by D; rotations repeat.
  std::size_t root = 0;
  while (root < c.translations.size() && !c.translations[root]) ++root;
  ASSERT_LT(root, c.translations.size());
  const Vec3 d = per_cycle_offset(*clip.translations[root], LoopForm::closed, dt);
  const TranslationTrack& p = *c.translations[root];
  for (std::size_t k = 0; k <= n; ++k) EXPECT_LT((p.keys[n + k] - p.keys[k] - d).norm(), 1e-9) << k;
  for (std::size_t j = 0; j < c.rotations.size(); ++j) {
    if (c.rotations[j].keys.size() <= 1) continue;
    for (std::size_t k = 0; k < n; ++k)
      EXPECT_LT(angular_distance(c.rotations[j].keys[n + k], c.rotations[j].keys[k]), 1e-12);
  }
  EXPECT_FALSE(twice->cycle.looped[static_cast<std::size_t>(c.skeleton.find("L_Arm"))]);  // the source's pop
}

TEST(RenderLoop, AnOpenCycleWithDriftKeepsMovingForwardInItsSecondPeriod) {
  const test::CycleTruth truth{1.0, Vec3(0.8, 0.0, 0.0)};
  const Clip clip = test::cycle_clip(truth, 24, LoopForm::open);
  auto twice = play_cycle_twice(clip, LoopPlay{LoopForm::open}, 5);
  ASSERT_TRUE(twice) << twice.error();
  const std::size_t n = twice->period_frames;
  ASSERT_EQ(n, 24u);
  const Clip& c = twice->clip;
  ASSERT_EQ(frame_grid(c).size(), 2 * n);  // open: no frame repeats
  for (std::size_t i = 0; i < 2 * n; ++i) {
    const double t = static_cast<double>(i) / 24.0;
    EXPECT_NEAR(c.translations[0]->times[i], t, 1e-12);
    // D: the parabola through the last three frames one frame on (clip/loop.h), within 4 mm of the drift.
    EXPECT_LT((c.translations[0]->keys[i] - truth.root(t)).norm(), 0.004) << i;
    if (i >= n) {
      EXPECT_LT((c.translations[0]->keys[i] - c.translations[0]->keys[i - n] -
                 per_cycle_offset(*clip.translations[0], LoopForm::open, 1.0 / 24.0)).norm(), 1e-12);
    }
    EXPECT_LT(angular_distance(c.rotations[2].keys[i], truth.swing(t)), 1e-12) << i;
  }
  EXPECT_EQ(twice->keys, (std::vector<std::size_t>{0, 5, 10, 15, 20, 24, 29, 34, 39, 44}));
}

TEST(RenderLoop, EveryFramesErrorIsEvalsOnThePeriodicCurvesInBothPeriods) {
  // Render's panel error at frame k and k + period is eval --loop's at frame k:
  // the seam frames (the last of a period, the first of the next) included.
  for (const char* file : {"fbx/digitalrune_Marine_Run.fbx", "fbx/digitalrune_Dude.fbx"}) {
    const Clip clip = load(file);
    for (const char* method : {"slerp", "c2", "clamped", "bf"}) {
      SCOPED_TRACE(std::string(file) + " " + method);
      ClipEvalOptions o;
      o.methods = {method};
      o.keep_every = {4};
      o.loop = true;
      auto reference = prepare_reference(clip, file, o);
      ASSERT_TRUE(reference) << reference.error();
      auto eval = per_frame_errors(*reference, method, 4);
      auto render = comparison_errors(clip, method, 4, LoopPlay{});
      auto twice = play_cycle_twice(clip, LoopPlay{}, 4);
      ASSERT_TRUE(eval && render && twice);
      const std::size_t n = twice->period_frames;
      ASSERT_EQ(render->size(), 2 * n + 1);
      // Frame n of the source (the closed form's end) repeats frame 0 only to its
      // closure miss; played in a loop, frames n and 2n are frame 0.
      for (std::size_t k = 0; k < n; ++k) {
        double worst = 0.0;
        for (std::size_t j = 0; j < eval->angle.size(); ++j)
          if (clip.rotations[j].keys.size() > 1) worst = std::max(worst, eval->angle[j][k]);
        for (std::size_t at : {k, n + k, k == 0 ? 2 * n : k}) EXPECT_NEAR((*render)[at].max, worst, 1e-9) << at;
      }
    }
  }
}

TEST(RenderLoop, CliDrawsTheSeamAndRefusesAClipThatIsNoCycle) {
  const fs::path out = fs::path(testing::TempDir()) / "rotinterp_render_loop";
  fs::remove_all(out);
  const std::string run = fs::path(ROTINTERP_SHARED_DATA).string() + "/fbx/digitalrune_Marine_Run.fbx";
  const auto r = test::run_cli("render " + run + " --loop -m c2 --keep-every 4 --size 320x180 -q -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* f : {"frame_000036.png", "frame_000040.png", "frame_000044.png"})
    EXPECT_TRUE(fs::exists(out / f)) << f << "\n" << r.out;  // one key interval either side of the seam (40)
  const auto walk = test::run_cli("render " + fs::path(ROTINTERP_SHARED_DATA).string() +
                                  "/bvh/NC_bandai1_walk_normal_001.bvh --loop -m c2 -q -o " + (out / "walk").string());
  EXPECT_EQ(walk.exit_code, 1);
  EXPECT_NE(walk.err.find("does not look like a cycle"), std::string::npos) << walk.err;
}

}  // namespace
}  // namespace rotinterp::render
