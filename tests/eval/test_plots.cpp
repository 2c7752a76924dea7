// The plots are written as real PNG files, atomically.
#include "rotinterp/eval/plot_layout.h"
#include "rotinterp/eval/plots.h"
#include "rotinterp/interp/interpolator.h"
#include "rotinterp/palette/method_style.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>

namespace rotinterp {
namespace {

namespace fs = std::filesystem;

Summary hand_summary() {
  Summary s;
  s.clips = 3;
  const char* methods[] = {"slerp", "squad", "bspline"};
  for (int m = 0; m < 3; ++m)
    for (int keep : {2, 4, 8, 16}) {
      SummaryEntry e;
      e.method = methods[m];
      e.keep_every = keep;
      e.rms_deg = 0.01 * keep * keep / (m + 1);
      e.max_deg = 10 * e.rms_deg;
      s.entries.push_back(e);
    }
  for (const char* clip : {"data/a.bvh", "data/still.fbx"})
    for (int m = 0; m < 3; ++m) {
      ClipResult c;
      c.clip = clip;
      c.method = methods[m];
      c.keep_every = 16;
      c.rms_deg = clip[5] == 'a' ? 2.0 : 0.0;  // equal for every method; the still clip all zero
      s.clip_results.push_back(c);
    }
  s.worst_clip = "data/bvh/some_clip.bvh";
  s.worst_keep_every = 16;
  for (int m = 0; m < 3; ++m)
    for (int j = 0; j < 31; ++j) {
      ErrorRow r;
      r.clip = s.worst_clip;
      r.method = methods[m];
      r.keep_every = 16;
      r.joint = "Joint" + std::to_string(j);
      r.rms_deg = (1 + j % 7) * (m + 1) * 0.3;
      s.worst_clip_rows.push_back(r);
    }
  return s;
}

bool is_png(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  char sig[8] = {};
  in.read(sig, 8);
  return in && sig[1] == 'P' && sig[2] == 'N' && sig[3] == 'G';
}

bool is_svg(const fs::path& p) {
  std::ifstream in(p);
  std::string head(256, '\0');
  in.read(head.data(), 256);
  return head.find("<svg") != std::string::npos;
}

TEST(Plots, WritesEveryPlotAsPngAndSvgAndNoTemporaries) {
  const fs::path dir = fs::path(testing::TempDir()) / "rotinterp_plots_test";
  fs::remove_all(dir);
  fs::create_directories(dir);
  ASSERT_TRUE(write_plots(hand_summary(), dir).ok());
  EXPECT_TRUE(is_png(dir / kSpacingPlotName));
  EXPECT_TRUE(is_png(dir / kWorstClipPlotName));
  EXPECT_TRUE(is_png(dir / kClipsPlotName));
  EXPECT_GT(fs::file_size(dir / kSpacingPlotName), 10000u);  // axes, labels and lines, not a blank page
  for (const char* svg : {"error_vs_spacing.svg", "worst_clip_joints.svg", "clip_errors.svg"}) EXPECT_TRUE(is_svg(dir / svg)) << svg;
  std::size_t files = 0;
  for (const auto& e : fs::directory_iterator(dir)) files += e.is_regular_file();
  EXPECT_EQ(files, 6u);
  EXPECT_EQ(plot_file_names().size(), 6u);
  if (const char* keep = std::getenv("ROTINTERP_KEEP_PLOTS")) fs::copy(dir, keep, fs::copy_options::overwrite_existing | fs::copy_options::recursive);
}

TEST(Plots, EveryRegisteredMethodHasAColourOfItsOwn) {
  // Nine methods since gltf-cubic: a palette of eight drew the ninth in the first's colour.
  Summary s;
  s.clips = 1;
  for (std::size_t m = 0; m < methods().size(); ++m)
    for (int keep : {2, 4, 8, 16}) {
      SummaryEntry e;
      e.method = methods()[m].name;
      e.keep_every = keep;
      e.rms_deg = 0.01 * keep * keep * static_cast<double>(m + 1);
      e.max_deg = 10 * e.rms_deg;
      s.entries.push_back(e);
    }
  const fs::path dir = fs::path(testing::TempDir()) / "rotinterp_plots_colours";
  fs::remove_all(dir);
  fs::create_directories(dir);
  ASSERT_TRUE(write_plots(s, dir).ok());
  std::ifstream in(dir / "error_vs_spacing.svg");
  std::stringstream text;
  text << in.rdbuf();
  const std::string svg = text.str();
  std::set<std::string> colours;  // every "rgb(…)" cairo writes
  for (std::size_t at = svg.find("rgb("); at != std::string::npos; at = svg.find("rgb(", at + 1))
    colours.insert(svg.substr(at, svg.find(')', at) - at));
  // The methods' colours (black among them), plus the white page and the grey grid.
  EXPECT_GE(colours.size(), methods().size() + 2);
}


// Issue 29: the plots coloured methods by order of appearance and render by registry
// place, so one method had two colours in one report. Both now take the method's slot.
TEST(Plots, AMethodHasItsRegistryColourWhateverElseIsPlotted) {
  auto svg_of = [](const std::vector<std::string>& names, const char* dir_name) {
    Summary s;
    s.clips = 1;
    for (const std::string& name : names)
      for (int keep : {2, 4}) {
        SummaryEntry e;
        e.method = name;
        e.keep_every = keep;
        e.rms_deg = e.max_deg = e.clip_rms_median_deg = 0.1 * keep;
        s.entries.push_back(e);
      }
    const fs::path dir = fs::path(testing::TempDir()) / dir_name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    EXPECT_TRUE(write_plots(s, dir).ok());
    std::ifstream in(dir / "error_vs_spacing.svg");
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  };
  auto cairo_rgb = [](const std::string& method) {  // cairo writes rgb(90.196078%,62.352941%,0%)
    std::string out = "rgb(";
    for (std::uint8_t c : method_style(method_slot(method)).rgb) {
      char v[32];
      std::snprintf(v, sizeof v, "%f", c / 255.0 * 100.0);
      std::string t = v;
      t.erase(t.find_last_not_of('0') + 1);
      if (t.back() == '.') t.pop_back();
      out += t + "%,";
    }
    out.back() = ')';
    return out;
  };
  const std::string alone = svg_of({"bf"}, "rotinterp_plots_bf_alone");
  const std::string reordered = svg_of({"c2", "BF", "slerp"}, "rotinterp_plots_bf_third");
  ASSERT_NE(method_slot("bf"), method_slot("slerp"));
  for (const std::string* svg : {&alone, &reordered}) {
    EXPECT_NE(svg->find(cairo_rgb("bf")), std::string::npos) << cairo_rgb("bf");
  }
  EXPECT_EQ(alone.find(cairo_rgb("slerp")), std::string::npos);  // the first slot's colour is slerp's
}

}  // namespace
}  // namespace rotinterp

