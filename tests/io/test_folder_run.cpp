// The folder-run facility (batch/folder_run.h): inputs and shards, tasks in input
// order, skip-existing, failures with their kind, the manifest.
#include "rotinterp/batch/folder_run.h"
#include "rotinterp/io/files/file_errors.h"
#include "rotinterp/io/process/process_errors.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace rotinterp {
namespace {

namespace fs = std::filesystem;

class FolderRun : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("rotinterp_folder_run_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "in" / "sub");
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Files the discovery takes for clips (their contents are never read here).
  std::vector<std::string> make_inputs(int count) {
    std::vector<std::string> made;
    for (int i = 0; i < count; ++i) {
      const fs::path p = dir_ / "in" / (i % 2 ? "sub" : "") / ("c" + std::to_string(i) + ".bvh");
      std::ofstream(p) << "x";
      made.push_back(p.string());
    }
    return made;
  }
  fs::path in() const { return dir_ / "in"; }

  fs::path dir_;
};

TEST_F(FolderRun, TheShardsOfARunPartitionTheFilesFound) {
  make_inputs(7);
  const auto all = find_run_inputs({in()});
  ASSERT_TRUE(all) << all.error();
  ASSERT_EQ(all->size(), 7u);
  std::multiset<std::string> joined;
  for (int s = 1; s <= 3; ++s) {
    const auto part = find_run_inputs({in()}, s, 3);
    ASSERT_TRUE(part) << part.error();
    EXPECT_GE(part->size(), 2u);
    joined.insert(part->begin(), part->end());
  }
  EXPECT_EQ(joined, std::multiset<std::string>(all->begin(), all->end()));
  EXPECT_FALSE(find_run_inputs({in()}, 4, 3));
  EXPECT_FALSE(find_run_inputs({in()}, 0, 3));
}

TEST_F(FolderRun, AFolderWithoutClipsAndAMissingPathAreErrorsNamingThem) {
  fs::create_directories(dir_ / "empty");
  const auto none = find_run_inputs({dir_ / "empty"});
  ASSERT_FALSE(none);
  EXPECT_NE(none.error().find("empty: no clip files found"), std::string::npos) << none.error();
  const auto missing = find_run_inputs({dir_ / "nowhere"});
  ASSERT_FALSE(missing);
  EXPECT_NE(missing.error().find("nowhere"), std::string::npos) << missing.error();
}

TEST_F(FolderRun, ResultsComeBackInInputOrderWithABoundedNumberInFlight) {
  constexpr std::size_t kTasks = 40, kWindow = 4;
  std::atomic<std::size_t> started{0}, taken{0}, most_ahead{0};
  std::vector<std::size_t> order;
  run_in_order<std::size_t>(
      kTasks, 3, kWindow,
      [&](std::size_t k) {
        const std::size_t ahead = ++started - taken;
        std::size_t seen = most_ahead;
        while (ahead > seen && !most_ahead.compare_exchange_weak(seen, ahead)) {
        }
        // Early tasks take longest, so later ones finish first.
        std::this_thread::sleep_for(std::chrono::microseconds(200 * ((kTasks - k) % 5)));
        return k * k;
      },
      [&](std::size_t k, std::size_t value) {
        EXPECT_EQ(value, k * k);
        order.push_back(k);
        ++taken;
        return true;
      });
  ASSERT_EQ(order.size(), kTasks);
  for (std::size_t k = 0; k < kTasks; ++k) EXPECT_EQ(order[k], k);
  EXPECT_LE(most_ahead.load(), kWindow);
}

TEST_F(FolderRun, NoTaskStartsItsWorkAfterTheCallerStops) {
  std::atomic<std::size_t> ran{0};
  std::size_t takes = 0;
  run_in_order<int>(
      100, 2, 4,
      [&](std::size_t) {
        ++ran;
        return 1;
      },
      [&](std::size_t k, int) {
        ++takes;
        return k < 9;
      });
  EXPECT_EQ(takes, 10u);
  EXPECT_LE(ran.load(), 10u + 4u);  // the ten taken, and at most the window behind them
}

TEST_F(FolderRun, FailuresKeepTheirKindAndComeInInputOrder) {
  const auto inputs = make_inputs(6);
  std::vector<RunFile> files;
  for (const std::string& f : inputs) files.push_back({f, {}});
  std::vector<std::string> said;
  std::vector<std::thread::id> said_on;
  FileRunOptions o;
  o.named = {in()};
  o.threads = 3;
  o.on_failure = [&](const FileFailure& f) {
    said.push_back(f.file);
    said_on.push_back(std::this_thread::get_id());
  };
  const FileRunReport r = run_files(files, o, [&](std::size_t i, unsigned) -> Status {
    if (i == 1) return make_error(files[i].input + ": the importer crashed", process_error::crashed);
    if (i == 2) return make_error(files[i].input + ": no animation", file_error::no_animation);
    if (i == 4) return make_error(files[i].input + ": too large", process_error::too_large);
    return Ok{};
  });
  ASSERT_EQ(r.outcomes.size(), 6u);
  ASSERT_EQ(r.failures.size(), 2u);
  EXPECT_EQ(r.failures[0].file, inputs[1]);
  EXPECT_EQ(r.failures[0].kind, process_error::crashed);
  EXPECT_EQ(r.failures[0].message, inputs[1] + ": the importer crashed");
  EXPECT_EQ(r.failures[1].file, inputs[4]);
  EXPECT_EQ(r.failures[1].kind, process_error::too_large);
  EXPECT_EQ(said, (std::vector<std::string>{inputs[1], inputs[4]}));
  for (const auto& id : said_on) EXPECT_EQ(id, std::this_thread::get_id());
  // A file found in a folder with no animation is a mesh next to the clips: skipped, not failed.
  EXPECT_EQ(r.outcomes[2].status, FileStatus::no_animation);
  EXPECT_EQ(r.count(FileStatus::ok), 3u);
  EXPECT_EQ(r.count(FileStatus::failed), 2u);
}

TEST_F(FolderRun, ANamedFileWithoutAnimationFails) {
  const auto inputs = make_inputs(1);
  FileRunOptions o;
  o.named = {fs::path(inputs[0])};
  const FileRunReport r = run_files({{inputs[0], {}}}, o, [&](std::size_t, unsigned) -> Status {
    return make_error("no animation", file_error::no_animation);
  });
  ASSERT_EQ(r.failures.size(), 1u);
  EXPECT_EQ(r.failures[0].kind, file_error::no_animation);
  EXPECT_EQ(r.outcomes[0].status, FileStatus::failed);
}

TEST_F(FolderRun, SkipExistingRunsNoJobForAnOutputAlreadyThere) {
  const auto inputs = make_inputs(3);
  std::vector<RunFile> files;
  for (std::size_t i = 0; i < inputs.size(); ++i)
    files.push_back({inputs[i], dir_ / "out" / "deep" / ("o" + std::to_string(i) + ".bvh")});
  fs::create_directories(dir_ / "out" / "deep");
  std::ofstream(files[1].output) << "earlier run";
  std::mutex m;
  std::set<std::size_t> ran;
  auto job = [&](std::size_t i, unsigned) -> Status {
    EXPECT_TRUE(fs::is_directory(files[i].output.parent_path()));  // made for it
    std::lock_guard<std::mutex> lock(m);
    ran.insert(i);
    return Ok{};
  };
  FileRunOptions o;
  o.skip_existing = true;
  const FileRunReport skipped = run_files(files, o, job);
  EXPECT_EQ(ran, (std::set<std::size_t>{0, 2}));
  EXPECT_EQ(skipped.outcomes[1].status, FileStatus::exists);
  EXPECT_EQ(skipped.count(FileStatus::exists), 1u);
  ran.clear();
  o.skip_existing = false;
  const FileRunReport again = run_files(files, o, job);
  EXPECT_EQ(ran, (std::set<std::size_t>{0, 1, 2}));
  EXPECT_EQ(again.count(FileStatus::ok), 3u);
}

TEST_F(FolderRun, AJobIsGivenItsShareOfTheWorkersAndProgressCountsEveryFile) {
  const auto inputs = make_inputs(1);
  unsigned given = 0;
  std::size_t last_done = 0, last_total = 0;
  FileRunOptions o;
  o.threads = 4;
  o.progress = [&](std::size_t done, std::size_t total) {
    last_done = done;
    last_total = total;
  };
  run_files({{inputs[0], {}}}, o, [&](std::size_t, unsigned threads) -> Status {
    given = threads;
    return Ok{};
  });
  EXPECT_EQ(given, 1u);  // one file: one worker, so its share is that worker
  EXPECT_EQ(last_done, 1u);
  EXPECT_EQ(last_total, 1u);
}

TEST_F(FolderRun, TheManifestHasARowPerFileWithItsStatusThenTheCallersColumns) {
  std::vector<FileOutcome> outcomes = {{"a.bvh", "out/a.bvh", FileStatus::ok, "", ErrorKind::other},
                                       {"b.bvh", "out/b.bvh", FileStatus::exists, "", ErrorKind::other},
                                       {"c, d.bvh", "out/c.bvh", FileStatus::failed, "c, d.bvh: bad", ErrorKind::other},
                                       {"m.fbx", "out/m.bvh", FileStatus::no_animation, "", file_error::no_animation}};
  const fs::path path = dir_ / "manifest.csv";
  ASSERT_TRUE(write_manifest(path, outcomes, {"message", "n"}, [&](std::size_t i) -> std::vector<std::string> {
    return {outcomes[i].message, std::to_string(i)};
  }));
  std::ifstream f(path);
  std::stringstream text;
  text << f.rdbuf();
  EXPECT_EQ(text.str(),
            "input,output,status,message,n\n"
            "a.bvh,out/a.bvh,ok,,0\n"
            "b.bvh,out/b.bvh,exists,,1\n"
            "\"c, d.bvh\",out/c.bvh,failed,\"c, d.bvh: bad\",2\n"
            "m.fbx,out/m.bvh,no-animation,,3\n");
}

}  // namespace
}  // namespace rotinterp
