// FBX curves read by our own reader and evaluated as Maya and MotionBuilder
// evaluate them: every value of dcc_reference.tsv within 1e-4 of its curve's range;
// key attributes (interpolation, tangents, weights) as the files store them.
#include "dcc_reference.h"
#include "rotinterp/io/fbx/fbx_curve_eval.h"
#include "rotinterp/io/fbx/fbx_curves.h"
#include "rotinterp/io/fbx/fbx_nodes.h"

#include <gtest/gtest.h>

namespace rotinterp {
namespace {

FbxAnimation read_animation(const std::string& path) { return test::read_fbx_curves(path); }

// The case's curve: by node name, or the one animated node's.
const FbxCurve* find_curve(const FbxAnimation& anim, const test::DccCase& c) {
  if (anim.takes.empty()) return nullptr;
  for (const FbxCurve& curve : anim.takes[0].curves)
    if ((c.node.front() == '(' || curve.node == c.node) && curve.property == c.property && curve.channel == c.channel &&
        curve.layer == c.layer && !curve.keys.empty())
      return &curve;
  return nullptr;
}

TEST(FbxCurves, EveryDccReferenceValueIsMatchedWithin1e4OfTheCurvesRange) {
  std::size_t matched = 0, total = 0;
  for (const test::DccCase& c : test::dcc_cases()) {
    SCOPED_TRACE(c.name + " " + c.file);
    const FbxAnimation anim = read_animation(c.file);
    const FbxCurve* curve = find_curve(anim, c);
    ASSERT_NE(curve, nullptr);
    for (std::size_t i = 0; i < c.values.size(); ++i) {
      const double ticks = (static_cast<double>(i) / 24.0 + c.time_offset_s) * static_cast<double>(kFbxTicksPerSecond);
      const double v = evaluate_fbx_curve(*curve, ticks);
      ++total;
      if (std::abs(v - c.values[i]) <= c.tolerance()) ++matched;
      else ADD_FAILURE() << "frame " << i << ": " << v << " against " << c.values[i] << " (tolerance " << c.tolerance() << ")";
    }
  }
  EXPECT_EQ(matched, total);
  EXPECT_GE(total, 250u);
  std::printf("matched %zu of %zu DCC values\n", matched, total);
}

TEST(FbxCurves, KeyAttributesAreReadAsStored) {
  const FbxAnimation anim = read_animation((test::kData / "fbx/ufbx_maya_interpolation_modes_7500_ascii.fbx").string());
  ASSERT_EQ(anim.takes.size(), 1u);
  const FbxCurve& c = anim.takes[0].curves.at(0);
  EXPECT_EQ(c.node, "pCube1");
  EXPECT_EQ(c.property, "Lcl Translation");
  ASSERT_EQ(c.keys.size(), 12u);
  EXPECT_EQ(c.keys[0].ticks, 1924423250);
  EXPECT_EQ(c.keys[0].interpolation, FbxInterpolation::cubic);
  EXPECT_EQ(c.keys[0].tangent, FbxTangent::user);
  EXPECT_NEAR(c.keys[0].next_left_slope, 2.71713, 1e-5);
  EXPECT_EQ(c.keys[2].interpolation, FbxInterpolation::linear);
  EXPECT_EQ(c.keys[5].tangent, FbxTangent::broken);
  EXPECT_NEAR(c.keys[5].right_weight, 0.540154, 1e-4);
  EXPECT_NEAR(c.keys[5].next_left_weight, 0.520752, 1e-4);
  EXPECT_EQ(c.keys[7].interpolation, FbxInterpolation::constant_previous);
  EXPECT_EQ(c.keys[9].interpolation, FbxInterpolation::constant_next);
  EXPECT_EQ(anim.takes[0].layers.size(), 1u);
}

TEST(FbxCurves, ExtrapolationRepeatsMirrorsAndKeepsTheSlope) {
  FbxCurve c;
  FbxKey a, b;
  a.ticks = 0, a.value = 0, a.interpolation = FbxInterpolation::linear;
  b.ticks = kFbxTicksPerSecond, b.value = 2;
  c.keys = {a, b};
  const double s = static_cast<double>(kFbxTicksPerSecond);
  EXPECT_EQ(evaluate_fbx_curve(c, 2.5 * s), 2.0);  // constant
  c.post.mode = FbxExtrapolation::repetition;
  EXPECT_NEAR(evaluate_fbx_curve(c, 2.25 * s), 0.5, 1e-12);
  c.post.mode = FbxExtrapolation::mirror;
  EXPECT_NEAR(evaluate_fbx_curve(c, 1.25 * s), 1.5, 1e-12);
  EXPECT_NEAR(evaluate_fbx_curve(c, 2.25 * s), 0.5, 1e-12);
  c.post.mode = FbxExtrapolation::keep_slope;
  EXPECT_NEAR(evaluate_fbx_curve(c, 3.0 * s), 6.0, 1e-12);
  c.pre.mode = FbxExtrapolation::keep_slope;
  EXPECT_NEAR(evaluate_fbx_curve(c, -1.0 * s), -2.0, 1e-12);
  c.post.mode = FbxExtrapolation::repetition;
  c.post.repetitions = 1;
  EXPECT_NEAR(evaluate_fbx_curve(c, 1.5 * s), 1.0, 1e-12);
  EXPECT_EQ(evaluate_fbx_curve(c, 5.5 * s), 2.0);  // past its one repetition
}

}  // namespace
}  // namespace rotinterp
