// Blender (Debian's 3.4, headless) opens the multi-take FBX and GLB that write_clips
// writes with one action per take, named after it, and plays each action as it
// plays the same take written alone: every bone head at every key, with nothing
// fitted, within 1e-3 of the figure's height.
#include "client_fixture.h"
#include "rotinterp/clip/frames.h"
#include "rotinterp/clip/resample.h"
#include "rotinterp/io/read.h"
#include "rotinterp/io/write.h"

#include <gtest/gtest.h>

#include <cstdio>

namespace rotinterp::test {
namespace {

// The actions Blender made for take `name`: Blender 3.4's FBX importer names them
// "OBJECT|STACK|LAYER" ("Armature|Jump|BaseLayer"), its glTF importer "ANIMATION"
// or "ANIMATION_OBJECT".
std::vector<std::string> actions_of(const BlenderImport& b, const std::string& name) {
  std::vector<std::string> out;
  for (const std::string& a : b.actions) {
    const bool fbx_style = a.find("|" + name + "|") != std::string::npos;
    if (a == name || fbx_style || a.rfind(name + "_", 0) == 0) out.push_back(a);
  }
  return out;
}

TEST(BlenderTakes, EachTakeIsOneNamedActionPlayedAsTheTakeWrittenAlone) {
  const std::vector<Clip> takes = {cut_take("bvh/cmu_01_01.bvh", "30", 0.0, 2.0, "Jump"),
                                   cut_take("bvh/cmu_01_03.bvh", "24", 1.0, 2.5, "Climb"),
                                   cut_take("bvh/cmu_01_01.bvh", "60", 3.0, 3.5, "Hop")};
  const TempDir dir;
  std::vector<std::string> paths;
  for (const char* ext : {".fbx", ".glb"}) {
    const auto all = dir / (std::string("takes") + ext);
    ASSERT_TRUE(write_clips(takes, all));
    paths.push_back(all.string());
    for (const Clip& take : takes) {
      const auto alone = dir / (take.name + ext);
      ASSERT_TRUE(write_clip(take, alone));
      paths.push_back(alone.string());
    }
  }
  const std::vector<BlenderImport> imports = blender_imports(paths, dir.path());
  for (std::size_t f = 0; f < 2; ++f) {
    const std::size_t base = f * (takes.size() + 1);
    const BlenderImport& many = imports[base];
    const std::string file = paths[base];
    ASSERT_EQ(many.armatures, 1) << file;
    std::string names;
    for (const std::string& a : many.actions) names += "'" + a + "' ";
    std::printf("[ blender ] %s: %zu actions: %s\n", file.c_str(), many.actions.size(), names.c_str());
    EXPECT_EQ(many.actions.size(), takes.size()) << file << ": " << names;
    for (std::size_t i = 0; i < takes.size(); ++i) {
      const std::vector<std::string> found = actions_of(many, takes[i].name);
      ASSERT_EQ(found.size(), 1u) << file << ": take " << takes[i].name << " among " << names;
      ASSERT_TRUE(many.action_keys.count(found[0])) << file;
      const BlenderImport& alone = imports[base + 1 + i];
      const BlenderImport played = playing(many, found[0]);
      EXPECT_EQ(played.times.size(), alone.times.size()) << file << " " << takes[i].name;
      const Deviation d = worst_deviation(played, alone);
      EXPECT_EQ(d.problem, "") << file << " " << takes[i].name;
      EXPECT_EQ(d.keys, alone.times.size()) << file << " " << takes[i].name;
      const double height = figure_height(alone);
      EXPECT_LE(d.distance, 1e-3 * height) << file << " " << takes[i].name << " at " << d.joint << ", " << d.time << " s";
      std::printf("[ blender ] %s action '%s': %zu keys (%zu compared), %.3g..%.3g s, worst %.3g mm of a %.3g m figure at %s\n",
                  file.c_str(), found[0].c_str(), played.times.size(), d.keys, played.times.front(), played.times.back(),
                  d.distance * 1000, height, d.joint.c_str());
    }
  }
}

}  // namespace
}  // namespace rotinterp::test
