// A generated BVH with all six Tait–Bryan rotation orders, position channels on
// non-root joints (before and after the rotations), a position-only joint, a
// 9-channel joint, a hinge and a two-axis joint: read exactly (checked against an
// independent evaluation of the channels) and round-tripped through the writer.
#include "io_test_util.h"
#include "rotinterp/io/bvh/bvh.h"
#include "rotinterp/io/read.h"
#include "rotinterp/io/write.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <map>

namespace rotinterp {
namespace {

constexpr double kDeg = kPi / 180.0;

struct GenJoint {
  const char* name;
  int parent;
  const char* channels;  // as in the file
  bool end_site;
};

// Parent indices refer to this table; the order is the file's depth-first order.
const GenJoint kJoints[] = {
    {"Root", -1, "Xposition Yposition Zposition Xrotation Yrotation Zrotation", false},  // XYZ
    {"A", 0, "Xrotation Zrotation Yrotation", false},                                    // XZY
    {"B", 1, "Yrotation Xrotation Zrotation Xposition Yposition Zposition", false},      // YXZ, positions last
    {"C", 2, "Yrotation Zrotation Xrotation", false},                                    // YZX
    {"D", 3, "Xposition Yposition Zposition", false},                                    // position only
    {"E", 4, "Xposition Yposition Zposition Zrotation Xrotation Yrotation Xrotation Yrotation Zrotation", true},
    {"F", 0, "Zrotation Xrotation Yrotation", false},  // ZXY
    {"G", 6, "Zrotation Yrotation Xrotation", true},   // ZYX
    {"H", 0, "Zrotation", false},                      // hinge
    {"I", 8, "Xrotation Yrotation", true},             // two axes
};
constexpr int kFrames = 40;

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::size_t i = 0;
  while (i < s.size()) {
    const std::size_t j = s.find(' ', i);
    out.push_back(s.substr(i, j == std::string::npos ? std::string::npos : j - i));
    if (j == std::string::npos) break;
    i = j + 1;
  }
  return out;
}

// Smooth curves with large excursions (up to ±400°) so that unwrapping matters.
double curve(int joint, int channel, int frame) {
  const double phase = 0.7 * joint + 1.3 * channel;
  return 400.0 * std::sin(0.05 * frame + phase) * std::cos(0.013 * frame * (channel + 1));
}

struct Generated {
  std::string text;
  // Independent expectation: per joint, per frame.
  std::vector<std::vector<Quat>> rotation;
  std::vector<std::vector<Vec3>> translation;
};

Generated generate() {
  Generated g;
  std::string& t = g.text;
  const int n = static_cast<int>(std::size(kJoints));
  std::vector<Vec3> offsets;
  for (int j = 0; j < n; ++j) offsets.emplace_back(1.0 + j, 2.0 - 0.5 * j, 0.25 * j);
  std::function<void(int, int)> emit = [&](int j, int depth) {
    const std::string in(static_cast<std::size_t>(depth), '\t');
    char buf[128];
    t += in + (kJoints[j].parent < 0 ? "ROOT " : "JOINT ") + kJoints[j].name + "\n" + in + "{\n";
    std::snprintf(buf, sizeof buf, "%s\tOFFSET %g %g %g\n", in.c_str(), offsets[j].x(), offsets[j].y(), offsets[j].z());
    t += buf;
    t += in + "\tCHANNELS " + std::to_string(split(kJoints[j].channels).size()) + " " + kJoints[j].channels + "\n";
    for (int c = 0; c < n; ++c)
      if (kJoints[c].parent == j) emit(c, depth + 1);
    if (kJoints[j].end_site) t += in + "\tEnd Site\n" + in + "\t{\n" + in + "\t\tOFFSET 0 1 0\n" + in + "\t}\n";
    t += in + "}\n";
  };
  t = "HIERARCHY\n";
  emit(0, 0);
  t += "MOTION\nFrames: " + std::to_string(kFrames) + "\nFrame Time: 0.016667\n";
  g.rotation.assign(static_cast<std::size_t>(n), {});
  g.translation.assign(static_cast<std::size_t>(n), {});
  // Depth-first order of the table is the file order (checked by construction).
  for (int f = 0; f < kFrames; ++f) {
    std::string row;
    for (int j = 0; j < n; ++j) {
      Quat q = Quat::Identity();
      Vec3 p = offsets[j];
      const auto names = split(kJoints[j].channels);
      for (std::size_t c = 0; c < names.size(); ++c) {
        char buf[64];
        const bool rot = names[c].find("rotation") != std::string::npos;
        double v = rot ? curve(j, static_cast<int>(c), f) : 3.0 * std::sin(0.1 * f + j + c);
        std::snprintf(buf, sizeof buf, "%.6f", v);
        v = std::stod(buf);  // the value as written
        row += (row.empty() ? "" : " ") + std::string(buf);
        const int axis = names[c][0] - 'X';
        if (rot) q = q * Quat(Eigen::AngleAxisd(v * kDeg, Vec3::Unit(axis)));
        else p[axis] = v;
      }
      g.rotation[static_cast<std::size_t>(j)].push_back(q.normalized());
      g.translation[static_cast<std::size_t>(j)].push_back(p);
    }
    t += row + "\n";
  }
  return g;
}

// Hinge and two-axis joints can only hold rotations their channels express; the
// generated ones do by construction.
TEST(GeneratedBvh, EveryLayoutReadsExactlyAndRoundTrips) {
  const Generated g = generate();
  test::TempDir dir;
  const auto src = dir / "generated.bvh";
  test::write_text(src, g.text);
  std::vector<std::string> warnings;
  ReadOptions options;
  options.on_warning = [&](const std::string& w) { warnings.push_back(w); };
  options.cross_check_with_assimp = true;
  Result<Clip> a = read_clip(src, options);
  ASSERT_TRUE(a) << a.error();
  EXPECT_TRUE(warnings.empty()) << warnings.front();  // assimp agrees on every joint
  // Without the cross-check (the default) the clip is the same, bit for bit.
  Result<Clip> own = read_clip(src);
  ASSERT_TRUE(own) << own.error();
  for (std::size_t j = 0; j < a->rotations.size(); ++j) {
    EXPECT_EQ(own->rotations[j].keys.size(), a->rotations[j].keys.size());
    for (std::size_t k = 0; k < a->rotations[j].keys.size(); ++k)
      ASSERT_EQ(own->rotations[j].keys[k].coeffs(), a->rotations[j].keys[k].coeffs()) << j << " " << k;
  }

  const std::size_t n = std::size(kJoints);
  ASSERT_EQ(a->skeleton.joints.size(), n);
  for (std::size_t j = 0; j < n; ++j) {
    EXPECT_EQ(a->skeleton.joints[j].name, kJoints[j].name);
    const bool has_position = std::string(kJoints[j].channels).find("position") != std::string::npos;
    ASSERT_EQ(a->translations[j].has_value(), has_position) << kJoints[j].name;
    for (int f = 0; f < kFrames; ++f) {
      EXPECT_LE(angular_distance(a->rotations[j].keys[static_cast<std::size_t>(f)], g.rotation[j][static_cast<std::size_t>(f)]), 1e-12)
          << kJoints[j].name << " frame " << f;
      if (has_position) {
        EXPECT_LE((a->translations[j]->keys[static_cast<std::size_t>(f)] - g.translation[j][static_cast<std::size_t>(f)]).norm(), 1e-12)
            << kJoints[j].name << " frame " << f;
      }
    }
  }

  const auto out = dir / "written.bvh";
  ASSERT_TRUE(write_clip(*a, out));
  Result<Clip> b = read_clip(out);
  ASSERT_TRUE(b) << b.error();
  for (std::size_t j = 0; j < n; ++j) {
    EXPECT_EQ(bvh_channels(*b, j), bvh_channels(*a, j)) << kJoints[j].name;
    EXPECT_EQ(b->skeleton.joints[j].offset, a->skeleton.joints[j].offset);
    for (int f = 0; f < kFrames; ++f) {
      const auto k = static_cast<std::size_t>(f);
      EXPECT_LE(angular_distance(a->rotations[j].keys[k], b->rotations[j].keys[k]), 1e-4 * kDeg) << kJoints[j].name << " " << f;
      if (a->translations[j]) {
        EXPECT_LE((a->translations[j]->keys[k] - b->translations[j]->keys[k]).norm(), 1e-4);
      }
    }
  }
  EXPECT_EQ(frame_time_text(*b), "0.016667");
  EXPECT_EQ(b->skeleton.end_sites.size(), a->skeleton.end_sites.size());
}

// A clip whose hinge joint turns about an axis its single channel cannot express
// is refused (nothing written) rather than silently bent.
TEST(GeneratedBvh, RotationAChannelLayoutCannotExpressIsRefused) {
  const Generated g = generate();
  test::TempDir dir;
  test::write_text(dir / "g.bvh", g.text);
  Result<Clip> a = read_clip(dir / "g.bvh");
  ASSERT_TRUE(a) << a.error();
  const int h = a->skeleton.find("H");
  a->rotations[static_cast<std::size_t>(h)].keys[3] = Quat(Eigen::AngleAxisd(0.3, Vec3::UnitX()));
  a->rotations[static_cast<std::size_t>(h)].make_sign_continuous();
  const Status s = write_clip(*a, dir / "bad.bvh");
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().find("frame 3, joint 'H'"), std::string::npos) << s.error();
  EXPECT_FALSE(std::filesystem::exists(dir / "bad.bvh"));
  EXPECT_EQ(dir.files().size(), 1u);  // only g.bvh: no temporary left behind
}

