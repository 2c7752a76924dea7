// eval --truth source: every method measured against the FBX file's own rotation
// curves, where between frames the interpolators of the baked keys miss them.
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
    EXPECT_NE(r.out.find("truth: each FBX file's own rotation curves"), std::string::npos) << r.out;
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

TEST(EvalSourceTruth, AClipWithoutCurvesIsNamedAndTheRunIsPartial) {
  const fs::path out = fresh_dir("bvh");
  const auto r = run_cli("eval " + kData + "/bvh/bvhio_example.bvh --truth source -m slerp -q --no-plots -o " +
                         out.string());
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(r.err.find("bvhio_example.bvh: --method source replays FBX curves"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace rotinterp
