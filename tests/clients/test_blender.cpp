// Blender (Debian's 3.4, headless) is the user's truth: what rotinterp writes must
// show in Blender as Blender's own import of the source does — every joint at every
// key, at true size, with nothing fitted or left out — within 0.1 % of the figure's
// height. Blender turns every format Z-up in metres itself, the same for both
// imports, so nothing else stands between the two. Source Nulls that Blender makes
// empties are taken at their FBX node's origin (blender_dump.py takes out the
// geometric offset Blender bakes into them). One Blender process imports every
// file (its start-up dominates the test's time).
#include "client_fixture.h"
#include "rotinterp/io/read.h"
#include "support/run_cli.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>

namespace rotinterp::test {
namespace {

// Each source resampled at its own rate (a key at every key of the source; a sparse
// source's frames between its keys are interpolated) to FBX and GLB.
struct Conversion {
  std::string name;    // of the files written
  std::string source;  // under ../shared/data
  std::string args;    // resample options after IN -o OUT
  std::string scale;   // a BVH source's global_scale in Blender, e.g. "@1" (default 0.01)
  double cut = 0.0;    // s, --range's start: key t of ours is the source's key at cut + t
  std::string blender_source() const { return (kData / source).string() + scale; }
};
const Conversion kConversions[] = {
    // Three roots, `$AssimpFbx$` helpers, Nulls with geometric offsets, and root
    // motion on Spine_0, which lies on Root's +Y axis (Blender connected it once).
    {"marine_run", "fbx/digitalrune_Marine_Run.fbx", "", ""},
    // joint1 has a PreRotation and no pivots: assimp multiplies it into the joint's
    // keys and also keeps it in a helper node (the read once counted it twice, 90° off).
    // Its keys start at frame 1, and ours at 0 (but in the FBX, which keeps the source's time axis).
    {"sausage", "fbx/ufbx_maya_game_sausage_7500_binary_wiggle.fbx", "", "", 1.0 / 24.0},
    // 59 joints, translation keys on most of them, many on their parent's +Y axis.
    {"kenney", "fbx/ufbx_maya_kenney_character_7700_binary.fbx", "", ""},
    // A BVH in centimetres: its unit inferred, and given.
    {"bandai_walk", "bvh/NC_bandai1_walk_normal_001.bvh", "", ""},
    {"bandai_walk_cm", "bvh/NC_bandai1_walk_normal_001.bvh", "--unit cm", ""},
    // ZYX channels with angles past 180°: the Euler curves must stay continuous.
    // Its unit given as the metre, as Blender's import at scale 1 takes it.
    {"cmu_01_01", "bvh/cmu_01_01.bvh", "--unit m --range 1:3", "@1", 1.0},
};
constexpr double kTolerance = 1e-3;  // of the figure's height

// An FBX written from an FBX character (these all have a mesh) is the source's file with
// its animation replaced (io/fbx/fbx_character.h): the source's nodes and time axis.
bool keeps_character(const Conversion& c, const std::string& ext) {
  return ext == ".fbx" && std::filesystem::path(c.source).extension() == ".fbx";
}
const char* const kFormats[] = {".fbx", ".glb"};

class BlenderClient : public ::testing::Test {
 protected:
  // A resample that fails leaves its error here, for its own tests to report.
  static void SetUpTestSuite() {
    dir_ = new TempDir();
    std::vector<std::string> files;
    for (const Conversion& c : kConversions) {
      for (const char* ext : kFormats) {
        const std::string out = (*dir_ / (c.name + ext)).string();
        const CliResult r = run_cli("resample " + (kData / c.source).string() + " -o " + out + " " + c.args + " -q");
        if (r.exit_code == 0)
          files.push_back(out);
        else
          errors_[out] = r.err;
      }
      // Blender's import of the source: a BVH at global_scale 0.01 (centimetres) unless said.
      const std::string source = c.blender_source();
      if (std::find(files.begin(), files.end(), source) == files.end()) files.push_back(source);
    }
    try {
      const std::vector<BlenderImport> imports = blender_imports(files, dir_->path());
      for (std::size_t i = 0; i < files.size(); ++i) imports_[files[i]] = imports[i];
    } catch (const std::exception& e) {
      blender_error_ = e.what();
    }
  }
  static void TearDownTestSuite() { delete dir_; }

  static std::string written(const Conversion& c, const char* ext) { return (*dir_ / (c.name + ext)).string(); }
  static const Conversion& conversion(const std::string& name) {
    return *std::find_if(std::begin(kConversions), std::end(kConversions), [&](const Conversion& c) { return c.name == name; });
  }
  // Blender's import of `file`, or null and (with `report`) a failure saying why there is none.
  static const BlenderImport* import_of(const std::string& file, bool report = true) {
    EXPECT_TRUE(blender_error_.empty()) << blender_error_;
    const auto error = errors_.find(file);
    if (report) {
      EXPECT_TRUE(error == errors_.end()) << file << ": resample failed: " << error->second;
    }
    const auto it = imports_.find(file);
    return it == imports_.end() ? nullptr : &it->second;
  }