// The writer keeps a non-BVH layout choice: joints without channels get
// WriteOptions::bvh_order, plus position channels where they have translation
// tracks; every order reproduces the orientations.
TEST(GeneratedBvh, BvhOrderOptionChoosesTheChannelsOfJointsWithoutLayout) {
  const Generated g = generate();
  test::TempDir dir;
  test::write_text(dir / "g.bvh", g.text);
  Result<Clip> a = read_clip(dir / "g.bvh");
  ASSERT_TRUE(a) << a.error();
  set_bvh_layout(*a, std::nullopt);  // as from FBX
  for (const char* order : {"XYZ", "XZY", "YXZ", "YZX", "ZXY", "ZYX"}) {
    WriteOptions w;
    w.bvh_order = order;
    ASSERT_TRUE(write_clip(*a, dir / "o.bvh", w)) << order;
    Result<Clip> b = read_clip(dir / "o.bvh");
    ASSERT_TRUE(b) << b.error();
    const std::string axes = std::string(1, order[0]) + "rotation";
    ASSERT_EQ(bvh_channels(*b, 1).size(), 3u);
    EXPECT_EQ(std::string(channel_name(bvh_channels(*b, 1)[0])), axes);
    EXPECT_EQ(bvh_channels(*b, 0).size(), 6u);  // root has a translation track
    for (std::size_t j = 0; j < a->skeleton.joints.size(); ++j)
      for (std::size_t k = 0; k < a->rotations[j].keys.size(); ++k)
        ASSERT_LE(angular_distance(a->rotations[j].keys[k], b->rotations[j].keys[k]), 1e-4 * kDeg) << order;
  }
  WriteOptions bad;
  bad.bvh_order = "XXY";
  const Status s = write_clip(*a, dir / "bad.bvh", bad);
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().find("'XXY' is not a rotation order"), std::string::npos) << s.error();
}

