// `rotinterp eval`'s tables: clips too short for a spacing, per-clip results and foot
// skating, every take a clip of its own, per-frame series and table formats, and bad
// option values.
#include "eval_cli_util.h"
#include "support/run_cli.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

namespace rotinterp {
namespace {

namespace fs = std::filesystem;
using test::clip_dir;
using test::fresh_dir;
using test::lines_of;
using test::run_cli;
using test::slurp;

std::vector<std::map<std::string, std::string>> csv_rows(const std::string& text) {
  const auto lines = lines_of(text);
  std::vector<std::map<std::string, std::string>> rows;
  if (lines.empty()) return rows;
  std::vector<std::string> head;
  std::stringstream hs(lines[0]);
  for (std::string h; std::getline(hs, h, ',');) head.push_back(h);
  for (std::size_t i = 1; i < lines.size(); ++i) {
    std::map<std::string, std::string> r;
    std::stringstream ls(lines[i] + ",");
    std::string f;
    for (std::size_t c = 0; c < head.size() && std::getline(ls, f, ','); ++c) r[head[c]] = f;
    rows.push_back(std::move(r));
  }
  return rows;
}

TEST(EvalCli, ClipsTooShortForASpacingAreSkippedThereAndListed) {
  const fs::path in = clip_dir("short", false), out = fresh_dir("short_out");
  // raise.bvh: 51 frames, enough for N = 2 and 16 (33), not for 32 (65); two_frames.bvh: for none.
  auto r = run_cli("eval " + in.string() + " --methods slerp --keep-every 2,16,32 -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("two_frames.bvh: 2 frames, too few for keep-every 2,16,32"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("raise.bvh: 51 frames, too few for keep-every 32"), std::string::npos) << r.err;
  auto j = nlohmann::json::parse(slurp(out / "summary.json"));
  std::map<std::string, std::vector<int>> listed;
  for (const auto& c : j["too_short"])
    listed[fs::path(c["clip"].get<std::string>()).filename().string()] = c["keep_every_skipped"].get<std::vector<int>>();
  EXPECT_EQ(listed["two_frames.bvh"], (std::vector<int>{2, 16, 32}));
  EXPECT_EQ(listed["raise.bvh"], (std::vector<int>{32}));
  for (const auto& row : csv_rows(slurp(out / "clips.csv"))) {
    EXPECT_EQ(row.at("clip").find("two_frames"), std::string::npos);
    if (row.at("clip").find("raise") != std::string::npos) {
      EXPECT_NE(row.at("keep_every"), "32");
    }
  }
  // --min-frames 60 skips raise.bvh (51 frames) and sausage.fbx (20) whole.
  r = run_cli("eval " + in.string() + " --methods slerp --keep-every 2 --min-frames 60 -q -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(slurp(out / "clips.csv").find("raise.bvh"), std::string::npos);
  j = nlohmann::json::parse(slurp(out / "summary.json"));
  EXPECT_EQ(j["clips_evaluated"], 1);  // walk.bvh, 195 frames
  EXPECT_EQ(j["too_short"].size(), 3u);
}

TEST(EvalCli, PerClipResultsAndFootSkatingAreInClipsCsvAndSummaryJson) {
  const fs::path in = clip_dir("perclip", false), out = fresh_dir("perclip_out");
  const auto r = run_cli("eval " + in.string() + " --methods slerp,squad --keep-every 1,8 -q -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto rows = csv_rows(slurp(out / "clips.csv"));
  ASSERT_EQ(rows.size(), 3u * 2 * 2);  // walk, raise, sausage × 2 methods × 2 spacings
  for (const auto& row : rows) {
    const bool human = row.at("clip").find("sausage") == std::string::npos;
    EXPECT_EQ(row.at("feet"), human ? "2" : "0") << row.at("clip");
    if (!human) {
      EXPECT_EQ(row.at("skate_ratio"), "");
      continue;
    }
    if (row.at("keep_every") == "1") {  // keys at every frame: the original itself, no extra skating
      EXPECT_EQ(row.at("contact_frames"), row.at("contact_frames_ref"));
      EXPECT_EQ(row.at("extra_skate_ratio"), "0");
      EXPECT_LT(std::stod(row.at("rms_deg")), 1e-9);
    }
  }
  // The walk touches the floor: contacts, in the CSV of joints (its Toes rows) and the per-clip rows.
  bool walk_contacts = false;
  for (const auto& row : rows)
    if (row.at("clip").find("walk") != std::string::npos) walk_contacts = walk_contacts || std::stod(row.at("contact_frames_ref")) > 10;
  EXPECT_TRUE(walk_contacts);
  std::size_t foot_rows = 0;
  for (const auto& row : csv_rows(slurp(out / "errors.csv")))
    if (!row.at("contact_frames").empty()) {
      ++foot_rows;
      EXPECT_TRUE(row.at("joint") == "Toes_L" || row.at("joint") == "Toes_R") << row.at("joint");
    }
  EXPECT_EQ(foot_rows, 2u * 2 * 2 * 2);  // 2 clips × 2 feet × 2 methods × 2 spacings
  const auto j = nlohmann::json::parse(slurp(out / "summary.json"));
  ASSERT_EQ(j["clips"].size(), 3u);
  EXPECT_TRUE(j["clips"][0].contains("motion_deg"));
  EXPECT_TRUE(j["results"][0]["foot_skating"].is_object());
  EXPECT_TRUE(j["results"][0].contains("clip_rms_median_deg"));
  EXPECT_EQ(j["options"]["contact_height_m"], 0.05);

  // --feet names the joints; a clip without them fails, named.
  const auto feet = run_cli("eval " + (in / "walk.bvh").string() + " --feet Foot_L --methods slerp --keep-every 4 -q -o " +
                            out.string());
  ASSERT_EQ(feet.exit_code, 0) << feet.err;
  EXPECT_NE(slurp(out / "clips.csv").find(",1,"), std::string::npos);  // one foot
  const auto none = run_cli("eval " + (in / "sausage.fbx").string() + " --feet Foot_L --methods slerp --keep-every 4 -q -o " +
                            out.string());
  EXPECT_EQ(none.exit_code, 3);
  EXPECT_NE(none.err.find("'Foot_L'"), std::string::npos) << none.err;
}

// A glTF file with two takes ("walk", "idle") of a two-joint chain, 9 keys at 25 fps.
fs::path two_take_gltf(const fs::path& dir) {
  std::vector<float> data;
  for (int k = 0; k < 9; ++k) data.push_back(static_cast<float>(k) / 25.0f);
  for (double speed : {0.3, 0.05})
    for (int k = 0; k < 9; ++k) {
      const double a = speed * k * k * 0.5;  // accelerating, so interpolation errs
      for (float v : {0.0f, 0.0f, static_cast<float>(std::sin(a / 2)), static_cast<float>(std::cos(a / 2))}) data.push_back(v);
    }
  std::ofstream(dir / "takes.bin", std::ios::binary).write(reinterpret_cast<const char*>(data.data()),
                                                          static_cast<std::streamsize>(data.size() * sizeof(float)));
  std::ofstream(dir / "takes.gltf") << R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],
"nodes":[{"name":"root","children":[1]},{"name":"child","translation":[0,1,0]}],
"buffers":[{"byteLength":)" << data.size() * 4 << R"(,"uri":"takes.bin"}],
"bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":144},
{"buffer":0,"byteOffset":180,"byteLength":144}],
"accessors":[{"bufferView":0,"componentType":5126,"count":9,"type":"SCALAR","min":[0],"max":[0.32]},
{"bufferView":1,"componentType":5126,"count":9,"type":"VEC4"},{"bufferView":2,"componentType":5126,"count":9,"type":"VEC4"}],
"animations":[
{"name":"walk","samplers":[{"input":0,"output":1,"interpolation":"LINEAR"}],"channels":[{"sampler":0,"target":{"node":1,"path":"rotation"}}]},
{"name":"idle","samplers":[{"input":0,"output":2,"interpolation":"LINEAR"}],"channels":[{"sampler":0,"target":{"node":1,"path":"rotation"}}]}]})";
  return dir / "takes.gltf";
}

