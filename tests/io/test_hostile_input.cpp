// Issue 47, classes 1–3 on every reader: a declared size is checked before anything
// is allocated for it, nothing waits on a FIFO or reads outside the file's folder,
// and bad keys are refused (or, exact repeats, dropped with a warning) on the default
// path as on our own curve reader. Each case is a shared clip mutated in the test.
#include "hostile_inputs.h"
#include "io_test_util.h"
#include "rotinterp/io/info.h"
#include "rotinterp/io/read.h"
#include "support/run_cli.h"

#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/stat.h>

#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

namespace rotinterp {
namespace {

namespace fs = std::filesystem;
using test::kData;

// The read's one-line error; a test failure (and "") when the read succeeds.
std::string refusal(const fs::path& file, const ReadOptions& options = {}) {
  Result<Clip> clip = read_clip(file, options);
  EXPECT_FALSE(clip.ok()) << file << " was read";
  if (clip.ok()) return "";
  EXPECT_EQ(clip.error().find('\n'), std::string::npos) << clip.error();
  EXPECT_EQ(clip.error().rfind(file.string(), 0), 0u) << clip.error();
  return clip.error();
}

long peak_rss_kib() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss;
}

// ---- class 1: memory ----------------------------------------------------------------

TEST(HostileInput, ZlibBombsInFbx7And61AreRefusedBeforeInflating) {
  test::TempDir dir;
  // 256 MiB of doubles from ~260 KB of zlib: more than the file's inflation budget.
  const std::string bomb = test::zlib_zeros(std::size_t{256} << 20);
  for (const char* source : {"fbx/ufbx_maya_game_sausage_7500_binary_wiggle.fbx",
                             "fbx/ufbx_maya_game_sausage_6100_binary_wiggle.fbx"}) {
    const fs::path file = dir / (fs::path(source).stem().string() + "_bomb.fbx");
    test::write_text(file, test::fbx_with_zlib_array(kData / source, std::uint32_t{1} << 25, bomb));
    const long before = peak_rss_kib();
    ReadOptions curves;
    curves.read_curves = true;  // our own reader, in the importer process
    for (const ReadOptions& options : {ReadOptions{}, curves}) {
      const std::string error = refusal(file, options);
      EXPECT_NE(error.find("FBX node Bomb"), std::string::npos) << error;
      EXPECT_NE(error.find("inflate past"), std::string::npos) << error;
    }
    Result<FbxDocument> doc = read_fbx_file(file.string(), file.string());  // in this process
    ASSERT_FALSE(doc.ok());
    EXPECT_LT(peak_rss_kib() - before, 128 * 1024) << "KiB more at peak";
  }
}

TEST(HostileInput, AnArrayCountPastItsBytesIsRefusedOnTheDefaultPath) {
  test::TempDir dir;
  for (std::uint32_t count : {0x7fffffffu, 0xffffffffu, 1000000u}) {
    const fs::path file = dir / ("count_" + std::to_string(count) + ".fbx");
    test::write_text(file, test::fbx_with_key_count(count));
    const std::string error = refusal(file);
    EXPECT_NE(error.find("FBX node Objects/AnimationCurve/KeyTime"), std::string::npos) << error;
  }
}

TEST(HostileInput, AGlbWhoseJsonLengthLiesIsRefusedAtOnce) {
  test::TempDir dir;
  for (std::uint32_t length : {0x7ffffff0u, 0xfffffff8u}) {
    const fs::path glb = test::glb_with_json_length(dir.path(), length);
    const auto start = std::chrono::steady_clock::now();
    const std::string error = refusal(glb);
    EXPECT_NE(error.find("passes the file's end"), std::string::npos) << error;
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
  }
}

TEST(HostileInput, ASparseBvhWithGarbageOnLine2IsRefusedWithoutReadingItAll) {
  test::TempDir dir;
  const fs::path bvh = test::sparse_file(dir / "sparse.bvh", "HIERARCHY\ngarbage\n", std::uintmax_t{3} << 30);
  const long before = peak_rss_kib();
  const std::string error = refusal(bvh);
  EXPECT_NE(error.find("line 2: expected ROOT or MOTION, found 'garbage'"), std::string::npos) << error;
  EXPECT_LT(peak_rss_kib() - before, 64 * 1024) << "KiB more at peak";
}

TEST(HostileInput, InfoCurvesRefusesASampleRateTooLargeOrNotANumber) {
  const std::string fbx = (kData / "fbx/ufbx_maya_game_sausage_7500_binary_wiggle.fbx").string();
  for (const char* rate : {"1e9", "nan", "inf"}) {
    const test::CliResult r = test::run_cli("info " + fbx + " --curves --json --sample " + rate);
    EXPECT_NE(r.exit_code, 0) << rate;
    EXPECT_NE(r.err.find("--sample"), std::string::npos) << rate << ": " << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
    EXPECT_TRUE(r.out.empty()) << rate;
  }
  EXPECT_EQ(test::run_cli("info " + fbx + " --curves --sample 30").exit_code, 0);
}

// ---- class 2: hangs -----------------------------------------------------------------

TEST(HostileInput, TwentyThousandNodesOfOneNameReadInLinearTime) {
  test::TempDir dir;
  test::GltfFile g = test::shared_gltf(dir.path());
  const std::size_t first = g.doc["nodes"].size(), root = g.doc["scenes"][0]["nodes"][0].get<std::size_t>();
  for (std::size_t i = 0; i < 20000; ++i) {
    g.doc["nodes"].push_back({{"name", "dup"}});
    g.doc["nodes"][root]["children"].push_back(first + i);
  }
  const auto start = std::chrono::steady_clock::now();
  Result<Clip> clip = read_clip(g.write(dir.path(), "dup.gltf"));
  ASSERT_TRUE(clip.ok()) << clip.error();
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(10));
  std::size_t dups = 0, longest = 0;
  for (const Joint& j : clip->skeleton.joints)
    if (j.name.rfind("dup", 0) == 0) ++dups, longest = std::max(longest, j.name.size());
  EXPECT_EQ(dups, 20000u);
  EXPECT_LE(longest, std::string("dup#20000").size());
  const test::CliResult info = test::run_cli("info " + (dir / "dup.gltf").string());
  EXPECT_EQ(info.exit_code, 0) << info.err;
}

