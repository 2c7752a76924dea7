// `rotinterp eval` end to end over folders: outputs, shards + merge, a bad file or a
// crashing one in a directory, subframes' memory, and synth clips' analytic truth.
#include "eval_cli_util.h"
#include "support/hostile_files.h"
#include "support/run_cli.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <vector>

namespace rotinterp {
namespace {

namespace fs = std::filesystem;
using test::clip_dir;
using test::fresh_dir;
using test::lines_of;
using test::run_cli;
using test::slurp;
using test::double_free_fbx;
using test::fbx_one_curve;
using test::nested_bvh;

TEST(EvalCli, WritesCsvSummaryAndPlotsForADirectory) {
  const fs::path in = clip_dir("outputs", false), out = fresh_dir("outputs_out");
  const auto r = run_cli("eval " + in.string() + " --methods slerp,squad --keep-every 4,2 -j 2 -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("slerp"), std::string::npos) << r.out;
  const auto csv = lines_of(slurp(out / "errors.csv"));
  ASSERT_GT(csv.size(), 1u);
  EXPECT_EQ(csv[0].rfind("clip,method,keep_every,joint,frames,mean_deg,rms_deg,p95_deg,max_deg,swing_rms_deg,"
                         "twist_rms_deg,pos_rms_m,pos_max_m",
                         0),
            0u);
  EXPECT_EQ(slurp(out / "errors.csv").find("nan"), std::string::npos);
  const auto j = nlohmann::json::parse(slurp(out / "summary.json"));
  EXPECT_EQ(j["clips_evaluated"], 3);  // two_frames.bvh is too short for N = 2 (needs 5 frames)
  EXPECT_EQ(j["failed"].size(), 0u);
  ASSERT_EQ(j["skipped"].size(), 1u);
  EXPECT_NE(j["skipped"][0].get<std::string>().find("triangle.obj"), std::string::npos);
  EXPECT_EQ(j["results"].size(), 4u);  // 2 methods × 2 spacings
  EXPECT_EQ(j["results"][0]["keep_every"], 2);
  EXPECT_TRUE(j.contains("version") && j.contains("seconds") && j.contains("inputs"));
  for (const char* plot : {"error_vs_spacing", "worst_clip_joints", "clip_errors"})
    for (const char* ext : {".png", ".svg"}) EXPECT_TRUE(fs::file_size(out / (std::string(plot) + ext)) > 0) << plot << ext;
  EXPECT_TRUE(fs::file_size(out / "clips.csv") > 0);
  for (const auto& e : fs::directory_iterator(out))
    EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
}

TEST(EvalCli, ShardsMergedEqualASingleRun) {
  const fs::path in = clip_dir("shards", false);
  const fs::path single = fresh_dir("shards_single"), a = fresh_dir("shards_a"), b = fresh_dir("shards_b"),
                 c = fresh_dir("shards_c"), merged = fresh_dir("shards_merged");
  const std::string common = "eval " + in.string() + " --methods slerp,squad,expmap --keep-every 2,8 -q --no-plots ";
  ASSERT_EQ(run_cli(common + "-j 2 -o " + single.string()).exit_code, 0);
  ASSERT_EQ(run_cli(common + "-j 1 --shard 1/3 -o " + a.string()).exit_code, 0);
  ASSERT_EQ(run_cli(common + "-j 1 --shard 2/3 -o " + b.string()).exit_code, 0);
  ASSERT_EQ(run_cli(common + "-j 1 --shard 3/3 -o " + c.string()).exit_code, 0);
  // Each shard holds a strict part of the clips.
  EXPECT_LT(slurp(a / "errors.csv").size(), slurp(single / "errors.csv").size());
  const auto r = run_cli("eval --merge " + c.string() + " " + a.string() + " " + b.string() + " -q -o " + merged.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(slurp(merged / "errors.csv"), slurp(single / "errors.csv"));  // byte-identical, already sorted
  const auto js = nlohmann::json::parse(slurp(single / "summary.json"));
  const auto jm = nlohmann::json::parse(slurp(merged / "summary.json"));
  EXPECT_EQ(jm["results"], js["results"]);
  EXPECT_EQ(jm["worst_clip"], js["worst_clip"]);
  EXPECT_EQ(jm["clips_evaluated"], js["clips_evaluated"]);
  EXPECT_EQ(jm["files"], js["files"]);
  EXPECT_EQ(jm["skipped"], js["skipped"]);
  EXPECT_EQ(jm["clips"], js["clips"]);
  EXPECT_EQ(jm["too_short"], js["too_short"]);  // two_frames.bvh, from the shard that read it
  EXPECT_EQ(js["too_short"].size(), 1u);
  EXPECT_EQ(slurp(merged / "clips.csv"), slurp(single / "clips.csv"));
  EXPECT_TRUE(fs::exists(merged / "error_vs_spacing.png"));

  // Merging a shard twice is refused.
  const auto twice = run_cli("eval --merge " + a.string() + " " + a.string() + " -q -o " + fresh_dir("twice").string());
  EXPECT_EQ(twice.exit_code, 1);
  EXPECT_NE(twice.err.find("more than one shard"), std::string::npos) << twice.err;
}

TEST(EvalCli, ADirectoryWithOneBadFileEvaluatesTheOthersAndExitsThree) {
  const fs::path in = clip_dir("bad", true), out = fresh_dir("bad_out");
  const auto r = run_cli("eval " + in.string() + " --methods slerp --keep-every 4 -q -o " + out.string());
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("broken.bvh"), std::string::npos) << r.err;
  const std::string csv = slurp(out / "errors.csv");
  EXPECT_NE(csv.find("walk.bvh"), std::string::npos);
  EXPECT_NE(csv.find("raise.bvh"), std::string::npos);
  EXPECT_NE(csv.find("sausage.fbx"), std::string::npos);
  EXPECT_EQ(csv.find("broken.bvh"), std::string::npos);
  const auto j = nlohmann::json::parse(slurp(out / "summary.json"));
  ASSERT_EQ(j["failed"].size(), 1u);
  EXPECT_NE(j["failed"][0]["file"].get<std::string>().find("broken.bvh"), std::string::npos);
  EXPECT_EQ(j["clips_evaluated"], 3);  // and two_frames.bvh too short
}

TEST(EvalCli, FilesThatCrashTheImporterAreFailuresOfABatchThatGoesOn) {
  // Found in a directory, each made the whole batch die (exit 134/139, nothing
  // written): after read_clip refused it, the batch asked assimp in-process
  // whether it held an animation.
  const fs::path in = fresh_dir("crashers"), out = fresh_dir("crashers_out");
  fs::create_symlink(fs::path(ROTINTERP_SHARED_DATA) / "bvh/NC_bandai1_walk_normal_001.bvh", in / "walk.bvh");
  const std::string double_free = double_free_fbx(fs::path(ROTINTERP_SHARED_DATA) / "fbx/assimp_huesitos.fbx");
  ASSERT_FALSE(double_free.empty());
  std::ofstream(in / "double_free.fbx", std::ios::binary) << double_free;
  std::ofstream(in / "no_keys.fbx") << fbx_one_curve("", "", 0);
  std::ofstream(in / "deep.bvh") << nested_bvh(20000);
  std::ofstream(in / "triangle.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";  // no animation: skipped
  const auto r = run_cli("eval " + in.string() + " --methods slerp --keep-every 4 -q -o " + out.string());
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(slurp(out / "errors.csv").find("walk.bvh"), std::string::npos);
  const auto j = nlohmann::json::parse(slurp(out / "summary.json"));
  std::vector<std::string> failed;
  for (const auto& f : j["failed"]) failed.push_back(fs::path(f["file"].get<std::string>()).filename().string());
  EXPECT_EQ(failed, (std::vector<std::string>{"deep.bvh", "double_free.fbx", "no_keys.fbx"}));
  EXPECT_EQ(j["clips_evaluated"], 1);
}

// Peak resident memory (KiB) of `rotinterp ARGS`, by GNU time.
long peak_kib(const std::string& args, const fs::path& scratch) {
  const fs::path out = scratch / "maxrss";
  const std::string cmd = "/usr/bin/time -f %M -o " + out.string() + " " + ROTINTERP_CLI + " " + args + " >/dev/null 2>&1";
  if (std::system(cmd.c_str()) != 0) return -1;
  return std::stol(slurp(out));
}

TEST(EvalCli, SubframesCostMemoryByTheClipNotByTheirCount) {
  // Every subframe sample was stored (≈ 12.6 MB per unit of --subframe on CMU
  // 01_01, then bad_alloc): now they stream, so K = 1000 costs what K = 0 does,
  // up to one block (≈ 20 MB).
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer's quarantine keeps freed blocks resident: peak memory says nothing here";
#endif
  const fs::path dir = fresh_dir("subframe_memory");
  ASSERT_EQ(run_cli("synth " + (dir / "walk.bvh").string() + " --kind walk --seconds 2 --fps 30 --quiet").exit_code, 0);
  const std::string args = "eval " + (dir / "walk.bvh").string() + " --methods slerp --keep-every 4 --no-plots -q -j 1 -o ";
  const long k0 = peak_kib(args + (dir / "k0").string(), dir);
  const long k1000 = peak_kib(args + (dir / "k1000").string() + " --subframe 1000", dir);
  ASSERT_GT(k0, 0);
  ASSERT_GT(k1000, 0);
  EXPECT_LT(k1000, k0 + 48 * 1024) << "K=0: " << k0 << " KiB, K=1000: " << k1000 << " KiB";
  const auto csv = lines_of(slurp(dir / "k1000" / "errors.csv"));
  ASSERT_GT(csv.size(), 1u);
  EXPECT_NE(csv[1].find(",60061,"), std::string::npos) << csv[1];  // samples: 60 intervals × 1001, and the last
}

TEST(EvalCli, SubframesOfSlerpAtEveryFrameMatchTheOriginalsOwnSlerp) {
  const fs::path out = fresh_dir("subframe");
  const std::string clip = std::string(ROTINTERP_SHARED_DATA) + "/bvh/NC_bandai2_raise-up-both-hands_active_031.bvh";
  const auto r = run_cli("eval " + clip + " --methods slerp,squad --keep-every 1,4 --subframe 3 -q --no-plots -o " +
                         out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(slurp(out / "summary.json"));
  ASSERT_EQ(j["results"].size(), 4u);
  for (const auto& e : j["results"]) {
    EXPECT_EQ(e["samples"].get<std::size_t>() % (50 * 4 + 1), 0u);  // 51 frames, 3 between each pair
    if (e["method"] == "slerp" && e["keep_every"] == 1) {
      EXPECT_LT(e["max_deg"].get<double>(), 1e-6);
    }
    if (e["keep_every"] == 4) {
      EXPECT_GT(e["rms_deg"].get<double>(), 1e-3);
    }
  }
}

TEST(EvalCli, SynthConstantVelocityClipsMatchTheirAnalyticTruthForSlerpSquadAndBf) {
  const fs::path dir = fresh_dir("truth"), out = fresh_dir("truth_out");
  const fs::path clip = dir / "constant.bvh";
  ASSERT_EQ(run_cli("synth " + clip.string() + " --kind constant --seconds 2 --fps 30 --joints 4 --seed 3 -q").exit_code, 0);
  const auto r = run_cli("eval " + clip.string() +
                         " --truth --methods slerp,squad,bf --keep-every 2,4,8 --subframe 3 -q --no-plots -o " +
                         out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(slurp(out / "summary.json"));
  EXPECT_EQ(j["options"]["truth"], "synth");
  ASSERT_EQ(j["results"].size(), 9u);
  for (const auto& e : j["results"]) EXPECT_LT(e["max_deg"].get<double>(), 1e-3) << e.dump();

  // Smooth random motion: against the truth between frames, error grows with the spacing.
  const fs::path smooth = dir / "smooth.bvh";
  ASSERT_EQ(run_cli("synth " + smooth.string() + " --kind smooth --seconds 3 --fps 30 --joints 3 -q").exit_code, 0);
  ASSERT_EQ(run_cli("eval " + smooth.string() + " --truth --methods squad --keep-every 2,4,8 --subframe 2 -q " +
                    "--no-plots -o " + out.string())
                .exit_code,
            0);
  const auto js = nlohmann::json::parse(slurp(out / "summary.json"));
  double previous = 0;
  for (const auto& e : js["results"]) {
    EXPECT_GT(e["rms_deg"].get<double>(), previous);
    previous = e["rms_deg"].get<double>();
  }

  // A clip without a synth spec cannot be compared with a truth: named, exit 3.
  const std::string real = std::string(ROTINTERP_SHARED_DATA) + "/bvh/bvhio_example.bvh";
  const auto none = run_cli("eval " + real + " " + clip.string() + " --truth --methods slerp -q --no-plots -o " +
                            out.string());
  EXPECT_EQ(none.exit_code, 3);
  EXPECT_NE(none.err.find("bvhio_example.bvh"), std::string::npos) << none.err;
}

// CSV text as rows of named fields.

}  // namespace
}  // namespace rotinterp