TEST(EvalCli, EveryTakeOfAFileIsAClipOfItsOwn) {
  const fs::path dir = fresh_dir("takes"), out = fresh_dir("takes_out");
  const std::string file = two_take_gltf(dir).string();
  const std::string common = "eval " + file + " --methods slerp,squad --keep-every 2 -q --no-plots -o " + out.string();
  auto clips_of = [&] {
    std::vector<std::string> clips;
    for (const auto& row : csv_rows(slurp(out / "clips.csv")))
      if (std::find(clips.begin(), clips.end(), row.at("clip")) == clips.end()) clips.push_back(row.at("clip"));
    return clips;
  };
  ASSERT_EQ(run_cli(common).exit_code, 0);
  EXPECT_EQ(clips_of(), std::vector<std::string>{file + "#walk"});  // the first take, named as a take
  auto r = run_cli(common + " --anim all");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(clips_of(), (std::vector<std::string>{file + "#idle", file + "#walk"}));
  const std::string csv = slurp(out / "errors.csv");
  EXPECT_NE(csv.find(file + "#idle,squad,2,child"), std::string::npos);
  const auto j = nlohmann::json::parse(slurp(out / "summary.json"));
  EXPECT_EQ(j["clips_evaluated"], 2);
  EXPECT_EQ(j["options"]["anim"], "all");
  // The two takes differ: their errors are not the same.
  EXPECT_NE(j["clips"][0]["results"][0]["rms_deg"], j["clips"][1]["results"][0]["rms_deg"]);
  for (const std::string pick : {"idle", "1"}) {
    ASSERT_EQ(run_cli(common + " --anim " + pick).exit_code, 0);
    EXPECT_EQ(clips_of(), std::vector<std::string>{file + "#idle"}) << pick;
  }
  // A take that is not there: the file fails, named; exit 3.
  r = run_cli(common + " --anim run");
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(r.err.find("takes.gltf"), std::string::npos) << r.err;
  // --per-frame picks a take by its clip id.
  r = run_cli(common + " --anim all --per-frame " + file + "#walk,slerp,2");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto pf = csv_rows(slurp(out / "per_frame.csv"));
  ASSERT_EQ(pf.size(), 9u);
  EXPECT_EQ(pf[0].at("key"), "1");
  EXPECT_EQ(pf[1].at("key"), "0");
  EXPECT_EQ(std::stod(pf[0].at("child")), 0.0);
  EXPECT_GT(std::stod(pf[1].at("child")), 0.01);
}

