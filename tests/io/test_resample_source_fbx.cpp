// resample --method source -o OUT.fbx without --fps (io/fbx/fbx_source.h
// encode_source_fbx): the written file holds the source's own curves — every key's
// time, value, interpolation, tangent mode, slopes and weights — for each joint, so
// that our reader replays exactly what the DCC keyed; assimp still reads it.
#include "io_test_util.h"
#include "rotinterp/io/fbx/fbx_curves.h"
#include "rotinterp/io/read.h"
#include "support/run_cli.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace rotinterp {
namespace {

FbxTake first_take(const std::filesystem::path& path) {
  auto anim = read_fbx_curves_file(path.string(), path.string());
  EXPECT_TRUE(anim.ok()) << anim.error();
  return anim && !anim->takes.empty() ? anim->takes.front() : FbxTake{};
}

const FbxCurve* find_curve(const FbxTake& take, const FbxCurve& like) {
  for (const FbxCurve& c : take.curves)
    if (c.node == like.node && c.property == like.property && c.channel == like.channel && c.layer == like.layer) return &c;
  return nullptr;
}

bool same_float(double a, double b) { return static_cast<float>(a) == static_cast<float>(b); }

// Maya-keyed (spline and user tangents) and DigitalRune files: each joint's rotation
// curves, and its translation curves where the sausage has them, come back key for key.
TEST(ResampleSourceFbx, TheSourcesCurvesComeBackKeyForKeyWithTheirTangents) {
  const struct {
    const char* file;
    bool translations;  // every joint's translation curves come back too
  } cases[] = {{"fbx/ufbx_maya_game_sausage_7500_binary_wiggle.fbx", true}, {"fbx/digitalrune_Marine_Run.fbx", false}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c.file);
    const test::TempDir dir;
    const auto in = test::kData / c.file, out = dir / "back.fbx";
    const test::CliResult r = test::run_cli("resample '" + in.string() + "' -o '" + out.string() + "' -m source");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("written back as stored"), std::string::npos) << r.out;
    auto clip = read_clip(in);
    ASSERT_TRUE(clip.ok()) << clip.error();
    std::set<std::string> joints;
    for (const Joint& j : clip->skeleton.joints) joints.insert(j.name);
    const FbxTake source = first_take(in), written = first_take(out);
    std::size_t rotation_curves = 0, keys = 0;
    for (const FbxCurve& s : source.curves) {
      if (!joints.count(s.node) || s.property == "Lcl Scaling") continue;
      if (s.property == "Lcl Translation" && !c.translations) continue;
      SCOPED_TRACE(s.node + "/" + s.property + "/" + s.channel);
      const FbxCurve* w = find_curve(written, s);
      ASSERT_NE(w, nullptr);
      ASSERT_EQ(w->keys.size(), s.keys.size());
      rotation_curves += s.property == "Lcl Rotation";
      for (std::size_t k = 0; k < s.keys.size(); ++k) {
        const FbxKey &a = s.keys[k], &b = w->keys[k];
        EXPECT_EQ(b.ticks, a.ticks);
        EXPECT_TRUE(same_float(b.value, a.value)) << b.value << " " << a.value;
        EXPECT_EQ(b.flags, a.flags);
        EXPECT_EQ(b.interpolation, a.interpolation);
        EXPECT_EQ(b.tangent, a.tangent);
        EXPECT_TRUE(same_float(b.right_slope, a.right_slope)) << b.right_slope << " " << a.right_slope;
        EXPECT_TRUE(same_float(b.next_left_slope, a.next_left_slope));
        EXPECT_NEAR(b.right_weight, a.right_weight, 1e-4);
        EXPECT_NEAR(b.next_left_weight, a.next_left_weight, 1e-4);
        ++keys;
      }
    }
    EXPECT_GE(rotation_curves, 9u);
    EXPECT_GT(keys, 100u);
    // assimp reads the file back, every joint there.
    auto back = read_clip(out);
    ASSERT_TRUE(back.ok()) << back.error();
    EXPECT_EQ(back->skeleton.joints.size(), clip->skeleton.joints.size());
  }
}

// With --fps the output is the curves sampled on that grid: a linear key per frame.
TEST(ResampleSourceFbx, WithFpsTheCurvesAreSampledAtEveryOutputFrame) {
  const test::TempDir dir;
  const auto in = test::kData / "fbx/ufbx_maya_game_sausage_7500_binary_wiggle.fbx", out = dir / "60.fbx";
  const test::CliResult r = test::run_cli("resample '" + in.string() + "' -o '" + out.string() + "' -m source --fps 60");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.find("written back"), std::string::npos) << r.out;
  for (const FbxCurve& c : first_take(out).curves)
    for (const FbxKey& k : c.keys) EXPECT_EQ(k.interpolation, FbxInterpolation::linear);
}

}  // namespace
}  // namespace rotinterp
