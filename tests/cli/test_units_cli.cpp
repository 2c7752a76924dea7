// True size: every command reads a clip's unit the same way (declared, given or
// inferred), says which, writes files at their true size, and gives the same results
// for the same motion in centimetres and in metres.
#include "rotinterp/io/files/file_record.h"
#include "rotinterp/clip/units.h"
#include "rotinterp/io/read.h"
#include "support/run_cli.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace rotinterp {
namespace {

namespace fs = std::filesystem;
using test::run_cli;
using test::slurp;

const fs::path kData = ROTINTERP_SHARED_DATA;
const std::string kBandai = (kData / "bvh" / "NC_bandai1_walk_normal_001.bvh").string();

fs::path temp_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("rotinterp_units_" + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

// The BVH text with every length (OFFSETs and position channels) times `k`: the same
// motion in another unit, made without rotinterp.
std::string scale_bvh(const std::string& text, double k) {
  std::istringstream in(text);
  std::ostringstream out;
  std::vector<bool> is_position;  // per channel, in file order
  bool motion = false, data = false;
  auto number = [](double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return std::string(buf);
  };
  for (std::string line; std::getline(in, line);) {
    std::istringstream words(line);
    std::string first;
    words >> first;
    if (!motion && first == "OFFSET") {
      double x, y, z;
      words >> x >> y >> z;
      out << line.substr(0, line.find("OFFSET")) << "OFFSET " << number(x * k) << ' ' << number(y * k) << ' '
          << number(z * k) << '\n';
      continue;
    }
    if (!motion && first == "CHANNELS") {
      int n = 0;
      words >> n;
      for (std::string c; n-- > 0 && words >> c;) is_position.push_back(c.find("position") != std::string::npos);
    }
    if (first == "MOTION") motion = true;
    if (data && !first.empty()) {
      std::istringstream values(line);
      std::string row;
      double v;
      for (std::size_t c = 0; values >> v; ++c) row += (c ? " " : "") + number(c < is_position.size() && is_position[c] ? v * k : v);
      out << row << '\n';
      continue;
    }
    if (first == "Frame" && line.find("Time:") != std::string::npos) data = true;
    out << line << '\n';
  }
  return out.str();
}

nlohmann::json info_json(const std::string& args) {
  const auto r = run_cli("info --json " + args);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return nlohmann::json::parse(r.out);
}

// Every shared BVH comes out a human-sized figure, and info says how it got its unit.
TEST(UnitsCli, EveryRealBvhIsAPlausibleHumanSizeAndInfoSaysWhy) {
  const struct {
    const char* file;
    const char* unit;
    const char* origin;
  } cases[] = {{"NC_bandai1_walk_normal_001.bvh", "cm", "inferred"},
               {"NC_bandai2_raise-up-both-hands_active_031.bvh", "cm", "inferred"},
               {"assimp_Boxing_Toes.bvh", "cm", "inferred"},
               {"bvhio_example.bvh", "in", "inferred"},
               {"cmu_01_01.bvh", nullptr, "assumed"},  // 1/0.45 inch per unit: no common unit
               {"cmu_01_03.bvh", nullptr, "assumed"}};
  for (const auto& c : cases) {
    const nlohmann::json j = info_json((kData / "bvh" / c.file).string());
    EXPECT_EQ(j["unit"]["origin"], c.origin) << c.file;
    if (c.unit) {
      EXPECT_EQ(j["unit"]["name"], c.unit) << c.file;
    }
    EXPECT_NE(j["unit"]["reason"].get<std::string>().find("--unit"), std::string::npos) << c.file;
    const double size = j["figure_size_m"];
    EXPECT_GE(size, 1.0) << c.file;
    EXPECT_LE(size, 2.5) << c.file;
  }
  const auto text = run_cli("info " + kBandai);
  EXPECT_NE(text.out.find("unit:        cm (inferred from its offsets, a skeleton "), std::string::npos) << text.out;
}

// A cut keeps the skeleton, so it keeps the unit: CMU 01_01's frames 100-300 read back
// in the whole clip's unit (by its first pose the cut measured 26.18 units against
// 26.56, 0.06494 m per unit against 0.064), and info says it came from the offsets.
TEST(UnitsCli, ACutOfAClipIsReadBackInTheWholeClipsUnit) {
  const fs::path dir = temp_dir("cut");
  const std::string cmu = (kData / "bvh" / "cmu_01_01.bvh").string();
  for (const char* range : {"100f:300f", "1500f:1600f"}) {
    const fs::path cut = dir / "cut.bvh";
    ASSERT_EQ(run_cli("resample " + cmu + " --range " + range + " -o " + cut.string() + " -q").exit_code, 0);
    const nlohmann::json whole = info_json(cmu), part = info_json(cut.string());
    EXPECT_NEAR(part["unit"]["metres_per_unit"].get<double>(), whole["unit"]["metres_per_unit"].get<double>(),
                1e-6 * whole["unit"]["metres_per_unit"].get<double>())
        << range;
    EXPECT_NE(part["unit"]["reason"].get<std::string>().find("its offsets"), std::string::npos) << part["unit"];
  }
}

TEST(UnitsCli, AGivenUnitWinsOverInferenceAndADeclaredUnitIsKept) {
  const nlohmann::json given = info_json("--unit m " + kBandai);
  EXPECT_EQ(given["unit"]["origin"], "given");
  EXPECT_EQ(given["unit"]["metres_per_unit"], 1.0);
  const std::string fbx = (kData / "fbx" / "digitalrune_Marine_Run.fbx").string();
  const auto r = run_cli("info --json --unit m " + fbx);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["unit"]["origin"], "declared");
  EXPECT_NE(r.err.find("declares its unit"), std::string::npos) << r.err;
  EXPECT_EQ(run_cli("info --unit furlong " + kBandai).exit_code, 2);
}

// The writers: FBX states the clip's unit and glTF is metres, so the figure read back
// is as many metres tall as the source; BVH keeps its numbers unless --out-unit.
TEST(UnitsCli, WrittenFilesReadBackAtTheSourcesTrueSize) {
  const fs::path dir = temp_dir("writers");
  auto source = read_clip(kBandai);
  ASSERT_TRUE(source) << source.error();
  const double metres = first_pose_size(*source) * source->unit.metres_per_unit;
  EXPECT_GT(metres, 1.0);  // a person, not a 138 m giant
  EXPECT_LT(metres, 2.5);
  for (const char* name : {"w.fbx", "w.glb", "w.bvh"}) {
    const auto r = run_cli("resample " + kBandai + " -o " + (dir / name).string() + " -q");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    auto back = read_clip(dir / name);
    ASSERT_TRUE(back) << back.error();
    EXPECT_NEAR(first_pose_size(*back) * back->unit.metres_per_unit, metres, 1e-4 * metres) << name;
  }
  EXPECT_EQ(read_clip(dir / "w.fbx")->unit.metres_per_unit, 0.01);  // UnitScaleFactor 1, as assimp reads it
  EXPECT_EQ(read_clip(dir / "w.glb")->unit.metres_per_unit, 1.0);
  const auto m = run_cli("resample " + kBandai + " -o " + (dir / "m.bvh").string() + " --out-unit m -q");
  ASSERT_EQ(m.exit_code, 0) << m.err;
  const nlohmann::json j = info_json((dir / "m.bvh").string());
  EXPECT_EQ(j["unit"]["name"], "m");
  EXPECT_NEAR(j["figure_size_m"].get<double>(), metres, 1e-4 * metres);
  EXPECT_EQ(run_cli("resample " + kBandai + " -o " + (dir / "x.glb").string() + " --out-unit cm -q").exit_code, 2);
}

// BVH → FBX → BVH gives back the numbers of the file.
TEST(UnitsCli, ABvhThroughFbxComesBackWithItsOwnNumbers) {
  const fs::path dir = temp_dir("roundtrip");
  ASSERT_EQ(run_cli("resample " + kBandai + " -o " + (dir / "a.fbx").string() + " -q").exit_code, 0);
  ASSERT_EQ(run_cli("resample " + (dir / "a.fbx").string() + " -o " + (dir / "b.bvh").string() + " -q").exit_code, 0);
  auto a = read_clip(kBandai), b = read_clip(dir / "b.bvh"), fbx = read_clip(dir / "a.fbx");
  ASSERT_TRUE(a && b && fbx);
  EXPECT_EQ(b->unit.metres_per_unit, 0.01);
  ASSERT_EQ(a->skeleton.joints.size(), b->skeleton.joints.size());
  // The CHANNELS lines, kept in the FBX (user properties, read back through assimp):
  // 22 joints × 6, not the 6 + 21 × 3 a BVH without a layout gets.
  std::size_t channels = 0;
  for (std::size_t j = 0; j < a->skeleton.joints.size(); ++j) {
    EXPECT_EQ(bvh_channels(*fbx, j), bvh_channels(*a, j)) << j;
    EXPECT_EQ(bvh_channels(*b, j), bvh_channels(*a, j)) << j;
    channels += bvh_channels(*b, j).size();
    for (std::size_t k = 0; k < a->frame_count(); ++k)
      EXPECT_LT(angular_distance(a->rotations[j].keys[k], b->rotations[j].keys[k]), 1e-4 * kPi / 180) << j << " " << k;
  }
  EXPECT_EQ(channels, 132u);
  // Each joint's local translation at each frame: its track's key, or its offset
  // where it has no track (a constant track may come back as an offset).
  auto local = [](const Clip& c, std::size_t j, std::size_t k) {
    const auto& t = c.translations[j];
    return t ? t->keys[std::min(k, t->keys.size() - 1)] : c.skeleton.joints[j].offset;
  };
  for (std::size_t j = 0; j < a->skeleton.joints.size(); ++j)
    for (std::size_t k = 0; k < a->frame_count(); ++k)
      EXPECT_LT((local(*a, j, k) - local(*b, j, k)).norm(), 1e-4) << j << " " << k;
}

// The same motion in centimetres and in metres: eval states its distances in metres
// and reduce its budgets in physical units, so every figure agrees to round-off.
TEST(UnitsCli, ACentimetreClipAndItsMetreTwinGiveTheSameEvalAndReduceResults) {
  const fs::path dir = temp_dir("twins");
  std::ofstream(dir / "walk_m.bvh") << scale_bvh(slurp(kBandai), 0.01);
  const std::string cm = kBandai, m = (dir / "walk_m.bvh").string();
  for (const auto& [clip, unit, out] : {std::tuple{cm, std::string(), "e_cm"}, std::tuple{m, std::string("--unit m"), "e_m"}}) {
    const auto r = run_cli("eval " + clip + " " + unit + " --methods slerp,c2 --keep-every 4 --no-plots -q -o " +
                           (dir / out).string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  const auto a = nlohmann::json::parse(slurp(dir / "e_cm" / "summary.json"));
  const auto b = nlohmann::json::parse(slurp(dir / "e_m" / "summary.json"));
  EXPECT_EQ(a["clips"][0]["unit"].get<std::string>().rfind("cm (inferred", 0), 0u);
  EXPECT_EQ(b["clips"][0]["unit"].get<std::string>().rfind("m (given", 0), 0u);
  ASSERT_EQ(a["results"].size(), b["results"].size());
  for (std::size_t i = 0; i < a["results"].size(); ++i)
    for (const auto& [key, va] : a["results"][i].items()) {
      if (!va.is_number() || key == "seconds") continue;
      const double x = va, y = b["results"][i][key];
      EXPECT_NEAR(x, y, 1e-9 * std::max(1.0, std::abs(x))) << key;
    }
  for (const std::string method : {"slerp", "c2"}) {
    const auto rc = run_cli("reduce " + cm + " --method " + method + " -o " + (dir / ("r_cm_" + method + ".json")).string() +
                            " --tolerance 0.5deg,1mm -q");
    const auto rm = run_cli("reduce " + m + " --unit m --method " + method + " -o " +
                            (dir / ("r_m_" + method + ".json")).string() + " --tolerance 0.5deg,1mm -q");
    ASSERT_EQ(rc.exit_code, 0) << rc.err;
    ASSERT_EQ(rm.exit_code, 0) << rm.err;
    const auto x = nlohmann::json::parse(slurp(dir / ("r_cm_" + method + ".json")));
    const auto y = nlohmann::json::parse(slurp(dir / ("r_m_" + method + ".json")));
    EXPECT_EQ(x["kept_keys"], y["kept_keys"]) << method;
    for (std::size_t j = 0; j < x["joints"].size(); ++j) {
      EXPECT_EQ(x["joints"][j]["rotation"]["frames"], y["joints"][j]["rotation"]["frames"]) << method << j;
      EXPECT_NEAR(x["joints"][j].value("max_shell_error_mm", 0.0), y["joints"][j].value("max_shell_error_mm", 0.0), 1e-6);
    }
  }
}

// Distances in options: a suffix, or a bare number in metres, the same in every command.
TEST(UnitsCli, DistancesInOptionsTakeUnitsAndABareNumberIsMetres) {
  const fs::path dir = temp_dir("options");
  for (const auto& [arg, out] : {std::pair{"--shell-distance 3cm", "a"}, std::pair{"--shell-distance 0.03", "b"}}) {
    const auto r = run_cli("eval " + kBandai + " " + arg + " --methods slerp --keep-every 4 --no-plots -q -o " +
                           (dir / out).string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  EXPECT_EQ(slurp(dir / "a" / "errors.csv"), slurp(dir / "b" / "errors.csv"));
  const auto bad = run_cli("eval " + kBandai + " --shell-distance 3furlongs -q -o " + (dir / "c").string());
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--shell-distance"), std::string::npos) << bad.err;
  const auto bare = run_cli("reduce " + kBandai + " -o " + (dir / "k.json").string() + " --tolerance 1 -q");
  EXPECT_EQ(bare.exit_code, 2);
  EXPECT_NE(bare.err.find("needs a unit"), std::string::npos) << bare.err;
}

}  // namespace
}  // namespace rotinterp