// A layout assimp refuses ("Missing position channel": 6 channels that are not 3
// positions + 3 rotations) is read by our own pass; with the cross-check on, a
// warning says that assimp could not read it, without it (default) nothing is said.
TEST(GeneratedBvh, LayoutAssimpRefusesIsReadByOurPassWithAWarning) {
  const std::string text =
      "HIERARCHY\nROOT R\n{\n OFFSET 0 0 0\n CHANNELS 6 Zrotation Xrotation Yrotation Zrotation Xrotation Yrotation\n"
      " End Site\n {\n  OFFSET 0 1 0\n }\n}\nMOTION\nFrames: 2\nFrame Time: 0.04\n"
      "10 20 30 40 50 60\n-10 0 5 0 0 90\n";
  test::TempDir dir;
  test::write_text(dir / "six.bvh", text);
  std::vector<std::string> warnings;
  ReadOptions options;
  options.on_warning = [&](const std::string& w) { warnings.push_back(w); };
  Result<Clip> quiet = read_clip(dir / "six.bvh", options);
  ASSERT_TRUE(quiet) << quiet.error();
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  options.cross_check_with_assimp = true;
  Result<Clip> c = read_clip(dir / "six.bvh", options);
  ASSERT_TRUE(c) << c.error();
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("assimp could not read the motion"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find("read with rotinterp's own BVH pass"), std::string::npos) << warnings[0];
  auto R = [](int axis, double deg) { return Quat(Eigen::AngleAxisd(deg * kDeg, Vec3::Unit(axis))); };
  const Quat q0 = R(2, 10) * R(0, 20) * R(1, 30) * R(2, 40) * R(0, 50) * R(1, 60);
  EXPECT_LE(angular_distance(c->rotations[0].keys[0], q0), 1e-12);
  EXPECT_FALSE(c->translations[0]);
  // And it writes back with the same layout (a Z-X-Y triple carries the rotation).
  ASSERT_TRUE(write_clip(*c, dir / "back.bvh"));
  Result<Clip> b = read_clip(dir / "back.bvh");
  ASSERT_TRUE(b) << b.error();
  EXPECT_EQ(bvh_channels(*b, 0), bvh_channels(*c, 0));
  for (std::size_t k = 0; k < 2; ++k)
    EXPECT_LE(angular_distance(b->rotations[0].keys[k], c->rotations[0].keys[k]), 1e-4 * kDeg);
}

}  // namespace
}  // namespace rotinterp
