// reduce -o OUT.fbx from an FBX character (io/fbx/fbx_reduced.h, options.character):
// the file is the source's tree with the reduced curves as its one take, so its
// meshes and skins pass through; and another reader (assimp, through read_clip)
// finds every joint, at each of its key times, within reduce's budget of the source.
#include "rotinterp/clip/frames.h"
#include "rotinterp/clip/units.h"
#include "rotinterp/io/fbx/fbx_reduced.h"
#include "rotinterp/io/read.h"
#include "rotinterp/reduce/reduce.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace rotinterp {
namespace {

const std::filesystem::path kData = ROTINTERP_SHARED_DATA;
constexpr double kDegreesPerRadian = 180.0 / kPi;
// FBX stores key values as floats: an angle of up to 360° within this, a translation
// within this relative to its size.
constexpr double kFloatDegrees = 1e-4, kFloatRelative = 1e-6;

TEST(ReduceFbxCharacter, TheCharacterPassesThroughAndAnotherReaderFindsEveryKeyWithinBudget) {
  const double budget_deg = 0.5, budget_m = 0.001;
  for (const char* name : {"ufbx_maya_kenney_character_7700_binary.fbx", "digitalrune_Dude.fbx", "digitalrune_Marine_Run.fbx"}) {
    SCOPED_TRACE(name);
    const std::filesystem::path path = kData / "fbx" / name;
    const Result<Clip> clip = read_clip(path);
    ASSERT_TRUE(clip) << clip.error();
    const Result<FbxCharacter> character = read_fbx_character(path);
    ASSERT_TRUE(character) << character.error();
    ReduceOptions opt;
    // Linear keys throughout: assimp reads an FBX curve linearly between its keys.
    opt.method = "slerp";
    opt.translation = TranslationInterp::linear;
    opt.budget.rotation_deg = budget_deg;
    opt.budget.translation = in_clip_units(*clip, budget_m);
    const Result<ReduceResult> reduced = reduce_clip(*clip, opt);
    ASSERT_TRUE(reduced) << reduced.error();
    FbxReducedOptions o;
    o.method = opt.method;
    o.translation = opt.translation;
    o.character = &*character;
    for (const ReducedJoint& j : reduced->joints) o.budgets.push_back({j.budget.rotation_deg, j.budget.shell, j.budget.translation});
    const Result<FbxReducedResult> fbx = encode_reduced_fbx(reduced->reduced, *clip, o);
    ASSERT_TRUE(fbx) << fbx.error();
    EXPECT_TRUE(fbx->within_budget);
    ASSERT_TRUE(fbx->kept.has_value());
    EXPECT_EQ(fbx->kept->meshes, 1u);
    EXPECT_EQ(fbx->kept->skins, 1u);
    const DenseClip source = dense_clip(*clip);
    EXPECT_LT(fbx->rotation_keys, source.grid.size() * clip->skeleton.joints.size() / 2);

    const std::filesystem::path out =
        std::filesystem::temp_directory_path() / ("rotinterp_reduce_character_" + std::to_string(::getpid()) + ".fbx");
    std::ofstream(out, std::ios::binary).write(fbx->bytes.data(), static_cast<std::streamsize>(fbx->bytes.size()));
    const Result<Clip> back = read_clip(out);
    std::filesystem::remove(out);
    ASSERT_TRUE(back) << back.error();
    ASSERT_EQ(back->skeleton.joints.size(), clip->skeleton.joints.size());
    EXPECT_EQ(back->source_meshes, clip->source_meshes);
    double worst_deg = 0.0, worst_m = 0.0;
    std::size_t keys = 0;
    for (std::size_t j = 0; j < clip->skeleton.joints.size(); ++j) {
      const int b = back->skeleton.find(clip->skeleton.joints[j].name);
      ASSERT_GE(b, 0) << clip->skeleton.joints[j].name;
      const RotationTrack& rotation = back->rotations[static_cast<std::size_t>(b)];
      for (std::size_t k = 0; k < rotation.times.size(); ++k, ++keys) {
        const std::optional<std::size_t> f = source.grid.frame_at(rotation.times[k]);
        ASSERT_TRUE(f) << "a key at " << rotation.times[k] << " s lies on no source frame";
        worst_deg = std::max(worst_deg, angular_distance(rotation.keys[k], source.rotation[j][*f]) * kDegreesPerRadian);
      }
      if (const auto& translation = back->translations[static_cast<std::size_t>(b)])
        for (std::size_t k = 0; k < translation->times.size(); ++k)
          if (const std::optional<std::size_t> f = source.grid.frame_at(translation->times[k])) {
            const Vec3& truth = source.translation[j][*f];
            const double m = (translation->keys[k] - truth).norm() * clip->unit.metres_per_unit;
            worst_m = std::max(worst_m, m - kFloatRelative * truth.norm() * clip->unit.metres_per_unit);
          }
    }
    EXPECT_GT(keys, 0u);
    EXPECT_LE(worst_deg, budget_deg + kFloatDegrees);
    EXPECT_LE(worst_m, budget_m);
    std::printf("[ reduce ] %s: %zu rotation keys of %zu frames x %zu joints; read back: worst %.4f deg, %.4f mm\n", name,
                fbx->rotation_keys, source.grid.size(), clip->skeleton.joints.size(), worst_deg, worst_m * 1000);
  }
}

}  // namespace
}  // namespace rotinterp
