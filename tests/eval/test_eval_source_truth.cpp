// eval --truth source: every method measured against the file's own motion — an FBX
// file's rotation curves, where between frames the interpolators of the baked keys miss
// them; a glTF file's samplers; a BVH's frames.
#include "support/run_cli.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>
#include <string>

namespace rotinterp {
namespace {

namespace fs = std::filesystem;
using test::run_cli;
using test::slurp;

const std::string kData = ROTINTERP_SHARED_DATA;

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("rotinterp_source_truth_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// Max error (degrees) per method at keep-every 1 with 4 subframes.
std::map<std::string, double> max_errors(const std::string& truth_option, const fs::path& out) {
  const auto r = run_cli("eval " + kData + "/fbx/digitalrune_Marine_Run.fbx " + truth_option +
                         " --methods slerp,squad,c2 --keep-every 1 --subframe 4 --no-plots -o " + out.string());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  if (!truth_option.empty()) {
    EXPECT_NE(r.out.find("truth: each file's own motion: FBX rotation curves"), std::string::npos) << r.out;
  }
  std::map<std::string, double> out_max;
  const nlohmann::json summary = nlohmann::json::parse(slurp(out / "summary.json"));
  EXPECT_EQ(summary["options"]["truth"], truth_option.empty() ? "frames" : "source");  // the record says which
  for (const auto& e : summary.at("results"))
    out_max[e["method"].get<std::string>()] = e["max_deg"].get<double>();
  return out_max;
}

TEST(EvalSourceTruth, BetweenKeysEveryMethodMissesTheCurvesThatItsOwnFramesHide) {
  const fs::path out = fresh_dir("out");
  const auto frames = max_errors("", out);
  const auto curves = max_errors("--truth source", out);
  ASSERT_EQ(curves.size(), 3u);
  EXPECT_LT(frames.at("slerp"), 1e-3);  // against the slerp of its own frames, slerp is exact
  for (const auto& [method, worst] : curves) {
    std::printf("%s: max %.3f° against the curves\n", method.c_str(), worst);
    EXPECT_GT(worst, 0.3) << method;
  }
}

// FBX 6.1 (clip and curves from our own reader) and a take whose joints are
// animated in several layers (blended) are measured like any keyed FBX.
TEST(EvalSourceTruth, AnFbx61FileAndALayeredFileAreMeasuredAgainstTheirCurves) {
  for (const char* file : {"fbx/ufbx_maya_game_sausage_6100_binary_wiggle.fbx",
                           "fbx/ufbx_maya_anim_layers_over_acc_orders_7500_ascii.fbx"}) {
    const fs::path out = fresh_dir("legacy_layers");
    const auto r = run_cli("eval " + kData + "/" + file + " --truth source -m slerp,c2 --keep-every 2 --no-plots -o " +
                           out.string());
    EXPECT_EQ(r.exit_code, 0) << file << ": " << r.err;
    EXPECT_NE(r.out.find("truth: each file's own motion: FBX rotation curves"), std::string::npos) << r.out;
    const nlohmann::json summary = nlohmann::json::parse(slurp(out / "summary.json"));
    EXPECT_EQ(summary.at("results").size(), 2u) << file;
  }
}

// A BVH's source is its frames: between them their slerp, so slerp's error is 0.
TEST(EvalSourceTruth, ABvhIsMeasuredAgainstItsFrames) {
  const fs::path out = fresh_dir("bvh");
  const auto r = run_cli("eval " + kData + "/bvh/NC_bandai2_raise-up-both-hands_active_031.bvh --truth source -m slerp "
                         "--keep-every 1 --subframe 4 --no-plots -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json summary = nlohmann::json::parse(slurp(out / "summary.json"));
  ASSERT_EQ(summary.at("results").size(), 1u);
  EXPECT_LT(summary["results"][0]["max_deg"].get<double>(), 1e-3);
}

// glTF: the samplers; a GLB written by our writer (LINEAR) and measured with its truth.
TEST(EvalSourceTruth, AGlbIsMeasuredAgainstItsAnimationSamplers) {
  const fs::path out = fresh_dir("glb");
  const std::string glb = (out / "clip.glb").string();
  ASSERT_EQ(run_cli("resample " + kData + "/fbx/digitalrune_Marine_Run.fbx -o " + glb + " -q").exit_code, 0);
  const auto r = run_cli("eval " + glb + " --truth source -m slerp,c2 --keep-every 2 --no-plots -o " + (out / "eval").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("glTF animation samplers"), std::string::npos) << r.out;
  const nlohmann::json summary = nlohmann::json::parse(slurp(out / "eval" / "summary.json"));
  EXPECT_EQ(summary.at("results").size(), 2u);
}

// Collada stores no motion we replay: the file is named and the run is partial.
TEST(EvalSourceTruth, AClipWithNoMotionToReplayIsNamedAndTheRunIsPartial) {
  const fs::path out = fresh_dir("dae");
  const std::string dae = (out / "walk.dae").string();
  ASSERT_EQ(run_cli("resample " + kData + "/bvh/bvhio_example.bvh -o " + dae + " -q").exit_code, 0);
  const auto r = run_cli("eval " + dae + " --truth source -m slerp -q --no-plots -o " + (out / "eval").string());
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(r.err.find("walk.dae: --method source replays a file's own motion"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace rotinterp
