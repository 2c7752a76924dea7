// The importer kept across files (include/rotinterp/io/process/importer.h): one process per reading thread
// reads file after file, and a file that crashes it, outlasts its deadline or
// answers too much costs that file alone — the next one on the same thread reads
// as it would in a fresh importer. The importer ends with its thread.
#include "identical_info.h"
#include "rotinterp/io/process/importer.h"
#include "importer_test_util.h"
#include "io_test_util.h"
#include "rotinterp/io/read.h"
#include "support/hostile_files.h"
#include "rotinterp/io/process/process_errors.h"

#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <filesystem>
#include <functional>
#include <thread>

namespace rotinterp {
namespace {

using test::kData;

std::vector<std::filesystem::path> shared_fbx() {
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(kData / "fbx")) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

const std::filesystem::path kGood = kData / "fbx" / "digitalrune_Dude.fbx";

// Runs `body` on a thread of its own: a thread that has no importer yet.
void on_a_new_thread(const std::function<void()>& body) { std::thread(body).join(); }

// Whether `pid` was a child of this process and has been reaped: no zombie left.
bool reaped(pid_t pid) {
  int status = 0;
  return ::waitpid(pid, &status, WNOHANG) < 0 && errno == ECHILD;
}

// After `gone` was stopped: the next file reads, in a new importer that is then kept.
void expect_a_new_importer_kept(pid_t gone) {
  const Result<Clip> after = read_clip(kGood);
  EXPECT_TRUE(after) << after.error();
  const pid_t next = detail::importer_of_this_thread();
  EXPECT_NE(next, gone);
  EXPECT_TRUE(read_clip(kGood));
  EXPECT_EQ(detail::importer_of_this_thread(), next);
}

TEST(ImporterReuse, OneImporterReadsEveryFileOfAThread) {
#ifdef ROTINTERP_SANITIZED
  GTEST_SKIP() << "ASan's quarantine and shadow memory pass the 256 MiB resident mark above which an importer "
                  "is replaced (kRestartAboveResidentBytes)";
#endif
  const auto files = shared_fbx();
  ASSERT_GE(files.size(), 2u);
  on_a_new_thread([&] {
    const long started = detail::importers_started();
    EXPECT_EQ(detail::importer_of_this_thread(), -1);
    std::vector<pid_t> pids;
    for (const auto& f : files) {
      (void)read_clip(f);
      pids.push_back(detail::importer_of_this_thread());
    }
    EXPECT_EQ(detail::importers_started() - started, 1);
    EXPECT_GT(pids.front(), 0);
    EXPECT_EQ(std::count(pids.begin(), pids.end(), pids.front()), static_cast<long>(pids.size()));
    EXPECT_EQ(test::children_named(::getpid(), "rotinterp-impor"), std::vector<pid_t>{pids.front()});
  });
}

TEST(ImporterReuse, ACrashCostsOnlyTheFileThatCausedIt) {
  test::TempDir dir;
  const auto no_keys = dir / "no_keys.fbx";  // assimp segfaults on it
  test::write_text(no_keys, test::fbx_one_curve("", "", 0));
  Result<Clip> fresh_crash = make_error("not read");
  on_a_new_thread([&] { fresh_crash = read_clip(no_keys); });
  ASSERT_FALSE(fresh_crash);
  const Result<Clip> before = read_clip(kGood);
  ASSERT_TRUE(before) << before.error();

  on_a_new_thread([&] {
    ASSERT_TRUE(read_clip(kGood));
    const pid_t first = detail::importer_of_this_thread();
    const Result<Clip> crash = read_clip(no_keys);
    ASSERT_FALSE(crash);
    EXPECT_EQ(crash.error_kind(), process_error::crashed);
    EXPECT_EQ(crash.error(), fresh_crash.error());  // the same message as from an importer's first file
    EXPECT_TRUE(reaped(first));
    const Result<Clip> after = read_clip(kGood);
    ASSERT_TRUE(after) << after.error();
    test::expect_identical(*after, *before, "after the crash");
    const pid_t second = detail::importer_of_this_thread();
    EXPECT_NE(second, first);
    ASSERT_TRUE(read_clip(kGood));
    EXPECT_EQ(detail::importer_of_this_thread(), second);  // kept again
  });
}

TEST(ImporterReuse, ATimeoutCostsOnlyTheFileThatTookTooLong) {
  test::TempDir dir;
  const auto slow = dir / "long.bvh";
  test::write_long_bvh(slow);
  on_a_new_thread([&] {
    ASSERT_TRUE(read_clip(kGood));
    const pid_t first = detail::importer_of_this_thread();
    ReadOptions options;
    options.cross_check_with_assimp = true;  // assimp, in the importer, for seconds
    options.import_timeout_seconds = 0.3;
    const Result<Clip> late = read_clip(slow, options);
    ASSERT_FALSE(late);
    EXPECT_EQ(late.error_kind(), process_error::timed_out);
    EXPECT_NE(late.error().find("took longer than 0.3 s"), std::string::npos) << late.error();
    EXPECT_TRUE(reaped(first));
    EXPECT_EQ(detail::importer_of_this_thread(), -1);
    expect_a_new_importer_kept(first);
  });
}

TEST(ImporterReuse, AReplyPastTheCapCostsOnlyThatFile) {
  on_a_new_thread([&] {
    ASSERT_TRUE(read_clip(kGood));
    const pid_t first = detail::importer_of_this_thread();
    ReadOptions options;
    options.max_import_bytes = 100;
    const Result<Clip> big = read_clip(kGood, options);
    ASSERT_FALSE(big);
    EXPECT_EQ(big.error_kind(), process_error::too_large);
    EXPECT_NE(big.error().find("passed 100 bytes"), std::string::npos) << big.error();
    EXPECT_TRUE(reaped(first));
    expect_a_new_importer_kept(first);
  });
}

TEST(ImporterReuse, AnImporterKilledWhileIdleIsReplacedNotBlamedOnTheNextFile) {
  on_a_new_thread([&] {
    ASSERT_TRUE(read_clip(kGood));
    const pid_t first = detail::importer_of_this_thread();
    ASSERT_EQ(::kill(first, SIGKILL), 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    expect_a_new_importer_kept(first);
    EXPECT_TRUE(reaped(first));
  });
}

TEST(ImporterReuse, AThreadsImporterEndsWithTheThread) {
  pid_t importer = -1;
  on_a_new_thread([&] {
    ASSERT_TRUE(read_clip(kGood));
    importer = detail::importer_of_this_thread();
  });
  ASSERT_GT(importer, 0);
  EXPECT_TRUE(reaped(importer)) << "the importer outlived its thread, or was left a zombie";
}

}  // namespace
}  // namespace rotinterp
