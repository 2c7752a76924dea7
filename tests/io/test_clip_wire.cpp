// The reader's private wire format (src/io/process/clip_wire.h), which carries a read from
// the isolated child to the parent: every field survives bit for bit, and bytes
// that are not one whole record are an error, never a crash or a huge allocation.
#include "clip_wire.h"
#include "identical_info.h"
#include "rotinterp/io/files/file_errors.h"
#include "rotinterp/io/process/process_errors.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>

namespace rotinterp {
namespace {

using test::expect_identical;

// Every field away from its default; doubles that only a bitwise copy keeps
// (−0.0, a NaN payload, a subnormal, infinity).
ClipFileInfo every_field_set() {
  ClipFileInfo info;
  info.format = "fbx";
  info.animations = {{"Take 001", 2.5, 30.0, false, 3}, {"", -0.0, 25.0, true, 0}, {"Gehen \xC3\xBC\xE2\x86\x92", 1e300, 1e-310, false, 7}};
  info.selected = 2;
  info.warnings = {"a.fbx: joint 'x' has animated scale; ignored", "", "\xE6\xAD\xA9\xE3\x81\x8F"};
  info.folded_helpers = 5;
  info.holds = "1 mesh, 2 nodes: RootNode, W\xC3\xBCrfel";
  Clip& c = info.clip;
  c.name = "Gehen \xC3\xBC";
  c.skeleton.joints = {
      {"Hips", -1, Vec3(1.0, -0.0, 3.25), Quat(0.5, 0.5, -0.5, 0.5)},
      {"", 0, Vec3(std::numeric_limits<double>::denorm_min(), 1e-300, -7.0), Quat(1.0, 0.0, 0.0, -0.0)},
      {"\xE8\x82\xA9", 1, Vec3(0.1, 0.2, 0.3), Quat(0.0, 1.0, 0.0, 0.0)},
  };
  c.skeleton.end_sites = {{2, Vec3(0.0, 4.5, 0.0), "EndSite_\xE8\x82\xA9"}, {0, Vec3(-1.0, 0.0, 1.0), ""}};
  c.rotations.resize(3);
  c.rotations[0] = {{0.0, 1.0 / 30.0, 2.0 / 30.0}, {Quat(1, 0, 0, 0), Quat(0.6, 0.8, 0, 0), Quat(0, 1, 0, 0)}};
  c.rotations[1] = {{-0.5}, {Quat(std::numeric_limits<double>::quiet_NaN(), 0, 0, 0)}};
  c.rotations[2] = {{0.0, std::numeric_limits<double>::infinity()}, {Quat(0, 0, 1, 0)}};  // sizes differ on purpose
  c.translations = {TranslationTrack{{0.0, 0.5}, {Vec3(1, 2, 3), Vec3(4, 5, 6)}}, std::nullopt,
                    TranslationTrack{{0.25}, {Vec3(-0.0, 0.0, 1e-320)}}};
  c.frame_time = 1.0 / 120.0;
  set_bvh_layout(c, BvhLayout{{{Channel::Xposition, Channel::Yposition, Channel::Zposition, Channel::Zrotation,
                                 Channel::Xrotation, Channel::Yrotation},
                                {},
                                {Channel::Yrotation}},
                               ".0083333",
                               nullptr,
                               0});
  set_file_rate_hz(c, 23.976);
  c.unit = {0.01, UnitOrigin::declared, "declared by the file: FBX UnitScaleFactor 1"};
  c.source_format = "bvh";
  CharacterBody& body = info.body.emplace();
  BodyPart part{{0, 0, -0.0f, 1, 0, 0, 0, 1, 0}, {0, 0, 1}, {}, {1, 1, 1, 0.5f}, {0, 1, 2}, 0, {}};
  part.bones.push_back({"\xE8\x82\xA9", RowMajor4{1, 0, 0, 2, 0, 1, 0, -0.0, 0, 0, 1, 1e-310, 0, 0, 0, 1}, {0, 2}, {0.5f, 1.0f}});
  body.meshes.push_back({"Body", RowMajor4{}, "Hips", {part, BodyPart{}}});
  body.materials = {{"Skin", {0.5, 0.25, 1.0, 0.75}, 0}, {"", {1, 1, 1, 1}, -1}};
  body.images = {{"skin.png", "image/png", std::string("\x89PNG\0\0", 6)}};
  body.notes = {"texture 'x.tga' is not beside the file"};
  return info;
}

TEST(ClipWire, EveryFieldSurvivesTheRoundTripBitForBit) {
  ReadOutcome out;
  out.info = every_field_set();
  const std::string bytes = wire::encode(out);
  Result<ReadOutcome> back = wire::decode(bytes);
  ASSERT_TRUE(back) << back.error();
  EXPECT_FALSE(back->error);
  expect_identical(back->info, out.info, "round trip");
  ASSERT_TRUE(back->info.body);  // and the body's fields, bit for bit through the re-encoding below
  EXPECT_EQ(back->info.body->meshes.at(0).parts.at(0).bones.at(0).weights, (std::vector<float>{0.5f, 1.0f}));
  EXPECT_EQ(back->info.body->images.at(0).bytes, out.info.body->images[0].bytes);
  EXPECT_EQ(wire::encode(*back), bytes);
}

TEST(ClipWire, AnErrorTravelsWithTheWarningsBeforeIt) {
  ReadOutcome out;
  out.error = "x.fbx: the animation moves no node of the scene";
  out.kind = file_error::no_animation;
  out.info.warnings = {"x.fbx: animation 'A' gives 0 ticks per second; assuming 25"};
  Result<ReadOutcome> back = wire::decode(wire::encode(out));
  ASSERT_TRUE(back) << back.error();
  ASSERT_TRUE(back->error);
  EXPECT_EQ(*back->error, *out.error);
  EXPECT_EQ(back->kind, file_error::no_animation);
  expect_identical(back->info, out.info, "error");
  ReadOutcome empty_message;
  empty_message.error = "";
  back = wire::decode(wire::encode(empty_message));
  ASSERT_TRUE(back) << back.error();
  EXPECT_EQ(back->error, std::optional<std::string>(""));
}

TEST(ClipWire, EveryFileKindCrossesAndAProcessKindIsRefused) {
  for (ErrorKind kind : file_error::all) {
    ReadOutcome out;
    out.error = "x";
    out.kind = kind;
    Result<ReadOutcome> back = wire::decode(wire::encode(out));
    ASSERT_TRUE(back) << static_cast<int>(kind);
    EXPECT_EQ(back->kind, kind);
  }
  // The parent gives the process kinds; an importer that sends one is not believed.
  ReadOutcome crashed;
  crashed.error = "x";
  crashed.kind = process_error::crashed;
  EXPECT_FALSE(wire::decode(wire::encode(crashed)));
}

TEST(ClipWire, EveryTruncationIsRejected) {
  ReadOutcome out;
  out.info = every_field_set();
  const std::string bytes = wire::encode(out);
  for (std::size_t n = 0; n < bytes.size(); ++n)
    EXPECT_FALSE(wire::decode(std::string_view(bytes).substr(0, n))) << n << " of " << bytes.size() << " bytes";
  EXPECT_FALSE(wire::decode(bytes + '\0')) << "a stray byte after the record";
}

TEST(ClipWire, CorruptedCountsAndValuesNeitherCrashNorAllocateWhatTheyClaim) {
  ReadOutcome out;
  out.info = every_field_set();
  const std::string bytes = wire::encode(out);
  // Every 8-byte window overwritten with a huge number: where it lands on a count
  // the decoder must refuse it rather than allocate (or read) that much; where it
  // lands on a double the record may still decode. Under ASan this also proves
  // that no read goes past the end.
  const std::uint64_t huge = std::numeric_limits<std::uint64_t>::max() / 2;
  std::size_t rejected = 0;
  for (std::size_t at = 0; at + sizeof huge <= bytes.size(); ++at) {
    std::string bad = bytes;
    std::memcpy(bad.data() + at, &huge, sizeof huge);
    rejected += !wire::decode(bad);
  }
  EXPECT_GT(rejected, 0u);
  std::string wrong_magic = bytes;
  wrong_magic[0] ^= 1;
  EXPECT_FALSE(wire::decode(wrong_magic));
  std::string bad_flag = bytes;
  bad_flag[std::string_view("rotinterp-clip-wire-2").size()] = 2;  // has-error: neither 0 nor 1
  EXPECT_FALSE(wire::decode(bad_flag));
  ReadOutcome failed;
  failed.error = "x";
  std::string bad_kind = wire::encode(failed);
  bad_kind[std::string_view("rotinterp-clip-wire-2").size() + 1 + 8 + 1] = 100;  // after the flag and the message
  EXPECT_FALSE(wire::decode(bad_kind));
}

TEST(ClipWire, GarbageIsRejected) {
  EXPECT_FALSE(wire::decode(""));
  EXPECT_FALSE(wire::decode("==1==ERROR: AddressSanitizer: attempting double-free"));
  std::string noise(4096, '\0');
  for (std::size_t i = 0; i < noise.size(); ++i) noise[i] = static_cast<char>((i * 2654435761u) >> 13);
  EXPECT_FALSE(wire::decode(noise));
}

}  // namespace
}  // namespace rotinterp