  static void expect_shows_the_source(const std::string& name) {
    const Conversion& c = conversion(name);
    const BlenderImport* source = import_of(c.blender_source());
    ASSERT_NE(source, nullptr);
    ASSERT_EQ(source->armatures, 1);
    const double height = figure_height(*source);
    for (const char* ext : kFormats) {
      const BlenderImport* ours = import_of(written(c, ext));
      if (!ours) continue;
      EXPECT_EQ(ours->armatures, 1) << name << ext;
      const double cut = keeps_character(c, ext) ? 0.0 : c.cut;
      const Deviation d = worst_deviation(*ours, *source, cut, CompareAt::every_key_of_the_source);
      EXPECT_EQ(d.problem, "") << name << ext;
      EXPECT_GT(ours->times.size(), 1u) << name << ext;
      if (cut == 0.0) {
        EXPECT_EQ(d.keys, source->times.size()) << name << ext << ": every key of the source";
      }
      EXPECT_LE(d.distance, kTolerance * height)
          << name << ext << ": " << d.joint << " at " << d.time << " s is " << d.distance * 1000 << " mm ("
          << d.distance / height * 100 << " % of the " << height << " m figure) from the source's";
      std::printf("[ blender ] %s%s: %zu joints × %zu keys, worst %.4g mm (%.4g %% of %.4g m) at %s, %.4g s\n",
                  name.c_str(), ext, ours->bones.size(), ours->times.size(), d.distance * 1000, d.distance / height * 100,
                  height, d.joint.c_str(), d.time);
    }
  }

  static TempDir* dir_;
  static std::map<std::string, BlenderImport> imports_;
  static std::map<std::string, std::string> errors_;
  static std::string blender_error_;
};
TempDir* BlenderClient::dir_ = nullptr;
std::map<std::string, BlenderImport> BlenderClient::imports_;
std::map<std::string, std::string> BlenderClient::errors_;
std::string BlenderClient::blender_error_;

TEST_F(BlenderClient, MarineRunMovesEveryJointAsInBlendersImportOfTheSource) { expect_shows_the_source("marine_run"); }
TEST_F(BlenderClient, SausageWithAPreRotatedKeyedJointMovesEveryJointAsInBlendersImportOfTheSource) {
  expect_shows_the_source("sausage");
}
TEST_F(BlenderClient, KenneyCharacterMovesEveryJointAsInBlendersImportOfTheSource) {
  expect_shows_the_source("kenney");
}
// Blender's BVH import at scale 0.01 is the walk at true size: 1.38 m from toe to head.
TEST_F(BlenderClient, BandaiWalkAtItsInferredUnitIsTheSizeOfBlendersBvhImportInCentimetres) {
  expect_shows_the_source("bandai_walk");
}
TEST_F(BlenderClient, BandaiWalkGivenInCentimetresIsTheSizeOfBlendersBvhImportInCentimetres) {
  expect_shows_the_source("bandai_walk_cm");
}
TEST_F(BlenderClient, BvhWithAnglesPast180MovesEveryJointAsInBlendersImportOfTheSource) {
  expect_shows_the_source("cmu_01_01");
}

// Blender connects a bone to a child on its +Y axis and then ignores the child's
// location keys (src/io/fbx/fbx_rest.h): no joint with translation keys may be connected.
TEST_F(BlenderClient, NoJointWithTranslationKeysIsConnectedInBlender) {
  for (const Conversion& c : kConversions) {
    const std::string file = written(c, ".fbx");
    const BlenderImport* ours = import_of(file, false);  // a failed resample fails its own test
    if (!ours) continue;
    const Result<Clip> clip = read_clip(file);
    ASSERT_TRUE(clip) << clip.error();
    for (const std::string& bone : ours->connected) {
      const int j = clip->skeleton.find(bone);
      ASSERT_GE(j, 0) << bone;
      EXPECT_FALSE(clip->translations[static_cast<std::size_t>(j)]) << c.name << ": " << bone << " is connected";
    }
  }
}

// One armature holding exactly the clip's joints (a kept character: the source's
// bones, its Nulls objects as in the source); an FBX sets the scene to the source's rate (glTF states none: Blender keeps its 24 fps, and blender_dump.py
// places keys at t·24).
TEST_F(BlenderClient, EveryFileIsOneArmatureOfTheClipsJointsAndFbxSetsTheSourcesRate) {
  for (const Conversion& c : kConversions) {
    const BlenderImport* source = import_of(c.blender_source());
    for (const char* ext : kFormats) {
      const std::string file = written(c, ext);
      const BlenderImport* ours = import_of(file, false);
      if (!ours || !source) continue;
      EXPECT_EQ(ours->armatures, 1) << file;
      const Result<Clip> clip = read_clip(file);
      ASSERT_TRUE(clip) << clip.error();
      std::set<std::string> joints;
      for (const Joint& j : clip->skeleton.joints) joints.insert(j.name);
      if (keeps_character(c, ext)) joints = std::set<std::string>(source->bones.begin(), source->bones.end());
      EXPECT_EQ(std::set<std::string>(ours->bones.begin(), ours->bones.end()), joints) << file;
      if (std::string(ext) == ".fbx") {
        EXPECT_NEAR(ours->fps, source->fps, 1e-4 * source->fps) << file;
      }
    }
  }
}

}  // namespace
}  // namespace rotinterp::test
