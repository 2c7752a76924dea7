// `rotinterp reduce PATH... -o DIR`: whole folders on the folder run resample uses —
// each output the same bytes as that clip's own reduce, a bad file one line and exit 3,
// resumable, in shards.
#include "support/run_cli.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace rotinterp {
namespace {

namespace fs = std::filesystem;
using test::run_cli;
using test::slurp;

class ReduceFolder : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("rotinterp_reduce_folder_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "in" / "walks");
  }
  void TearDown() override { fs::remove_all(dir_); }

  // The shipped walk and `synthesized` synthetic clips, in in/ and in/walks; their paths.
  std::vector<std::string> make_inputs(int synthesized) {
    std::vector<std::string> made = {(dir_ / "in" / "walk.bvh").string()};
    fs::copy_file(fs::path(ROTINTERP_SOURCE_DIR) / "samples" / "walk.bvh", made.front());
    for (int i = 0; i < synthesized; ++i) {
      const std::string p = (dir_ / "in" / (i % 2 ? "" : "walks") / ("clip" + std::to_string(i) + ".bvh")).string();
      const auto r = run_cli("synth " + p + " --kind walk --seconds 1 --fps 60 --seed " + std::to_string(i + 1) + " -q");
      EXPECT_EQ(r.exit_code, 0) << r.err;
      made.push_back(p);
    }
    return made;
  }
  std::string in() const { return (dir_ / "in").string(); }
  fs::path out() const { return dir_ / "out"; }

  // Relative path → bytes of every file under `root`.
  static std::map<std::string, std::string> files_under(const fs::path& root) {
    std::map<std::string, std::string> files;
    for (const auto& e : fs::recursive_directory_iterator(root))
      if (e.is_regular_file()) files[e.path().lexically_relative(root).string()] = slurp(e.path());
    return files;
  }

  // The "input" column of a manifest.
  static std::vector<std::string> manifest_inputs(const fs::path& csv) {
    std::istringstream text(slurp(csv));
    std::string line;
    std::getline(text, line);
    EXPECT_EQ(line.rfind("input,output,status,method,", 0), 0u) << line;
    std::vector<std::string> inputs;
    while (std::getline(text, line)) inputs.push_back(line.substr(0, line.find(',')));
    return inputs;
  }

  fs::path dir_;
};

TEST_F(ReduceFolder, EachOutputIsItsOwnReduceAndABadFileIsOneLineWithExit3) {
  const std::vector<std::string> inputs = make_inputs(2);
  std::ofstream(dir_ / "in" / "walks" / "broken.bvh") << "HIERARCHY\nROOT Hips\n{\n";
  const std::string options = " -m squad --tolerance 1deg,2mm";
  const auto r = run_cli("reduce " + in() + " -o " + out().string() + options + " -j 2 -q");
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("broken.bvh"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  const auto folder = files_under(out());
  ASSERT_EQ(folder.size(), inputs.size());
  for (const std::string& input : inputs) {
    const std::string rel = fs::path(input).lexically_relative(in()).replace_extension(".json").string();
    const fs::path one = dir_ / "one.json";
    const auto single = run_cli("reduce " + input + " -o " + one.string() + options + " -q");
    ASSERT_EQ(single.exit_code, 0) << single.err;
    ASSERT_EQ(folder.count(rel), 1u) << rel;
    EXPECT_TRUE(folder.at(rel) == slurp(one)) << rel << " differs from its own reduce";
  }
}

TEST_F(ReduceFolder, FormatWritesThatFormatForEveryFileAsItsOwnReduceDoes) {
  const std::vector<std::string> inputs = make_inputs(1);
  const auto r = run_cli("reduce " + in() + " -o " + out().string() + " --format glb -m gltf-cubic -q");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const fs::path one = dir_ / "one.glb";
  ASSERT_EQ(run_cli("reduce " + inputs.front() + " -o " + one.string() + " -m gltf-cubic -q").exit_code, 0);
  EXPECT_TRUE(slurp(out() / "walk.glb") == slurp(one));
  EXPECT_TRUE(fs::exists(out() / "walks" / "clip0.glb"));
}

TEST_F(ReduceFolder, WithoutFormatAGlbInputStaysGlbAndAMethodItCannotReplayFailsThatFileAlone) {
  const std::vector<std::string> inputs = make_inputs(1);
  const std::string glb = (dir_ / "in" / "walks" / "g.glb").string();
  ASSERT_EQ(run_cli("resample " + inputs.front() + " -o " + glb + " -q").exit_code, 0);
  auto r = run_cli("reduce " + in() + " -o " + out().string() + " -q");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(out() / "walks" / "g.glb"));
  EXPECT_TRUE(fs::exists(out() / "walk.json"));
  fs::remove_all(out());
  r = run_cli("reduce " + in() + " -o " + out().string() + " -m squad -q");
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("g.glb: a glTF viewer replays only"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(files_under(out()).size(), 2u);
}

TEST_F(ReduceFolder, SkipExistingLeavesAnExistingOutputUntouched) {
  make_inputs(2);
  fs::create_directories(out());
  std::ofstream(out() / "walk.json") << "kept as it was\n";
  const auto r = run_cli("reduce " + in() + " -o " + out().string() + " --skip-existing -q");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(slurp(out() / "walk.json"), "kept as it was\n");
  EXPECT_EQ(files_under(out()).size(), 3u);
  // Without it the output is made again.
  ASSERT_EQ(run_cli("reduce " + in() + " -o " + out().string() + " -q").exit_code, 0);
  EXPECT_NE(slurp(out() / "walk.json"), "kept as it was\n");
}

TEST_F(ReduceFolder, ShardsPartitionTheInputs) {
  const std::vector<std::string> inputs = make_inputs(4);
  std::multiset<std::string> seen;
  for (const char* shard : {"1/2", "2/2"}) {
    const fs::path csv = dir_ / (std::string("m") + shard[0] + ".csv");
    const auto r = run_cli("reduce " + in() + " -o " + out().string() + " --shard " + shard + " --manifest " +
                           csv.string() + " -q");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto mine = manifest_inputs(csv);
    EXPECT_FALSE(mine.empty()) << shard;
    seen.insert(mine.begin(), mine.end());
  }
  EXPECT_EQ(seen, std::multiset<std::string>(inputs.begin(), inputs.end()));
  EXPECT_EQ(files_under(out()).size(), inputs.size());
}

TEST_F(ReduceFolder, FolderOptionsAreUsageErrorsForOneFileAndFolderRunsRefuseWhatTheyCannotDo) {
  make_inputs(1);
  const std::string clip = in() + "/walk.bvh", dir_out = " -o " + out().string();
  for (const std::string& args :
       {clip + " -o k.json --manifest m.csv", clip + " -o k.json --shard 1/2", clip + " -o k.json --skip-existing",
        in() + dir_out + " --format bvh", in() + dir_out + " --format glb -m squad", in() + dir_out + " -m slerp,squad",
        in() + dir_out + " --report r.json", in() + " -o k.json", in()}) {
    const auto r = run_cli("reduce " + args);
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
  }
  EXPECT_FALSE(fs::exists(out()));
}

}  // namespace
}  // namespace rotinterp
