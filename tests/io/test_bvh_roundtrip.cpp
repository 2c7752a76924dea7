// BVH → clip → BVH → clip with the real clips of ../shared/data: the written file
// keeps the hierarchy, joint order, OFFSETs, End Sites, CHANNELS lines and Frame
// Time, and reproduces every orientation within 1e-4° and the root path within
// 1e-4 units.
#include "io_test_util.h"
#include "rotinterp/clip/resample.h"
#include "rotinterp/io/bvh/bvh.h"
#include "rotinterp/io/read.h"
#include "rotinterp/io/write.h"

#include <gtest/gtest.h>

#include <memory>
#include <sstream>

namespace rotinterp {
namespace {

using test::kData;

constexpr double kDeg = kPi / 180.0;

// The lines of the HIERARCHY section that must survive, whitespace-normalized:
// ROOT/JOINT/End Site/CHANNELS lines as text, OFFSET lines as parsed numbers.
std::vector<std::string> structure_lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string w, norm;
    std::vector<std::string> ws;
    while (words >> w) ws.push_back(w);
    if (ws.empty()) continue;
    if (ws[0] == "MOTION") break;
    if (ws[0] == "OFFSET") {
      norm = "OFFSET";
      for (std::size_t i = 1; i < ws.size(); ++i) norm += " " + std::to_string(std::stod(ws[i]));
    } else {
      for (const auto& x : ws) norm += (norm.empty() ? "" : " ") + x;
    }
    if (norm != "{" && norm != "}") out.push_back(norm);
  }
  return out;
}

std::string frame_time_line(const std::string& text) {
  const std::size_t p = text.find("Frame Time:");
  std::istringstream in(text.substr(p + 11));
  std::string v;
  in >> v;
  return v;
}

class RealBvh : public ::testing::TestWithParam<const char*> {};

TEST_P(RealBvh, RoundTripKeepsLayoutFrameTimeAndMotion) {
  const auto src = kData / "bvh" / GetParam();
  Result<Clip> a = read_clip(src);
  ASSERT_TRUE(a) << a.error();
  test::TempDir dir;
  const auto out = dir / "out.bvh";
  ASSERT_TRUE(write_clip(*a, out)) << "write failed";
  Result<Clip> b = read_clip(out);
  ASSERT_TRUE(b) << b.error();

  const std::string src_text = test::read_text(src), out_text = test::read_text(out);
  EXPECT_EQ(structure_lines(src_text), structure_lines(out_text));
  EXPECT_EQ(frame_time_line(src_text), frame_time_line(out_text));
  EXPECT_EQ(a->frame_time, b->frame_time);
  EXPECT_EQ(a->frame_count(), b->frame_count());

  const Skeleton& sa = a->skeleton;
  const Skeleton& sb = b->skeleton;
  ASSERT_EQ(sa.joints.size(), sb.joints.size());
  for (std::size_t j = 0; j < sa.joints.size(); ++j) {
    EXPECT_EQ(sa.joints[j].name, sb.joints[j].name);
    EXPECT_EQ(sa.joints[j].parent, sb.joints[j].parent);
    EXPECT_EQ(sa.joints[j].offset, sb.joints[j].offset) << sa.joints[j].name;
    EXPECT_EQ(bvh_channels(*a, j), bvh_channels(*b, j)) << sa.joints[j].name;
  }
  ASSERT_EQ(sa.end_sites.size(), sb.end_sites.size());
  for (std::size_t e = 0; e < sa.end_sites.size(); ++e) {
    EXPECT_EQ(sa.end_sites[e].parent, sb.end_sites[e].parent);
    EXPECT_EQ(sa.end_sites[e].offset, sb.end_sites[e].offset);
  }

  double worst_angle = 0.0, worst_position = 0.0;
  for (std::size_t j = 0; j < sa.joints.size(); ++j) {
    const RotationTrack& ra = a->rotations[j];
    const RotationTrack& rb = b->rotations[j];
    ASSERT_EQ(ra.keys.size(), rb.keys.size());
    for (std::size_t k = 0; k < ra.keys.size(); ++k) {
      EXPECT_DOUBLE_EQ(ra.times[k], rb.times[k]);
      worst_angle = std::max(worst_angle, angular_distance(ra.keys[k], rb.keys[k]));
    }
    ASSERT_EQ(a->translations[j].has_value(), b->translations[j].has_value());
    if (a->translations[j])
      for (std::size_t k = 0; k < a->translations[j]->keys.size(); ++k)
        worst_position = std::max(worst_position, (a->translations[j]->keys[k] - b->translations[j]->keys[k]).norm());
  }
  EXPECT_LE(worst_angle, 1e-4 * kDeg) << worst_angle / kDeg << " degrees";
  EXPECT_LE(worst_position, 1e-4);
  RecordProperty("worst_angle_deg", std::to_string(worst_angle / kDeg));
  RecordProperty("worst_position", std::to_string(worst_position));
  std::printf("[ %s ] worst orientation %.3g deg, worst position %.3g units\n", GetParam(), worst_angle / kDeg,
              worst_position);
}

