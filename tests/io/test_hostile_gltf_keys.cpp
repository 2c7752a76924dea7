// Issue 47, class 3 on glTF: sampler keys that the default (assimp) path used to take
// in silence — times that go back or repeat, NaN times, NaN or zero quaternions, a
// buffer view whose offset wraps around — are refused with one line naming the file,
// the animation and the sampler; a key that exactly repeats the one before is dropped
// with a warning that counts it. Each file is the shared Bandai clip written to glTF
// by rotinterp, then mutated.
#include "hostile_inputs.h"
#include "io_test_util.h"
#include "rotinterp/io/info.h"
#include "rotinterp/io/read.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace rotinterp {
namespace {

namespace fs = std::filesystem;

class HostileGltfKeys : public ::testing::Test {
 protected:
  void SetUp() override { gltf_ = test::shared_gltf(dir_.path()); }

  // The read of the shared file with `mutate` applied; its one-line error.
  std::string refusal(const std::string& name, const std::function<void(test::GltfFile&)>& mutate) {
    test::GltfFile g = gltf_;
    mutate(g);
    const fs::path file = g.write(dir_.path(), name);
    Result<Clip> clip = read_clip(file);
    EXPECT_FALSE(clip.ok()) << name << " was read";
    if (clip.ok()) return "";
    EXPECT_EQ(clip.error().rfind(file.string() + ": glTF animations: animation '", 0), 0u) << clip.error();
    EXPECT_EQ(clip.error().find('\n'), std::string::npos) << clip.error();
    return clip.error();
  }
  // Offsets of the first rotation sampler's time k and quaternion k.
  std::size_t time_at(const test::GltfFile& g, std::size_t k) const { return g.offset_of(g.rotation_sampler().first) + 4 * k; }
  std::size_t quat_at(const test::GltfFile& g, std::size_t k) const {
    return g.offset_of(g.rotation_sampler().second) + 16 * k;
  }

  test::TempDir dir_;
  test::GltfFile gltf_;
};

TEST_F(HostileGltfKeys, TimesThatGoBackAreRefused) {
  const std::string error = refusal("reversed.gltf", [&](test::GltfFile& g) {
    std::string t = g.bin.substr(time_at(g, 1), 8);
    std::memcpy(&g.bin[time_at(g, 1)], t.data() + 4, 4);
    std::memcpy(&g.bin[time_at(g, 2)], t.data(), 4);
  });
  EXPECT_NE(error.find("key 2: its time"), std::string::npos) << error;
  EXPECT_NE(error.find("(times must increase)"), std::string::npos) << error;
}

TEST_F(HostileGltfKeys, ARepeatedTimeWithAnotherValueIsRefused) {
  const std::string error = refusal("same_time.gltf", [&](test::GltfFile& g) {
    std::memcpy(&g.bin[time_at(g, 1)], &g.bin[time_at(g, 0)], 4);
  });
  EXPECT_NE(error.find("key 1: its time 0 is key 0's, with another value"), std::string::npos) << error;
}

TEST_F(HostileGltfKeys, NanTimesAndNanOrZeroQuaternionsAreRefused) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_NE(refusal("nan_time.gltf", [&](test::GltfFile& g) { test::put_f32(g.bin, time_at(g, 3), nan); })
                .find("key 3: its time is not finite"),
            std::string::npos);
  EXPECT_NE(refusal("nan_quat.gltf", [&](test::GltfFile& g) { test::put_f32(g.bin, quat_at(g, 2) + 4, nan); })
                .find("key 2: a value is not finite"),
            std::string::npos);
  EXPECT_NE(refusal("zero_quat.gltf",
                    [&](test::GltfFile& g) {
                      for (int c = 0; c < 4; ++c) test::put_f32(g.bin, quat_at(g, 4) + 4 * c, 0.0f);
                    })
                .find("key 4: a rotation of length 0 (no direction)"),
            std::string::npos);
}

TEST_F(HostileGltfKeys, ABufferViewOffsetThatWrapsAroundIsRefused) {
  test::GltfFile g = gltf_;
  const std::size_t view = g.doc["accessors"][g.rotation_sampler().second]["bufferView"].get<std::size_t>();
  g.doc["bufferViews"][view]["byteOffset"] = std::numeric_limits<std::uint64_t>::max() - 7;
  const fs::path file = g.write(dir_.path(), "wrap.gltf");
  Result<Clip> clip = read_clip(file);
  ASSERT_FALSE(clip.ok());
  EXPECT_NE(clip.error().find("its buffer view passes its buffer's end"), std::string::npos) << clip.error();
}

TEST_F(HostileGltfKeys, AKeyThatRepeatsTheOneBeforeIsDroppedWithAWarning) {
  // Key 1 of every sampler becomes key 0 again, time and values (all share one input).
  test::GltfFile g = gltf_;
  for (const auto& s : g.doc["animations"][0]["samplers"]) {
    const std::size_t out = s["output"].get<std::size_t>();
    const std::size_t width = g.doc["accessors"][out]["type"] == "VEC4" ? 16 : 12;
    std::memcpy(&g.bin[g.offset_of(out) + width], &g.bin[g.offset_of(out)], width);
  }
  std::memcpy(&g.bin[time_at(g, 1)], &g.bin[time_at(g, 0)], 4);
  std::vector<std::string> warnings;
  ReadOptions options;
  options.on_warning = [&](const std::string& w) { warnings.push_back(w); };
  Result<ClipFileInfo> info = inspect_clip(g.write(dir_.path(), "repeat.gltf"), options);
  ASSERT_TRUE(info.ok()) << info.error();
  std::size_t repaired = 0;
  for (const std::string& w : warnings)
    if (w.find(": 1 key at a time already keyed with the same values dropped") != std::string::npos) ++repaired;
  EXPECT_EQ(repaired, g.doc["animations"][0]["samplers"].size());
  for (const RotationTrack& r : info->clip.rotations)
    for (const Quat& q : r.keys) EXPECT_TRUE(q.coeffs().allFinite());
}

}  // namespace
}  // namespace rotinterp
