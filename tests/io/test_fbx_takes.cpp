// FBX 6.1 read by our own reader (assimp 5.2.5 refuses it): the takes' curves
// equal their 7.5 twins', the clip built from them equals the 7.5 twin's clip
// replayed from its curves, and malformed 6.1 key lists are refused in one line
// naming the file and the node.
#include "io_test_util.h"
#include "rotinterp/io/fbx/fbx_curve_eval.h"
#include "rotinterp/io/fbx/fbx_curves.h"
#include "rotinterp/io/fbx/fbx_nodes.h"
#include "rotinterp/io/fbx/fbx_source.h"
#include "rotinterp/io/source_motion.h"
#include "rotinterp/io/read.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace rotinterp {
namespace {

constexpr double kDegreesPerRadian = 180.0 / kPi;

FbxAnimation read_animation(const std::string& relative) {
  return test::read_fbx_curves((test::kData / relative).string());
}

const FbxCurve* curve_of(const FbxAnimation& anim, const std::string& node, const std::string& property, char channel) {
  for (const FbxCurve& c : anim.takes.at(0).curves)
    if (c.node == node && c.property == property && c.channel == channel) return &c;
  return nullptr;
}

TEST(Fbx61, TheInterpolationModesTwinSamplesAsThe75FileWithin1e4OfTheRange) {
  const FbxAnimation old = read_animation("curves/ufbx_maya_interpolation_modes_6100_binary.fbx");
  const FbxAnimation now = read_animation("fbx/ufbx_maya_interpolation_modes_7500_ascii.fbx");
  ASSERT_EQ(old.version, 6100u);
  ASSERT_EQ(old.takes.size(), 1u);
  EXPECT_EQ(old.takes[0].start, now.takes.at(0).start);
  EXPECT_EQ(old.takes[0].stop, now.takes.at(0).stop);
  const FbxCurve* a = curve_of(old, "pCube1", "Lcl Translation", 'X');
  const FbxCurve* b = curve_of(now, "pCube1", "Lcl Translation", 'X');
  ASSERT_TRUE(a && b);
  ASSERT_EQ(a->keys.size(), b->keys.size());
  for (std::size_t k = 0; k < a->keys.size(); ++k) {
    EXPECT_EQ(a->keys[k].ticks, b->keys[k].ticks) << k;
    EXPECT_EQ(a->keys[k].interpolation, b->keys[k].interpolation) << k;
    EXPECT_EQ(a->keys[k].tangent, b->keys[k].tangent) << k;
  }
  const std::vector<double> sa = sample_fbx_curve(*a, 24.0, old.takes[0].stop);
  const std::vector<double> sb = sample_fbx_curve(*b, 24.0, now.takes[0].stop);
  ASSERT_EQ(sa.size(), sb.size());
  const auto [lo, hi] = std::minmax_element(sb.begin(), sb.end());
  double worst = 0.0;
  for (std::size_t i = 0; i < sa.size(); ++i) worst = std::max(worst, std::abs(sa[i] - sb[i]));
  std::printf("6.1 against 7.5: %zu samples, worst difference %.3g (range %.3g)\n", sa.size(), worst, *hi - *lo);
  EXPECT_LE(worst, 1e-4 * (*hi - *lo));
}

// The 6.1 sausage has the 7.5 sausage's skeleton and curves: its clip (built by
// our reader) equals the 7.5 clip (assimp's) with its rotations replayed from the
// curves.
TEST(Fbx61, TheSausageClipEqualsThe75TwinReplayedFromItsCurves) {
  const auto old_path = test::kData / "fbx/ufbx_maya_game_sausage_6100_binary_wiggle.fbx";
  Result<Clip> old = read_clip(old_path);
  ASSERT_TRUE(old.ok()) << old.error();
  auto now = read_source_clip(test::kData / "fbx/ufbx_maya_game_sausage_7500_binary_wiggle.fbx", {});
  ASSERT_TRUE(now.ok()) << now.error();
  Clip replayed = now->clip;
  ASSERT_TRUE(replay_fbx_rotations(replayed, *now, {}, "sausage 7.5").ok());
  ASSERT_EQ(old->skeleton.joints.size(), replayed.skeleton.joints.size());
  EXPECT_EQ(old->name, "wiggle");
  EXPECT_DOUBLE_EQ(old->frame_time, replayed.frame_time);
  EXPECT_DOUBLE_EQ(old->unit.metres_per_unit, replayed.unit.metres_per_unit);
  double worst_degrees = 0.0, worst_offset = 0.0;
  for (std::size_t j = 0; j < replayed.skeleton.joints.size(); ++j) {
    const Joint& a = old->skeleton.joints[j];
    const Joint& b = replayed.skeleton.joints[j];
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.parent, b.parent) << a.name;
    worst_offset = std::max(worst_offset, (a.offset - b.offset).norm());
    ASSERT_EQ(old->rotations[j].times.size(), replayed.rotations[j].times.size()) << a.name;
    for (std::size_t k = 0; k < replayed.rotations[j].times.size(); ++k) {
      EXPECT_NEAR(old->rotations[j].times[k], replayed.rotations[j].times[k], 1e-9);
      worst_degrees = std::max(
          worst_degrees, old->rotations[j].keys[k].angularDistance(replayed.rotations[j].keys[k]) * kDegreesPerRadian);
    }
  }
  std::printf("sausage 6.1 against 7.5 replayed: worst rotation %.3g°, worst offset %.3g cm\n", worst_degrees,
              worst_offset);
  EXPECT_LT(worst_degrees, 1e-5);  // float keys in both files
  EXPECT_LT(worst_offset, 1e-5);
}

