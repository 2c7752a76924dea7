// Blender (Debian's 3.4, headless) shows the FBX `resample -m source` writes without
// --fps — the source's own curves written back, keys and tangents — as it shows its
// import of the source: the same keys (Blender reads every FBX key as linear, the
// copied ones as the source's), every joint within 0.1 % of the figure's height.
#include "client_fixture.h"
#include "support/run_cli.h"

#include <gtest/gtest.h>

#include <cstdio>

namespace rotinterp::test {
namespace {

TEST(BlenderSourceFbx, TheCurvesWrittenBackShowInBlenderAsTheSourceDoes) {
  const TempDir dir;
  const char* sources[] = {"fbx/ufbx_maya_game_sausage_7500_binary_wiggle.fbx", "fbx/digitalrune_Marine_Run.fbx"};
  std::vector<std::string> paths;
  for (const char* s : sources) {
    const std::string out = (dir / (std::filesystem::path(s).stem().string() + ".fbx")).string();
    const auto r = run_cli("resample " + (kData / s).string() + " -o " + out + " -m source -q");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    paths.push_back(out);
    paths.push_back((kData / s).string());
  }
  const std::vector<BlenderImport> imports = blender_imports(paths, dir.path());
  for (std::size_t i = 0; i < paths.size(); i += 2) {
    const BlenderImport &ours = imports[i], &source = imports[i + 1];
    ASSERT_EQ(ours.armatures, 1) << paths[i];
    const double height = figure_height(source);
    const Deviation d = worst_deviation(ours, source, 0.0, CompareAt::every_key_of_the_source);
    EXPECT_EQ(d.keys, source.times.size()) << paths[i];
    EXPECT_EQ(d.problem, "") << paths[i];
    EXPECT_LE(d.distance, 1e-3 * height) << paths[i] << ": " << d.joint << " at " << d.time << " s";
    std::printf("[ blender ] %s: %zu keys, worst %.4g mm at %s, %.4g s\n", paths[i].c_str(), ours.times.size(),
                d.distance * 1000, d.joint.c_str(), d.time);
  }
}

}  // namespace
}  // namespace rotinterp::test
