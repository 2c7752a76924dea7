// The later passes of a hierarchical run (remeasure.cpp) and the local insertion (select_local.cpp)
// on a real clip: the same keys, values and errors as measuring every frame again, for every method.
#include "reducer.h"

#include "rotinterp/interp/interpolator.h"
#include "rotinterp/io/read.h"
#include "rotinterp/reduce/reduce.h"

#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <vector>

namespace rotinterp::detail {
namespace {

const std::string kWalk = std::string(ROTINTERP_SHARED_DATA) + "/bvh/NC_bandai1_walk_normal_001.bvh";

struct Selection {
  ReduceResult result;
  std::size_t frames_measured = 0;
};

Selection reduce_with(const Clip& clip, const ReduceOptions& o, bool everything) {
  std::vector<ReduceBudget> budgets(clip.skeleton.joints.size(), o.budget);
  for (ReduceBudget& b : budgets) b.translation = translation_tolerance(b);
  Reducer reducer(clip, o, budgets, std::nullopt);
  if (everything) reducer.measure_everything();
  auto r = reducer.run();
  EXPECT_TRUE(r) << r.error();
  return {r ? std::move(*r) : ReduceResult{}, reducer.frames_measured()};
}

TEST(Remeasure, LaterPassesKeepTheKeysOfMeasuringEveryFrameAgainAndMeasureFarFewerFrames) {
  auto clip = read_clip(kWalk);
  ASSERT_TRUE(clip) << clip.error();
  for (const MethodInfo& m : methods()) {
    ReduceOptions o;
    o.method = m.name;
    o.budget.shell = 0.1;  // 1 mm at 10 cm, in centimetres
    o.budget.translation = 0.1;
    o.shell_distance = 10;
    const Selection all = reduce_with(*clip, o, true), moved = reduce_with(*clip, o, false);
    ASSERT_EQ(all.result.joints.size(), moved.result.joints.size());
    for (std::size_t j = 0; j < all.result.joints.size(); ++j) {
      const ReducedJoint &a = all.result.joints[j], &b = moved.result.joints[j];
      EXPECT_EQ(a.rotation_frames, b.rotation_frames) << m.name << " joint " << j;
      EXPECT_EQ(a.translation_frames, b.translation_frames) << m.name << " joint " << j;
      EXPECT_EQ(a.max_rotation_error, b.max_rotation_error) << m.name << " joint " << j;
      EXPECT_EQ(a.max_shell_error, b.max_shell_error) << m.name << " joint " << j;
      const auto &ka = all.result.reduced.rotations[j].keys, &kb = moved.result.reduced.rotations[j].keys;
      ASSERT_EQ(ka.size(), kb.size());
      for (std::size_t k = 0; k < ka.size(); ++k) EXPECT_EQ(ka[k].coeffs(), kb[k].coeffs()) << m.name << " joint " << j;
    }
    // The walk needs passes after the first (frames passed up to ancestors); each
    // measures only what moved, and local methods check a new key only where it moves
    // (measured: 0.55–0.58 of the frames for slerp, nlerp, clamped and gltf-cubic; 0.83 for bf).
    EXPECT_LT(moved.frames_measured, all.frames_measured * (m.support > 0 ? 0.65 : 0.9))
        << m.name << ": " << moved.frames_measured << " of " << all.frames_measured;
  }
}

}  // namespace
}  // namespace rotinterp::detail
