// Blender (Debian's 3.4, headless) opens the FBX that `resample` writes from an FBX
// character as it opens the source: the same meshes (vertex and face counts,
// vertex groups, materials), one action per take, and the skin deformed the same
// at the first, middle and last time, within 0.1 % of the figure's height, with
// nothing fitted. assimp reads every output too.
#include "blender_character.h"
#include "support/run_cli.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

namespace rotinterp::test {
namespace {

struct Case {
  const char* source;
  const char* command;  // "resample … --fps 30" or "reduce …"; IN and OUT appended
};

void expect_same_character(const std::vector<Case>& cases, double step) {
  const TempDir dir;
  std::vector<std::pair<std::string, std::string>> pairs;
  for (const Case& c : cases) {
    const std::string in = (kData / c.source).string();
    const std::string out = (dir / (std::to_string(pairs.size()) + ".fbx")).string();
    const std::string command = c.command;
    const std::string verb = command.substr(0, command.find(' '));
    const auto r = run_cli(verb + " " + in + " -o " + out + command.substr(verb.size()));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find(" kept"), std::string::npos) << c.source << ": " << r.out;
    EXPECT_EQ(r.err.find("are not written"), std::string::npos) << c.source << ": " << r.err;
    const auto log = dir / (std::to_string(pairs.size()) + ".assimp");
    EXPECT_EQ(std::system(("assimp info '" + out + "' >" + log.string() + " 2>&1").c_str()), 0) << out << ": " << read_text(log);
    pairs.emplace_back(in, out);
  }
  const std::vector<BlenderCharacter> imports = blender_characters(pairs, step, dir.path());
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const BlenderCharacter &source = imports[2 * i], &ours = imports[2 * i + 1];
    const std::string& name = pairs[i].first;
    ASSERT_FALSE(source.meshes.empty()) << name;
    EXPECT_EQ(ours.meshes, source.meshes) << name;
    EXPECT_EQ(ours.takes, source.takes) << name;
    const PoseDeviation d = pose_deviation(ours, source);
    EXPECT_EQ(d.times, 3u) << name;
    EXPECT_LE(d.distance, 1e-3 * d.height) << name;
    std::printf("[ blender ] %s (%s): %zu vertices, worst %.4g mm of %.4g m at 3 times\n", name.c_str(),
                cases[i].command, ours.meshes.front().vertices, d.distance * 1000, d.height);
  }
}

TEST(BlenderCharacter, ResampledFbxCharactersDeformAsTheirSources) {
  // 24 Hz and 30 Hz sources at 30 Hz: every 1/6 s is a key of both.
  expect_same_character({{"fbx/ufbx_maya_kenney_character_7700_binary.fbx", "resample --fps 30"},
                         {"fbx/digitalrune_Dude.fbx", "resample --fps 30"},
                         {"fbx/digitalrune_Marine_Run.fbx", "resample --fps 30"}},
                        1.0 / 6.0);
}

}  // namespace
}  // namespace rotinterp::test
