// ReadOptions::isolate_assimp reads a non-BVH file in a forked child that sends
// its result to the parent: what the caller sees (clip, info, errors, warnings and
// their order) is exactly what the in-process read gives.
#include "identical_info.h"
#include "io_test_util.h"
#include "rotinterp/io/info.h"
#include "rotinterp/io/read.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

namespace rotinterp {
namespace {

using test::expect_identical;
using test::kData;

struct Reading {
  Result<ClipFileInfo> info = make_error("not read");
  std::vector<std::string> info_warnings;  // as passed to on_warning
  Result<Clip> clip = make_error("not read");
  std::vector<std::string> clip_warnings;
};

Reading read(const std::filesystem::path& path, ReadOptions options, bool isolate) {
  Reading r;
  options.isolate_assimp = isolate;
  options.on_warning = [&](const std::string& w) { r.info_warnings.push_back(w); };
  r.info = inspect_clip(path, options);
  options.on_warning = [&](const std::string& w) { r.clip_warnings.push_back(w); };
  r.clip = read_clip(path, options);
  return r;
}

// Returns whether the file read.
bool expect_same_reading(const std::filesystem::path& path, const ReadOptions& options = {}) {
  const std::string where = path.filename().string() + (options.animation.empty() ? "" : " --anim " + options.animation);
  SCOPED_TRACE(where);
  const Reading a = read(path, options, true);
  const Reading b = read(path, options, false);
  EXPECT_EQ(a.info_warnings, b.info_warnings);
  EXPECT_EQ(a.clip_warnings, b.clip_warnings);
  EXPECT_EQ(a.info.ok(), b.info.ok());
  EXPECT_EQ(a.clip.ok(), b.clip.ok());
  if (a.info && b.info) {
    expect_identical(*a.info, *b.info, where);
    EXPECT_EQ(a.info->warnings, a.info_warnings);
  } else if (!a.info && !b.info) {
    EXPECT_EQ(a.info.error(), b.info.error());
  }
  if (a.clip && b.clip) {
    expect_identical(*a.clip, *b.clip, where);
  } else if (!a.clip && !b.clip) {
    EXPECT_EQ(a.clip.error(), b.clip.error());
  }
  return a.clip.ok();
}

std::vector<std::filesystem::path> shared_fbx() {
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(kData / "fbx")) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

TEST(IsolatedRead, EverySharedFbxReadsTheSameAsInProcess) {
  const auto files = shared_fbx();
  ASSERT_FALSE(files.empty()) << kData / "fbx";
  std::size_t read = 0;
  for (const auto& f : files) read += expect_same_reading(f);
  EXPECT_GT(read, files.size() / 2);
}

TEST(IsolatedRead, ErrorsAreTheSameAsInProcess) {
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

TEST(IsolatedRead, WarningsReachTheCallerInTheSameOrder) {
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

}  // namespace
}  // namespace rotinterp
