// Render's panel titles and eval's errors.csv measure the same thing: both take
// the clip's frames, the reference at each frame and the key frames from
// clip/frames.h, so for the same clip, method and spacing their errors agree.
#include "synthetic_clip.h"

#include "rotinterp/eval/evaluate_clip.h"
#include "rotinterp/render/comparison.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace rotinterp::render {
namespace {

// Key times off the frame grid by a thousandth of a frame, as float32 times are on
// long clips: the frames must still take the keys, in eval and render alike.
Clip jittered_clip() {
  Clip clip = test::synthetic_clip(61, 30.0);
  for (RotationTrack& track : clip.rotations)
    for (std::size_t k = 1; k + 1 < track.times.size(); ++k) track.times[k] += (k % 2 ? 1e-3 : -1e-3) * clip.frame_time;
  return clip;
}

TEST(FramesAgree, RenderPerFrameErrorsAndEvalPerJointErrorsDescribeTheSameSamples) {
  const Clip clip = jittered_clip();
  for (const char* method : {"slerp", "c2", "clamped", "bf"}) {
    SCOPED_TRACE(method);
    ClipEvalOptions options;
    options.methods = {method};
    options.keep_every = {4};
    auto rows = evaluate_clip(clip, "jittered", options);
    ASSERT_TRUE(rows.ok()) << rows.error();
    auto frames = comparison_errors(clip, method, 4);
    ASSERT_TRUE(frames.ok()) << frames.error();
    ASSERT_EQ(frames->size(), 61u);

    // Every joint is animated, so render's mean over joints and eval's mean over
    // frames are two orders of one double sum; the largest errors are one sample.
    double eval_mean = 0.0, eval_max = 0.0, render_mean = 0.0, render_max = 0.0;
    std::size_t joints = 0;
    for (const ErrorRow& r : *rows) {
      if (r.end_site) continue;
      ASSERT_EQ(r.frames, 61u);
      eval_mean += r.mean_deg;
      eval_max = std::max(eval_max, r.max_deg);
      ++joints;
    }
    eval_mean /= static_cast<double>(joints);
    for (const FrameError& e : *frames) {
      render_mean += e.mean;
      render_max = std::max(render_max, e.max);
    }
    render_mean /= static_cast<double>(frames->size());
    EXPECT_GT(eval_max, 0.1);  // the methods do err between keys
    EXPECT_NEAR(render_mean, eval_mean, 1e-12 * eval_max);
    EXPECT_NEAR(render_max, eval_max, 1e-12 * eval_max);
    // At the key frames the rebuilt pose is the key itself.
    for (std::size_t k = 0; k < 61; k += 4) EXPECT_LT((*frames)[k].max, 1e-9) << "frame " << k;
  }
}

}  // namespace
}  // namespace rotinterp::render