TEST(HostileInput, ABufferUriNamingAFifoIsRefusedWithoutWaiting) {
  test::TempDir dir;
  const test::GltfFile g = test::shared_gltf(dir.path());
  ASSERT_EQ(::mkfifo((dir / "fifo.bin").c_str(), 0600), 0);
  const std::string error = refusal(g.write(dir.path(), "fifo.gltf", "fifo.bin"));
  EXPECT_NE(error.find("uri 'fifo.bin': not a regular file"), std::string::npos) << error;
}

TEST(HostileInput, UrisLeavingTheFilesFolderAreRefusedUnlessAllowed) {
  test::TempDir dir;
  const test::GltfFile g = test::shared_gltf(dir.path());
  g.write(dir.path(), "beside.gltf");
  fs::create_directories(dir / "sub");
  ReadOptions allow;
  allow.allow_external_files = true;
  for (const std::string& uri : {std::string("../beside.gltf.bin"), (dir / "beside.gltf.bin").string()}) {
    const fs::path file = g.write(dir / "sub", "out.gltf", uri);
    const std::string error = refusal(file);
    EXPECT_NE(error.find("leads out of the file's folder"), std::string::npos) << error;
    // Allowed, our reader reads it; assimp then reads `..` (an absolute uri it joins to the folder).
    if (uri[0] == '.') {
      EXPECT_TRUE(read_clip(file, allow).ok()) << uri;
    }
  }
  // The command names the option that allows it, and takes it.
  const fs::path out = dir / "sub" / "out.gltf";
  const test::CliResult refused = test::run_cli("info " + out.string());
  EXPECT_EQ(refused.exit_code, 1);
  EXPECT_NE(refused.err.find("refused unless --allow-external-files"), std::string::npos) << refused.err;
  g.write(dir / "sub", "out.gltf", "../beside.gltf.bin");
  const std::string in = out.string() + " -q";
  for (const std::string& command :
       {"info " + out.string(), "resample " + in + " -o " + (dir / "out.bvh").string(),
        "reduce " + in + " -o " + (dir / "keys.json").string(),
        "eval " + in + " -m slerp --keep-every 2 --no-plots -o " + (dir / "eval").string()}) {
    const test::CliResult allowed = test::run_cli(command + " --allow-external-files");
    EXPECT_EQ(allowed.exit_code, 0) << command << ": " << allowed.err;
    EXPECT_NE(test::run_cli(command).exit_code, 0) << command;
  }
  // A link in the folder that points out of it is refused the same way.
  fs::create_symlink(dir / "beside.gltf.bin", dir / "sub" / "link.bin");
  EXPECT_NE(refusal(g.write(dir / "sub", "link.gltf", "link.bin")).find("leads out"), std::string::npos);
  EXPECT_TRUE(read_clip(dir / "beside.gltf").ok());
}

