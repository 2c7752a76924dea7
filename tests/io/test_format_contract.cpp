// The format contract, one test run over every format the registry says it writes
// (io/files/formats.h), as the interpolators' contract runs over every method: a
// clip written and read back has the same joints (names and parents), the same
// world orientations and positions at every source frame, the same rate, the same
// unit where the format keeps one, and, where the format holds takes, every take
// under its name. A format joins the registry and this test in the same commit.
#include "io_test_util.h"
#include "rotinterp/io/files/formats.h"
#include "rotinterp/io/info.h"
#include "rotinterp/io/read.h"
#include "rotinterp/io/write.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

namespace rotinterp {
namespace {

using test::kData;

constexpr double kDegreesTolerance = 1e-4;  // every writer stores floats (FBX: float Euler degrees)
constexpr double kSizeTolerance = 1e-5;     // positions, relative to the skeleton's size

// The clips each format is written from: a BVH with translations and an inferred
// unit, and an FBX with a declared unit, rest rotations and sparse keys.
const std::vector<std::filesystem::path>& sources() {
  static const std::vector<std::filesystem::path> all = {std::filesystem::path(ROTINTERP_SOURCE_DIR) / "samples" / "walk.bvh",
                                                         kData / "fbx" / "assimp_huesitos.fbx"};
  return all;
}

std::vector<const FormatInfo*> writable_formats() {
  std::vector<const FormatInfo*> out;
  for (const FormatInfo& f : formats())
    if (f.writes) out.push_back(&f);
  return out;
}

// The parent's name of joint j ("" for a root).
std::string parent_name(const Skeleton& s, std::size_t j) {
  const int p = s.joints[j].parent;
  return p < 0 ? std::string() : s.joints[static_cast<std::size_t>(p)].name;
}

// b is a written and read back: same joints, world pose at every frame of a.
void expect_same_motion(const Clip& a, const Clip& b, const FormatInfo& format, const std::string& what) {
  std::vector<std::size_t> in_b(a.skeleton.joints.size());
  for (std::size_t j = 0; j < in_b.size(); ++j) {
    const int found = b.skeleton.find(a.skeleton.joints[j].name);
    ASSERT_GE(found, 0) << what << ": joint " << a.skeleton.joints[j].name << " is lost";
    in_b[j] = static_cast<std::size_t>(found);
    EXPECT_EQ(parent_name(b.skeleton, in_b[j]), parent_name(a.skeleton, j)) << what << ": " << a.skeleton.joints[j].name;
  }
  EXPECT_NEAR(b.frame_time, a.frame_time, 1e-9) << what;
  // Positions in metres where the format keeps a unit, else in the file's units.
  const bool keeps_unit = format.unit != "inferred";
  if (keeps_unit) {
    EXPECT_NEAR(b.unit.metres_per_unit * test::skeleton_size(b), a.unit.metres_per_unit * test::skeleton_size(a),
                1e-6 * a.unit.metres_per_unit * test::skeleton_size(a))
        << what;
  }
  const double scale_a = keeps_unit ? a.unit.metres_per_unit : 1.0, scale_b = keeps_unit ? b.unit.metres_per_unit : 1.0;
  const double size = test::skeleton_size(a) * scale_a;
  double angle = 0.0, distance = 0.0;
  for (std::size_t k = 0; k < a.frame_count(); ++k) {
    const double t = a.start_time() + static_cast<double>(k) * a.frame_time;
    const WorldPose pa = test::pose_at(a, t), pb = test::pose_at(b, t);
    for (std::size_t j = 0; j < in_b.size(); ++j) {
      angle = std::max(angle, test::angle_degrees(pa.rotation[j], pb.rotation[in_b[j]]));
      distance = std::max(distance, (pa.position[j] * scale_a - pb.position[in_b[j]] * scale_b).norm());
    }
  }
  EXPECT_LE(angle, kDegreesTolerance) << what;
  EXPECT_LE(distance, kSizeTolerance * size) << what;
  std::printf("[ %s ] world %.3g deg, position %.3g of the size\n", what.c_str(), angle, distance / size);
}

class FormatContract : public ::testing::TestWithParam<const FormatInfo*> {};

TEST_P(FormatContract, AWrittenClipReadsBackAsTheSameMotion) {
  const FormatInfo& format = *GetParam();
  for (const std::filesystem::path& source : sources()) {
    Result<Clip> a = read_clip(source);
    ASSERT_TRUE(a) << a.error();
    if (format.frames_only) *a = test::resample_uniform(*a, a->frame_time);
    test::TempDir dir;
    const auto out = dir / ("out." + std::string(format.name));
    ASSERT_TRUE(can_write_format(out));
    const Status written = write_clip(*a, out);
    ASSERT_TRUE(written) << written.error();
    Result<Clip> b = read_clip(out);
    ASSERT_TRUE(b) << b.error();
    expect_same_motion(*a, *b, format, source.filename().string() + " -> " + std::string(format.name));
    // Only the written file (plus a .gltf's buffer): no temporaries left.
    for (const std::string& f : dir.files()) EXPECT_EQ(f.rfind("out", 0), 0u) << f;
  }
}

// A format that holds takes keeps each under its name; one that does not refuses several.
TEST_P(FormatContract, EveryTakeReadsBackUnderItsName) {
  const FormatInfo& format = *GetParam();
  Result<Clip> a = read_clip(sources().front());
  ASSERT_TRUE(a) << a.error();
  std::vector<Clip> takes = {*a, *a};
  takes[0].name = "first";
  takes[1].name = "second";
  test::TempDir dir;
  const auto out = dir / ("takes." + std::string(format.name));
  EXPECT_EQ(can_write_takes(out), format.takes);
  const Status written = write_clips(takes, out);
  if (!format.takes) {
    EXPECT_FALSE(written);
    return;
  }
  ASSERT_TRUE(written) << written.error();
  Result<ClipFileInfo> info = inspect_clip(out);
  ASSERT_TRUE(info) << info.error();
  ASSERT_EQ(info->animations.size(), 2u);
  for (std::size_t i = 0; i < takes.size(); ++i) {
    EXPECT_EQ(info->animations[i].name, takes[i].name);
    ReadOptions options;
    options.animation = takes[i].name;
    Result<Clip> b = read_clip(out, options);
    ASSERT_TRUE(b) << b.error();
    expect_same_motion(*a, *b, format, takes[i].name + " -> " + std::string(format.name));
  }
}

INSTANTIATE_TEST_SUITE_P(EveryWritableFormat, FormatContract, ::testing::ValuesIn(writable_formats()),
                         [](const auto& info) { return std::string(info.param->name); });

}  // namespace
}  // namespace rotinterp

