// write_clips: several takes of one skeleton in one FBX (binary and ASCII) or GLB,
// each read back by name with its own frames, key times, rotations and translations,
// its FBX stack named and spanning its own keys from 0; refusals of other skeletons
// and single-take formats.
#include "io_test_util.h"
#include "rotinterp/clip/frames.h"
#include "rotinterp/clip/resample.h"
#include "rotinterp/io/fbx/fbx_curves.h"
#include "rotinterp/io/read.h"
#include "rotinterp/io/write.h"

#include <gtest/gtest.h>

#include <cmath>

namespace rotinterp {
namespace {

using test::cut_take;
using test::kData;

constexpr double kDegrees = 180.0 / kPi;

// Three takes of CMU subject 01's skeleton: lengths 2 s, 1.5 s (starting at 1 s in its
// source: written from 0) and 0.5 s; rates 30, 24 and 60 Hz; two motions (01_01
// jumps, 01_03 climbs), the last take played backwards.
std::vector<Clip> three_takes() {
  std::vector<Clip> takes = {cut_take("bvh/cmu_01_01.bvh", "30", 0.0, 2.0, "Jump"),
                             cut_take("bvh/cmu_01_03.bvh", "24", 1.0, 2.5, "Climb"),
                             cut_take("bvh/cmu_01_01.bvh", "60", 3.0, 3.5, "Back")};
  Clip& back = takes[2];
  for (RotationTrack& r : back.rotations) std::reverse(r.keys.begin(), r.keys.end());
  for (auto& tr : back.translations)
    if (tr) std::reverse(tr->keys.begin(), tr->keys.end());
  return takes;
}

struct Worst {
  double degrees = 0.0, translation = 0.0, time = 0.0;
};

// `back` (read from a file) against `take` keyed from 0: frames, key times, and the
// local rotation and translation of every joint at every key. Translations in metres.
Worst compare_take(const Clip& take, const Clip& back, const std::string& what) {
  Worst w;
  EXPECT_EQ(back.frame_count(), take.frame_count()) << what;
  EXPECT_EQ(clip_rate(back), clip_rate(take)) << what;
  EXPECT_NEAR(back.start_time(), 0.0, 1e-9) << what;
  const double t0 = take.start_time();
  for (std::size_t j = 0; j < take.skeleton.joints.size(); ++j) {
    const int found = back.skeleton.find(take.skeleton.joints[j].name);
    EXPECT_GE(found, 0) << what << ": " << take.skeleton.joints[j].name;
    if (found < 0) continue;
    const auto jb = static_cast<std::size_t>(found);
    const RotationTrack& a = take.rotations[j];
    const RotationTrack& b = back.rotations[jb];
    EXPECT_EQ(b.times.size(), a.times.size()) << what << ": " << take.skeleton.joints[j].name;
    if (b.times.size() != a.times.size()) continue;
    for (std::size_t k = 0; k < a.times.size(); ++k) {
      w.time = std::max(w.time, std::abs(b.times[k] - (a.times[k] - t0)));
      w.degrees = std::max(w.degrees, a.keys[k].angularDistance(b.keys[k]) * kDegrees);
      if (take.translations[j]) {
        const Vec3 pa = test::sample(take.translations[j], take.skeleton.joints[j].offset, a.times[k]);
        const Vec3 pb = test::sample(back.translations[jb], back.skeleton.joints[jb].offset, b.times[k]);
        w.translation = std::max(w.translation, (pa * take.unit.metres_per_unit - pb * back.unit.metres_per_unit).norm());
      }
    }
  }
  return w;
}

TEST(WriteTakes, EveryTakeReadsBackByNameWithItsOwnFramesTimesAndPoses) {
  const std::vector<Clip> takes = three_takes();
  for (const char* name : {"out.fbx", "ascii.fbx", "out.glb"}) {
    test::TempDir dir;
    WriteOptions w;
    w.fbx_ascii = std::string(name) == "ascii.fbx";
    const Status s = write_clips(takes, dir / name, w);
    ASSERT_TRUE(s) << s.error();
    for (const Clip& take : takes) {
      ReadOptions o;
      o.animation = take.name;
      Result<Clip> back = read_clip(dir / name, o);
      ASSERT_TRUE(back) << name << " " << take.name << ": " << back.error();
      const Worst worst = compare_take(take, *back, std::string(name) + " " + take.name);
      const double size = test::skeleton_size(take) * take.unit.metres_per_unit;
      EXPECT_LE(worst.degrees, 1e-4) << name << " " << take.name;
      EXPECT_LE(worst.translation, 1e-6 * size) << name << " " << take.name;
      EXPECT_LE(worst.time, 1e-6) << name << " " << take.name;
      std::printf("[ %s %s ] %zu frames, worst rotation %.3g deg, translation %.3g m, key time %.3g s\n", name,
                  take.name.c_str(), back->frame_count(), worst.degrees, worst.translation, worst.time);
    }
  }
}

TEST(WriteTakes, EachFbxStackIsNamedAndSpansItsOwnKeysFromZero) {
  const std::vector<Clip> takes = three_takes();
  test::TempDir dir;
  ASSERT_TRUE(write_clips(takes, dir / "out.fbx"));
  const FbxAnimation anim = test::read_fbx_curves((dir / "out.fbx").string());
  ASSERT_EQ(anim.takes.size(), takes.size());
  for (std::size_t i = 0; i < takes.size(); ++i) {
    EXPECT_EQ(anim.takes[i].name, takes[i].name);
    const FbxTickSpan span = fbx_take_span(anim.takes[i]);
    const double duration = takes[i].rotations.front().times.back() - takes[i].start_time();
    EXPECT_EQ(span.start, 0) << takes[i].name;
    EXPECT_EQ(span.stop, std::llround(duration * static_cast<double>(kFbxTicksPerSecond))) << takes[i].name;
  }
}

TEST(WriteTakes, EmptyAndRepeatedNamesBecomeUnique) {
  std::vector<Clip> takes = three_takes();
  takes[0].name = "";
  takes[2].name = takes[1].name;
  test::TempDir dir;
  ASSERT_TRUE(write_clips(takes, dir / "out.fbx"));
  const FbxAnimation anim = test::read_fbx_curves((dir / "out.fbx").string());
  ASSERT_EQ(anim.takes.size(), 3u);
  EXPECT_EQ(anim.takes[0].name, "Take 1");
  EXPECT_EQ(anim.takes[1].name, "Climb");
  EXPECT_EQ(anim.takes[2].name, "Climb 2");
  ReadOptions o;
  o.animation = "Climb 2";
  ASSERT_TRUE(write_clips(takes, dir / "out.glb"));
  Result<Clip> back = read_clip(dir / "out.glb", o);
  ASSERT_TRUE(back) << back.error();
  EXPECT_EQ(back->frame_count(), takes[2].frame_count());
}

TEST(WriteTakes, AnotherSkeletonIsRefusedNamingTheTakeAndTheFileStaysIntact) {
  std::vector<Clip> takes = three_takes();
  takes[1] = cut_take("bvh/NC_bandai1_walk_normal_001.bvh", "30", 0.0, 1.0, "Walk");
  test::TempDir dir;
  test::write_text(dir / "out.fbx", "previous");
  for (const char* name : {"out.fbx", "out.glb"}) {
    const Status s = write_clips(takes, dir / name);
    ASSERT_FALSE(s);
    EXPECT_NE(s.error().find("take 'Walk' has another skeleton"), std::string::npos) << s.error();
    EXPECT_EQ(s.error().find('\n'), std::string::npos) << s.error();
  }
  EXPECT_EQ(test::read_text(dir / "out.fbx"), "previous");
  EXPECT_FALSE(std::filesystem::exists(dir / "out.glb"));

  takes = three_takes();
  takes[2].skeleton.joints[3].offset.x() += 1e-6;
  const Status s = write_clips(takes, dir / "out.fbx");
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().find("take 'Back'"), std::string::npos) << s.error();
  EXPECT_NE(s.error().find("offset"), std::string::npos) << s.error();
}

TEST(WriteTakes, SingleTakeFormatsAreRefusedWithTheWayToOneFilePerTake) {
  const std::vector<Clip> takes = three_takes();
  test::TempDir dir;
  const Status s = write_clips(takes, dir / "out.bvh");
  ASSERT_FALSE(s);
  EXPECT_EQ(s.error(), (dir / "out.bvh").string() +
                           ": a .bvh file holds one take; put {anim} in the output name to write one file per take");
  EXPECT_FALSE(write_clips(takes, dir / "out.csv"));
  EXPECT_FALSE(std::filesystem::exists(dir / "out.bvh"));
}

TEST(WriteTakes, OneTakeWritesTheSameFbxAndGlbAsWriteClip) {
  Clip take = cut_take("bvh/cmu_01_01.bvh", "30", 0.0, 1.0, "Jump");
  test::TempDir dir;
  for (const char* ext : {".fbx", ".glb"}) {
    ASSERT_TRUE(write_clip(take, dir / (std::string("one") + ext)));
    ASSERT_TRUE(write_clips({take}, dir / (std::string("many") + ext)));
    EXPECT_EQ(test::read_text(dir / (std::string("one") + ext)), test::read_text(dir / (std::string("many") + ext))) << ext;
  }
}

}  // namespace
}  // namespace rotinterp
