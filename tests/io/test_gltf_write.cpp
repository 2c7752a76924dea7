// Our glTF writer: a skin over every joint with the rest pose's inverse bind
// matrices, a .gltf buffer named by its content, and times that read back on the
// exact grid (60 Hz, where float times jitter by 4e-6 s).
#include "io_test_util.h"
#include "rotinterp/clip/frames.h"
#include "rotinterp/clip/resample.h"
#include "rotinterp/io/read.h"
#include "rotinterp/io/write.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstring>

namespace rotinterp {
namespace {

using test::kData;

Clip resampled(const char* source, const char* fps) {
  Result<Clip> a = read_clip(kData / source);
  EXPECT_TRUE(a) << a.error();
  ResampleOptions o;
  o.fps = *parse_rate(fps);
  Result<Clip> b = resample_clip(*a, o);
  EXPECT_TRUE(b) << b.error();
  return *b;
}

std::vector<std::string> bin_files(const test::TempDir& dir) {
  std::vector<std::string> out;
  for (const std::string& f : dir.files())
    if (f.size() > 4 && f.substr(f.size() - 4) == ".bin") out.push_back(f);
  return out;
}

TEST(GltfWrite, SkinCoversEveryJointWithTheRestPosesInverseBindMatrices) {
  const Clip clip = resampled("fbx/digitalrune_Marine_Run.fbx", "30");  // rest rotations, three roots
  test::TempDir dir;
  ASSERT_TRUE(write_clip(clip, dir / "out.gltf"));
  const nlohmann::json doc = nlohmann::json::parse(test::read_text(dir / "out.gltf"));
  const std::size_t n = clip.skeleton.joints.size();
  ASSERT_EQ(doc["skins"].size(), 1u);
  const nlohmann::json& skin = doc["skins"][0];
  ASSERT_EQ(skin["joints"].size(), n);
  EXPECT_EQ(doc["scenes"][0]["nodes"].size(), 3u);
  const std::string bin = test::read_text(dir / doc["buffers"][0]["uri"].get<std::string>());
  const nlohmann::json& acc = doc["accessors"][skin["inverseBindMatrices"].get<std::size_t>()];
  const nlohmann::json& view = doc["bufferViews"][acc["bufferView"].get<std::size_t>()];
  ASSERT_EQ(acc["type"], "MAT4");
  ASSERT_EQ(acc["count"], n);
  std::vector<float> m(16 * n);
  std::memcpy(m.data(), bin.data() + view["byteOffset"].get<std::size_t>(), m.size() * 4);
  // glTF's unit is the metre: this FBX is in centimetres (unit scale 0.01), so node
  // translations and the matrices' translations are its offsets × 0.01.
  const double metres = clip.unit.metres_per_unit;
  ASSERT_EQ(metres, 0.01);
  for (std::size_t j = 0; j < n; ++j)
    for (int a = 0; a < 3; ++a)
      EXPECT_NEAR(doc["nodes"][j]["translation"][static_cast<std::size_t>(a)].get<double>(),
                  clip.skeleton.joints[j].offset[a] * metres, 1e-12)
          << clip.skeleton.joints[j].name;
  // World rest transforms by forward kinematics (in metres); IBM · world = identity.
  std::vector<Quat> rest(n);
  std::vector<Vec3> offsets(n);
  for (std::size_t j = 0; j < n; ++j) rest[j] = clip.skeleton.joints[j].rest_rotation, offsets[j] = clip.skeleton.joints[j].offset;
  WorldPose w;
  forward_kinematics(clip.skeleton, rest, offsets, w);
  const double size = test::skeleton_size(clip);
  double worst = 0.0;
  for (std::size_t j = 0; j < n; ++j) {
    const std::size_t node = skin["joints"][j].get<std::size_t>();
    EXPECT_EQ(doc["nodes"][node]["name"], clip.skeleton.joints[j].name);
    Eigen::Matrix4d ibm;
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) ibm(r, c) = m[16 * j + static_cast<std::size_t>(4 * c + r)];
    Eigen::Matrix4d world = Eigen::Matrix4d::Identity();
    world.topLeftCorner<3, 3>() = w.rotation[j].toRotationMatrix();
    world.topRightCorner<3, 1>() = w.position[j] * metres;
    const Eigen::Matrix4d id = ibm * world;
    worst = std::max(worst, (id.topLeftCorner<3, 3>() - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff());
    worst = std::max(worst, id.topRightCorner<3, 1>().cwiseAbs().maxCoeff() / (size * metres));
  }
  EXPECT_LT(worst, 1e-5);
}

// Runs writing the same .gltf name: each buffer is named by its bytes, so a .gltf
// always names its own run's buffer; the buffer of the .gltf it replaces goes with
// it (issue 28: three runs left three buffers), and other files' buffers stay.
TEST(GltfWrite, ARerunReplacesItsBufferAndLeavesNoneBehind) {
  test::TempDir dir;
  const Clip a = resampled("bvh/NC_bandai2_raise-up-both-hands_active_031.bvh", "30");
  const Clip b = resampled("bvh/NC_bandai2_raise-up-both-hands_active_031.bvh", "60");
  ASSERT_TRUE(write_clip(a, dir / "other.gltf"));  // a neighbour: its buffer is not ours to remove
  ASSERT_TRUE(write_clip(a, dir / "out.gltf"));
  ASSERT_TRUE(write_clip(b, dir / "out.gltf"));
  EXPECT_EQ(bin_files(dir).size(), 2u) << "out's first buffer removed, other's kept";
  ASSERT_TRUE(write_clip(a, dir / "out.gltf"));
  EXPECT_EQ(bin_files(dir).size(), 2u);
  Result<Clip> other = read_clip(dir / "other.gltf"), out = read_clip(dir / "out.gltf");
  ASSERT_TRUE(other) << other.error();
  ASSERT_TRUE(out) << out.error();
  EXPECT_EQ(other->frame_count(), a.frame_count());
  EXPECT_EQ(out->frame_count(), a.frame_count());
  // The same clip again: the same buffer name, kept.
  ASSERT_TRUE(write_clip(a, dir / "out.gltf"));
  EXPECT_EQ(bin_files(dir).size(), 2u);
  EXPECT_TRUE(read_clip(dir / "out.gltf"));
}

// Float32 times at 60 Hz (and NTSC) come back on the exact grid: same joints,
// frames and rate, poses within float precision.
TEST(GltfWrite, FloatTimesReadBackOnTheExactGrid) {
  for (const char* fps : {"60", "30000/1001", "120"})
    for (const char* ext : {".glb", ".gltf"}) {
      const Clip clip = resampled("bvh/NC_bandai1_walk_normal_001.bvh", fps);
      test::TempDir dir;
      ASSERT_TRUE(write_clip(clip, dir / (std::string("out") + ext)));
      Result<Clip> back = read_clip(dir / (std::string("out") + ext));
      ASSERT_TRUE(back) << back.error();
      ASSERT_EQ(back->skeleton.joints.size(), clip.skeleton.joints.size());
      EXPECT_EQ(back->frame_count(), clip.frame_count()) << fps << ext;
      ASSERT_TRUE(clip_rate(*back)) << fps << ext;
      EXPECT_EQ(*clip_rate(*back), *parse_rate(fps)) << fps << ext;
      double worst = 0.0;
      for (std::size_t k = 0; k < clip.frame_count(); ++k) {
        const double t = clip.start_time() + static_cast<double>(k) * clip.frame_time;
        const WorldPose pa = test::pose_at(clip, t), pb = test::pose_at(*back, t);
        for (std::size_t j = 0; j < pa.position.size(); ++j) worst = std::max(worst, (pa.position[j] - pb.position[j]).norm());
      }
      EXPECT_LE(worst, 1e-5 * test::skeleton_size(clip)) << fps << ext;
    }
}

}  // namespace
}  // namespace rotinterp
