// The one import layer (include/rotinterp/io/process/importer.h): every assimp import runs in the
// importer process, rotinterp-import. What the caller sees (clip, info, errors and
// their kinds, warnings and their order) is exactly what the same read in this
// process gives; an importer that crashes, hangs, answers too much or loses its
// parent ends, and only the one file fails.
#include "identical_info.h"
#include "rotinterp/io/process/importer.h"
#include "importer_test_util.h"
#include "io_test_util.h"
#include "rotinterp/io/info.h"
#include "rotinterp/io/read.h"
#include "support/hostile_files.h"
#include "rotinterp/io/files/file_errors.h"
#include "rotinterp/io/process/process_errors.h"

#include <gtest/gtest.h>

#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <thread>

namespace rotinterp {
namespace {

using test::alive;
using test::children_named;
using test::expect_identical;
using test::FakeImporter;
using test::kData;

struct Reading {
  Result<ClipFileInfo> info = make_error("not read");
  std::vector<std::string> warnings;  // as passed to on_warning
};

// Through the importer, as every caller reads.
Reading read_through_importer(const std::filesystem::path& path, ReadOptions options) {
  Reading r;
  options.on_warning = [&](const std::string& w) { r.warnings.push_back(w); };
  r.info = inspect_clip(path, options);
  return r;
}

// Returns whether the file read.
bool expect_same_reading(const std::filesystem::path& path, const ReadOptions& options = {}) {
  const std::string where = path.filename().string() + (options.animation.empty() ? "" : " --anim " + options.animation);
  SCOPED_TRACE(where);
  const Reading a = read_through_importer(path, options);
  const ReadOutcome b = detail::read_in_this_process(path, options);
  EXPECT_EQ(a.warnings, b.info.warnings);
  EXPECT_EQ(a.info.ok(), !b.error);
  if (a.info && !b.error) {
    expect_identical(*a.info, b.info, where);
    EXPECT_EQ(a.info->warnings, a.warnings);
  } else if (!a.info && b.error) {
    EXPECT_EQ(a.info.error(), *b.error);
    EXPECT_EQ(a.info.error_kind(), b.kind);
  }
  Result<Clip> clip = read_clip(path, options);
  EXPECT_EQ(clip.ok(), a.info.ok());
  if (clip && a.info) expect_identical(*clip, a.info->clip, where);
  return a.info.ok();
}

std::vector<std::filesystem::path> shared_fbx() {
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(kData / "fbx")) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

TEST(ImportProcess, EverySharedFbxReadsTheSameAsInProcess) {
  const auto files = shared_fbx();
  ASSERT_FALSE(files.empty()) << kData / "fbx";
  std::size_t read = 0;
  for (const auto& f : files) read += expect_same_reading(f);
  EXPECT_GT(read, files.size() / 2);
}

TEST(ImportProcess, ErrorsAreTheSameAsInProcess) {
  for (const auto& f : shared_fbx()) {
    ReadOptions missing;
    missing.animation = "no such take";
    EXPECT_FALSE(expect_same_reading(f, missing));
    missing.animation = "99";
    EXPECT_FALSE(expect_same_reading(f, missing));
  }
  test::TempDir dir;
  test::write_text(dir / "garbage.fbx", "Kaydara FBX Binary  \0 not really");
  test::write_text(dir / "unknown.xyz", "nothing any importer knows\n");
  test::write_text(dir / "still.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  for (const char* name : {"garbage.fbx", "unknown.xyz", "still.obj"}) EXPECT_FALSE(expect_same_reading(dir / name));
}

TEST(ImportProcess, WarningsReachTheCallerInTheSameOrder) {
  test::TempDir dir;
  // A zero tick rate and a non-uniform scale: two warnings, then a clip.
  test::write_text(dir / "zero_rate.x", test::zero_rate_x_scene("2.0"));
  ASSERT_TRUE(expect_same_reading(dir / "zero_rate.x"));
  std::vector<std::string> warnings;
  ReadOptions options;
  options.on_warning = [&](const std::string& w) { warnings.push_back(w); };
  ASSERT_TRUE(read_clip(dir / "zero_rate.x", options));
  ASSERT_EQ(warnings.size(), 2u) << ::testing::PrintToString(warnings);
  EXPECT_NE(warnings[0].find("gives 0 ticks per second"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[1].find("non-uniform scale"), std::string::npos) << warnings[1];
}

TEST(ImportProcess, ErrorsComeBackWithTheirKind) {
  test::TempDir dir;
  test::write_text(dir / "garbage.fbx", std::string(200, 'x'));
  test::write_text(dir / "still.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  test::write_text(dir / "no_keys.fbx", test::fbx_one_curve("", "", 0));
  test::write_text(dir / "empty.fbx", "");
  std::filesystem::create_symlink(dir / "missing.fbx", dir / "dangling.fbx");
  std::filesystem::create_directory(dir / "folder.fbx");
  // What the file system says has kinds of its own (the Python module raises
  // FileNotFoundError, IsADirectoryError by them).
  const struct {
    std::filesystem::path path;
    ErrorKind kind;
  } cases[] = {{dir / "missing.fbx", file_error::no_file},
               {dir / "dangling.fbx", file_error::no_file},
               {dir / "folder.fbx", file_error::directory},
               {dir / "empty.fbx", file_error::unreadable},
               {dir / "garbage.fbx", file_error::unreadable},
               {dir / "still.obj", file_error::no_animation},
               {dir / "no_keys.fbx", process_error::crashed}};
  for (const auto& c : cases) {
    Result<Clip> clip = read_clip(c.path);
    ASSERT_FALSE(clip) << c.path;
    EXPECT_EQ(clip.error_kind(), c.kind) << clip.error();
    EXPECT_EQ(clip.error().rfind(c.path.string() + ": ", 0), 0u) << clip.error();
  }
}

TEST(ImportProcess, ReadsFromManyThreadsAtOnceAgree) {
  // The importer is spawned, never forked from this process: safe while other
  // threads allocate, in release and sanitizer builds alike (GCC 12's ASan
  // allocator hung a forked child under eval -j 2).
  const auto files = shared_fbx();
  std::vector<Result<Clip>> alone;
  for (const auto& f : files) alone.push_back(read_clip(f));
  std::vector<std::thread> threads;
  std::vector<int> mismatches(4, 0);
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&, t] {
      for (std::size_t i = 0; i < files.size(); ++i) {
          std::vector<int> churn(1000 + static_cast<std::size_t>(t));  // allocations while others spawn
          Result<Clip> c = read_clip(files[(i + static_cast<std::size_t>(t)) % files.size()]);
          const Result<Clip>& a = alone[(i + static_cast<std::size_t>(t)) % files.size()];
          if (c.ok() != a.ok() || (c && c->rotations.size() != a->rotations.size())) ++mismatches[static_cast<std::size_t>(t)];
        }
    });
  for (std::thread& t : threads) t.join();
  EXPECT_EQ(mismatches, std::vector<int>(4, 0));
}

TEST(ImportProcess, AnImporterThatHangsIsKilledAtTheDeadline) {
  test::TempDir dir;
  test::write_text(dir / "a.fbx", "anything");
  const FakeImporter fake(dir, "exec sleep 60");
  ReadOptions options;
  options.import_timeout_seconds = 0.5;
  const auto start = std::chrono::steady_clock::now();
  Result<Clip> clip = read_clip(dir / "a.fbx", options);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_FALSE(clip);
  EXPECT_EQ(clip.error_kind(), process_error::timed_out);
  EXPECT_NE(clip.error().find("took longer than 0.5 s"), std::string::npos) << clip.error();
  EXPECT_LT(seconds, 5.0);
}

TEST(ImportProcess, AnImporterThatAnswersTooMuchIsStopped) {
  test::TempDir dir;
  test::write_text(dir / "a.fbx", "anything");
  const FakeImporter fake(dir, "exec yes");
  ReadOptions options;
  options.max_import_bytes = 1 << 20;
  Result<Clip> clip = read_clip(dir / "a.fbx", options);
  ASSERT_FALSE(clip);
  EXPECT_EQ(clip.error_kind(), process_error::too_large);
  EXPECT_NE(clip.error().find("passed 1048576 bytes"), std::string::npos) << clip.error();
}

TEST(ImportProcess, AGarbledOrMissingImporterIsAnErrorNotACrash) {
  test::TempDir dir;
  test::write_text(dir / "a.fbx", "anything");
  {
    const FakeImporter fake(dir, "echo not a clip record");
    Result<Clip> clip = read_clip(dir / "a.fbx");
    ASSERT_FALSE(clip);
    EXPECT_EQ(clip.error_kind(), process_error::crashed);
    EXPECT_NE(clip.error().find("its report was cut short or garbled"), std::string::npos) << clip.error();
  }
  ::setenv("ROTINTERP_IMPORTER", (dir / "nowhere").c_str(), 1);
  Result<Clip> clip = read_clip(dir / "a.fbx");
  ::unsetenv("ROTINTERP_IMPORTER");
  ASSERT_FALSE(clip);
  EXPECT_NE(clip.error().find("ROTINTERP_IMPORTER=" + (dir / "nowhere").string() + ": not an executable file"),
            std::string::npos)
      << clip.error();
  Result<std::filesystem::path> found = find_importer();  // without the variable: the build's
  ASSERT_TRUE(found) << found.error();
  EXPECT_EQ(found->filename(), "rotinterp-import");
}

TEST(ImportProcess, TheImporterDiesWithItsParent) {
  // A parent killed with SIGKILL cannot clean up: the importer must end by itself
  // (PR_SET_PDEATHSIG) rather than keep importing (it ran on for seconds).
  test::TempDir dir;
  const auto path = dir / "long.bvh";
  test::write_long_bvh(path);
  const pid_t parent = ::fork();
  ASSERT_GE(parent, 0);
  if (parent == 0) {
    ReadOptions options;
    options.cross_check_with_assimp = true;  // a BVH through assimp: in the importer
    (void)read_clip(path, options);
    ::_exit(0);
  }
  std::vector<pid_t> importer;
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (importer.empty() && std::chrono::steady_clock::now() < give_up) {
    importer = children_named(parent, "rotinterp-impor");  // names are cut at 15 bytes
    if (importer.empty()) std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  ::kill(parent, SIGKILL);
  int status = 0;
  ::waitpid(parent, &status, 0);
  ASSERT_EQ(importer.size(), 1u) << "the importer was not seen running";
  const auto killed = std::chrono::steady_clock::now();
  while (alive(importer[0]) && std::chrono::steady_clock::now() - killed < std::chrono::seconds(2))
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  EXPECT_FALSE(alive(importer[0])) << "the importer outlived its parent";
}

}  // namespace
}  // namespace rotinterp
