// Foot skating: feet found by the names of common rigs; contacts and sliding in
// real units over the clip's own frame times.
#include "rotinterp/eval/foot_skating.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace rotinterp {
namespace {

// Every joint a child of the first, or of the joint before it when `nested`.
Skeleton chain(const std::vector<std::string>& names, bool nested = false) {
  Skeleton s;
  for (std::size_t i = 0; i < names.size(); ++i) {
    Joint j;
    j.name = names[i];
    j.parent = i == 0 ? -1 : nested ? static_cast<int>(i) - 1 : 0;
    s.joints.push_back(j);
  }
  return s;
}

std::vector<std::string> feet_of(const std::vector<std::string>& names, bool nested = false) {
  const Skeleton s = chain(names, nested);
  std::vector<std::string> out;
  for (std::size_t j : find_feet(s)) out.push_back(s.joints[j].name);
  return out;
}

TEST(FootSkating, FeetOfCommonRigsAreFoundByNameToesFirst) {
  using V = std::vector<std::string>;
  // CMU
  EXPECT_EQ(feet_of({"Hips", "LeftUpLeg", "LeftLeg", "LeftFoot", "LeftToeBase", "RightFoot", "RightToeBase",
                     "LeftHand", "LThumb"}),
            (V{"LeftToeBase", "RightToeBase"}));
  // Mixamo: the toe, not its leaf marker
  EXPECT_EQ(feet_of({"mixamorig:Hips", "mixamorig:LeftFoot", "mixamorig:LeftToeBase", "mixamorig:LeftToe_End",
                     "mixamorig:RightFoot", "mixamorig:RightToeBase", "mixamorig:RightToe_End"}),
            (V{"mixamorig:LeftToeBase", "mixamorig:RightToeBase"}));
  // Bandai Namco, and the assimp boxing clip (ankles and toes)
  EXPECT_EQ(feet_of({"Hips", "Foot_L", "Toes_L", "Foot_R", "Toes_R"}), (V{"Toes_L", "Toes_R"}));
  EXPECT_EQ(feet_of({"Hips", "LeftAnkle", "LeftToes", "RightAnkle", "RightToes"}), (V{"LeftToes", "RightToes"}));
  // Blender (Rigify-style) and l_/r_ prefixes; a rig with feet but no toes
  EXPECT_EQ(feet_of({"root", "foot.L", "toe.L", "foot.R", "toe.R"}), (V{"toe.L", "toe.R"}));
  EXPECT_EQ(feet_of({"pelvis", "l_foot", "r_foot"}), (V{"l_foot", "r_foot"}));
  // A Maya rig's controls beside its bones (kenney character), IK helpers only (an Xbox avatar)
  EXPECT_EQ(feet_of({"Hips", "LeftFootCtrl", "LeftFootIK", "LeftToeRoll", "LeftFootRollCtrl", "LeftFoot", "LeftToes",
                     "LeftToes_end", "RightFootCtrl", "RightToeRoll", "RightFoot", "RightToes"}),
            (V{"LeftToes", "RightToes"}));
  EXPECT_TRUE(feet_of({"root", "lf_toe_ik", "lf_toe_pivot", "rt_toe_pivot_snapper", "LF_Leg_IK__MotionFootLeft"}).empty());
  // IK targets named like feet near the root, the foot bones at the end of the legs (DigitalRune's marine)
  EXPECT_EQ(feet_of({"Root", "L_TOE", "R_TOE", "Spine", "L_Thigh", "L_Ankle", "L_FootBall", "L_FootToe"}, true),
            (V{"L_FootToe", "R_TOE"}));
  // No feet: a box chain, an arm, fingers
  EXPECT_TRUE(feet_of({"pCube1", "pCube2", "pCube3"}).empty());
  EXPECT_TRUE(feet_of({"Shoulder", "LeftHandIndex1", "LeftHandThumb1"}).empty());
}

TEST(FootSkating, FeetByNameNameTheMissingJoint) {
  const Skeleton s = chain({"Hips", "A", "B"});
  auto ok = feet_by_name(s, {"B", "A", "B"});
  ASSERT_TRUE(ok.ok());
  EXPECT_EQ(*ok, (std::vector<std::size_t>{2, 1}));
  auto bad = feet_by_name(s, {"A", "Toe"});
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().find("'Toe'"), std::string::npos);
}

// A foot at height `y` (metres above the floor at 0) moving along x at `speed` m/s,
// sampled at `fps` for one second, in units of `metres_per_unit`.
FootContact slide(double y, double speed, double fps, double metres_per_unit = 1.0) {
  std::vector<Vec3> p;
  std::vector<double> t;
  for (int k = 0; k <= static_cast<int>(fps); ++k) {
    t.push_back(k / fps);
    p.push_back(Vec3(speed * t.back(), y, 0.3) / metres_per_unit);
  }
  return foot_contact(p.data(), t.data(), p.size(), 0.0, metres_per_unit, FootContactOptions{});
}

TEST(FootSkating, AFootSlidesOnlyInContactAndFasterThanTheThreshold) {
  const FootContact fast = slide(0.01, 1.0, 30);
  EXPECT_EQ(fast.contact, 30u);
  EXPECT_EQ(fast.skating, 30u);
  EXPECT_NEAR(fast.mean_speed(), 1.0, 1e-12);
  const FootContact slow = slide(0.01, 0.2, 30);
  EXPECT_EQ(slow.contact, 30u);
  EXPECT_EQ(slow.skating, 0u);
  EXPECT_NEAR(slow.mean_speed(), 0.2, 1e-12);
  const FootContact lifted = slide(0.06, 1.0, 30);  // above the 5 cm contact height
  EXPECT_EQ(lifted.contact, 0u);
  EXPECT_EQ(lifted.skating, 0u);
  EXPECT_EQ(lifted.mean_speed(), 0.0);
}

TEST(FootSkating, ThresholdsAreRealUnitsAtAnyFrameRateAndClipUnit) {
  // The same motion at 20, 30 and 120 fps, in metres or centimetres: the same speed
  // and the same share of intervals sliding (a per-frame threshold fixed at 20 fps
  // would call the 120 fps slide six times slower).
  for (double fps : {20.0, 30.0, 120.0})
    for (double unit : {1.0, 0.01}) {
      const FootContact c = slide(0.02, 0.6, fps, unit);
      EXPECT_EQ(c.contact, static_cast<std::size_t>(fps)) << fps << " " << unit;
      EXPECT_EQ(c.skating, c.contact) << fps << " " << unit;
      EXPECT_NEAR(c.mean_speed(), 0.6, 1e-9) << fps << " " << unit;
    }
  // Zero-length intervals (repeated times) are skipped, never divided by.
  const Vec3 p[3] = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0)};
  const double t[3] = {0.0, 0.0, 0.1};
  const FootContact c = foot_contact(p, t, 3, 0.0, 1.0, FootContactOptions{});
  EXPECT_EQ(c.contact, 1u);
  EXPECT_NEAR(c.mean_speed(), 10.0, 1e-12);
}

}  // namespace
}  // namespace rotinterp
