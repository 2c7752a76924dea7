// The plots are written as real PNG files, atomically.
#include "rotinterp/eval/plots.h"
#include "rotinterp/interp/interpolator.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace rotinterp
