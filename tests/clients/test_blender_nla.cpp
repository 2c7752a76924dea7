// Takes a DCC made (issue 44): Blender builds an armature with two actions of
// different lengths and start frames (NLA tracks) and exports them as an FBX of two
// takes and a GLB of two animations (blender_nla_rig.py). `resample --anim all` to
// FBX and to GLB; Blender opens ours with one action per take, and each action plays
// as Blender plays the source's: every bone head at every key of the source action,
// frame k of ours against frame k of the source take (each take starts at its own
// frame 0), nothing fitted, within 0.1 % of the figure's height.
#include "client_fixture.h"
#include "support/run_cli.h"

#include <gtest/gtest.h>

#include <cstdio>

namespace rotinterp::test {
namespace {

// The one action of `b` whose name holds `take` ("Rig|Walk|BaseLayer", "Walk_Rig", "Walk").
std::string action_named(const BlenderImport& b, const std::string& take) {
  std::string found;
  for (const std::string& a : b.actions)
    if (a.find(take) != std::string::npos) {
      EXPECT_TRUE(found.empty()) << "two actions hold '" << take << "': " << found << ", " << a;
      found = a;
    }
  return found;
}

TEST(BlenderNla, EveryTakeOfABlenderExportComesBackAsOneActionPlayedAsTheSource) {
  const TempDir dir;
  const std::string stem = make_blender_rig(dir.path(), false);
  std::vector<std::string> files;
  for (const char* ext : {".fbx", ".glb"}) {
    const std::string source = stem + ext, ours = (dir / (std::string("ours") + ext)).string();
    const CliResult r = run_cli("resample '" + source + "' --anim all -q -o '" + ours + "'");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    files.push_back(source);
    files.push_back(ours);
  }
  const std::vector<BlenderImport> imports = blender_imports(files, dir.path());
  for (std::size_t f = 0; f < files.size(); f += 2) {
    const BlenderImport &source = imports[f], &ours = imports[f + 1];
    ASSERT_EQ(ours.armatures, 1) << files[f + 1];
    EXPECT_EQ(ours.actions.size(), source.actions.size()) << files[f + 1];
    for (const char* take : {"Walk", "Wave"}) {
      const BlenderImport src = playing(source, action_named(source, take));
      const BlenderImport out = playing(ours, action_named(ours, take));
      ASSERT_FALSE(src.times.empty()) << files[f] << " " << take;
      ASSERT_FALSE(out.times.empty()) << files[f + 1] << " " << take;
      // Frame k of our take is frame k of the source's: the source action starts at its
      // first key (frame 10 for Wave), ours at 0.
      EXPECT_NEAR(out.times.front(), 0.0, 1e-6) << files[f + 1] << " " << take;
      const double start = src.times.front();
      const Deviation d = worst_deviation(out, src, start, CompareAt::every_key_of_the_source);
      EXPECT_EQ(d.problem, "") << files[f + 1] << " " << take;
      EXPECT_EQ(d.keys, src.times.size()) << files[f + 1] << " " << take;
      const double height = figure_height(src);
      EXPECT_LE(d.distance, 1e-3 * height) << files[f + 1] << " " << take << ": " << d.joint << " at " << d.time << " s";
      std::printf("[ blender ] %s take %s: %zu keys from %.4g s (source from %.4g s), worst %.3g mm of a %.3g m figure\n",
                  files[f + 1].c_str(), take, d.keys, out.times.front(), src.times.front(), d.distance * 1000, height);
    }
  }
}

}  // namespace
}  // namespace rotinterp::test
