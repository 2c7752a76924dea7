// Many takes out (issue 44, item 4): --anim all or a comma list in resample and eval,
// on the three takes of one shared timeline (support/take_fixtures.h).
#include "rotinterp/core/rotation.h"
#include "rotinterp/io/read.h"
#include "rotinterp/io/takes.h"
#include "support/run_cli.h"
#include "support/take_fixtures.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace rotinterp {
namespace {

namespace fs = std::filesystem;

class TakesCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("rotinterp_takes_cli_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    source_ = (dir_ / "shared.fbx").string();
    std::ofstream(source_) << test::shared_timeline_fbx();
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string q(const fs::path& p) const { return "'" + p.string() + "'"; }
  fs::path dir_;
  std::string source_;
};

double z_degrees(const Quat& q) { return std::abs(2.0 * std::atan2(q.z(), q.w()) * 180.0 / kPi); }

struct TakeOut {
  const char* name;
  const char* file;
  std::size_t frames;
  double first_z, last_z;
};
constexpr TakeOut kTakes[] = {{"anim 1", "anim_1", 21, 0, 0}, {"anim 2", "anim_2", 16, 0, 0}, {"spin", "spin", 16, 0, 180}};

// Each take read back from its own file: its own span at the file's 30 Hz, from its
// own first pose to its last.
void expect_take(const fs::path& path, const TakeOut& want, const std::string& anim = "") {
  ReadOptions options;
  options.animation = anim;
  Result<Clip> clip = read_clip(path, options);
  ASSERT_TRUE(clip.ok()) << clip.error();
  EXPECT_EQ(clip->frame_count(), want.frames) << path;
  EXPECT_NEAR(clip->frame_time, 1.0 / 30, 1e-9) << path;
  const RotationTrack& r = clip->rotations.at(0);
  EXPECT_NEAR(z_degrees(r.keys.front()), want.first_z, 1e-3) << path;
  EXPECT_NEAR(z_degrees(r.keys.back()), want.last_z, 1e-3) << path;
}

TEST_F(TakesCli, AllTakesToOneBvhPerTakeNamedByTheTake) {
  const auto r = test::run_cli("resample " + q(source_) + " --anim all -o " + q(dir_ / "out_{anim}.bvh"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const TakeOut& t : kTakes) expect_take(dir_ / (std::string("out_") + t.file + ".bvh"), t);
  EXPECT_NE(r.out.find("shared.fbx#spin → "), std::string::npos) << r.out;
}

// One FBX (an AnimationStack per take) and one GLB (an animation per take): each take
// read back by its name is the source's take.
TEST_F(TakesCli, AllTakesIntoOneFbxAndOneGlbReadBackTakeByTake) {
  for (const char* ext : {".fbx", ".glb"}) {
    const fs::path out = dir_ / (std::string("all") + ext);
    const auto r = test::run_cli("resample " + q(source_) + " --anim all -q -o " + q(out));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const TakeOut& t : kTakes) expect_take(out, t, t.name);
  }
}

TEST_F(TakesCli, AListOfNamesAndIndicesTakesThoseInItsOrder) {
  const auto r = test::run_cli("resample " + q(source_) + " --anim 'spin,0' -o " + q(dir_ / "{anim}.glb") + " -q");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir_ / "spin.glb"));
  EXPECT_TRUE(fs::exists(dir_ / "anim_1.glb"));
  EXPECT_FALSE(fs::exists(dir_ / "anim_2.glb"));
}

TEST_F(TakesCli, ManyTakesIntoAOneTakeFormatWithoutAPlaceholderIsOneLine) {
  const auto r = test::run_cli("resample " + q(source_) + " --anim all -o " + q(dir_ / "out.bvh"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("holds one take; put {anim} in the output name"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "out.bvh"));
}

TEST_F(TakesCli, ATakeThatIsNotThereIsNamedAndNothingIsWritten) {
  const auto r = test::run_cli("resample " + q(source_) + " --anim 'spin,walk' -o " + q(dir_ / "{anim}.bvh"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find(source_ + ": --anim spin,walk: no take 'walk' (the file has 0 'anim 1', 1 'anim 2', 2 'spin')"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "spin.bvh"));
}

TEST_F(TakesCli, ReduceWritesAFilePerTake) {
  const auto r = test::run_cli("reduce " + q(source_) + " --anim all -q -o " + q(dir_ / "keys_{anim}.glb"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const TakeOut& t : kTakes) {
    Result<Clip> clip = read_clip(dir_ / (std::string("keys_") + t.file + ".glb"));
    ASSERT_TRUE(clip.ok()) << clip.error();
    EXPECT_NEAR(clip->end_time() - clip->start_time(), (t.frames - 1) / 30.0, 1e-6) << t.name;
  }
  const auto one = test::run_cli("reduce " + q(source_) + " --anim all -o " + q(dir_ / "keys.json"));
  EXPECT_EQ(one.exit_code, 2);
  EXPECT_NE(one.err.find("put {anim} in the output name"), std::string::npos) << one.err;
}

TEST_F(TakesCli, EvalReportsEachTakeOfAList) {
  const auto r = test::run_cli("eval " + q(source_) + " --anim 'anim 2,spin' -m slerp --keep-every 2 --no-plots -q -o " +
                               q(dir_ / "eval"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream csv(dir_ / "eval" / "clips.csv");
  const std::string text((std::istreambuf_iterator<char>(csv)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("shared.fbx#anim 2"), std::string::npos) << text;
  EXPECT_NE(text.find("shared.fbx#spin"), std::string::npos) << text;
  EXPECT_EQ(text.find("shared.fbx#anim 1"), std::string::npos) << text;
}

TEST(TakeNames, AreMadeSafeForAFileName) {
  EXPECT_EQ(take_file_part({2, "anim 2"}), "anim_2");
  EXPECT_EQ(take_file_part({0, "../x"}), ".._x");
  EXPECT_EQ(take_file_part({3, ""}), "take3");
  EXPECT_EQ(take_file_part({4, "//"}), "take4");
  EXPECT_EQ(with_take_name("out/{anim}_{anim}.bvh", {1, "Run"}), "out/Run_Run.bvh");
  EXPECT_TRUE(names_several_takes("all"));
  EXPECT_TRUE(names_several_takes("walk,run"));
  EXPECT_FALSE(names_several_takes("walk"));
}

}  // namespace
}  // namespace rotinterp
