// eval --loop: the seam of a real cycle, measured on the periodic curves, next to the
// same figures inside; without the loop the ordinary curves jump there. And the seam
// columns of errors.csv, clips.csv and summary.json, present with --loop only.
#include "clip/cycle_clips.h"
#include "support/run_cli.h"

#include "rotinterp/eval/error_row.h"
#include "rotinterp/eval/evaluate_clip.h"
#include "rotinterp/eval/seam.h"
#include "rotinterp/io/read.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <algorithm>
#include <string>
#include <vector>

namespace rotinterp {
namespace {

namespace fs = std::filesystem;
constexpr double kDeg = 180.0 / kPi;

// Round-off of the seam stencils on a C¹ curve (deg/s); a slerp seam jumps by hundreds.
constexpr double kRoundOffVelocity = 0.01;
// A closure miss of the source (≤ 0.005°; Marine_Run's joints miss by up to 0.0008°)
// as a velocity over two 30 Hz frames, °/s.
constexpr double kClosureVelocity = 0.02;

Clip load(const std::string& rel) {
  auto c = read_clip(fs::path(ROTINTERP_SHARED_DATA) / rel);
  EXPECT_TRUE(c) << rel << ": " << (c ? "" : c.error());
  return c ? std::move(*c) : Clip{};
}

const char* const kCycles[] = {"fbx/digitalrune_Dude.fbx", "fbx/digitalrune_Marine_Run.fbx"};

ClipEvalOptions all_methods(bool loop) {
  ClipEvalOptions o;
  for (const MethodInfo& m : methods()) o.methods.push_back(m.name);
  o.keep_every = {2, 4, 8};
  o.loop = loop;
  return o;
}

TEST(EvalSeam, OnPeriodicCurvesTheSeamJumpsNoMoreThanTheLargestKeyInside) {
  for (const char* file : kCycles) {
    auto rows = evaluate_clip(load(file), file, all_methods(true));
    ASSERT_TRUE(rows) << rows.error();
    std::size_t joints = 0;
    for (const ErrorRow& r : *rows) {
      if (r.end_site) continue;
      ASSERT_TRUE(r.seam) << r.joint;
      if (r.joint == "L_Arm" && std::string(file).find("Marine_Run") != std::string::npos) {
        EXPECT_EQ(r.looped, 0.0) << "the source's 4.4° pop is kept, not looped";
        continue;
      }
      ASSERT_EQ(r.looped, 1.0) << file << " " << r.joint;
      ++joints;
      // C¹ and C²: the seam is as smooth as the keys inside, to round-off. C⁰ (slerp,
      // nlerp) needs nothing periodic: its seam jump is the ordinary curve's (next test),
      // and the shorter last key interval of a period that N does not divide can make it
      // the clip's roughest key (Dude every 4th: 410 against 328°/s inside).
      if (find_method(r.method)->continuity < 1) continue;
      EXPECT_LT(r.seam_vel_jump, kRoundOffVelocity) << file << " " << r.method << " " << r.keep_every << " " << r.joint;
      EXPECT_LE(r.seam_vel_jump, r.vel_jump_max + kRoundOffVelocity) << file << " " << r.method << " " << r.joint;
    }
    EXPECT_GT(joints, 100u) << file;
  }
}

TEST(EvalSeam, WithoutTheLoopTheOrdinaryCurvesJumpAtTheSeam) {
  // The same keys rebuilt without --loop and played end to start: the C¹ methods'
  // one-sided end tangents leave a velocity jump far above their keys' round-off;
  // slerp and nlerp look at no neighbour, so their seam is the same either way.
  for (const char* file : kCycles) {
    const Clip clip = load(file);
    for (const MethodInfo& m : methods()) {
      for (int keep : {2, 4, 8}) {
        ClipEvalOptions o = all_methods(false);
        auto plain = prepare_reference(clip, file, o);
        o.loop = true;
        auto looped = prepare_reference(clip, file, o);
        ASSERT_TRUE(plain && looped);
        double worst_plain = 0.0, worst_looped = 0.0;
        for (std::size_t j = 0; j < clip.skeleton.joints.size(); ++j) {
          if (!looped->cycle->looped[j]) continue;
          auto a = rebuild_joint(*plain, j, m.name, keep), b = rebuild_joint(*looped, j, m.name, keep);
          ASSERT_TRUE(a && b);
          EXPECT_FALSE(a->periodic);
          EXPECT_TRUE(b->periodic);
          const double with = seam_figures(*looped, j, *b).jumps.velocity * kDeg;
          const double without = seam_figures(*plain, j, *a).jumps.velocity * kDeg;
          if (m.continuity == 0) {  // up to the closure misses (≤ 0.005°): frame 0 against the last frame
            EXPECT_NEAR(with, without, 0.01 * without + kClosureVelocity) << file << " " << m.name << " " << keep;
          }
          worst_plain = std::max(worst_plain, without);
          worst_looped = std::max(worst_looped, with);
        }
        if (m.continuity == 0) continue;
        EXPECT_GT(worst_plain, 1.0) << file << " " << m.name << " every " << keep;
        EXPECT_LT(worst_looped, kRoundOffVelocity) << file << " " << m.name << " every " << keep;
      }
    }
  }
}

TEST(EvalSeam, KeyFramesWrapAroundThePeriod) {
  // per_frame.csv's key column: the period's keys, and the closed form's last frame (the wrap key).
  ClipEvalOptions o = all_methods(true);
  const char* run = "fbx/digitalrune_Marine_Run.fbx";
  auto closed = prepare_reference(load(run), run, o);
  ASSERT_TRUE(closed) << closed.error();
  std::vector<std::size_t> want;
  for (std::size_t k = 0; k < 40; k += 4) want.push_back(k);  // 1.333 s at its file's 30 Hz
  want.push_back(40);
  EXPECT_EQ(key_frames(*closed, 4), want);
  o.loop_form = LoopForm::open;
  auto open = prepare_reference(test::cycle_clip(test::CycleTruth{1.0, Vec3(0.5, 0.0, 0.0)}, 24, LoopForm::open),
                                "open", o);
  ASSERT_TRUE(open) << open.error();
  EXPECT_EQ(key_frames(*open, 5), (std::vector<std::size_t>{0, 5, 10, 15, 20}));  // frame 24 is the next period's 0
  o.loop = false;
  auto plain = prepare_reference(load(run), run, o);
  ASSERT_TRUE(plain);
  EXPECT_EQ(key_frames(*plain, 8), (std::vector<std::size_t>{0, 8, 16, 24, 32, 40}));
}

TEST(EvalSeam, AClipThatIsNotACycleFailsUnlessItsFormIsGiven) {
  const char* walk = "bvh/NC_bandai1_walk_normal_001.bvh";
  ClipEvalOptions o = all_methods(true);
  auto detected = prepare_reference(load(walk), walk, o);
  ASSERT_FALSE(detected);
  EXPECT_NE(detected.error().find("does not look like a cycle"), std::string::npos) << detected.error();
  o.loop_form = LoopForm::closed;
  EXPECT_TRUE(prepare_reference(load(walk), walk, o));
}

TEST(EvalSeam, SeamColumnsRoundTripAndAreAbsentWithoutTheLoop) {
  ErrorRow r;
  r.clip = "c.bvh", r.method = "slerp", r.joint = "Hips", r.frames = 39, r.samples = 39;
  r.seam = true, r.seam_angle_deg = 1.5, r.inner_angle_deg = 2.25, r.seam_vel_jump = 3.0625, r.seam_acc_jump = 4.5;
  r.looped = 1;
  EXPECT_EQ(error_csv_schema().header().find("seam"), std::string::npos);
  EXPECT_EQ(format_error_row(r), format_error_row(ErrorRow(r), csv_metrics(MetricSet::all(), false)));
  const std::string header = error_csv_schema(csv_metrics(MetricSet::all(), true)).header(), line = format_error_row(r, csv_metrics(MetricSet::all(), true));
  EXPECT_NE(header.find(",seam_angle_deg,inner_angle_deg,seam_vel_jump_dps,seam_acc_jump_dps2,looped"),
            std::string::npos);
  auto parser = ErrorRowParser::from_header(header);
  ASSERT_TRUE(parser);
  EXPECT_TRUE(parser->has_seam_columns());
  auto back = parser->parse(line);
  ASSERT_TRUE(back) << back.error();
  EXPECT_TRUE(back->seam);
  EXPECT_EQ(back->inner_angle_deg, 2.25);
  EXPECT_EQ(back->seam_vel_jump, 3.0625);
  EXPECT_EQ(format_error_row(*back, csv_metrics(MetricSet::all(), true)), line);
  EXPECT_FALSE(ErrorRowParser::from_header(error_csv_schema().header())->has_seam_columns());
}

TEST(EvalSeam, CliWritesTheSeamFiguresWithLoopOnlyAndMergesThem) {
  const fs::path out = fs::path(testing::TempDir()) / "rotinterp_eval_seam";
  fs::remove_all(out);
  const std::string run = fs::path(ROTINTERP_SHARED_DATA).string() + "/fbx/digitalrune_Marine_Run.fbx " +
                          fs::path(ROTINTERP_SHARED_DATA).string() + "/fbx/digitalrune_Dude.fbx" +
                          " --methods slerp,c2 --keep-every 4 --no-plots -q -j 1 ";
  ASSERT_EQ(test::run_cli("eval " + run + "--loop -o " + (out / "loop").string()).exit_code, 0);
  ASSERT_EQ(test::run_cli("eval " + run + "-o " + (out / "plain").string()).exit_code, 0);
  for (int i : {1, 2})
    ASSERT_EQ(test::run_cli("eval " + run + "--loop --shard " + std::to_string(i) + "/2 -o " +
                            (out / ("shard" + std::to_string(i))).string())
                  .exit_code,
              0);
  const auto merged = test::run_cli("eval --merge " + (out / "shard1").string() + " " + (out / "shard2").string() +
                                    " --no-plots -q -o " + (out / "merged").string());
  ASSERT_EQ(merged.exit_code, 0) << merged.err;
  EXPECT_EQ(test::slurp(out / "merged/clips.csv"), test::slurp(out / "loop/clips.csv"));
  EXPECT_EQ(test::slurp(out / "merged/errors.csv"), test::slurp(out / "loop/errors.csv"));

  const std::string clips = test::slurp(out / "loop/clips.csv");
  EXPECT_NE(clips.find(",seam_vel_jump_dps,inner_vel_jump_dps,"), std::string::npos);
  EXPECT_EQ(test::slurp(out / "plain/clips.csv").find("seam"), std::string::npos);
  EXPECT_EQ(test::slurp(out / "plain/errors.csv").find("seam"), std::string::npos);
  const auto j = nlohmann::json::parse(test::slurp(out / "loop/summary.json"));
  EXPECT_EQ(j["options"]["loop"], "auto");
  for (const auto& e : j["results"]) {
    ASSERT_TRUE(e.contains("seam")) << e.dump();
    if (e["method"] == "c2") {
      EXPECT_LT(e["seam"]["seam_vel_jump_dps"].get<double>(), kRoundOffVelocity);
    } else {  // slerp's seam is a key like the others
      EXPECT_GT(e["seam"]["seam_vel_jump_dps"].get<double>(), 1.0);
    }
    EXPECT_EQ(e["seam"]["not_looped_joints"], 1);  // Marine_Run's L_Arm
  }
  const auto plain = nlohmann::json::parse(test::slurp(out / "plain/summary.json"));
  EXPECT_FALSE(plain["results"][0].contains("seam"));
  EXPECT_EQ(plain["options"]["loop"], "off");
  // Shards of another --loop do not merge.
  const auto mixed = test::run_cli("eval --merge " + (out / "shard1").string() + " " + (out / "plain").string() +
                                   " --no-plots -q -o " + (out / "mixed").string());
  EXPECT_NE(mixed.exit_code, 0);
}

}  // namespace
}  // namespace rotinterp
