// The streamed BVH read (read_bvh_text: rows parsed straight into keys, no table of
// values) against the table-based parse_bvh + bvh_to_clip: the same keys bit for bit
// and the same first error, on real clips and on a long generated clip that takes
// the two-thread path.
#include "bvh_clip.h"
#include "io_test_util.h"
#include "rotinterp/io/bvh.h"
#include "rotinterp/io/read.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace rotinterp {
namespace {

constexpr unsigned kTwoThreads = 2;

// Same bits, not just equal values (-0.0 and 0.0 differ here).
template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

void expect_same_clip(const Clip& streamed, const Clip& table) {
  ASSERT_EQ(streamed.rotations.size(), table.rotations.size());
  EXPECT_EQ(streamed.name, table.name);
  EXPECT_EQ(streamed.frame_time, table.frame_time);
  EXPECT_EQ(streamed.skeleton.joints.size(), table.skeleton.joints.size());
  EXPECT_EQ(streamed.skeleton.end_sites.size(), table.skeleton.end_sites.size());
  ASSERT_TRUE(streamed.bvh_layout && table.bvh_layout);
  EXPECT_EQ(streamed.bvh_layout->channels, table.bvh_layout->channels);
  EXPECT_EQ(streamed.bvh_layout->frame_time_text, table.bvh_layout->frame_time_text);
  for (std::size_t j = 0; j < table.rotations.size(); ++j) {
    EXPECT_TRUE(same_bits(streamed.rotations[j].times, table.rotations[j].times)) << "joint " << j;
    EXPECT_TRUE(same_bits(streamed.rotations[j].keys, table.rotations[j].keys)) << "joint " << j;
    ASSERT_EQ(streamed.translations[j].has_value(), table.translations[j].has_value()) << "joint " << j;
    if (table.translations[j]) {
      EXPECT_TRUE(same_bits(streamed.translations[j]->times, table.translations[j]->times)) << "joint " << j;
      EXPECT_TRUE(same_bits(streamed.translations[j]->keys, table.translations[j]->keys)) << "joint " << j;
    }
  }
}

// Both reads of `text`: both succeed with the same clip and extra rows, or both fail
// with the same message.
void expect_same_read(const std::string& text, unsigned threads = kTwoThreads) {
  const Result<StreamedBvh> streamed = read_bvh_text(text, "x.bvh", "x", threads);
  const Result<BvhFile> table = parse_bvh(text, "x.bvh");
  ASSERT_EQ(streamed.ok(), table.ok()) << (streamed ? table.error() : streamed.error());
  if (!table) {
    EXPECT_EQ(streamed.error(), table.error());
    return;
  }
  EXPECT_EQ(streamed->extra_rows, table->extra_rows);
  expect_same_clip(streamed->clip, bvh_to_clip(*table, "x", threads));
}

// A root with position channels and three joints of different rotation orders, each
// angle wrapping at ±180° (so the keys' signs flip), one row per frame.
struct LongClip {
  static constexpr std::size_t kColumns = 15;
  std::size_t frames;
  std::string header;
  std::vector<std::string> rows;

