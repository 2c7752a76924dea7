// `rotinterp resample PATH... -o DIR`: whole folders, in parallel, in shards,
// resumable, with a manifest — and always the same bytes as one file at a time.
#include "support/processes.h"
#include "support/run_cli.h"

#include <gtest/gtest.h>

#include <signal.h>

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

class ResampleFolder : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("rotinterp_resample_folder_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "in" / "walks");
    fs::create_directories(dir_ / "in" / "runs" / "fast");
  }
  void TearDown() override { fs::remove_all(dir_); }

  // `count` synthetic clips spread over in/, in/walks and in/runs/fast.
  std::vector<std::string> make_inputs(int count, double seconds = 2.0) {
    std::vector<std::string> made;
    const char* subdirs[] = {"", "walks/", "runs/fast/"};
    for (int i = 0; i < count; ++i) {
      const std::string p = (dir_ / "in" / (std::string(subdirs[i % 3]) + "clip" + std::to_string(i) + ".bvh")).string();
      const auto r = run_cli("synth " + p + " --kind walk --seconds " + std::to_string(seconds) + " --fps 120 --seed " +
                             std::to_string(i + 1));
      EXPECT_EQ(r.exit_code, 0) << r.err;
      made.push_back(p);
    }
    return made;
  }
  std::string in() const { return (dir_ / "in").string(); }
  fs::path out(const std::string& name = "out") const { return dir_ / name; }

  // Relative path → bytes of every file under `root`.
  static std::map<std::string, std::string> files_under(const fs::path& root) {
    std::map<std::string, std::string> files;
    for (const auto& e : fs::recursive_directory_iterator(root))
      if (e.is_regular_file()) files[e.path().lexically_relative(root).string()] = slurp(e.path());
    return files;
  }

  // Manifest rows as column name → value.
  static std::vector<std::map<std::string, std::string>> manifest(const fs::path& csv) {
    std::istringstream text(slurp(csv));
    std::string line;
    std::getline(text, line);
    std::vector<std::string> header;
    std::stringstream h(line);
    for (std::string c; std::getline(h, c, ',');) header.push_back(c);
    std::vector<std::map<std::string, std::string>> rows;
    while (std::getline(text, line)) {
      std::map<std::string, std::string> row;
      std::stringstream l(line);
      std::string cell;
      for (std::size_t c = 0; c < header.size() && std::getline(l, cell, ','); ++c) row[header[c]] = cell;
      rows.push_back(row);
    }
    return rows;
  }

  fs::path dir_;
};

TEST_F(ResampleFolder, EqualsTheRunsFileByFileByteForByteWithTheLayoutMirrored) {
  const std::vector<std::string> inputs = make_inputs(5);
  const auto r = run_cli("resample " + in() + " -o " + out().string() + " --fps 24 -j 2 -q");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const auto folder = files_under(out());
  ASSERT_EQ(folder.size(), inputs.size());
  for (const std::string& input : inputs) {
    const std::string rel = fs::path(input).lexically_relative(in()).string();
    const fs::path one = dir_ / "one.bvh";
    const auto single = run_cli("resample " + input + " -o " + one.string() + " --fps 24 -q");
    ASSERT_EQ(single.exit_code, 0) << single.err;
    ASSERT_EQ(folder.count(rel), 1u) << rel;
    EXPECT_TRUE(folder.at(rel) == slurp(one)) << rel << " differs from its own run";
  }
}

TEST_F(ResampleFolder, FormatChangesTheExtensionAndTheManifestDescribesEveryFile) {
  const std::vector<std::string> inputs = make_inputs(3);
  const fs::path csv = dir_ / "manifest.csv";
  const auto r = run_cli("resample " + in() + " -o " + out().string() + " --keep-every 4 --format glb --manifest " +
                         csv.string() + " -q");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(out() / "walks" / "clip1.glb"));
  const auto rows = manifest(csv);
  ASSERT_EQ(rows.size(), inputs.size());
  for (const auto& row : rows) {
    EXPECT_EQ(row.at("status"), "ok");
    EXPECT_EQ(row.at("rate"), "120");
    EXPECT_EQ(row.at("frames"), "241");
    EXPECT_EQ(row.at("output_frames"), "241");
    EXPECT_EQ(row.at("method"), "clamped");
    EXPECT_NE(row.at("joints"), "");
    EXPECT_TRUE(fs::exists(row.at("output"))) << row.at("output");
  }
}

TEST_F(ResampleFolder, ShardsTogetherCoverEveryFileExactlyOnce) {
  const std::vector<std::string> inputs = make_inputs(7);
  std::multiset<std::string> seen;
  for (const char* shard : {"1/3", "2/3", "3/3"}) {
    const fs::path csv = dir_ / (std::string("m") + shard[0] + ".csv");
    const auto r = run_cli("resample " + in() + " -o " + out().string() + " --shard " + shard + " --manifest " +
                           csv.string() + " -q");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const auto& row : manifest(csv)) seen.insert(row.at("input"));
  }
  EXPECT_EQ(seen, std::multiset<std::string>(inputs.begin(), inputs.end()));
  EXPECT_EQ(files_under(out()).size(), inputs.size());
}