// Every channel value of `written` against `source`'s at frame f + first (a cut
// starting at the source's frame `first`): the worst difference.
double worst_value_gap(const BvhFile& source, const BvhFile& written, std::size_t first) {
  double worst = 0.0;
  for (std::size_t f = 0; f < written.frames; ++f)
    for (std::size_t c = 0; c < written.columns; ++c)
      worst = std::max(worst, std::abs(written.values[f * written.columns + c] -
                                       source.values[(f + first) * source.columns + c]));
  return worst;
}

// Where it writes the file's own rotation at one of the file's frame times, the
// writer gives back the file's own numbers (θ + 360° and the other gimbal branch are
// the same rotation, but not the same numbers): written as read, resampled at the
// file's own rate with a method that passes its keys, and a cut of it.
TEST_P(RealBvh, TheFilesOwnRotationsAreWrittenWithItsOwnNumbers) {
  const auto src = kData / "bvh" / GetParam();
  Result<BvhFile> source = parse_bvh(test::read_text(src), "src.bvh");
  Result<Clip> a = read_clip(src);
  ASSERT_TRUE(source && a);
  const auto written = [](const Clip& clip) {
    std::ostringstream text;
    EXPECT_TRUE(write_bvh(clip, text, WriteOptions{}, "mem.bvh"));
    return parse_bvh(text.str(), "mem.bvh");
  };
  const double printed = 5e-7 + 1e-12;  // 6 decimals: the source may have more
  EXPECT_LE(worst_value_gap(*source, *written(*a), 0), printed);
  for (const char* method : {"slerp", "c2"}) {
    ResampleOptions same;
    same.method = method;
    const Result<Clip> round = resample_clip(*a, same);
    ASSERT_TRUE(round) << round.error();
    EXPECT_LE(worst_value_gap(*source, *written(*round), 0), printed) << method;
  }
  if (a->frame_count() < 4) return;
  ResampleOptions cut;
  const std::size_t first = a->frame_count() / 3;
  cut.range = TimeRange{static_cast<double>(first), static_cast<double>(2 * first), true, true};  // frames
  const Result<Clip> part = resample_clip(*a, cut);
  ASSERT_TRUE(part) << part.error();
  const Result<BvhFile> part_file = written(*part);
  ASSERT_TRUE(part_file);
  EXPECT_EQ(part_file->frames, first + 1);
  EXPECT_LE(worst_value_gap(*source, *part_file, first), printed);
}

// Where it computes the Euler angles (no source numbers: another rate, a rotation
// that is not the file's), the written curves have no ±180° wraps and no branch
// flips: a step of 90° or more in any rotation channel happens only where the joint
// itself turns by 45° or more between the two frames (CMU frame 0 is a reference
// pose, 154° away).
TEST_P(RealBvh, WrittenEulerCurvesHaveNoWrapsOrFlips) {
  Result<Clip> a = read_clip(kData / "bvh" / GetParam());
  ASSERT_TRUE(a) << a.error();
  BvhLayout computed = *bvh_layout(*a);
  computed.source_angles = nullptr;
  set_bvh_layout(*a, computed);
  std::ostringstream text;
  ASSERT_TRUE(write_bvh(*a, text, WriteOptions{}, "mem.bvh"));
  Result<BvhFile> f = parse_bvh(text.str(), "mem.bvh");
  ASSERT_TRUE(f) << f.error();
  for (std::size_t j = 0; j < f->joints.size(); ++j)
    for (std::size_t c = 0; c < f->joints[j].channels.size(); ++c) {
      if (!is_rotation(f->joints[j].channels[c])) continue;
      for (std::size_t fr = 1; fr < f->frames; ++fr) {
        const double step = std::abs(f->value(fr, j, c) - f->value(fr - 1, j, c));
        if (step < 90.0) continue;
        const double turn = angular_distance(f->rotation(fr, j), f->rotation(fr - 1, j)) / kDeg;
        ASSERT_GE(turn, 45.0) << f->joints[j].name << " " << channel_name(f->joints[j].channels[c]) << " frame " << fr
                              << ": step " << step << " degrees for a turn of " << turn;
      }
    }
}

INSTANTIATE_TEST_SUITE_P(SharedData, RealBvh,
                         ::testing::Values("cmu_01_01.bvh", "cmu_01_03.bvh", "assimp_Boxing_Toes.bvh", "bvhio_example.bvh",
                                           "NC_bandai1_walk_normal_001.bvh",
                                           "NC_bandai2_raise-up-both-hands_active_031.bvh"),
                         [](const auto& info) {
                           std::string s = info.param;
                           for (char& c : s)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return s;
                         });

}  // namespace
}  // namespace rotinterp