// ---- class 3: bad numbers -----------------------------------------------------------

// The default (assimp) path and our curve reader refuse the same FBX keys.
TEST(HostileInput, BadFbxKeysAreRefusedOnTheDefaultPathAsOnTheCurveReader) {
  test::TempDir dir;
  struct Case {
    const char* name;
    std::string bytes;
    const char* says;
  };
  const std::vector<Case> cases = {
      {"reversed", test::fbx_ascii_with("KeyTime", [](auto& t) { std::swap(t[1], t[2]); }), "is before key 1's"},
      {"same_time", test::fbx_ascii_with("KeyTime", [](auto& t) { t[2] = t[1]; }), "with another value"},
      {"nan_value", test::fbx_ascii_with("KeyValueFloat", [](auto& v) { v[1] = "nan"; }), "key 1: a value is not finite"},
      {"inf_value", test::fbx_ascii_with("KeyValueFloat", [](auto& v) { v[1] = "-inf"; }), "key 1: a value is not finite"},
  };
  ReadOptions curves;
  curves.read_curves = true;
  for (const Case& c : cases) {
    const fs::path file = dir / (std::string(c.name) + ".fbx");
    test::write_text(file, c.bytes);
    for (const ReadOptions& options : {ReadOptions{}, curves}) {
      const std::string error = refusal(file, options);
      EXPECT_NE(error.find("FBX curve pCube1/Lcl Translation/X: "), std::string::npos) << c.name << ": " << error;
      EXPECT_NE(error.find(c.says), std::string::npos) << c.name << ": " << error;
    }
  }
}

TEST(HostileInput, ANonFiniteBvhValueIsRefusedNamingItsFrameLineAndJoint) {
  test::TempDir dir;
  const std::string text = test::read_text(kData / "bvh/NC_bandai2_raise-up-both-hands_active_031.bvh");
  std::size_t row = text.find('\n', text.find("Frame Time:")) + 1;  // frame 0
  for (int frame = 0; frame < 2; ++frame) row = text.find('\n', row) + 1;
  row = text.find_first_not_of(" \t", row);  // frame 2's first value: joint_Root's Xposition
  const long line = std::count(text.begin(), text.begin() + static_cast<long>(row), '\n') + 1;
  for (const char* bad : {"nan", "-inf"}) {
    std::string mutated = text;
    mutated.replace(row, mutated.find_first_of(" \t", row) - row, bad);
    const fs::path file = dir / (std::string(bad) + ".bvh");
    test::write_text(file, mutated);
    const std::string error = refusal(file);
    EXPECT_NE(error.find("frame 2 (line " + std::to_string(line) + "), joint 'joint_Root' Xposition: value is " + bad +
                         " (not finite)"),
              std::string::npos)
        << error;
  }
}

TEST(HostileInput, AnExactlyRepeatedFbx7KeyIsDroppedByOurReaderAndRefusedWhereAssimpMakesTheClip) {
  test::TempDir dir;
  const fs::path file = dir / "repeat.fbx";
  // Key 2 becomes key 1 again, time and value.
  test::write_text(file, test::edit_ascii_array(test::fbx_ascii_with("KeyTime", [](auto& t) { t[2] = t[1]; }),
                                                "KeyValueFloat", [](auto& v) { v[2] = v[1]; }));
  // Our curve reader repairs it; assimp, which makes the clip on the default path,
  // drops the whole curve, so there the file is refused rather than left at rest.
  ReadOptions with_curves;
  with_curves.read_curves = true;
  for (const ReadOptions& options : {ReadOptions{}, with_curves}) {
    const std::string error = refusal(file, options);
    EXPECT_NE(error.find("Lcl Translation/X: 1 key at a time already keyed with the same values dropped by our reader, "
                         "but assimp"),
              std::string::npos)
        << error;
    EXPECT_NE(error.find("would leave its joint at rest: refused"), std::string::npos) << error;
  }
  Result<FbxAnimation> curves = read_fbx_curves_file(file.string(), file.string());
  ASSERT_TRUE(curves.ok()) << curves.error();
  ASSERT_EQ(curves->repairs.size(), 1u);
  EXPECT_NE(curves->repairs[0].find("Lcl Translation/X: 1 key at a time already keyed with the same values dropped"),
            std::string::npos)
      << curves->repairs[0];
  const FbxCurve& x = curves->takes[0].curves[0];
  for (std::size_t k = 1; k < x.keys.size(); ++k) EXPECT_LT(x.keys[k - 1].ticks, x.keys[k].ticks);
}

}  // namespace
}  // namespace rotinterp
