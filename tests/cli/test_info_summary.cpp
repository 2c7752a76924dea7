// `rotinterp info PATH... --summary`: a dataset's files, its rate histogram, and
// what a user should know before resampling it.
#include "support/run_cli.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

namespace rotinterp {
namespace {

namespace fs = std::filesystem;
using test::run_cli;

// A one-joint BVH with `frames` frames and this Frame Time text.
std::string bvh(int frames, const std::string& frame_time) {
  std::string text =
      "HIERARCHY\nROOT Hips\n{\n  OFFSET 0 0 0\n  CHANNELS 3 Zrotation Xrotation Yrotation\n  End Site\n  {\n"
      "    OFFSET 0 1 0\n  }\n}\nMOTION\nFrames: " +
      std::to_string(frames) + "\nFrame Time: " + frame_time + "\n";
  for (int f = 0; f < frames; ++f) text += std::to_string(f) + " 0 0\n";
  return text;
}

class InfoSummary : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("rotinterp_info_summary_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "set" / "sub");
    std::ofstream(dir_ / "set" / "sixty.bvh") << bvh(30, "0.016667");      // 59.9988 Hz as written
    std::ofstream(dir_ / "set" / "thirty.bvh") << bvh(30, "0.0333333");    // 30.00003 Hz: nothing to say
    std::ofstream(dir_ / "set" / "sub" / "copy.bvh") << bvh(30, "0.0333333");  // the same bytes
    std::ofstream(dir_ / "set" / "single.bvh") << bvh(1, "0.0333333");     // one frame
    std::ofstream(dir_ / "set" / "notes.txt") << "not a clip\n";            // not looked at
  }
  void TearDown() override { fs::remove_all(dir_); }

  nlohmann::json summary(const std::string& extra, int code) {
    const auto r = run_cli("info --summary --json " + (dir_ / "set").string() + " " + extra);
    EXPECT_EQ(r.exit_code, code) << r.err;
    return nlohmann::json::parse(r.out);
  }
  // The notes of `file` (a name under set/) joined by "; ".
  static std::string notes_of(const nlohmann::json& s, const std::string& name) {
    for (const auto& f : s["files"])
      if (fs::path(f["file"].get<std::string>()).filename() == name) {
        std::string all;
        for (const auto& n : f["notes"]) all += n.get<std::string>() + "; ";
        return all;
      }
    ADD_FAILURE() << name << " not in the summary";
    return "";
  }

  fs::path dir_;
};

TEST_F(InfoSummary, FlagsRateLabelsEmptyClipsAndIdenticalFilesAndCountsTheRates) {
  const auto s = summary("", 0);
  ASSERT_EQ(s["files"].size(), 4u);
  EXPECT_NE(notes_of(s, "sixty.bvh").find("Frame Time 0.016667 is 59.9988 Hz; read as 60 Hz"), std::string::npos)
      << notes_of(s, "sixty.bvh");
  EXPECT_EQ(notes_of(s, "thirty.bvh").find("Frame Time"), std::string::npos);
  EXPECT_NE(notes_of(s, "thirty.bvh").find("same bytes as"), std::string::npos);
  EXPECT_NE(notes_of(s, "copy.bvh").find("same bytes as"), std::string::npos);
  EXPECT_NE(notes_of(s, "single.bvh").find("zero-length clip (1 frame)"), std::string::npos);
  ASSERT_EQ(s["duplicates"].size(), 1u);
  EXPECT_EQ(s["duplicates"][0].size(), 2u);
  EXPECT_EQ(s["rates"][0]["rate"], "30 Hz");
  EXPECT_EQ(s["rates"][0]["files"], 3);
  EXPECT_EQ(s["rates"][1]["rate"], "60 Hz");
  EXPECT_EQ(s["rates"][1]["files"], 1);
  EXPECT_EQ(s["unreadable"], 0);
}

TEST_F(InfoSummary, NamesUnevenKeysOfARealFileAndListsAnUnreadableOneWithExit3) {
  std::ofstream(dir_ / "set" / "broken.bvh") << "HIERARCHY\nROOT\n";
  const std::string uneven = std::string(ROTINTERP_SHARED_DATA) + "/fbx/ufbx_maya_interpolation_modes_7500_ascii.fbx";
  const auto s = summary(uneven, 3);
  EXPECT_EQ(s["unreadable"], 1);
  bool listed = false;
  for (const auto& f : s["files"])
    if (f.contains("error")) listed = f["file"].get<std::string>().find("broken.bvh") != std::string::npos;
  EXPECT_TRUE(listed);
  EXPECT_NE(notes_of(s, "ufbx_maya_interpolation_modes_7500_ascii.fbx").find("non-uniform key spacing"),
            std::string::npos);
}

TEST_F(InfoSummary, TheTextTableHasARowPerFileAndTheHistogram) {
  const auto r = run_cli("info --summary " + (dir_ / "set").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("4 files: 4 read, 0 unreadable, 4 with notes, 1 group of identical files"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("30 Hz  3 files"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("0.016667"), std::string::npos) << r.out;
}

TEST_F(InfoSummary, WithoutSummaryAFolderOrSeveralFilesAreAUsageError) {
  for (const std::string& args : {(dir_ / "set").string(),
                                  (dir_ / "set" / "sixty.bvh").string() + " " + (dir_ / "set" / "thirty.bvh").string()}) {
    const auto r = run_cli("info " + args);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("--summary"), std::string::npos) << r.err;
  }
}

}  // namespace
}  // namespace rotinterp
