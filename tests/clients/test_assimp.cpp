// assimp, the reader most tools use, reads what rotinterp writes: the library reads
// back the unit an FBX declares, and `assimp info` (assimp-utils, its command-line
// client) loads every BVH written.
#include "io/io_test_util.h"
#include "rotinterp/io/read.h"
#include "support/run_cli.h"

#include <assimp/Importer.hpp>
#include <assimp/scene.h>
#include <gtest/gtest.h>

#include <cstdlib>

namespace rotinterp::test {
namespace {

// The FBX's GlobalSettings UnitScaleFactor (centimetres per unit) as assimp reads it, or −1.
double unit_scale_factor(const std::string& fbx) {
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(fbx, 0);
  if (!scene || !scene->mMetaData) return -1.0;
  double f = 0.0;
  float ff = 0.0f;
  if (scene->mMetaData->Get("UnitScaleFactor", f)) return f;
  if (scene->mMetaData->Get("UnitScaleFactor", ff)) return ff;
  return -1.0;
}

// A centimetre clip is written at one centimetre per unit (UnitScaleFactor 1), a
// metre clip at 100: the values are the clip's and the factor says what they are.
TEST(Assimp, ReadsBackTheUnitScaleFactorOfTheClipsUnit) {
  const TempDir dir;
  const struct {
    std::string source, args;
    double factor;
  } cases[] = {
      {(kData / "fbx/ufbx_maya_kenney_character_7700_binary.fbx").string(), "", 1.0},  // declares centimetres
      {(kData / "bvh/NC_bandai1_walk_normal_001.bvh").string(), "", 1.0},              // inferred centimetres
      {(kData / "bvh/NC_bandai1_walk_normal_001.bvh").string(), "--unit cm", 1.0},
      {(dir / "kenney.glb").string(), "", 100.0},  // glTF is in metres (written below)
  };
  ASSERT_EQ(run_cli("resample " + cases[0].source + " -o " + (dir / "kenney.glb").string() + " -q").exit_code, 0);
  int k = 0;
  for (const auto& c : cases) {
    const std::string out = (dir / ("out" + std::to_string(k++) + ".fbx")).string();
    const CliResult r = run_cli("resample " + c.source + " -o " + out + " " + c.args + " -q");
    EXPECT_EQ(r.exit_code, 0) << c.source << " " << c.args << ": " << r.err;
    if (r.exit_code != 0) continue;
    EXPECT_DOUBLE_EQ(unit_scale_factor(out), c.factor) << c.source << " " << c.args;
  }
}

// `assimp info` loads every BVH written — among them Marine_Run's three roots,
// written under one synthetic root — with one node per joint and End Site.
TEST(Assimp, CommandLineReadsEveryBvhWritten) {
  const TempDir dir;
  const struct {
    const char *name, *source, *args;
  } cases[] = {
      {"bandai_walk", "bvh/NC_bandai1_walk_normal_001.bvh", "--fps 60 --range 0:1"},
      {"cmu_01_01", "bvh/cmu_01_01.bvh", "--fps 30 --range 1:3"},  // ZYX, angles past 180°
      {"marine_run", "fbx/digitalrune_Marine_Run.fbx", "--fps 30"},
      {"dude", "fbx/digitalrune_Dude.fbx", "--fps 30"},  // pivot helpers
  };
  for (const auto& c : cases) {
    const auto bvh = dir / (std::string(c.name) + ".bvh");
    const CliResult r = run_cli("resample " + (kData / c.source).string() + " -o " + bvh.string() + " " + c.args + " -q");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto log = dir / (std::string(c.name) + ".assimp");
    const int status = std::system(("assimp info " + bvh.string() + " >" + log.string() + " 2>&1").c_str());
    const std::string out = read_text(log);
    ASSERT_EQ(status, 0) << c.name << ":\n" << out;
    const Result<Clip> clip = read_clip(bvh);
    ASSERT_TRUE(clip) << clip.error();
    const std::size_t nodes = clip->skeleton.joints.size() + clip->skeleton.end_sites.size();
    EXPECT_NE(out.find("Nodes:              " + std::to_string(nodes) + "\n"), std::string::npos) << c.name << ":\n" << out;
    EXPECT_NE(out.find("Animations:         1\n"), std::string::npos) << c.name;
    const std::string text = read_text(bvh);
    std::size_t roots = 0;
    for (std::size_t at = text.find("ROOT "); at != std::string::npos; at = text.find("ROOT ", at + 1)) ++roots;
    EXPECT_EQ(roots, 1u) << c.name;
  }
}

}  // namespace
}  // namespace rotinterp::test