TEST(EvalCli, PerFrameSeriesAndTableFormats) {
  const fs::path out = fresh_dir("per_frame");
  const std::string clip = std::string(ROTINTERP_SHARED_DATA) + "/bvh/NC_bandai2_raise-up-both-hands_active_031.bvh";
  auto r = run_cli("eval " + clip + " --methods slerp,squad --keep-every 4 --no-plots --per-frame " + clip +
                   ",squad,4 --table md -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("| method | N | clips | mean° | RMS° | p95° | max°", 0), 0u) << r.out;
  const auto pf = csv_rows(slurp(out / "per_frame.csv"));
  ASSERT_EQ(pf.size(), 51u);
  double sum = 0;
  for (std::size_t m = 0; m < pf.size(); ++m) {
    EXPECT_EQ(pf[m].at("key"), m % 4 == 0 || m == 50 ? "1" : "0") << m;
    if (pf[m].at("key") == "1") {
      EXPECT_EQ(std::stod(pf[m].at("Hips")), 0.0) << m;
    }
    sum += std::stod(pf[m].at("Hips"));
  }
  EXPECT_GT(sum, 0.0);
  r = run_cli("eval " + clip + " --methods slerp --keep-every 4 --no-plots --table latex -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("\\begin{tabular}", 0), 0u) << r.out;
  EXPECT_FALSE(fs::exists(out / "per_frame.csv"));  // not asked for this time: no stale series left
  // A clip not among the inputs: an error, nothing written over the last run.
  const std::string before = slurp(out / "errors.csv");
  r = run_cli("eval " + clip + " --methods slerp --keep-every 2 --no-plots --per-frame other.bvh,slerp,4 -q -o " +
              out.string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("other.bvh"), std::string::npos) << r.err;
  EXPECT_EQ(slurp(out / "errors.csv"), before);
  EXPECT_EQ(run_cli("eval " + clip + " --per-frame " + clip + ",nosuch,4 -o " + out.string()).exit_code, 2);
  EXPECT_EQ(run_cli("eval " + clip + " --per-frame " + clip + " -o " + out.string()).exit_code, 2);
  EXPECT_EQ(run_cli("eval " + clip + " --table html -o " + out.string()).exit_code, 2);
  EXPECT_EQ(run_cli("eval " + clip + " --floor nan -o " + out.string()).exit_code, 2);
  EXPECT_EQ(run_cli("eval " + clip + " --contact-speed 0 -o " + out.string()).exit_code, 2);
}

TEST(EvalCli, BadOptionValuesAreUsageErrors) {
  const fs::path out = fresh_dir("usage");
  const std::string clip = std::string(ROTINTERP_SHARED_DATA) + "/bvh/bvhio_example.bvh";
  EXPECT_EQ(run_cli("eval " + clip + " --methods nosuch -o " + out.string()).exit_code, 2);
  EXPECT_EQ(run_cli("eval " + clip + " --keep-every 0 -o " + out.string()).exit_code, 2);
  EXPECT_EQ(run_cli("eval " + clip + " --shard 3/2 -o " + out.string()).exit_code, 2);
  const auto missing = run_cli("eval /no/such/dir -o " + out.string());
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_NE(missing.err.find("/no/such/dir"), std::string::npos);
}

}  // namespace
}  // namespace rotinterp
