// BVH reading without assimp (the default) and with ReadOptions::cross_check_with_assimp
// gives the same clip, bit for bit, on every real BVH; and assimp agrees with our
// pass on each of them (no warning beyond the ones our pass gives by itself).
#include "io_test_util.h"
#include "rotinterp/io/read.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

namespace rotinterp {
namespace {

using test::kData;

TEST(BvhCrossCheck, SameClipWithAndWithoutAssimpAndAssimpAgreesOnEveryRealBvh) {
  std::size_t files = 0;
  for (const auto& e : std::filesystem::directory_iterator(kData / "bvh")) {
    if (e.path().extension() != ".bvh") continue;
    const std::string name = e.path().filename().string();
    std::vector<std::string> plain_warnings, checked_warnings;
    ReadOptions plain;
    plain.on_warning = [&](const std::string& w) { plain_warnings.push_back(w); };
    ReadOptions checked = plain;
    checked.on_warning = [&](const std::string& w) { checked_warnings.push_back(w); };
    checked.cross_check_with_assimp = true;
    Result<Clip> a = read_clip(e.path(), plain);
    Result<Clip> b = read_clip(e.path(), checked);
    ASSERT_TRUE(a) << a.error();
    ASSERT_TRUE(b) << b.error();
    EXPECT_EQ(plain_warnings, checked_warnings) << name;
    ASSERT_EQ(a->rotations.size(), b->rotations.size()) << name;
    for (std::size_t j = 0; j < a->rotations.size(); ++j) {
      ASSERT_EQ(a->rotations[j].times, b->rotations[j].times) << name;
      for (std::size_t k = 0; k < a->rotations[j].keys.size(); ++k)
        ASSERT_EQ(a->rotations[j].keys[k].coeffs(), b->rotations[j].keys[k].coeffs()) << name << " joint " << j;
      ASSERT_EQ(a->translations[j].has_value(), b->translations[j].has_value()) << name;
      if (a->translations[j]) {
        EXPECT_EQ(a->translations[j]->times, b->translations[j]->times) << name;
        for (std::size_t k = 0; k < a->translations[j]->keys.size(); ++k)
          ASSERT_EQ(a->translations[j]->keys[k], b->translations[j]->keys[k]) << name << " joint " << j;
      }
    }
    EXPECT_EQ(a->frame_time, b->frame_time) << name;
    ++files;
  }
  EXPECT_GE(files, 5u);
}

}  // namespace
}  // namespace rotinterp