  explicit LongClip(std::size_t n) : frames(n) {
    header =
        "HIERARCHY\nROOT Hips\n{\n\tOFFSET 0 0 0\n"
        "\tCHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"
        "\tJOINT A\n\t{\n\t\tOFFSET 0 10 0\n\t\tCHANNELS 3 Xrotation Yrotation Zrotation\n"
        "\t\tJOINT B\n\t\t{\n\t\t\tOFFSET 0 10 0\n\t\t\tCHANNELS 3 Yrotation Zrotation Xrotation\n"
        "\t\t\tEnd Site\n\t\t\t{\n\t\t\t\tOFFSET 0 5 0\n\t\t\t}\n\t\t}\n\t}\n"
        "\tJOINT C\n\t{\n\t\tOFFSET 5 0 0\n\t\tCHANNELS 3 Zrotation Yrotation Xrotation\n"
        "\t\tEnd Site\n\t\t{\n\t\t\tOFFSET 5 0 0\n\t\t\t}\n\t}\n}\n"
        "MOTION\nFrames: " + std::to_string(n) + "\nFrame Time: 0.008333\n";
    for (std::size_t f = 0; f < n; ++f) {
      std::string row;
      char buf[32];
      for (std::size_t c = 0; c < kColumns; ++c) {
        const double t = static_cast<double>(f);
        // Positions wander; angles turn at different speeds, wrapped to (−180, 180].
        const double v = c < 3 ? 40.0 * std::sin(0.001 * t + static_cast<double>(c))
                               : std::remainder(0.37 * t * static_cast<double>(c - 2) + 11.0 * static_cast<double>(c), 360.0);
        std::snprintf(buf, sizeof buf, "%s%.6f", c ? " " : "", v);
        row += buf;
      }
      rows.push_back(row);
    }
  }
  std::string text() const {
    std::string t = header;
    for (const std::string& r : rows) t += r + "\n";
    return t;
  }
};

TEST(BvhStream, ReadsRealClipsBitForBitAsTheTableDoes) {
  for (const char* name : {"cmu_01_01.bvh", "NC_bandai1_walk_normal_001.bvh", "assimp_Boxing_Toes.bvh"}) {
    SCOPED_TRACE(name);
    const std::string text = test::read_text(test::kData / "bvh" / name);
    expect_same_read(text, 1);
    expect_same_read(text, kTwoThreads);
  }
}

TEST(BvhStream, ReadClipGivesTheTableReadsKeys) {
  const auto path = test::kData / "bvh" / "cmu_01_01.bvh";
  const Result<Clip> read = read_clip(path);
  ASSERT_TRUE(read) << read.error();
  const Result<BvhFile> table = parse_bvh(test::read_text(path), path.string());
  ASSERT_TRUE(table) << table.error();
  expect_same_clip(*read, bvh_to_clip(*table, "cmu_01_01"));
}

TEST(BvhStream, ALongClipReadOnTwoThreadsJoinsTheSignsAcrossTheSplitBitForBit) {
  const LongClip clip(30001);
  ASSERT_TRUE(bvh_clip::worth_two_threads(clip.frames, LongClip::kColumns, kTwoThreads));
  const std::string text = clip.text();
  const Result<StreamedBvh> streamed = read_bvh_text(text, "long.bvh", "long", kTwoThreads);
  ASSERT_TRUE(streamed) << streamed.error();
  const Result<BvhFile> table = parse_bvh(text, "long.bvh");
  ASSERT_TRUE(table) << table.error();
  expect_same_clip(streamed->clip, bvh_to_clip(*table, "long", kTwoThreads));
  expect_same_clip(streamed->clip, bvh_to_clip(*table, "long", 1));
  // The second half starts from its raw key: the join turned it for some joints, so
  // the case the split has to get right is exercised.
  const std::size_t split = clip.frames / 2;
  int turned = 0;
  for (std::size_t j = 0; j < streamed->clip.rotations.size(); ++j) {
    const Quat raw = table->rotation(split, j);
    const Quat& key = streamed->clip.rotations[j].keys[split];
    turned += key.coeffs() == -raw.coeffs();
    EXPECT_TRUE(key.coeffs() == raw.coeffs() || key.coeffs() == -raw.coeffs());
  }
  EXPECT_GT(turned, 0);
}

TEST(BvhStream, TheFirstErrorInFileOrderWinsWhenBothHalvesHaveErrors) {
  LongClip clip(30000);
  const std::size_t late = clip.frames - 100;
  clip.rows[late] = "1 2 3";  // too few values, in the second half
  clip.rows[late + 10].replace(0, 1, "x");
  {
    const Result<StreamedBvh> r = read_bvh_text(clip.text(), "x.bvh", "x", kTwoThreads);
    ASSERT_FALSE(r);
    EXPECT_NE(r.error().find("frame " + std::to_string(late) + " "), std::string::npos) << r.error();
    expect_same_read(clip.text());
  }
  clip.rows[200] += " 7";  // one value too many, in the first half: the first error now
  const Result<StreamedBvh> r = read_bvh_text(clip.text(), "x.bvh", "x", kTwoThreads);
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().find("x.bvh: frame 200 "), 0u) << r.error();
  expect_same_read(clip.text());
}

TEST(BvhStream, BadRowsTruncationAndExtraRowsReadAsTheTableReadsThem) {
  const LongClip clip(30000);
  const std::string good = clip.text();
  auto with_row = [&](std::size_t f, const std::string& row) {
    LongClip c = clip;
    c.rows[f] = row;
    return c.text();
  };
  const std::string row = clip.rows[0];
  const std::vector<std::pair<const char*, std::string>> cases = {
      {"not a number, first half", with_row(10, "abc" + row.substr(row.find(' ')))},
      {"not a number, second half", with_row(20000, row.substr(0, row.rfind(' ')) + " 1.5e")},
      {"not finite", with_row(29999, row.substr(0, row.rfind(' ')) + " inf")},
      {"too many values", with_row(15000, row + " 0")},
      {"too few values, at the split", with_row(15000, "0 0")},
      {"cut in the first half", good.substr(0, good.size() / 3)},
      {"cut in the second half", good.substr(0, good.size() * 2 / 3)},
      {"cut inside the last row", good.substr(0, good.size() - 4)},
      {"one row short", good.substr(0, good.rfind('\n', good.size() - 2) + 1)},
      {"extra rows", good + row + "\n\n" + row + "\n"},
      {"blank lines and CRLF", clip.header + "\n" + row + " \r\n\t\n" + good.substr(clip.header.size() + row.size() + 1)},
      {"Frames beyond what the text can hold", clip.header.substr(0, clip.header.find("Frames:")) +
                                                   "Frames: 99999999\nFrame Time: 0.008333\n" +
                                                   good.substr(clip.header.size())},
      {"text after the Frame Time", clip.header.substr(0, clip.header.size() - 1) + " x\n" + good.substr(clip.header.size())},
  };
  for (const auto& [what, text] : cases) {
    SCOPED_TRACE(what);
    expect_same_read(text, kTwoThreads);
    expect_same_read(text, 1);
  }
}

}  // namespace
}  // namespace rotinterp
