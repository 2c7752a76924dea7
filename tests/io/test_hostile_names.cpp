// Issue 47, class 4: whatever names a clip holds, every file rotinterp writes reads
// back with its own readers, and no JSON writer fails on a name
// (io/files/written_names.h). The names come from shared clips mutated in the test:
// NUL, control characters and invalid UTF-8 in a BVH; spaces, braces, a tab and
// 20 000 equal names in a glTF.
#include "hostile_inputs.h"
#include "io_test_util.h"
#include "rotinterp/io/files/limits.h"
#include "rotinterp/io/files/written_names.h"
#include "rotinterp/io/read.h"
#include "support/run_cli.h"

#include <gtest/gtest.h>

#include <sys/resource.h>

#include <chrono>
#include <set>
#include <string>
#include <vector>

namespace rotinterp {
namespace {

namespace fs = std::filesystem;
using test::kData;

const char* const kBandai = "bvh/NC_bandai2_raise-up-both-hands_active_031.bvh";
const char* const kWrittenFormats[] = {"bvh", "fbx", "glb", "gltf"};

// A flat skeleton (joint 0 the parent of all others) of these names.
Skeleton skeleton_of(const std::vector<std::string>& names) {
  Skeleton sk;
  for (const std::string& name : names) sk.joints.push_back(Joint{name, sk.joints.empty() ? -1 : 0});
  return sk;
}

// CPU seconds of this process and its finished children (each command run):
// what the work costs, whatever else the machine runs.
double cpu_seconds() {
  double total = 0.0;
  for (int who : {RUSAGE_SELF, RUSAGE_CHILDREN}) {
    rusage u{};
    getrusage(who, &u);
    total += static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
             static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec) * 1e-6;
  }
  return total;
}

std::string text_name(const std::string& name) { return written_joint_names(skeleton_of({name}), NameForm::text)[0]; }

// The shared Bandai BVH with its first joints (ROOT, then each JOINT in file order)
// renamed to `names` in the file's bytes.
fs::path bandai_named(const fs::path& dir, const std::vector<std::string>& names) {
  std::string text = test::read_text(kData / kBandai);
  std::size_t at = text.find("ROOT ") + 5;
  for (const std::string& name : names) {
    const std::size_t end = text.find_first_of(" \t\r\n", at);
    text.replace(at, end - at, name);
    at = text.find("JOINT ", at + name.size()) + 6;
  }
  const fs::path file = dir / "named.bvh";
  test::write_text(file, text);
  return file;
}

// `file` resampled by the command into each format, read back by our readers: the
// same joint count, and the names the writers promise.
void expect_every_format_reads_back(const fs::path& file, const fs::path& dir) {
  Result<Clip> source = read_clip(file);
  ASSERT_TRUE(source.ok()) << source.error();
  for (const char* format : kWrittenFormats) {
    const fs::path out = dir / (std::string("out.") + format);
    const test::CliResult r = test::run_cli("resample '" + file.string() + "' -o " + out.string() + " -q");
    ASSERT_EQ(r.exit_code, 0) << format << ": " << r.err;
    Result<Clip> back = read_clip(out);
    ASSERT_TRUE(back.ok()) << format << ": " << back.error();
    ASSERT_EQ(back->skeleton.joints.size(), source->skeleton.joints.size()) << format;
    const std::vector<std::string> promised = written_joint_names(
        source->skeleton, std::string(format) == "bvh" ? NameForm::bvh_token : NameForm::text);
    for (std::size_t j = 0; j < promised.size(); ++j)
      EXPECT_NE(back->skeleton.find(promised[j]), -1) << format << ": no joint '" << promised[j] << "'";
  }
}

TEST(WrittenNames, ControlCharactersBecomeUnderscores) {
  EXPECT_EQ(text_name(std::string("a\0b", 3) + "\f\v\t\r\n\x7f\xc2\x85" + "c"), "a_b_______c");  // 7 controls
  EXPECT_EQ(text_name(""), "_");
}

TEST(WrittenNames, EachByteOfInvalidUtf8BecomesTheReplacementCharacter) {
  const std::string fffd = "\xEF\xBF\xBD";
  EXPECT_EQ(text_name("a\xff" "b"), "a" + fffd + "b");
  EXPECT_EQ(text_name("cut\xc3"), "cut" + fffd);                        // a sequence cut short
  EXPECT_EQ(text_name("\xc0\xaf"), fffd + fffd);                        // an overlong '/'
  EXPECT_EQ(text_name("\xed\xa0\x80"), fffd + fffd + fffd);             // a surrogate
  EXPECT_EQ(text_name("\xf4\x90\x80\x80"), fffd + fffd + fffd + fffd);  // past U+10FFFF
  const std::string valid = "Gr\xc3\xb6\xc3\x9f" "e_\xe8\x85\x95_\xf0\x9f\x98\x80";  // Größe_腕_😀
  EXPECT_EQ(text_name(valid), valid);
}

TEST(WrittenNames, BvhTokensHaveNoSpaceOrBraceWhereQuotedFormatsKeepThem) {
  const Skeleton sk = skeleton_of({"Bip01 L Thigh", "{x}"});
  EXPECT_EQ(written_joint_names(sk, NameForm::text), (std::vector<std::string>{"Bip01 L Thigh", "{x}"}));
  EXPECT_EQ(written_joint_names(sk, NameForm::bvh_token), (std::vector<std::string>{"Bip01_L_Thigh", "_x_"}));
}

TEST(WrittenNames, TwentyThousandEqualNamesBecomeDistinctInLinearTime) {
  const auto start = std::chrono::steady_clock::now();
  const std::vector<std::string> names =
      written_joint_names(skeleton_of(std::vector<std::string>(20000, "a b")), NameForm::bvh_token);
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(1));
  EXPECT_EQ(std::set<std::string>(names.begin(), names.end()).size(), 20000u);
  EXPECT_EQ(names[1], "a_b#");
  EXPECT_EQ(names.back(), "a_b#19999");
}

