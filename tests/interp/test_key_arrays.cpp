// Keys as flat (K, J, 4) arrays (interp/key_arrays.h): what the Python module's
// interpolate runs, here where the sanitizers run it. J = 0 reads no key and writes
// nothing; J = 1 and J > 1 give each joint's own curve, in either layout and from
// float32 as from float64 components.
#include "support.h"

#include "rotinterp/interp/key_arrays.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace rotinterp {
namespace {

using test::random_track;

// Tracks of `joints` joints at one set of times, flattened to (K, J, 4), scaled by
// 3 so that unit_quat has work to do.
template <class Component>
std::vector<Component> flat_keys(const std::vector<RotationTrack>& tracks, bool scalar_first) {
  const std::size_t k = tracks.front().times.size(), joints = tracks.size();
  std::vector<Component> flat(k * joints * 4);
  for (std::size_t i = 0; i < k; ++i)
    for (std::size_t j = 0; j < joints; ++j) {
      double q[4];
      put_quat(tracks[j].keys[i], q, scalar_first);
      for (int c = 0; c < 4; ++c)
        flat[4 * (i * joints + j) + static_cast<std::size_t>(c)] = static_cast<Component>(3.0 * q[c]);
    }
  return flat;
}

std::vector<RotationTrack> tracks_on_one_grid(std::size_t joints) {
  std::vector<RotationTrack> tracks;
  for (std::size_t j = 0; j < joints; ++j) {
    RotationTrack t = random_track(40 + j, 12, 0.6, 0.1, 0.3);
    if (j > 0) t.times = tracks.front().times;  // one grid for every joint
    tracks.push_back(t);
  }
  return tracks;
}

TEST(KeyArrays, ZeroJointsReadNoKeyAndWriteNothing) {
  const std::vector<double> times = {0.0, 1.0, 2.0};
  const std::vector<double> no_quats;  // a (3, 0, 4) array holds no component
  const std::vector<double> at = {0.5, 1.5};
  std::vector<double> out(at.size() * 4, 7.0);  // room for a (2, 4) answer, which J = 0 must not write
  for (const char* method : {"slerp", "c2"}) {
    const Status s = interpolate_key_arrays(KeyArrays<double>{times.data(), no_quats.data(), times.size(), 0, false},
                                            at.data(), at.size(), KeyArraysCurve{method}, out.data());
    EXPECT_TRUE(s) << method << ": " << s.error();
    for (double v : out) EXPECT_EQ(v, 7.0) << method;
  }
}

template <class Component>
void expect_each_joint_its_own_curve(const char* method, std::size_t joints, bool in_first, bool out_first) {
  const std::vector<RotationTrack> tracks = tracks_on_one_grid(joints);
  const std::vector<Component> flat = flat_keys<Component>(tracks, in_first);
  const std::vector<double>& times = tracks.front().times;
  std::vector<double> at;
  for (int i = 0; i <= 100; ++i) at.push_back(times.front() - 0.1 + (times.back() - times.front() + 0.2) * i / 100.0);
  std::vector<double> out(at.size() * joints * 4);
  const Status s =
      interpolate_key_arrays(KeyArrays<Component>{times.data(), flat.data(), times.size(), joints, in_first}, at.data(),
                             at.size(), KeyArraysCurve{method, false, out_first}, out.data());
  ASSERT_TRUE(s) << s.error();
  const double tolerance = sizeof(Component) == 4 ? 1e-6 : 1e-12;  // float32 keys are rounded
  for (std::size_t j = 0; j < joints; ++j) {
    const auto curve = make_interpolator(method, tracks[j]);
    ASSERT_TRUE(curve) << curve.error();
    for (std::size_t i = 0; i < at.size(); ++i)
      EXPECT_LT(angular_distance(quat_at(&out[4 * (i * joints + j)], out_first), (*curve)->evaluate(at[i])), tolerance)
          << method << " joint " << j << " of " << joints << " at " << at[i];
  }
}

TEST(KeyArrays, EveryJointGetsTheCurveOfItsOwnKeysInEitherLayout) {
  for (const char* method : {"slerp", "c2", "clamped"})  // slerp's joints are built together, the others one by one
    for (std::size_t joints : {1, 3, 11}) {  // 11: the one-by-one methods gather keys 8 joints a pass
      expect_each_joint_its_own_curve<double>(method, joints, false, false);
      expect_each_joint_its_own_curve<double>(method, joints, true, false);
      expect_each_joint_its_own_curve<double>(method, joints, false, true);
      expect_each_joint_its_own_curve<float>(method, joints, false, false);
    }
}

TEST(KeyArrays, AZeroKeyIsNamedByJointAndKey) {
  // Joint 2 of 3, and joint 9 of 11 (the second gather pass of the one-by-one methods):
  // the first bad joint is named, though a later one is bad too.
  for (const char* method : {"c2", "slerp"})
    for (const auto& [joints, bad] : {std::pair<std::size_t, std::size_t>{3, 2}, {11, 9}}) {
      std::vector<RotationTrack> tracks = tracks_on_one_grid(joints);
      std::vector<double> flat = flat_keys<double>(tracks, false);
      for (std::size_t c = 0; c < 4; ++c) {  // key 5 of `bad`; key 7 of the last joint, a later one
        flat[4 * (5 * joints + bad) + c] = 0.0;
        flat[4 * (7 * joints + joints - 1) + c] = std::numeric_limits<double>::quiet_NaN();
      }
      const double at = 0.5;
      std::vector<double> out(joints * 4);
      const Status s = interpolate_key_arrays(KeyArrays<double>{tracks[0].times.data(), flat.data(), 12, joints, false},
                                              &at, 1, KeyArraysCurve{method}, out.data());
      ASSERT_FALSE(s);
      EXPECT_EQ(s.error(), "joint " + std::to_string(bad) + ", key 5 is not a finite non-zero quaternion") << method;
    }
}

TEST(KeyArrays, ATrackTheMethodRefusesIsNamedByItsJointWhereThereAreSeveral) {
  const std::vector<double> times = {0.0, 2.0, 1.0};  // not increasing
  const std::vector<double> flat(3 * 2 * 4, 0.5);
  const double at = 0.5;
  std::vector<double> out(2 * 4);
  const Status two = interpolate_key_arrays(KeyArrays<double>{times.data(), flat.data(), 3, 2, false}, &at, 1,
                                            KeyArraysCurve{"slerp"}, out.data());
  ASSERT_FALSE(two);
  EXPECT_EQ(two.error().rfind("joint 0: ", 0), 0u) << two.error();
  const Status one = interpolate_key_arrays(KeyArrays<double>{times.data(), flat.data(), 3, 1, false}, &at, 1,
                                            KeyArraysCurve{"slerp"}, out.data());
  ASSERT_FALSE(one);
  EXPECT_EQ(one.error().find("joint"), std::string::npos) << one.error();
}

}  // namespace
}  // namespace rotinterp
