// clip/frames.h: the one definition of a clip's frames, the source's motion at
// them, the key frames and the bone axes, shared by eval, render and resample.
#include "rotinterp/clip/frames.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace rotinterp;

namespace {

Clip two_joint_clip(std::size_t frames, double frame_time) {
  Clip clip;
  clip.frame_time = frame_time;
  clip.skeleton.joints = {Joint{"root", -1, Vec3::Zero(), Quat::Identity()},
                          Joint{"arm", 0, Vec3(0, 1, 0), Quat::Identity()}};
  clip.rotations.resize(2);
  clip.translations.resize(2);
  for (std::size_t k = 0; k < frames; ++k) {
    const double t = static_cast<double>(k) * frame_time;
    clip.rotations[0].times.push_back(t);
    clip.rotations[0].keys.push_back(exp(RotVec(0, 0.1 * static_cast<double>(k), 0)));
  }
  clip.rotations[1] = RotationTrack{{0.0}, {Quat::Identity()}};
  return clip;
}

TEST(Frames, KeepEveryAlwaysKeepsTheLastFrame) {
  EXPECT_EQ(keep_every_indices(10, 4), (std::vector<std::size_t>{0, 4, 8, 9}));
  EXPECT_EQ(keep_every_indices(9, 4), (std::vector<std::size_t>{0, 4, 8}));
  EXPECT_EQ(keep_every_indices(3, 1), (std::vector<std::size_t>{0, 1, 2}));
  EXPECT_EQ(keep_every_indices(1, 8), (std::vector<std::size_t>{0}));
  EXPECT_EQ(keep_every_indices(5, 100), (std::vector<std::size_t>{0, 4}));
  EXPECT_EQ(keep_every_indices(4, 0), (std::vector<std::size_t>{0, 1, 2, 3}));
  EXPECT_TRUE(keep_every_indices(0, 3).empty());
}

TEST(Frames, AClipWithAFrameTimeHasItsFramesOnTheReadersTimelineAndAnExactRate) {
  const Clip clip = two_joint_clip(2752, 0.0083333);  // CMU: 120 Hz printed to 7 decimals
  const FrameGrid g = frame_grid(clip);
  ASSERT_EQ(g.size(), 2752u);
  ASSERT_TRUE(g.rate.has_value());
  EXPECT_EQ(*g.rate, (Rate{120, 1}));
  EXPECT_EQ(g.times[100], 100 * 0.0083333);  // what the reader gave, bit for bit
  EXPECT_EQ(g.times.back(), clip.end_time());
  EXPECT_EQ(g.exact_time(120), 1.0);         // the exact grid, for other rates
  // Each frame is found again from its own time and from the exact grid's.
  for (std::size_t k : {0u, 1u, 1000u, 2751u}) {
    EXPECT_EQ(g.frame_at(g.times[k]), k);
    EXPECT_EQ(g.frame_at(g.exact_time(k)), k);
  }
  EXPECT_FALSE(g.frame_at(g.times[10] + 0.5 * 0.0083333).has_value());  // between frames
}

TEST(Frames, KeysOnNoGridMakeTheLongestTracksTimesTheFrames) {
  Clip clip = two_joint_clip(5, 0.0);
  clip.rotations[0].times = {0.0, 0.3, 0.35, 1.0, 2.5};  // sparse, uneven keys
  const FrameGrid g = frame_grid(clip);
  EXPECT_EQ(g.times, clip.rotations[0].times);
  EXPECT_FALSE(g.rate.has_value());
  EXPECT_EQ(g.exact_time(3), 1.0);
}

TEST(Frames, DenseClipAndDecimationTakeTheKeysAtTheKeptFrames) {
  Clip clip = two_joint_clip(10, 0.1);
  clip.translations[0] = TranslationTrack{{0.0, 0.9}, {Vec3::Zero(), Vec3(9, 0, 0)}};
  const DenseClip d = dense_clip(clip);
  ASSERT_EQ(d.rotation.size(), 2u);
  ASSERT_EQ(d.rotation[0].size(), 10u);
  EXPECT_EQ(d.rotation[0][7].coeffs(), clip.rotations[0].keys[7].coeffs());
  EXPECT_EQ(d.rotation[1][7].coeffs(), Quat::Identity().coeffs());  // one key: held
  EXPECT_NEAR(d.translation[0][3].x(), 3.0, 1e-12);                // linear between keys
  EXPECT_EQ(d.translation[1][3], Vec3(0, 1, 0));                      // no track: the rest offset
  const RotationTrack keys = decimated_track(d.grid.times, d.rotation[0], keep_every_indices(10, 4));
  EXPECT_EQ(keys.times, (std::vector<double>{d.grid.times[0], d.grid.times[4], d.grid.times[8], d.grid.times[9]}));
  EXPECT_EQ(keys.keys[2].coeffs(), clip.rotations[0].keys[8].coeffs());
}

}  // namespace