namespace rotinterp {
namespace {

// docs/formats.md's first table has a row for every format of the registry, and says
// it writes exactly those the registry writes.
TEST(FormatRegistry, TheDocsFormatTableHasARowPerFormat) {
  const std::string page = test::read_text(std::filesystem::path(ROTINTERP_SOURCE_DIR) / "docs" / "formats.md");
  std::vector<std::string> rows;  // the first table's rows
  std::size_t at = page.find("\n| format |");
  ASSERT_NE(at, std::string::npos);
  for (std::size_t end; (end = page.find('\n', at + 1)) != std::string::npos && page.compare(at + 1, 1, "|") == 0;
       at = end)
    rows.push_back(page.substr(at + 1, end - at - 1));
  for (const FormatInfo& f : formats()) {
    const auto row = std::find_if(rows.begin(), rows.end(), [&](const std::string& r) {
      return r.find(std::string(f.title)) != std::string::npos && r.find("| format") != 0;
    });
    ASSERT_NE(row, rows.end()) << f.title << " has no row";
    // Columns: format | reads | writes | round trip.
    std::vector<std::string> cells;
    for (std::size_t p = 1, q; (q = row->find(" |", p)) != std::string::npos; p = q + 2) cells.push_back(row->substr(p, q - p));
    ASSERT_GE(cells.size(), 3u) << *row;
    EXPECT_EQ(cells[2].find("—") == std::string::npos, f.writes) << f.title << ": " << cells[2];
  }
}

}  // namespace
}  // namespace rotinterp
