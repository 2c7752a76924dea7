// Our FBX writer: exact tick times and the rate's TimeMode, the stack spanning the
// clip, Euler curves without jumps, LimbNode skeletons, and binary and ASCII files
// that assimp reads back with the same joints, frames, rate and poses.
#include "rotinterp/io/fbx/fbx_write.h"
#include "io_test_util.h"
#include "rotinterp/io/files/file_record.h"
#include "rotinterp/clip/frames.h"
#include "rotinterp/clip/resample.h"
#include "rotinterp/io/read.h"
#include "rotinterp/io/write.h"
#include "support/run_cli.h"

#include <gtest/gtest.h>

#include <zlib.h>

#include <chrono>
#include <cmath>
#include <sstream>

namespace rotinterp {
namespace {

using test::kData;

// Every numeric array of the ASCII FBX nodes named `node` ("KeyTime", …), in file order.
std::vector<std::vector<double>> ascii_arrays(const std::string& text, const std::string& node) {
  std::vector<std::vector<double>> out;
  const std::string tag = "\t" + node + ": *";
  for (std::size_t at = text.find(tag); at != std::string::npos; at = text.find(tag, at + 1)) {
    const std::size_t a = text.find("a: ", at);
    const std::size_t close = text.find('}', a);
    std::string values = text.substr(a + 3, close - a - 3);
    for (char& c : values)
      if (c == ',') c = ' ';
    std::istringstream in(values);
    out.emplace_back();
    for (double v; in >> v;) out.back().push_back(v);
    EXPECT_EQ(out.back().size(), std::stoul(text.substr(at + tag.size()))) << node;
  }
  return out;
}

// The value of the Properties70 entry `name` (its 5th field) in an ASCII FBX.
std::string ascii_property(const std::string& text, const std::string& name) {
  const std::size_t at = text.find("P: \"" + name + "\"");
  if (at == std::string::npos) return "";
  std::size_t v = at;
  for (int field = 0; field < 4; ++field) v = text.find(',', v + 1);
  return text.substr(v + 2, text.find('\n', v) - v - 2);
}

Clip resampled(const std::string& source, const std::string& fps, double start = 0.0, double end = INFINITY) {
  Result<Clip> a = read_clip(kData / source);
  EXPECT_TRUE(a) << a.error();
  ResampleOptions o;
  if (!fps.empty()) o.fps = *parse_rate(fps);
  o.range = TimeRange{start, end};
  Result<Clip> b = resample_clip(*a, o);
  EXPECT_TRUE(b) << b.error();
  return *b;
}

using i128 = __int128;

// Tick k of `rate`: k·den/num seconds in FBX ticks, rounded half up, exactly.
std::int64_t expected_tick(std::int64_t k, const Rate& rate) {
  const i128 n = static_cast<i128>(k) * rate.den * kFbxTicksPerSecond;
  return static_cast<std::int64_t>((2 * n + rate.num) / (2 * static_cast<i128>(rate.num)));
}

TEST(FbxWrite, KeyTimesAreTheRatesExactTicksAndTheStackSpansTheClip) {
  const struct {
    const char* fps;
    int time_mode;
  } cases[] = {{"30000/1001", 9}, {"30", 6}, {"24", 11}, {"60", 3}, {"23", 14}};
  for (const auto& c : cases) {
    const Clip clip = resampled("bvh/NC_bandai1_walk_normal_001.bvh", c.fps, 0.0, 2.0);
    Result<std::string> text = encode_fbx(clip, FbxEncoding::ascii);
    ASSERT_TRUE(text) << text.error();
    const Rate rate = *parse_rate(c.fps);
    const auto times = ascii_arrays(*text, "KeyTime");
    // A rotation and a translation curve node per joint (6 channels on every joint).
    ASSERT_EQ(times.size(), 3 * 2 * clip.skeleton.joints.size()) << c.fps;
    const std::size_t frames = clip.frame_count();
    for (const auto& t : times) {
      ASSERT_EQ(t.size(), frames) << c.fps;
      for (std::size_t k = 0; k < frames; ++k)
        ASSERT_EQ(static_cast<std::int64_t>(t[k]), expected_tick(static_cast<std::int64_t>(k), rate)) << c.fps << " key " << k;
    }
    const std::string last = std::to_string(expected_tick(static_cast<std::int64_t>(frames - 1), rate));
    EXPECT_EQ(ascii_property(*text, "LocalStop"), last) << c.fps;
    EXPECT_EQ(ascii_property(*text, "ReferenceStop"), last) << c.fps;
    EXPECT_EQ(ascii_property(*text, "TimeSpanStop"), last) << c.fps;
    EXPECT_EQ(ascii_property(*text, "LocalStart"), "0") << c.fps;
    EXPECT_EQ(ascii_property(*text, "TimeMode"), std::to_string(c.time_mode)) << c.fps;
    EXPECT_EQ(std::stod(ascii_property(*text, "CustomFrameRate")), rate.hz()) << c.fps;
  }
}

// CMU 01_03 has angles up to 370° (ZYX channels) and a thumb that flips by 179.8°
// in one frame. At every key each joint's angles are the equivalent triple nearest
// the previous key's: no component moves by more than 180° (a 360° shift would be
// nearer) and the other Euler branch, (θ₀ + 180°, 180° − θ₁, θ₂ + 180°) in
// sequence order with the nearest 360° shifts, is never nearer.
TEST(FbxWrite, EulerCurvesTakeTheSolutionNearestThePreviousKey) {
  const Clip clip = resampled("bvh/cmu_01_03.bvh", "", 1.0, 20.0);
  Result<std::string> text = encode_fbx(clip, FbxEncoding::ascii);
  ASSERT_TRUE(text) << text.error();
  const auto values = ascii_arrays(*text, "KeyValueFloat");
  ASSERT_EQ(values.size(), 3 * (clip.skeleton.joints.size() + 1));  // rotations, and the root's translation
  auto nearest = [](double angle, double target) { return angle + 360.0 * std::round((target - angle) / 360.0); };
  double worst_component = 0.0, widest = 0.0, worst_branch = -INFINITY;
  for (std::size_t j = 0; j < clip.skeleton.joints.size(); ++j) {
    const std::size_t first = j == 0 ? 0 : 3 + 3 * j;  // the root's translation curves follow its rotation curves
    std::vector<std::size_t> seq;  // curve index (X, Y, Z) of each angle in sequence order
    for (Channel c : bvh_channels(clip, j))
      if (c >= Channel::Xrotation) seq.push_back(first + static_cast<std::size_t>(c) - static_cast<std::size_t>(Channel::Xrotation));
    ASSERT_EQ(seq.size(), 3u);
    for (std::size_t k = 1; k < values[first].size(); ++k) {
      Vec3 prev, cur;
      for (std::size_t i = 0; i < 3; ++i) {
        prev[static_cast<Eigen::Index>(i)] = values[seq[i]][k - 1];
        cur[static_cast<Eigen::Index>(i)] = values[seq[i]][k];
        widest = std::max(widest, std::abs(cur[static_cast<Eigen::Index>(i)]));
      }
      worst_component = std::max(worst_component, (cur - prev).cwiseAbs().maxCoeff());
      const Vec3 other(nearest(cur[0] + 180.0, prev[0]), nearest(180.0 - cur[1], prev[1]), nearest(cur[2] + 180.0, prev[2]));
      worst_branch = std::max(worst_branch, (cur - prev).norm() - (other - prev).norm());
    }
  }
  std::printf("[ cmu_01_03 ] largest component step %.4g°, nearer other branch by at most %.3g°; largest angle %.4g°\n",
              worst_component, worst_branch, widest);
  EXPECT_LE(worst_component, 180.0);
  EXPECT_LE(worst_branch, 1e-3);  // float storage of the angles
  EXPECT_GT(widest, 180.0) << "the clip should need angles past 180°";
}

// Every joint is a LimbNode Model with a Skeleton NodeAttribute; rest rotations are
// baked (no PreRotation); joints keep their BVH rotation order (ZXY → FBX YXZ = 3).
TEST(FbxWrite, JointsAreLimbNodesWithSkeletonAttributesInTheirRotationOrder) {
  const Clip clip = resampled("bvh/NC_bandai1_walk_normal_001.bvh", "30", 0.0, 0.5);
  Result<std::string> text = encode_fbx(clip, FbxEncoding::ascii);
  ASSERT_TRUE(text) << text.error();
  auto count = [&](const std::string& what) {
    std::size_t c = 0;
    for (std::size_t at = text->find(what); at != std::string::npos; at = text->find(what, at + 1)) ++c;
    return c;
  };
  const std::size_t n = clip.skeleton.joints.size();
  EXPECT_EQ(count("\", \"LimbNode\" {"), 2 * n);  // Model and NodeAttribute
  EXPECT_EQ(count("TypeFlags: \"Skeleton\""), n);
  EXPECT_EQ(count("P: \"RotationOrder\", \"enum\", \"\", \"\", 3"), n);
  EXPECT_EQ(count("PreRotation"), 0u);
  EXPECT_EQ(count("AnimationStack:"), 1u);
  EXPECT_EQ(count("AnimationLayer:"), 1u);
  EXPECT_NE(text->find("Model::" + clip.skeleton.joints[0].name), std::string::npos);
}

std::uint32_t u32_at(const std::string& s, std::size_t at) {
  std::uint32_t v = 0;
  for (std::size_t i = 0; i < 4; ++i) v |= static_cast<std::uint32_t>(static_cast<unsigned char>(s[at + i])) << (8 * i);
  return v;
}

// Binary FBX 7.4: header, version, zlib-compressed arrays that inflate to the
// ticks, the footer, and every top-level record's end offset chaining to the next.
TEST(FbxWrite, BinaryLayoutIsFbx74WithCompressedArrays) {
  const Clip clip = resampled("bvh/NC_bandai1_walk_normal_001.bvh", "30", 0.0, 2.0);
  Result<std::string> bin = encode_fbx(clip, FbxEncoding::binary);
  ASSERT_TRUE(bin) << bin.error();
  const std::string& b = *bin;
  ASSERT_GT(b.size(), 200u);
  EXPECT_EQ(b.substr(0, 23), std::string("Kaydara FBX Binary  \0\x1a\0", 23));
  EXPECT_EQ(u32_at(b, 23), 7400u);
  EXPECT_EQ(b.substr(b.size() - 16), std::string("\xf8\x5a\x8c\x6a\xde\xf5\xd9\x7e\xec\xe9\x0c\xe3\x75\x8f\x29\x0b", 16));
  // Top-level records chain by their end offsets up to the 13-byte null record.
  std::size_t at = 27, records = 0;
  while (u32_at(b, at) != 0) {
    const std::uint32_t end = u32_at(b, at);
    ASSERT_GT(end, at);
    ASSERT_LT(end, b.size());
    at = end;
    ++records;
  }
  EXPECT_EQ(b.substr(at, 13), std::string(13, '\0'));
  EXPECT_GE(records, 9u);  // header extension, FileId, …, Connections, Takes
  // The first KeyTime: one 'l' array, zlib (encoding 1), inflating to the ticks.
  const std::size_t name = b.find("\x07KeyTime");
  ASSERT_NE(name, std::string::npos);
  const std::size_t prop = name + 8;
  ASSERT_EQ(b[prop], 'l');
  const std::uint32_t count = u32_at(b, prop + 1), encoding = u32_at(b, prop + 5), packed = u32_at(b, prop + 9);
  ASSERT_EQ(count, clip.frame_count());
  ASSERT_EQ(encoding, 1u);
  std::vector<std::int64_t> ticks(count);
  uLongf len = count * 8;
  ASSERT_EQ(uncompress(reinterpret_cast<Bytef*>(ticks.data()), &len, reinterpret_cast<const Bytef*>(b.data() + prop + 13), packed), Z_OK);
  ASSERT_EQ(len, count * 8u);
  for (std::size_t k = 0; k < count; ++k) EXPECT_EQ(ticks[k], expected_tick(static_cast<std::int64_t>(k), Rate{30, 1}));
}

// Binary and ASCII files read back by assimp alike: the same joints, frames and
// rate, and every joint's world position at every frame within float precision.
TEST(FbxWrite, AssimpReadsBothEncodingsBackWithTheSameJointsFramesRateAndPoses) {
  const struct {
    const char* source;
    const char* fps;
  } cases[] = {{"bvh/NC_bandai1_walk_normal_001.bvh", "30"}, {"bvh/cmu_01_01.bvh", "60"},
               {"fbx/digitalrune_Marine_Run.fbx", "30"}, {"fbx/assimp_huesitos.fbx", "25"}};
  for (const auto& c : cases) {
    const Clip clip = resampled(c.source, c.fps, 0.0, c.source[0] == 'b' ? 3.0 : INFINITY);
    const double size = test::skeleton_size(clip);
    for (bool ascii : {false, true}) {
      test::TempDir dir;
      WriteOptions w;
      w.fbx_ascii = ascii;
      const Status s = write_clip(clip, dir / "out.fbx", w);
      ASSERT_TRUE(s) << s.error();
      Result<Clip> back = read_clip(dir / "out.fbx");
      ASSERT_TRUE(back) << c.source << ": " << back.error();
      ASSERT_EQ(back->skeleton.joints.size(), clip.skeleton.joints.size()) << c.source;
      for (const Joint& j : clip.skeleton.joints) EXPECT_GE(back->skeleton.find(j.name), 0) << j.name;
      EXPECT_EQ(back->frame_count(), clip.frame_count()) << c.source;
      ASSERT_TRUE(clip_rate(*back)) << c.source;
      EXPECT_EQ(*clip_rate(*back), *parse_rate(c.fps)) << c.source;
      double worst = 0.0;
      for (std::size_t k = 0; k < clip.frame_count(); ++k) {
        const double t = clip.start_time() + static_cast<double>(k) * clip.frame_time;
        const WorldPose a = test::pose_at(clip, t), bp = test::pose_at(*back, back->start_time() + (t - clip.start_time()));
        for (std::size_t j = 0; j < a.position.size(); ++j) {
          const auto jb = static_cast<std::size_t>(back->skeleton.find(clip.skeleton.joints[j].name));
          worst = std::max(worst, (a.position[j] - bp.position[jb]).norm());
        }
      }
      EXPECT_LE(worst, 1e-5 * size) << c.source << (ascii ? " ascii" : " binary");
      std::printf("[ %s -> %s fbx ] worst joint position %.3g of skeleton size %.3g\n", c.source, ascii ? "ascii" : "binary",
                  worst, size);
    }
  }
}

TEST(FbxWrite, AJointWhoseRotationChannelsRepeatAnAxisKeepsItsOrientations) {
  // BVH allows any channel layout (Xrotation Xrotation Yrotation); FBX has only the
  // six orders of three different axes, so such a joint is written in XYZ and its
  // orientations must survive (an order made of a repeated axis cannot express them).
  test::TempDir dir;
  test::write_text(dir / "repeat.bvh",
                   "HIERARCHY\nROOT A\n{\n  OFFSET 0 0 0\n  CHANNELS 3 Xrotation Xrotation Yrotation\n"
                   "  End Site\n  {\n    OFFSET 0 1 0\n  }\n}\nMOTION\nFrames: 3\nFrame Time: 0.1\n"
                   "10 20 30\n-40 15 70\n5 -60 -25\n");
  Result<Clip> clip = read_clip(dir / "repeat.bvh");
  ASSERT_TRUE(clip) << clip.error();
  ASSERT_TRUE(write_clip(*clip, dir / "repeat.fbx"));
  Result<Clip> back = read_clip(dir / "repeat.fbx");
  ASSERT_TRUE(back) << back.error();
  ASSERT_EQ(back->frame_count(), 3u);
  const int a = back->skeleton.find("A");
  ASSERT_GE(a, 0);
  for (std::size_t k = 0; k < 3; ++k)
    EXPECT_LT(angular_distance(clip->rotations[0].keys[k], back->rotations[static_cast<std::size_t>(a)].keys[k]), 1e-4)
        << "frame " << k;
}

// A chain 10 000 joints deep (rigs of generated or scanned content get there):
// every writer walks the skeleton without recursion, so none runs out of stack,
// and in time linear in the joints (BVH indentation stops at 64 levels).
TEST(FbxWrite, DeepChainsAreWrittenInEveryFormat) {
  Clip clip;
  clip.name = "chain";
  clip.frame_time = 1.0 / 30.0;
  constexpr std::size_t kDepth = 10000;
  for (std::size_t j = 0; j < kDepth; ++j) {
    Joint joint;
    joint.name = "j" + std::to_string(j);
    joint.parent = static_cast<int>(j) - 1;
    joint.offset = Vec3(0.0, 1.0, 0.0);
    clip.skeleton.joints.push_back(joint);
    RotationTrack r;
    r.times = {0.0, 1.0 / 30.0};
    r.keys = {Quat::Identity(), Quat(Eigen::AngleAxisd(1e-3, Vec3::UnitZ()))};
    clip.rotations.push_back(r);
    clip.translations.emplace_back();
  }
  ASSERT_TRUE(clip.validate());
  test::TempDir dir;
  for (const char* name : {"out.fbx", "out.glb", "out.gltf", "out.bvh"}) {
    const auto t0 = std::chrono::steady_clock::now();
    const Status s = write_clip(clip, dir / name);
    std::printf("[ chain of %zu ] %s in %.2f s\n", kDepth, name, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    ASSERT_TRUE(s) << name << ": " << s.error();
    EXPECT_GT(std::filesystem::file_size(dir / name), kDepth) << name;
  }
}

// A skinned source written as BVH: one warning line on stderr says its meshes are
// not written; as FBX they are kept (io/fbx/fbx_character.h) and nothing is said; a
// BVH source gets none.
TEST(FbxWrite, ResampleSaysOnceThatTheSourcesMeshesAreNotWritten) {
  test::TempDir dir;
  const std::string dude = (kData / "fbx" / "digitalrune_Dude.fbx").string();
  const test::CliResult kept = test::run_cli("resample '" + dude + "' -o '" + (dir / "dude.fbx").string() + "' --fps 30 -q");
  ASSERT_EQ(kept.exit_code, 0) << kept.err;
  EXPECT_EQ(kept.err, "");
  const test::CliResult skinned = test::run_cli("resample '" + dude + "' -o '" + (dir / "dude.bvh").string() + "' --fps 30 -q");
  ASSERT_EQ(skinned.exit_code, 0) << skinned.err;
  EXPECT_EQ(std::count(skinned.err.begin(), skinned.err.end(), '\n'), 1) << skinned.err;
  EXPECT_NE(skinned.err.find("rotinterp: warning: "), std::string::npos) << skinned.err;
  EXPECT_NE(skinned.err.find("mesh(es) and their skins are not written"), std::string::npos) << skinned.err;
  const test::CliResult bvh = test::run_cli("resample '" + (kData / "bvh" / "bvhio_example.bvh").string() + "' -o '" +
                                            (dir / "b.fbx").string() + "' -q");
  ASSERT_EQ(bvh.exit_code, 0) << bvh.err;
  EXPECT_EQ(bvh.err, "");
}

}  // namespace
}  // namespace rotinterp
