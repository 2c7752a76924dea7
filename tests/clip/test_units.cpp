// clip/units.h: unit names, the inference for files that state none, the parsers of
// physical quantities, and converting a clip to another unit.
#include "rotinterp/clip/clip.h"
#include "rotinterp/clip/units.h"

#include <gtest/gtest.h>

namespace rotinterp {
namespace {

// A standing figure `size` units tall: a root, a toe on the floor below it, a joint
// straight above, and an End Site on top.
Clip figure(double size) {
  Clip c;
  c.skeleton.joints.push_back({"Root", -1, Vec3(0, 0, 0), Quat::Identity()});
  c.skeleton.joints.push_back({"Toe", 0, Vec3(0, 0, 0), Quat::Identity()});
  c.skeleton.joints.push_back({"Head", 1, Vec3(0, 0.9 * size, 0), Quat::Identity()});
  c.skeleton.end_sites.push_back({2, Vec3(0, size / 10, 0), "EndSite_Head"});
  for (int j = 0; j < 3; ++j) {
    c.rotations.push_back({{0.0}, {Quat::Identity()}});
    c.translations.emplace_back();
  }
  return c;
}

TEST(Units, CommonUnitsParseByNameAndNumbersAsMetresPerUnit) {
  EXPECT_EQ(*parse_unit("cm"), 0.01);
  EXPECT_EQ(*parse_unit("in"), 0.0254);
  EXPECT_EQ(*parse_unit("ft"), 0.3048);
  EXPECT_EQ(*parse_unit("0.05644"), 0.05644);
  for (const char* bad : {"", "0", "-1", "inch", "nan", "1cm"}) EXPECT_FALSE(parse_unit(bad)) << bad;
  EXPECT_EQ(unit_name(0.01), "cm");
  EXPECT_EQ(unit_name(0.05644), "0.05644 m");
}

TEST(Units, LengthsTakeASuffixAndABareNumberIsMetres) {
  EXPECT_DOUBLE_EQ(*parse_length("3cm"), 0.03);
  EXPECT_DOUBLE_EQ(*parse_length("0.5mm"), 0.0005);
  EXPECT_DOUBLE_EQ(*parse_length("0.03m"), 0.03);
  EXPECT_DOUBLE_EQ(*parse_length("0.03"), 0.03);
  EXPECT_DOUBLE_EQ(*parse_length("2 in"), 0.0508);
  EXPECT_DOUBLE_EQ(*parse_signed_length("-2cm"), -0.02);
  for (const char* bad : {"0", "-1cm", "3 furlongs", "cm", "nan", "inf m"}) EXPECT_FALSE(parse_length(bad)) << bad;
  EXPECT_TRUE(parse_length("0", true));
}

TEST(Units, AnglesAreDegreesUnlessGivenInRadians) {
  EXPECT_DOUBLE_EQ(*parse_angle_deg("0.5deg"), 0.5);
  EXPECT_DOUBLE_EQ(*parse_angle_deg("0.5"), 0.5);
  EXPECT_NEAR(*parse_angle_deg("1rad"), 57.29577951308232, 1e-12);
  for (const char* bad : {"0deg", "-1", "1mm", "x"}) EXPECT_FALSE(parse_angle_deg(bad)) << bad;
  EXPECT_DOUBLE_EQ(*parse_speed("50cm/s"), 0.5);
  EXPECT_DOUBLE_EQ(*parse_speed("0.5"), 0.5);
  EXPECT_FALSE(parse_speed("0.5m"));
}

// Each common unit is found from a figure of plausible human size in it, and the
// reason says how big the figure was.
TEST(Units, AFigureOfHumanSizeInACommonUnitIsInferredAsThatUnit) {
  const struct {
    double size, unit;
  } cases[] = {{1.8, 1.0}, {180.0, 0.01}, {1750.0, 0.001}, {70.0, 0.0254}, {5.9, 0.3048}};
  for (const auto& c : cases) {
    const ClipUnit u = infer_unit(figure(c.size));
    EXPECT_EQ(u.origin, UnitOrigin::inferred) << c.size;
    EXPECT_EQ(u.metres_per_unit, c.unit) << c.size;
    EXPECT_NE(u.reason.find("units tall"), std::string::npos) << u.reason;
  }
}

TEST(Units, AFigureNoCommonUnitFitsIsScaledToTheAssumedHeightAndSaysSo) {
  const ClipUnit u = infer_unit(figure(26.0));  // CMU's BVH: 1/0.45 inch per unit
  EXPECT_EQ(u.origin, UnitOrigin::assumed);
  EXPECT_DOUBLE_EQ(u.metres_per_unit * 0.9 * 26.0, kAssumedFigureMetres);  // the joints: Toe to Head
  EXPECT_NE(u.reason.find("assumed"), std::string::npos);
  const ClipUnit point = infer_unit(figure(0.0));
  EXPECT_EQ(point.origin, UnitOrigin::assumed);
  EXPECT_EQ(point.metres_per_unit, 1.0);
}

// The skeleton at rest, not a pose: a clip whose first frames crouch (or a cut that
// starts there) is as tall as its skeleton, so every range of a clip gets its unit.
TEST(Units, TheFigureIsMeasuredAtRestSoEveryCutOfAClipHasItsUnit) {
  Clip c = figure(180.0);
  c.translations[2] = TranslationTrack{{0.0, 1.0}, {Vec3(0, 60, 0), Vec3(0, 162, 0)}};  // crouched, then up
  c.rotations[1] = RotationTrack{{0.0, 1.0}, {exp(RotVec(Vec3(1.2, 0, 0))), Quat::Identity()}};
  const ClipUnit whole = infer_unit(c);
  EXPECT_NEAR(rest_pose_size(c), 162.0, 1e-9);  // Toe to Head: End Sites are left out
  EXPECT_LT(first_pose_size(c), 100.0);  // the pose would have said inches
  EXPECT_EQ(whole.metres_per_unit, 0.01);
  EXPECT_NE(whole.reason.find("its offsets, a skeleton 162 units tall at rest"), std::string::npos) << whole.reason;
  // The cut from the second frame on: standing.
  c.translations[2] = TranslationTrack{{1.0}, {Vec3(0, 162, 0)}};
  c.rotations[1] = RotationTrack{{1.0}, {Quat::Identity()}};
  EXPECT_EQ(infer_unit(c).metres_per_unit, whole.metres_per_unit);
  EXPECT_EQ(infer_unit(c).reason, whole.reason);
}

// A root on the floor whose pelvis rests far from it (the Bandai clips' ground marker)
// is left out of the box; a skeleton whose joints' offsets are all zero is measured in
// its first pose.
TEST(Units, AGroundMarkerRootIsLeftOutAndZeroOffsetsFallBackToTheFirstPose) {
  Clip c = figure(180.0);
  c.skeleton.joints[1].offset = Vec3(4, 0, -430);  // the body, 4.3 m from the marker
  EXPECT_NEAR(rest_pose_size(c), 162.0, 1e-9);
  EXPECT_EQ(infer_unit(c).metres_per_unit, 0.01);

  Clip points = figure(0.0);
  points.translations[2] = TranslationTrack{{0.0}, {Vec3(0, 1.62, 0)}};
  points.skeleton.end_sites[0].offset = Vec3(0, 0.18, 0);
  EXPECT_EQ(rest_pose_size(points), 0.0);  // an End Site is no joint
  const ClipUnit u = infer_unit(points);
  EXPECT_EQ(u.metres_per_unit, 1.0);
  EXPECT_NE(u.reason.find("its first pose, a figure 1.8 units tall"), std::string::npos) << u.reason;
}

TEST(Units, ConvertingAClipKeepsItsSizeInMetres) {
  Clip c = figure(180.0);
  c.unit = {0.01, UnitOrigin::inferred, "inferred"};
  c.translations[1] = TranslationTrack{{0.0, 1.0}, {Vec3(1, 0, 2), Vec3(3, 91, 4)}};
  const double before = first_pose_size(c) * c.unit.metres_per_unit;
  convert_unit(c, 1.0, "--out-unit m");
  EXPECT_EQ(c.unit.metres_per_unit, 1.0);
  EXPECT_EQ(c.unit.origin, UnitOrigin::given);
  EXPECT_DOUBLE_EQ(first_pose_size(c), before);
  EXPECT_DOUBLE_EQ(c.translations[1]->keys[1].y(), 0.91);
  EXPECT_DOUBLE_EQ(c.skeleton.end_sites[0].offset.y(), 0.18);
}

}  // namespace
}  // namespace rotinterp