TEST_F(ResampleFolder, ABadFileIsNamedSkippedAndGivesExit3WithTheRestWritten) {
  make_inputs(3);
  std::ofstream(dir_ / "in" / "walks" / "broken.bvh") << "HIERARCHY\nROOT Hips\n{\n";
  const auto r = run_cli("resample " + in() + " -o " + out().string() + " -q");
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("broken.bvh"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  const auto written = files_under(out());
  EXPECT_EQ(written.size(), 3u);
  EXPECT_EQ(written.count("walks/broken.bvh"), 0u);
}

TEST_F(ResampleFolder, SkipExistingAfterASigtermFinishesTheRestAsAnUninterruptedRunWould) {
  make_inputs(12, 10.0);
  const std::vector<std::string> args = {"resample", in(), "-o", out().string(), "--fps", "240", "-j", "1", "-q"};
  const pid_t pid = test::spawn(args);
  // Stop it once some outputs are complete and others are not.
  auto outputs = [&] {
    std::size_t n = 0;
    std::error_code ec;
    for (const auto& e : fs::recursive_directory_iterator(out(), ec))
      n += e.is_regular_file() && e.path().extension() == ".bvh";
    return n;
  };
  ASSERT_TRUE(test::wait_until(pid, [&] { return outputs() >= 3; }, 120.0)) << "the run ended early";
  ::kill(pid, SIGTERM);
  EXPECT_EQ(test::exit_status(pid), 128 + SIGTERM);
  const std::size_t before = outputs();
  ASSERT_LT(before, 12u);
  for (const auto& [rel, bytes] : files_under(out()))
    EXPECT_NE(fs::path(rel).filename().string()[0], '.') << "temporary left: " << rel;

  const fs::path csv = dir_ / "resume.csv";
  auto resume = args;
  resume.insert(resume.end(), {"--skip-existing", "--manifest", csv.string()});
  std::string command;
  for (const std::string& word : resume) command += word + " ";
  const auto r = run_cli(command);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::size_t existing = 0;
  for (const auto& row : manifest(csv)) existing += row.at("status") == "exists";
  EXPECT_EQ(existing, before);

  const auto fresh = run_cli("resample " + in() + " -o " + out("fresh").string() + " --fps 240 -q");
  ASSERT_EQ(fresh.exit_code, 0) << fresh.err;
  EXPECT_TRUE(files_under(out()) == files_under(out("fresh")));
}

TEST_F(ResampleFolder, OutputsInsideTheInputFolderAreNotTakenAsInputsNextTime) {
  make_inputs(3);
  const std::string inner = (dir_ / "in" / "out30").string();
  for (int run = 0; run < 2; ++run) {
    const auto r = run_cli("resample " + in() + " -o " + inner + " --fps 30");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("3 files"), std::string::npos) << r.out;
  }
}

TEST_F(ResampleFolder, RefusesTwoInputsThatWouldShareAnOutput) {
  make_inputs(3);
  fs::create_directories(dir_ / "other");
  fs::copy_file(dir_ / "in" / "clip0.bvh", dir_ / "other" / "clip0.bvh");
  const auto r = run_cli("resample " + in() + " " + (dir_ / "other").string() + " -o " + out().string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("would both be written to"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out()));
}

TEST_F(ResampleFolder, FolderOptionsAreUsageErrorsForOneFileAndBadValuesAreRefused) {
  const std::string clip = make_inputs(1).front();
  const std::string file_out = (dir_ / "x.bvh").string();
  for (const std::string& args :
       {clip + " -o " + file_out + " --manifest m.csv", clip + " -o " + file_out + " --shard 1/2",
        in() + " -o " + out().string() + " --format xyz", in() + " -o " + out().string() + " --shard 3/2"}) {
    const auto r = run_cli("resample " + args);
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  std::ofstream(file_out) << "x";
  const auto r = run_cli("resample " + in() + " -o " + file_out);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("output directory"), std::string::npos) << r.err;
}

// A run that would do nothing fails with its one line: the inputs' own folder as the
// output (every input lies inside it), or a folder holding no clip.
TEST_F(ResampleFolder, ARunThatWouldDoNothingFailsSayingWhy) {
  make_inputs(3);
  for (const std::string command : {"resample", "reduce"}) {
    const auto same = run_cli(command + " " + in() + " -o " + in() + " -q");
    EXPECT_EQ(same.exit_code, 1) << command << ": " << same.err;
    EXPECT_NE(same.err.find("rotinterp: " + in() + ": all 3 input file(s) lie inside this output folder"),
              std::string::npos)
        << same.err;
    EXPECT_EQ(std::count(same.err.begin(), same.err.end(), '\n'), 1) << same.err;
  }
  fs::create_directories(dir_ / "empty");
  std::ofstream(dir_ / "empty" / "notes.txt") << "no clip\n";
  const auto none = run_cli("resample " + (dir_ / "empty").string() + " -o " + out().string() + " -q");
  EXPECT_EQ(none.exit_code, 1) << none.err;
  EXPECT_NE(none.err.find("no clip files found"), std::string::npos) << none.err;
  EXPECT_FALSE(fs::exists(out()));
}

}  // namespace
}  // namespace rotinterp
