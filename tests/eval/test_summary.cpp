// Summary aggregates: hand-computed values over a few rows.
#include "rotinterp/eval/summary.h"
#include "rotinterp/io/files/csv.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace rotinterp {
namespace {

ErrorRow row(const std::string& clip, const std::string& method, int keep, const std::string& joint, std::size_t n,
             double rms, double max) {
  ErrorRow r;
  r.clip = clip;
  r.method = method;
  r.keep_every = keep;
  r.joint = joint;
  r.frames = r.samples = n;
  r.mean_deg = rms;
  r.rms_deg = rms;
  r.p95_deg = max;
  r.max_deg = max;
  r.height = 2.0;
  r.shell_rms = 0.02;
  r.shell_max = 0.04;
  return r;
}

TEST(Summary, AggregatesAreSampleWeightedAndMaxOverAll) {
  SummaryBuilder b;
  b.add_clip({row("a", "slerp", 2, "j0", 100, 1.0, 2.0), row("a", "slerp", 2, "j1", 100, 3.0, 5.0),
              row("a", "slerp", 4, "j0", 100, 4.0, 9.0)});
  b.add_clip({row("b", "slerp", 2, "j0", 300, 2.0, 7.0), row("b", "slerp", 4, "j0", 300, 1.0, 1.5)});
  const Summary s = b.finish();
  ASSERT_EQ(s.entries.size(), 2u);
  const SummaryEntry& e = s.entries[0];
  EXPECT_EQ(e.method, "slerp");
  EXPECT_EQ(e.keep_every, 2);
  EXPECT_EQ(e.clips, 2u);
  EXPECT_EQ(e.joints, 3u);
  EXPECT_EQ(e.samples, 500u);
  EXPECT_DOUBLE_EQ(e.rms_deg, std::sqrt((100 * 1.0 + 100 * 9.0 + 300 * 4.0) / 500));
  EXPECT_DOUBLE_EQ(e.mean_deg, (100 * 1.0 + 100 * 3.0 + 300 * 2.0) / 500);
  EXPECT_DOUBLE_EQ(e.max_deg, 7.0);
  EXPECT_EQ(e.worst_clip, "b");
  EXPECT_DOUBLE_EQ(e.p95_deg, 5.0 + 0.9 * (7.0 - 5.0));  // p95 of {2, 5, 7}
  EXPECT_DOUBLE_EQ(e.shell_rms_pct, 1.0);                  // 0.02 of height 2
  // Worst clip: largest RMS at the largest spacing (4): clip a (4.0) over b (1.0).
  EXPECT_EQ(s.worst_clip, "a");
  EXPECT_EQ(s.worst_keep_every, 4);
  ASSERT_EQ(s.worst_clip_rows.size(), 1u);
  EXPECT_EQ(s.clips, 2u);
  EXPECT_NE(format_summary_table(s).find("slerp"), std::string::npos);
}

TEST(Summary, PerClipResultsAndTheMedianOverClipsCountEachClipOnce) {
  SummaryBuilder b;
  // Clip a: two joints of 100 samples; b and c: one joint of 1000. Weighted by samples
  // clip b dominates; the median over clips does not care how long each clip is.
  b.add_clip({row("a", "slerp", 2, "j0", 100, 1.0, 2.0), row("a", "slerp", 2, "j1", 100, 3.0, 5.0)});
  b.add_clip({row("b", "slerp", 2, "j0", 1000, 20.0, 30.0)});
  b.add_clip({row("c", "slerp", 2, "j0", 1000, 0.5, 0.7)});
  const Summary s = b.finish();
  ASSERT_EQ(s.clip_results.size(), 3u);
  const ClipResult& a = s.clip_results[0];
  EXPECT_EQ(a.clip, "a");
  EXPECT_EQ(a.joints, 2u);
  EXPECT_EQ(a.samples, 200u);
  EXPECT_DOUBLE_EQ(a.rms_deg, std::sqrt((1.0 + 9.0) / 2));
  EXPECT_DOUBLE_EQ(a.mean_deg, 2.0);
  EXPECT_DOUBLE_EQ(a.max_deg, 5.0);
  EXPECT_EQ(a.max_joint, "j1");
  ASSERT_EQ(s.entries.size(), 1u);
  EXPECT_DOUBLE_EQ(s.entries[0].clip_rms_median_deg, std::sqrt(5.0));  // median of {√5, 20, 0.5}
  EXPECT_DOUBLE_EQ(s.entries[0].clip_max_median_deg, 5.0);
  EXPECT_GT(s.entries[0].rms_deg, 10.0);  // by samples: clip b
  const std::string csv = clips_csv(s);
  EXPECT_EQ(csv.rfind("clip,method,keep_every,frames,joints,keys,motion_deg,samples,mean_deg,rms_deg,p95_deg,max_deg", 0),
            0u);
  EXPECT_NE(csv.find("\nb,slerp,2,1000,1,"), std::string::npos) << csv;
  const auto j = nlohmann::json::parse(summary_json(RunRecord{}, s));
  ASSERT_EQ(j["clips"].size(), 3u);
  EXPECT_EQ(j["clips"][1]["clip"], "b");
  EXPECT_DOUBLE_EQ(j["clips"][1]["results"][0]["rms_deg"].get<double>(), 20.0);
  EXPECT_NE(j["weighting"].get<std::string>().find("median"), std::string::npos);
}

TEST(Summary, FootSkatingSumsIntervalsOverFeetAndClipsAndReportsTheExtra) {
  auto foot = [](const std::string& clip, const std::string& joint, double contact, double skate, double speed,
                 double skate_ref, double speed_ref) {
    ErrorRow r = row(clip, "slerp", 2, joint, 101, 1.0, 1.0);  // 100 intervals
    r.foot = true;
    r.contact_frames = r.contact_frames_ref = contact;
    r.skate_frames = skate;
    r.skate_speed = speed;
    r.skate_frames_ref = skate_ref;
    r.skate_speed_ref = speed_ref;
    return r;
  };
  SummaryBuilder b;
  b.add_clip({foot("a", "LeftToeBase", 40, 10, 0.3, 5, 0.2), foot("a", "RightToeBase", 60, 20, 0.5, 5, 0.2),
              row("a", "slerp", 2, "Hips", 101, 1.0, 1.0)});
  b.add_clip({row("box", "slerp", 2, "pCube1", 101, 1.0, 1.0)});  // no feet
  const Summary s = b.finish();
  const FootSkating& a = s.clip_results[0].skating;
  EXPECT_EQ(a.feet, 2u);
  EXPECT_DOUBLE_EQ(a.ratio(), 30.0 / 200.0);
  EXPECT_DOUBLE_EQ(a.ratio_ref(), 10.0 / 200.0);
  EXPECT_DOUBLE_EQ(a.speed(), (40 * 0.3 + 60 * 0.5) / 100.0);
  EXPECT_DOUBLE_EQ(a.speed_ref(), 0.2);
  EXPECT_EQ(s.clip_results[1].skating.feet, 0u);
  EXPECT_DOUBLE_EQ(s.entries[0].skating.ratio(), 30.0 / 200.0);  // the clip without feet adds nothing
  const auto j = nlohmann::json::parse(summary_json(RunRecord{}, s));
  EXPECT_DOUBLE_EQ(j["results"][0]["foot_skating"]["extra_skate_ratio"].get<double>(), 0.1);
  EXPECT_TRUE(j["clips"][1]["results"][0]["foot_skating"].is_null());
  const std::string csv = clips_csv(s);
  EXPECT_NE(csv.find("\nbox,slerp,2,101,1,0,0,101,1,1,1,1,pCube1,"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",0,,,,,,,,\n"), std::string::npos) << csv;  // no feet: skating columns empty
}

TEST(Summary, EveryClipsCsvLineHasOneFieldPerColumnWithFeetAndSeam) {
  for (bool seam : {false, true}) {
    ErrorRow foot = row("a,b", "slerp", 2, "LeftToeBase", 101, 1.0, 1.0);
    foot.foot = true;
    foot.contact_frames = foot.contact_frames_ref = 40;
    foot.seam = seam;
    ErrorRow plain = row("box", "slerp", 2, "pCube1", 101, 1.0, 1.0);
    plain.seam = seam;
    SummaryBuilder b;
    b.add_clip({foot});
    b.add_clip({plain});
    Summary s = b.finish();
    s.seam = seam;  // set by the run (eval --loop)
    const std::string csv = clips_csv(s);
    std::size_t columns = 0, lines = 0;
    for (std::size_t at = 0; at < csv.size();) {
      const std::size_t end = csv.find('\n', at);
      auto fields = split_csv_line(csv.substr(at, end - at));
      ASSERT_TRUE(fields) << fields.error();
      if (lines++ == 0) columns = fields->size();
      EXPECT_EQ(fields->size(), columns) << csv;
      at = end + 1;
    }
    EXPECT_EQ(lines, 3u);
    EXPECT_EQ(csv.find("looped_joints") != std::string::npos, seam) << csv;
  }
}

TEST(Summary, TablesShowMeanRmsP95MaxToFourSignificantFiguresInEveryFormat) {
  SummaryBuilder b;
  ErrorRow r = row("a", "slerp", 2, "j0", 100, 6.488e-15, 1234.5678);
  r.mean_deg = 0.0123456;
  b.add_clip({r, row("a", "squad", 2, "j0", 100, 0.0, 0.0)});
  const Summary s = b.finish();
  const std::string text = format_summary_table(s);
  EXPECT_NE(text.find("mean°"), std::string::npos) << text;
  EXPECT_NE(text.find("0.01235"), std::string::npos) << text;  // mean
  EXPECT_NE(text.find("< 0.001"), std::string::npos) << text;  // 6.488e-15: no exponent
  EXPECT_NE(text.find("1235"), std::string::npos) << text;     // max (p95 the same)
  EXPECT_EQ(text.find("e-"), std::string::npos) << text;
  const std::string md = format_summary_table(s, TableFormat::markdown);
  EXPECT_EQ(md.rfind("| method | N | clips | mean° | RMS° | p95° | max° |", 0), 0u) << md;
  EXPECT_NE(md.find("|---|---:|"), std::string::npos) << md;
  EXPECT_NE(md.find("| squad | 2 | 1 | 0 | 0 | 0 | 0 |"), std::string::npos) << md;
  const std::string tex = format_summary_table(s, TableFormat::latex);
  EXPECT_EQ(tex.rfind("\\begin{tabular}", 0), 0u) << tex;
  EXPECT_NE(tex.find("RMS$^\\circ$"), std::string::npos) << tex;
  EXPECT_NE(tex.find("$<$\\,0.001"), std::string::npos) << tex;
  EXPECT_NE(tex.find("\\end{tabular}"), std::string::npos) << tex;
}

TEST(Summary, TooShortClipsAndTheNewOptionsReadBackFromTheJson) {
  RunRecord r;
  r.options.methods = {"slerp"};
  r.options.keep_every = {2, 16};
  r.options.animation = "all";
  r.options.min_frames = 30;
  r.options.feet = {"LeftToeBase"};
  r.options.contact_height_m = 0.05;
  r.options.contact_speed_mps = 0.5;
  r.options.floor_m = 0.1;
  r.options.truth = "source";
  r.too_short.push_back({"clip.bvh", 20, {16}});
  const std::filesystem::path f = std::filesystem::path(testing::TempDir()) / "rotinterp_summary_roundtrip.json";
  std::ofstream(f) << summary_json(r, Summary{});
  auto back = read_summary_json(f);
  ASSERT_TRUE(back.ok()) << back.error();
  EXPECT_TRUE(back->options == r.options);
  ASSERT_EQ(back->too_short.size(), 1u);
  EXPECT_EQ(back->too_short[0].clip, "clip.bvh");
  EXPECT_EQ(back->too_short[0].frames, 20u);
  EXPECT_EQ(back->too_short[0].keep_every, std::vector<int>{16});
}

}  // namespace
}  // namespace rotinterp