// A 6.1 ASCII file whose one key list is `keys` with KeyCount `count`.
std::string take_with_keys(const std::string& count, const std::string& keys) {
  return R"(; FBX 6.1.0 project file
FBXHeaderExtension:  {
	FBXVersion: 6100
}
Objects:  {
	Model: "Model::arm", "LimbNode" {
		Properties60:  {
			Property: "PreRotation", "Vector3D", "",0,0,90
		}
	}
}
Takes:  {
	Take: "run" {
		LocalTime: 0,46186158000
		Model: "Model::arm" {
			Channel: "Transform" {
				Channel: "R" {
					Channel: "Z" {
						Default: 0
						KeyCount: )" +
         count + R"(
						Key: )" +
         keys + R"(
					}
				}
			}
		}
	}
}
)";
}

std::string read_error(const std::string& text) {
  auto doc = parse_fbx_ascii(text, "hostile.fbx");
  if (!doc.ok()) return doc.error();
  auto anim = read_fbx_animation(*doc, "hostile.fbx");
  return anim.ok() ? "" : anim.error();
}

TEST(Fbx61, AWellFormedKeyListIsReadWithItsLettersDecoded) {
  auto doc = parse_fbx_ascii(take_with_keys("2", "0,0,U,s,0,1.5,a,0.25,0.5,46186158000,90,C,n"), "ok.fbx");
  ASSERT_TRUE(doc.ok()) << doc.error();
  auto anim = read_fbx_animation(*doc, "ok.fbx");
  ASSERT_TRUE(anim.ok()) << anim.error();
  ASSERT_EQ(anim->takes.size(), 1u);
  const FbxCurve& c = anim->takes[0].curves.at(0);
  EXPECT_EQ(c.node, "arm");
  EXPECT_EQ(c.property, "Lcl Rotation");
  EXPECT_EQ(c.channel, 'Z');
  ASSERT_EQ(c.keys.size(), 2u);
  EXPECT_EQ(c.keys[0].interpolation, FbxInterpolation::cubic);
  EXPECT_EQ(c.keys[0].tangent, FbxTangent::user);
  EXPECT_DOUBLE_EQ(c.keys[0].next_left_slope, 1.5);
  EXPECT_DOUBLE_EQ(c.keys[0].right_weight, 0.25);
  EXPECT_DOUBLE_EQ(c.keys[0].next_left_weight, 0.5);
  EXPECT_EQ(c.keys[1].interpolation, FbxInterpolation::constant_next);
  EXPECT_EQ(anim->models.at(0).pre_rotation[2], 90.0);
}

TEST(Fbx61, HostileKeyListsAreRefusedInOneLineNamingTheFileAndTheNode) {
  const std::string node = "hostile.fbx: FBX node Takes/Take 'run'/Model 'arm'/Channel Transform/R/Z/Key: ";
  const struct {
    const char* count;
    const char* keys;
    const char* says;
  } cases[] = {
      {"1000000000", "0,0,L,46186158000,90,L", "KeyCount 1000000000 is past the end of its 6 values"},
      {"-1", "0,0,L", "KeyCount -1 is past the end"},
      {"2", "0,0,L,46186158000", "KeyCount 2 is past the end of its 4 values"},
      {"2", "0,0,U,s,0,0,n,46186158000", "key 1 of 2: no time and finite value"},
      {"2", "0,0,U,s,0,0,n,46186158000,90", "key 1 of 2: no interpolation letter"},
      {"2", "0,0,U,s,0,n,46186158000,90,L", "key 0 of 2: a cubic key without its two slopes"},
      {"1", "0,0,U,s,0,0,a,0.3", "key 0 of 1: a weighted key without its weight"},
      {"2", "0,0,Q,46186158000,90,L", "key 0 of 2: unknown interpolation 'Q'"},
      {"2", "0,0,U,z,46186158000,90,L", "key 0 of 2: unknown tangent mode 'z'"},
      {"2", "46186158000,0,L,0,90,L", "key 1: its time 0 is before key 0's 4.6186158e+10 (times must increase)"},
      {"1", "0,0,L,46186158000,90,L", "values after the last of its 1 keys"},
  };
  for (const auto& c : cases) {
    const std::string error = read_error(take_with_keys(c.count, c.keys));
    EXPECT_EQ(error.rfind(node, 0), 0u) << error;
    EXPECT_NE(error.find(c.says), std::string::npos) << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
  }
}

TEST(Fbx61, AKeyListWithoutKeyCountIsRefused) {
  std::string text = take_with_keys("2", "0,0,L,46186158000,90,L");
  text.erase(text.find("KeyCount: 2"), std::string("KeyCount: 2").size());
  EXPECT_NE(read_error(text).find("a Key list without its KeyCount"), std::string::npos) << read_error(text);
}

}  // namespace
}  // namespace rotinterp
