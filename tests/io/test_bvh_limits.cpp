// Hostile BVH text: nesting, joint counts, huge tokens, encodings, frame times and
// paths that used to crash, crawl or print megabytes. Each fails (or reads) with
// one short line, through the library and every subcommand.
#include "io_test_util.h"
#include "rotinterp/io/bvh/bvh.h"
#include "rotinterp/io/read.h"
#include "support/hostile_files.h"
#include "support/run_cli.h"

#include <gtest/gtest.h>

#include <sys/resource.h>

#include <filesystem>
#include <string>

namespace rotinterp {
namespace {

// A root with `n` child joints (siblings), each with an End Site.
std::string sibling_bvh(std::size_t n) {
  std::string s = "HIERARCHY\nROOT Root\n{\nOFFSET 0 0 0\nCHANNELS 3 Zrotation Xrotation Yrotation\n";
  for (std::size_t i = 0; i < n; ++i)
    s += "JOINT J" + std::to_string(i) + "\n{\nOFFSET 0 1 0\nCHANNELS 3 Zrotation Xrotation Yrotation\nEnd Site\n{\nOFFSET 0 1 0\n}\n}\n";
  s += "}\nMOTION\nFrames: 1\nFrame Time: 0.01\n";
  for (std::size_t i = 0; i < 3 * (n + 1); ++i) s += "0 ";
  return s + "\n";
}

// One joint and two frames; `rows` replaces the two zero rows.
std::string one_joint_bvh(const std::string& name, const std::string& frame_time, const std::string& rows = "0 0 0\n0 0 0\n") {
  return "HIERARCHY\nROOT " + name + "\n{\nOFFSET 0 0 0\nCHANNELS 3 Zrotation Xrotation Yrotation\n}\nMOTION\nFrames: 2\n" +
         "Frame Time: " + frame_time + "\n" + rows;
}

void expect_one_line(const test::CliResult& r, const std::filesystem::path& file, const std::string& what) {
  ASSERT_FALSE(r.err.empty());
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "more than one line: " << r.err.substr(0, 400);
  EXPECT_NE(r.err.find(file.string()), std::string::npos) << r.err.substr(0, 400);
  EXPECT_NE(r.err.find(what), std::string::npos) << r.err.substr(0, 400);
}

TEST(BvhLimits, NestingBeyondTheLimitIsOneLineInEverySubcommand) {
  // 15 000 nested joints overflowed the stack of the recursive parser (SIGSEGV).
  test::TempDir dir;
  const auto path = dir / "deep.bvh";
  test::write_text(path, test::nested_bvh(15000));
  const std::string what = "joints nested more than " + std::to_string(kMaxJointDepth) + " levels deep";
  const std::string out = (dir / "out").string();
  for (const std::string& command :
       {std::string("info"), "resample -o " + out + ".bvh", "eval --no-plots -q -o " + out, "render --methods slerp -q -o " + out}) {
    SCOPED_TRACE(command);
    const test::CliResult r = test::run_cli(command + " '" + path.string() + "'");
    if (command.rfind("render", 0) == 0 && r.exit_code == 2) continue;  // no renderer in this build
    EXPECT_TRUE(r.exit_code == 1 || r.exit_code == 3) << r.exit_code << " " << r.err.substr(0, 400);
    // eval names each failed file on a line of its own, then how many failed.
    expect_one_line(command.rfind("eval", 0) == 0 ? test::CliResult{0, "", r.err.substr(0, r.err.find('\n') + 1)} : r,
                    path, what);
  }
}

TEST(BvhLimits, NestingUpToTheLimitReads) {
  test::TempDir dir;
  test::write_text(dir / "deepest.bvh", test::nested_bvh(kMaxJointDepth));
  Result<Clip> clip = read_clip(dir / "deepest.bvh");
  ASSERT_TRUE(clip) << clip.error();
  EXPECT_EQ(clip->skeleton.joints.size(), kMaxJointDepth);
  EXPECT_EQ(clip->skeleton.joints.back().parent, static_cast<int>(kMaxJointDepth) - 2);
  test::write_text(dir / "deeper.bvh", test::nested_bvh(kMaxJointDepth + 1));
  Result<Clip> refused = read_clip(dir / "deeper.bvh");
  ASSERT_FALSE(refused);
  EXPECT_NE(refused.error().find("nested more than"), std::string::npos) << refused.error();
}

TEST(BvhLimits, SiblingJointsReadInLinearTime) {
  // 200 000 siblings took `info` 64 s: each name was compared with every earlier one.
  test::TempDir dir;
  const auto path = dir / "wide.bvh";
  test::write_text(path, sibling_bvh(200000));
  // CPU time of the command (≈ 1 s), not wall time, which a loaded machine stretches.
  auto children_cpu = [] {
    rusage u{};
    ::getrusage(RUSAGE_CHILDREN, &u);
    return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
           1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
  };
  const double before = children_cpu();
  const test::CliResult r = test::run_cli("info '" + path.string() + "'");
  const double seconds = children_cpu() - before;
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("J199999"), std::string::npos);
  EXPECT_LT(seconds, 15.0);
}

TEST(BvhLimits, AHugeTokenIsQuotedAsAShortExcerpt) {
  test::TempDir dir;
  const std::string huge(10'000'000, 'A');
  const auto first = dir / "first.bvh";
  test::write_text(first, huge + "\n");
  const test::CliResult a = test::run_cli("info '" + first.string() + "'");
  EXPECT_EQ(a.exit_code, 1);
  expect_one_line(a, first, "expected 'HIERARCHY', found 'AAAA");
  EXPECT_NE(a.err.find("(10000000 bytes)"), std::string::npos) << a.err.substr(0, 400);
  EXPECT_LT(a.err.size(), 300u);

  const auto name = dir / "name.bvh";
  test::write_text(name, one_joint_bvh(huge, "0.01"));
  const test::CliResult b = test::run_cli("info '" + name.string() + "'");
  EXPECT_EQ(b.exit_code, 1);
  expect_one_line(b, name, "is longer than 1024 bytes");
  EXPECT_LT(b.err.size(), 300u);

  // A bad value quotes an excerpt too, and control bytes as \xNN.
  const auto value = dir / "value.bvh";
  test::write_text(value, one_joint_bvh("Hips", "0.01", "0 0 " + huge + "\x01\n0 0 0\n"));
  const test::CliResult c = test::run_cli("info '" + value.string() + "'");
  EXPECT_EQ(c.exit_code, 1);
  expect_one_line(c, value, "not a number: 'AAAA");
  EXPECT_LT(c.err.size(), 300u);
}

TEST(BvhLimits, Utf8ByteOrderMarkIsAccepted) {
  test::TempDir dir;
  test::write_text(dir / "bom.bvh", "\xEF\xBB\xBF" + one_joint_bvh("Hips", "0.01"));
  Result<Clip> clip = read_clip(dir / "bom.bvh");
  ASSERT_TRUE(clip) << clip.error();
  EXPECT_EQ(clip->skeleton.joints[0].name, "Hips");
  // Under another extension too (found by its content).
  test::write_text(dir / "bom.txt", "\xEF\xBB\xBF" + one_joint_bvh("Hips", "0.01"));
  EXPECT_TRUE(read_clip(dir / "bom.txt"));
}

TEST(BvhLimits, Utf16TextIsNamedAsSuch) {
  test::TempDir dir;
  const std::string ascii = one_joint_bvh("Hips", "0.01");
  std::string le = "\xFF\xFE", be = "\xFE\xFF";
  for (char c : ascii) le += {c, '\0'}, be += {'\0', c};
  for (const auto& [file, bytes] : {std::pair{"le.bvh", le}, {"be.bvh", be}, {"nobom.bvh", le.substr(2)}}) {
    const auto path = dir / file;
    test::write_text(path, bytes);
    const test::CliResult r = test::run_cli("info '" + path.string() + "'");
    EXPECT_EQ(r.exit_code, 1) << file;
    expect_one_line(r, path, "UTF-16");
    EXPECT_EQ(r.err.find('\0'), std::string::npos) << file;
  }
}

TEST(BvhLimits, ImplausibleFrameTimeIsRefusedWithTheRange) {
  test::TempDir dir;
  for (const char* ft : {"1e-300", "1e300", "1e-7", "3601"}) {
    const auto path = dir / "ft.bvh";
    test::write_text(path, one_joint_bvh("Hips", ft));
    Result<Clip> clip = read_clip(path);
    ASSERT_FALSE(clip) << ft;
    EXPECT_NE(clip.error().find(std::string("'Frame Time: ") + ft + "' is outside the accepted range 1e-06 to 3600 seconds"),
              std::string::npos)
        << clip.error();
  }
  for (const char* ft : {"0.000001", "0.0083333", "3600"}) {
    test::write_text(dir / "ok.bvh", one_joint_bvh("Hips", ft));
    EXPECT_TRUE(read_clip(dir / "ok.bvh")) << ft;
  }
}

TEST(BvhLimits, SymbolicLinkLoopIsNamed) {
  test::TempDir dir;
  std::filesystem::create_symlink(dir / "b.bvh", dir / "a.bvh");
  std::filesystem::create_symlink(dir / "a.bvh", dir / "b.bvh");
  const test::CliResult loop = test::run_cli("info '" + (dir / "a.bvh").string() + "'");
  EXPECT_EQ(loop.exit_code, 1);
  expect_one_line(loop, dir / "a.bvh", "a loop of symbolic links");
  std::filesystem::create_symlink(dir / "missing.bvh", dir / "dangling.bvh");
  Result<Clip> dangling = read_clip(dir / "dangling.bvh");
  ASSERT_FALSE(dangling);
  EXPECT_NE(dangling.error().find("a symbolic link to a missing file"), std::string::npos) << dangling.error();
}

}  // namespace
}  // namespace rotinterp
