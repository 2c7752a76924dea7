// The one track sampler (track/sample.h): keys where they lie, the shortest-arc slerp
// or the lerp between, held outside; what every reader and the frame grid rely on.
#include "rotinterp/track/sample.h"

#include "rotinterp/core/geodesic.h"
#include "rotinterp/core/rotation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace rotinterp {
namespace {

TEST(TrackSample, ATimeTakesAKeyWithinItsSnapElseTheSlerpOfItsNeighbours) {
  RotationTrack track;
  track.times = {0.0, 1.0 + 0.01, 3.0};  // the middle key a hundredth of a frame late
  track.keys = {Quat::Identity(), exp(RotVec(0.5, 0, 0)), exp(RotVec(1.5, 0, 0))};
  const std::vector<double> times = {-1.0, 0.0, 1.0, 2.0, 3.0, 4.0};
  std::vector<Quat> out(times.size());
  sample_rotations(track, times, 0.05, out.data());
  EXPECT_EQ(out[0].coeffs(), track.keys[0].coeffs());  // held before the first key
  EXPECT_EQ(out[1].coeffs(), track.keys[0].coeffs());
  EXPECT_EQ(out[2].coeffs(), track.keys[1].coeffs());  // the late key is frame 1's
  const Quat between = slerp(track.keys[1], track.keys[2], (2.0 - 1.01) / (3.0 - 1.01));
  EXPECT_EQ(out[3].coeffs(), between.coeffs());
  EXPECT_EQ(out[4].coeffs(), track.keys[2].coeffs());
  EXPECT_EQ(out[5].coeffs(), track.keys[2].coeffs());  // held after the last
  // With no snap the late key is not frame 1's: frame 1 lies between keys.
  sample_rotations(track, times, 0.0, out.data());
  EXPECT_NE(out[2].coeffs(), track.keys[1].coeffs());
}

TEST(TrackSample, BetweenKeysOfOppositeSignsTakesTheShortArc) {
  // Two keys 40° apart about X, the second stored with the other sign (a reader's
  // raw data before make_sign_continuous): halfway is 20°, not 160°.
  RotationTrack track;
  track.times = {0.0, 1.0};
  const Quat b = exp(RotVec(0.7, 0, 0));
  track.keys = {Quat::Identity(), Quat(-b.coeffs())};
  const Quat half = sample_rotation(track, 0.5);
  EXPECT_NEAR(angular_distance(half, exp(RotVec(0.35, 0, 0))), 0.0, 1e-12);
  EXPECT_NEAR(half.norm(), 1.0, 1e-15);
}

TEST(TrackSample, OneKeyIsHeldAtEveryTimeAndTranslationsAreLinear) {
  const RotationTrack still{{2.0}, {exp(RotVec(0, 0.3, 0))}};
  for (double t : {-5.0, 2.0, 9.0}) EXPECT_EQ(sample_rotation(still, t).coeffs(), still.keys[0].coeffs()) << t;
  const TranslationTrack root{{0.0, 0.5, 2.0}, {Vec3::Zero(), Vec3(1, 0, 0), Vec3(1, 3, 0)}};
  EXPECT_EQ(sample_translation(root, 0.25), Vec3(0.5, 0, 0));
  EXPECT_EQ(sample_translation(root, 1.25), Vec3(1, 1.5, 0));
  EXPECT_EQ(sample_translation(root, -1.0), Vec3::Zero());
  EXPECT_EQ(sample_translation(root, 3.0), Vec3(1, 3, 0));
  // The batch form at exact times gives what the one-time form gives.
  std::vector<Vec3> out(3);
  sample_translations(root, {0.25, 1.25, 3.0}, 0.0, out.data());
  EXPECT_EQ(out[0], sample_translation(root, 0.25));
  EXPECT_EQ(out[1], sample_translation(root, 1.25));
}

}  // namespace
}  // namespace rotinterp
