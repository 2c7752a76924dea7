// eval's plots are readable on real data (issue 45): checked on the numbers they are
// drawn with — axes, ticks, texts and legends from eval/plot_layout.h.
#include "eval_cli_util.h"
#include "plot_checks.h"
#include "rotinterp/eval/batch.h"
#include "rotinterp/eval/plot_layout.h"
#include "rotinterp/interp/interpolator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace rotinterp {
namespace {

std::string joined(const std::vector<std::string>& problems) {
  std::string out;
  for (const std::string& p : problems) out += p + "\n";
  return out;
}

// The shapes of data that broke the plots on the shared clips, and their extremes.
TEST(PlotAxis, EveryAngleAxisHasThreeLabelledTicksAndHoldsItsValuesInHalfItsLength) {
  const std::vector<std::vector<double>> cases = {
      {175.8, 177.2, 179.9, 180.0},  // error_vs_spacing's max panel on the CMU clips: one tick ("100") before
      {1.4, 2.1, 2.9, 4.3},          // its RMS panel: less than a decade
      {2.4, 3.9, 4.8, 9.3, 11.6},    // clip_errors: 60 % of a 1…100 axis empty before
      {1e-4, 3e-2, 0.5, 40},         // several decades
      {1e-12, 5e-7, 2e-3, 3, 90},    // ten decades
      {2.0, 2.0, 2.0},               // all one value
      {0.0, 0.0, 3.0, 3.0001},       // zeros and one value
      {0.0, 1e-14, 0.0},             // all zero to round-off
      {0.003, 0.0031},               // tiny, close together
      {0.5, 179.99},
      {NAN, 1.0, INFINITY, 30.0},    // non-finite values ignored
  };
  for (AxisScale scale : {AxisScale::log, AxisScale::automatic})
    for (const std::vector<double>& values : cases) {
      const PlotAxis a = angle_axis(values, scale);
      std::string shown;
      for (double v : values) shown += std::to_string(v) + " ";
      SCOPED_TRACE(shown + (scale == AxisScale::log ? "log" : "automatic"));
      EXPECT_EQ(joined(test::axis_problems(a, "y")), "");
      // Every value, as drawn, is inside the axis (zeros on a log axis at its bottom edge).
      for (double v : values) {
        if (!std::isfinite(v)) continue;
        const double at = !a.log ? v : v > kZeroDeg ? std::log10(v) : a.lo;
        EXPECT_GE(at, a.lo);
        EXPECT_LE(at, a.hi);
      }
      // Angles stop at 180°: the axis ends within its pad above.
      const double cap = a.log ? std::log10(kMaxDeg) : kMaxDeg;
      EXPECT_LE(a.hi, cap + kAxisPad * (a.hi - a.lo) + 1e-9);
      std::set<std::string> labels;
      for (const PlotTick& t : a.ticks) labels.insert(t.label);
      EXPECT_EQ(labels.size(), a.ticks.size()) << "two ticks read the same";
    }
}

TEST(PlotAxis, ValuesOverDecadesGetALogAxisAndValuesWithinOneALinearOne) {
  EXPECT_TRUE(angle_axis({0.01, 0.5, 20}, AxisScale::automatic).log);
  EXPECT_FALSE(angle_axis({2.4, 11.6}, AxisScale::automatic).log);
  const PlotAxis decades = angle_axis({1e-4, 1e2}, AxisScale::log);
  for (const PlotTick& t : decades.ticks) EXPECT_DOUBLE_EQ(t.at, std::round(t.at)) << t.label;
}

TEST(PlotAxis, KeySpacingAxisHasThreePowersOfTwoEvenForOneSpacing) {
  for (const std::vector<int>& n : {std::vector<int>{8}, {2, 4}, {2, 4, 8, 16}, {3, 6, 100}, {1}}) {
    const PlotAxis a = spacing_axis(n);
    EXPECT_EQ(joined(test::axis_problems(a, "x", false)), "");
    EXPECT_GE(a.ticks.size(), 3u);
    EXPECT_LE(a.lo, a.data_lo - 0.25);  // room for the methods' sideways offsets
    EXPECT_GE(a.hi, a.data_hi + 0.25);
  }
}

TEST(PlotLabels, JointNamesAreShortenedInTheMiddleAndNeverReadTheSame) {
  const std::vector<std::string> names = {"LeftHandThumb1",         "LeftHandThumb2",        "LeftHandIndex1",
                                          "mixamorig:LeftHandThumb1", "mixamorig:LeftHandThumb2", "mixamorig:RightHandThumb2",
                                          "Hips",                   "LeftUpLeg_$AssimpFbx$_Rotation", "LeftUpLeg_$AssimpFbx$_PreRotation",
                                          "LeftUpLeg_$AssimpFbx$_Translation"};
  const std::vector<std::string> labels = short_labels(names, 14);
  EXPECT_EQ(std::set<std::string>(labels.begin(), labels.end()).size(), names.size());
  EXPECT_EQ(labels[6], "Hips");
  EXPECT_EQ(labels[0], "LeftHandThumb1");
  // The ends of a long name stay: its start and its distinguishing end.
  EXPECT_EQ(labels[3].rfind("mixamo", 0), 0u) << labels[3];
  EXPECT_NE(labels[3].find("…"), std::string::npos) << labels[3];
  EXPECT_EQ(labels[3].substr(labels[3].size() - 6), "Thumb1") << labels[3];
  // Within the limit, but for names that would otherwise read the same ("mixamo…Thumb2"
  // for Left and Right), lengthened at both ends until they differ.
  for (std::size_t i = 0; i < labels.size(); ++i) {
    bool collides = false;
    for (std::size_t j = 0; j < names.size(); ++j) collides |= j != i && middle_ellipsis(names[j], 14) == middle_ellipsis(names[i], 14);
    EXPECT_LE(text_chars(labels[i]), collides ? 24u : 14u) << labels[i];
  }
  EXPECT_EQ(middle_ellipsis("LeftUpLegHandThumb2", 14), "LeftUpL…Thumb2");
  EXPECT_EQ(middle_ellipsis("ÄÖÜäöüßÄÖÜäöüß", 5), "ÄÖ…üß");  // whole characters only
}

TEST(PlotLabels, ClipLabelsAreFileNamesNeverPaths) {
  EXPECT_EQ(clip_file_name("/home/someone/data/bvh/cmu_01_01.bvh"), "cmu_01_01.bvh");
  EXPECT_EQ(clip_file_name("/data/fbx/two.fbx#Take 001"), "two.fbx#Take 001");
  EXPECT_EQ(clip_file_name("/data/fbx/two.fbx#run/left"), "two.fbx#run/left");  // a '/' in a take's name
  EXPECT_EQ(clip_file_name("/data/#1/walk.bvh"), "walk.bvh");                   // a '#' in a directory
  const std::vector<std::string> labels = clip_labels({"/a/x/walk.bvh", "/a/y/walk.bvh", "/a/y/run.bvh"});
  EXPECT_EQ(labels, (std::vector<std::string>{"x/walk.bvh", "y/walk.bvh", "run.bvh"}));
}

// A summary shaped like the failing real cases: long absolute paths, long similar
// joint names, values over decades, a still clip (zeros) and a max near 180°.
Summary hostile_summary() {
  Summary s;
  const std::vector<std::string> methods = {"slerp", "squad", "expmap", "nlerp", "bf", "c2", "expmap-c2", "clamped", "gltf-cubic"};
  const std::string dir = "/very/long/absolute/path/to/a/shared/motion/capture/dataset/bandai_namco_research/";
  std::vector<std::string> clips;
  for (int i = 0; i < 12; ++i) clips.push_back(dir + "NC_bandai2_raise-up-both-hands_active_0" + std::to_string(10 + i) + ".bvh");
  clips.push_back(dir + "still.bvh");
  s.clips = clips.size();
  for (std::size_t m = 0; m < methods.size(); ++m) {
    for (int keep : {2, 4, 8, 16}) {
      SummaryEntry e;
      e.method = methods[m], e.keep_every = keep;
      e.rms_deg = 1e-6 * std::pow(keep, 4.0) * double(m + 1);
      e.clip_rms_median_deg = 0.3 * keep;
      e.max_deg = 176.0 + 0.2 * double(m);
      s.entries.push_back(e);
    }
    for (std::size_t c = 0; c < clips.size(); ++c) {
      ClipResult r;
      r.clip = clips[c], r.method = methods[m], r.keep_every = 16;
      r.rms_deg = c + 1 == clips.size() ? 0.0 : 2.0 + double(c);
      s.clip_results.push_back(r);
    }
  }
  s.worst_clip = clips.front();
  s.worst_keep_every = 16;
  for (const std::string& m : methods)
    for (int j = 0; j < 70; ++j) {
      ErrorRow r;
      r.clip = s.worst_clip, r.method = m, r.keep_every = 16;
      r.joint = "mixamorig:" + std::string(j % 2 ? "Left" : "Right") + "HandThumb" + std::to_string(j);
      r.rms_deg = 0.01 * (1 + j);
      s.worst_clip_rows.push_back(r);
    }
  return s;
}

TEST(PlotLayout, PlotsOfLongPathsSimilarJointsAndDecadesAreReadable) {
  const Summary s = hostile_summary();
  for (const PlotLayout& L : plot_layouts(s)) {
    EXPECT_EQ(joined(test::readability_problems(L)), "") << L.png_name;
    for (const PlotText& t : L.texts) EXPECT_EQ(t.text.find("/very/long"), std::string::npos) << t.text;
    if (!L.panels.front().slots.empty()) {
      std::set<std::string> labels;
      for (const PlotTick& t : L.panels.front().x.ticks) labels.insert(t.label);
      EXPECT_EQ(labels.size(), L.panels.front().slots.size()) << L.png_name << ": two slots read the same";
    }
  }
}

// The plots of a run on shared real clips, given by absolute paths: the CMU clips
// (max near 180°), the Bandai walk and dance (22 joints).
TEST(PlotLayout, PlotsOfSharedRealClipsAreReadable) {
  const std::filesystem::path data = std::filesystem::absolute(ROTINTERP_SHARED_DATA);
  EvalOptions o;
  for (const char* clip : {"bvh/cmu_01_01.bvh", "bvh/NC_bandai1_walk_normal_001.bvh", "bvh/NC_bandai2_raise-up-both-hands_active_031.bvh"})
    o.inputs.push_back(data / clip);
  o.output_dir = test::fresh_dir("plot_layout_real");
  o.clip.keep_every = {4, 16};
  for (const MethodInfo& m : methods()) o.clip.methods.push_back(m.name);
  o.jobs = 2;
  o.plots = false;
  auto report = run_eval(o);
  ASSERT_TRUE(report.ok()) << report.error();
  const std::vector<PlotLayout> layouts = plot_layouts(report.value().summary);
  ASSERT_EQ(layouts.size(), 3u);
  for (const PlotLayout& L : layouts) {
    EXPECT_EQ(joined(test::readability_problems(L)), "") << L.png_name;
    for (const PlotText& t : L.texts) EXPECT_EQ(t.text.find(data.string()), std::string::npos) << t.text;
  }
  // The max panel near 180° reads on at least three ticks (one, "100", before).
  EXPECT_GE(layouts[0].panels[2].y.ticks.size(), 3u);
}

}  // namespace
}  // namespace rotinterp
