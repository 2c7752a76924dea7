#include "rotinterp/clip/synth_spec.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

using namespace rotinterp;

namespace {

SynthOptions options(SynthKind kind, std::uint64_t seed, double seconds, Rate fps, int joints) {
  SynthOptions o;
  o.kind = kind;
  o.seed = seed;
  o.seconds = seconds;
  o.fps = fps;
  o.joints = joints;
  return o;
}

}  // namespace

TEST(SynthSpec, RoundTripsTheOptionsAndRejectsUnknownKeysAndKinds) {
  const SynthOptions o = options(SynthKind::spin, 12345, 2.5, Rate{30000, 1001}, 7);
  const std::string spec = synth_spec(o);
  EXPECT_EQ(spec, "kind=spin seconds=2.5 fps=30000/1001 seed=12345 joints=7");
  auto back = parse_synth_spec(spec);
  ASSERT_TRUE(back.ok()) << back.error();
  EXPECT_EQ(back->kind, SynthKind::spin);
  EXPECT_EQ(back->seconds, 2.5);
  EXPECT_EQ(back->fps, (Rate{30000, 1001}));
  EXPECT_EQ(back->seed, 12345u);
  EXPECT_EQ(back->joints, 7);
  EXPECT_FALSE(parse_synth_spec("kind=dance").ok());
  EXPECT_FALSE(parse_synth_spec("speed=3").ok());
}

TEST(SynthSpec, AFileNextToAClipRebuildsItsMotion) {
  const std::filesystem::path clip = std::filesystem::temp_directory_path() / "rotinterp_synth_spec_test.bvh";
  const SynthOptions o = options(SynthKind::smooth, 31, 1.5, Rate{24, 1}, 5);
  {
    std::ofstream(synth_spec_path(clip)) << synth_spec(o) << "\n";
  }
  auto m = read_synth_spec(clip);
  ASSERT_TRUE(m.ok()) << m.error();
  const SynthMotion direct = make_synth_motion(o).value();
  ASSERT_EQ(m->skeleton().joints.size(), 5u);
  for (std::size_t j = 0; j < 5; ++j)
    EXPECT_EQ(m->rotation(j, 0.37).coeffs(), direct.rotation(j, 0.37).coeffs());
  std::filesystem::remove(synth_spec_path(clip));
  auto missing = read_synth_spec(clip);
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.error().find("rotinterp_synth_spec_test.bvh.synth"), std::string::npos) << missing.error();
}
