// The method registry's lookup: one spelling per method, found whatever its case,
// and a near miss answered with the nearest name.
#include "rotinterp/interp/interpolator.h"

#include <gtest/gtest.h>

#include <string>

namespace rotinterp {
namespace {

TEST(MethodRegistry, NamesAreFoundWhateverTheirCaseAndGiveTheOneSpelling) {
  for (const MethodInfo& m : methods()) {
    std::string upper = m.name;
    for (char& c : upper) c = static_cast<char>(c >= 'a' && c <= 'z' ? c - 'a' + 'A' : c);
    const MethodInfo* found = find_method(upper);
    ASSERT_NE(found, nullptr) << upper;
    EXPECT_EQ(found->name, m.name);
  }
  RotationTrack t;
  t.times = {0.0, 1.0};
  t.keys = {Quat::Identity(), Quat::Identity()};
  EXPECT_TRUE(make_interpolator("Squad", t));
}

TEST(MethodRegistry, AMisspelledNameGetsDidYouMeanTheNearestName) {
  EXPECT_NE(unknown_method_message("slrep").find("did you mean slerp?"), std::string::npos);
  EXPECT_NE(unknown_method_message("expmapc2").find("did you mean expmap-c2?"), std::string::npos);
  EXPECT_NE(unknown_method_message("gltfcubic").find("did you mean gltf-cubic?"), std::string::npos);
  // Nothing near: no guess, but the valid names.
  const std::string far = unknown_method_message("catmull-rom-spline");
  EXPECT_EQ(far.find("did you mean"), std::string::npos) << far;
  EXPECT_NE(far.find("valid: slerp"), std::string::npos) << far;
  RotationTrack t;
  t.times = {0.0, 1.0};
  t.keys = {Quat::Identity(), Quat::Identity()};
  const auto made = make_interpolator("sqaud", t);
  ASSERT_FALSE(made);
  EXPECT_NE(made.error().find("did you mean squad?"), std::string::npos) << made.error();
}

}  // namespace
}  // namespace rotinterp