namespace rotinterp {
namespace {

// Issue 28: error_vs_spacing's RMS panel ran to ~30 000° to make room for its legend,
// and clip_errors' axis to 10^1.2 times its largest value. Every angle axis covers its
// values and stops at 180° (plus the pad that keeps a marker there inside the frame).
TEST(Plots, EveryAngleAxisCoversItsValuesAndStopsAt180Degrees) {
  for (double scale : {1.0, 50.0, 800.0}) {  // largest values 2.56°·scale, capped at 179°
    Summary s = hand_summary();
    auto grow = [scale](double& v) { v = std::min(v * scale, 179.0); };
    for (SummaryEntry& e : s.entries) grow(e.rms_deg), grow(e.max_deg), grow(e.clip_rms_median_deg);
    for (ClipResult& c : s.clip_results) grow(c.rms_deg);
    for (ErrorRow& r : s.worst_clip_rows) grow(r.rms_deg);
    std::vector<double> largest = {0, 0, 0, 0, 0};
    for (const SummaryEntry& e : s.entries)
      largest[0] = std::max(largest[0], e.rms_deg), largest[1] = std::max(largest[1], e.clip_rms_median_deg),
      largest[2] = std::max(largest[2], e.max_deg);
    for (const ErrorRow& r : s.worst_clip_rows) largest[3] = std::max(largest[3], r.rms_deg);
    for (const ClipResult& c : s.clip_results) largest[4] = std::max(largest[4], c.rms_deg);
    std::vector<PlotAxis> axes;
    for (const PlotLayout& L : plot_layouts(s))
      for (const PlotPanel& p : L.panels) axes.push_back(p.y);
    ASSERT_EQ(axes.size(), 5u);
    for (std::size_t i = 0; i < axes.size(); ++i) {
      SCOPED_TRACE("axis " + std::to_string(i) + ", scale " + std::to_string(scale));
      const PlotAxis& a = axes[i];
      const double hi_deg = a.log ? std::pow(10.0, a.hi) : a.hi;
      const double pad_deg = a.log ? std::pow(10.0, kAxisPad * (a.hi - a.lo)) : 1.0 + kAxisPad * (a.hi - a.lo) / kMaxDeg;
      EXPECT_LE(hi_deg, 180.0 * pad_deg + 1e-9);
      EXPECT_GE(hi_deg, largest[i] - 1e-9);
      EXPECT_LT(a.lo, a.hi);
    }
  }
}

}  // namespace
}  // namespace rotinterp