TEST(WrittenNames, ALongNameIsCutAtACharacterBoundaryLeavingRoomForItsSuffix) {
  std::string long_name = "x";
  for (int i = 0; i < 600; ++i) long_name += "\xc3\xa9";  // é: 1 201 bytes in all
  const std::vector<std::string> names = written_joint_names(skeleton_of({long_name, long_name}), NameForm::text);
  EXPECT_EQ(names[0].size(), 999u);  // 1 + 2 × 499: the next é would pass 1 000
  EXPECT_EQ(text_name(names[0]), names[0]) << "cut inside a character";
  EXPECT_EQ(names[1], names[0] + "#");
  EXPECT_LE(names[1].size(), kMaxNameBytes);
}

TEST(HostileNames, NulControlAndInvalidUtf8NamesInABvhReadBackFromEveryFormat) {
  test::TempDir dir;
  // x\x01 and x\x02 are one name once cleaned, as is x_ (the next joint's own name).
  const fs::path file = bandai_named(dir.path(), {std::string("nul\0name", 8), "bad\xff\xfe", "cut\xc3", "x\x01",
                                                  "x\x02", "x_", "\x7f"});
  expect_every_format_reads_back(file, dir.path());
}

TEST(HostileNames, InfoJsonShowsSuchNamesAsTheWritersDoNotANlohmannError) {
  test::TempDir dir;
  const fs::path file = bandai_named(dir.path(), {std::string("nul\0name", 8), "bad\xff\xfe"});
  const test::CliResult r = test::run_cli("info '" + file.string() + "' --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("json.exception"), std::string::npos) << r.err;
  const nlohmann::json doc = nlohmann::json::parse(r.out);  // throws on invalid UTF-8
  Result<Clip> clip = read_clip(file);
  ASSERT_TRUE(clip.ok()) << clip.error();
  const std::vector<std::string> names = written_joint_names(clip->skeleton, NameForm::text);
  ASSERT_EQ(doc["joints"].size(), names.size());
  for (std::size_t j = 0; j < names.size(); ++j) EXPECT_EQ(doc["joints"][j]["name"], names[j]);
  EXPECT_EQ(doc["joints"][0]["name"], "nul_name");
  EXPECT_EQ(doc["joints"][1]["name"], "bad\xEF\xBF\xBD\xEF\xBF\xBD");
}

TEST(HostileNames, AFileNameThatIsNotUtf8IsShownInJsonWithTheReplacementCharacter) {
  test::TempDir dir;
  const fs::path file = dir / "bad\xff.bvh";
  fs::copy_file(kData / kBandai, file);
  for (const std::string options : {" --json", " --summary --json"}) {
    const test::CliResult r = test::run_cli("info '" + file.string() + "'" + options);
    ASSERT_EQ(r.exit_code, 0) << options << ": " << r.err;
    EXPECT_NE(nlohmann::json::parse(r.out).dump().find("bad\xEF\xBF\xBD.bvh"), std::string::npos) << options;
  }
  // A .gltf names its buffer after itself, in JSON: such a name is refused in one line.
  const test::CliResult gltf = test::run_cli("resample '" + file.string() + "' -q -o '" + (dir / "out\xfe.gltf").string() + "'");
  EXPECT_EQ(gltf.exit_code, 1);
  EXPECT_NE(gltf.err.find("this name is not valid UTF-8"), std::string::npos) << gltf.err;
  EXPECT_EQ(gltf.err.find("json.exception"), std::string::npos) << gltf.err;
}

TEST(HostileNames, SpacesBracesTabsAndEmptyNamesInAGltfReadBackFromEveryFormat) {
  test::TempDir dir;
  test::GltfFile g = test::shared_gltf(dir.path());
  const char* const names[] = {"a b", "{", "}", "tab\there", "", "a_b"};
  for (std::size_t i = 0; i < std::size(names); ++i) g.doc["nodes"][i]["name"] = names[i];
  expect_every_format_reads_back(g.write(dir.path(), "odd.gltf"), dir.path());
}

TEST(HostileNames, TwentyThousandNodesOfOneSpacedNameWriteAndReadBackInSeconds) {
  test::TempDir dir;
  test::GltfFile g = test::shared_gltf(dir.path());
  const std::size_t first = g.doc["nodes"].size(), root = g.doc["scenes"][0]["nodes"][0].get<std::size_t>();
  for (std::size_t i = 0; i < 20000; ++i) {
    g.doc["nodes"].push_back({{"name", "dup dup"}});
    g.doc["nodes"][root]["children"].push_back(first + i);
  }
  const fs::path file = g.write(dir.path(), "dup.gltf");
  for (const char* format : {"bvh", "glb"}) {
    const fs::path out = dir / (std::string("dup.") + format);
    const double before = cpu_seconds();
    const test::CliResult r = test::run_cli("resample " + file.string() + " -o " + out.string() + " -q");
    ASSERT_EQ(r.exit_code, 0) << format << ": " << r.err;
    Result<Clip> back = read_clip(out);
    ASSERT_TRUE(back.ok()) << format << ": " << back.error();
    // About 1.5 CPU-s each in Release (11 under the sanitizers); the quadratic renaming
    // it replaces took minutes.
#ifdef ROTINTERP_SANITIZED
    const double limit = 60.0;
#else
    const double limit = 10.0;
#endif
    EXPECT_LT(cpu_seconds() - before, limit) << format;
    EXPECT_EQ(back->skeleton.joints.size(), first + 20000) << format;
  }
}

}  // namespace
}  // namespace rotinterp
