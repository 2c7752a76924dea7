// Pictures that show the difference (issue 45): the default camera frames the body,
// not a ground marker at the root, at least half the view high in every frame — seen
// through the renderer's own projection and in its pixels; one colour scale for a
// whole run; the strip's axes.
#include "png_pixels.h"
#include "synthetic_clip.h"

#include "rotinterp/io/read.h"
#include "rotinterp/render/comparison.h"
#include "rotinterp/render/context.h"
#include "rotinterp/render/layout.h"
#include "rotinterp/render/renderer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace rotinterp::render {
namespace {

namespace fs = std::filesystem;

const fs::path kBandaiWalk = fs::path(ROTINTERP_SHARED_DATA) / "bvh/NC_bandai1_walk_normal_001.bvh";

// A figure whose root is a marker left at the origin while its hips walk 10 m along
// +Z over 4 s (centimetres), its legs swinging: the Bandai Namco captures' layout.
Clip marker_walk() {
  std::ostringstream bvh;
  bvh << "HIERARCHY\nROOT marker\n{\n  OFFSET 0 0 0\n  CHANNELS 3 Zrotation Xrotation Yrotation\n"
         "  JOINT Hips\n  {\n    OFFSET 0 90 0\n    CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"
         "    JOINT Chest\n    {\n      OFFSET 0 30 0\n      CHANNELS 3 Zrotation Xrotation Yrotation\n"
         "      JOINT Head\n      {\n        OFFSET 0 40 0\n        CHANNELS 3 Zrotation Xrotation Yrotation\n"
         "        End Site\n        {\n          OFFSET 0 20 0\n        }\n      }\n"
         "      JOINT LeftArm\n      {\n        OFFSET 20 35 0\n        CHANNELS 3 Zrotation Xrotation Yrotation\n"
         "        End Site\n        {\n          OFFSET 0 -55 0\n        }\n      }\n"
         "      JOINT RightArm\n      {\n        OFFSET -20 35 0\n        CHANNELS 3 Zrotation Xrotation Yrotation\n"
         "        End Site\n        {\n          OFFSET 0 -55 0\n        }\n      }\n    }\n";
  for (const char* side : {"Left", "Right"})
    bvh << "    JOINT " << side << "Leg\n    {\n      OFFSET " << (side[0] == 'L' ? 10 : -10)
        << " 0 0\n      CHANNELS 3 Zrotation Xrotation Yrotation\n      JOINT " << side
        << "Shin\n      {\n        OFFSET 0 -45 0\n        CHANNELS 3 Zrotation Xrotation Yrotation\n"
           "        End Site\n        {\n          OFFSET 0 -45 0\n        }\n      }\n    }\n";
  bvh << "  }\n}\nMOTION\nFrames: 121\nFrame Time: 0.0333333\n";
  for (int f = 0; f <= 120; ++f) {
    const double swing = 30.0 * std::sin(f * 0.2);
    bvh << "0 0 0  0 90 " << 1000.0 * f / 120.0 << " 0 0 0  0 0 0  0 0 0  0 " << swing << " 0  0 " << -swing
        << " 0  0 " << -swing << " 0  0 " << std::abs(swing) << " 0  0 " << swing << " 0  0 " << std::abs(swing)
        << " 0\n";
  }
  const fs::path path = test::fresh_dir("marker_walk") / "walk.bvh";
  fs::create_directories(path.parent_path());
  std::ofstream(path) << bvh.str();
  auto clip = read_clip(path);
  EXPECT_TRUE(clip.ok()) << clip.error();
  return clip.ok() ? *clip : Clip{};
}

Clip bandai_walk() {
  auto clip = read_clip(kBandaiWalk);
  EXPECT_TRUE(clip.ok()) << clip.error();
  return clip.ok() ? *clip : Clip{};
}

ComparisonOptions every_frame(const Clip& clip) {
  ComparisonOptions o;  // the defaults a user meets: the overlay, the automatic camera
  o.methods = {"slerp", "squad", "c2"};
  o.keep_every = 8;
  o.frames = FrameRange{0, frame_grid(clip).size() - 1, 1};
  return o;
}

// A frame's joints (not the ground marker) and End Sites, projected by the camera
// the renderer draws the frame's panel with: pixels in the panel, y down.
std::vector<Eigen::Vector2d> projected_body(const ComparisonPlan& plan, const Panel& panel, const WorldPose& pose,
                                            int width, int height, Rect* viewport = nullptr) {
  const PanelCamera pc = panel_camera(plan.scene(), panel, width, height);
  if (viewport) *viewport = pc.viewport;
  const Eigen::Matrix4d m = pc.camera.projection() * pc.camera.view();
  std::vector<Eigen::Vector2d> out;
  auto add = [&](const Vec3& p) {
    const Eigen::Vector4d c = m * p.homogeneous();
    out.emplace_back(pc.viewport.x + (c.x() / c.w() + 1.0) * 0.5 * pc.viewport.width,
                     pc.viewport.y + (1.0 - c.y() / c.w()) * 0.5 * pc.viewport.height);
  };
  const std::vector<bool>& thin = plan.scene().thin;
  for (std::size_t j = 0; j < pose.position.size(); ++j)
    if (thin.size() != pose.position.size() || !thin[j]) add(pose.position[j]);
  for (std::size_t e = 0; e < pose.end_site_position.size(); ++e) add(pose.end_site_position[e]);
  return out;
}

// In every frame of the default render, the body is at least half the view high.
void expect_body_fills_half_the_view(const Clip& clip, const char* name) {
  auto plan = ComparisonPlan::make(clip, every_frame(clip));
  ASSERT_TRUE(plan.ok()) << plan.error();
  const Rect panel = grid_layout(1, plan->columns(), 960, 540).front();
  double smallest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < plan->frames().size(); ++i) {
    const ComparisonPlan::Frame frame = plan->frame(i);
    ASSERT_EQ(frame.panels.size(), 1u);
    Rect view;
    const auto body = projected_body(*plan, frame.panels[0], frame.panels[0].ghost, panel.width, panel.height, &view);
    double top = 1e9, bottom = -1e9;
    for (const auto& p : body) {
      top = std::min(top, p.y());
      bottom = std::max(bottom, p.y());
      EXPECT_GE(p.x(), view.x - 1.0) << name << " frame " << i;  // and inside the view
      EXPECT_LE(p.x(), view.x + view.width + 1.0) << name << " frame " << i;
    }
    smallest = std::min(smallest, (bottom - top) / view.height);
  }
  EXPECT_GE(smallest, 0.5) << name << ": the body's height over the view's in its smallest frame";
  std::printf("%s: the body spans at least %.2f of the view's height\n", name, smallest);
}

TEST(BodyFraming, TheBandaiWalkFillsAtLeastHalfTheViewInEveryFrame) {
  expect_body_fills_half_the_view(bandai_walk(), "Bandai walk");
}

TEST(BodyFraming, ABodyWalkingTenMetresFromAMarkerAtTheOriginFillsHalfTheView) {
  const Clip clip = marker_walk();
  expect_body_fills_half_the_view(clip, "marker walk");
  auto plan = ComparisonPlan::make(clip, every_frame(clip));
  ASSERT_TRUE(plan.ok()) << plan.error();
  EXPECT_TRUE(plan->followed());
  // The marker's bone is drawn thin; no other.
  const std::vector<bool>& thin = plan->scene().thin;
  ASSERT_EQ(thin.size(), clip.skeleton.joints.size());
  for (std::size_t j = 0; j < thin.size(); ++j) EXPECT_EQ(thin[j], j == 0) << clip.skeleton.joints[j].name;
}

TEST(BodyFraming, AFigureWhoseRootIsItsPelvisHasNoMarker) {
  const Clip clip = test::synthetic_clip();
  auto plan = ComparisonPlan::make(clip, every_frame(clip));
  ASSERT_TRUE(plan.ok()) << plan.error();
  for (bool t : plan->scene().thin) EXPECT_FALSE(t);
}

// The pixels agree with the projection: at every projected joint of a method's
// pose, the image differs from the same panel drawn with no figure.
TEST(BodyFraming, TheRenderedBonesLieAtTheProjectedJoints) {
  const Clip clip = bandai_walk();
  ComparisonOptions o = every_frame(clip);
  o.frames = FrameRange{20, 180, 80};
  o.methods = {"slerp"};
  auto plan = ComparisonPlan::make(clip, o);
  ASSERT_TRUE(plan.ok()) << plan.error();
  auto context = create_context(default_backend());
  ASSERT_TRUE(context.ok()) << context.error();
  auto renderer = Renderer::create(std::move(context).value(), plan->scene());
  ASSERT_TRUE(renderer.ok()) << renderer.error();
  for (std::size_t i = 0; i < plan->frames().size(); ++i) {
    const ComparisonPlan::Frame frame = plan->frame(i);
    auto image = (*renderer)->render(frame.panels, 960, 540, plan->columns());
    ASSERT_TRUE(image.ok()) << image.error();
    const Panel& panel = frame.panels[0];
    ASSERT_EQ(panel.figures.size(), 1u);
    Panel empty = panel;
    empty.figures.clear();
    empty.ghost = WorldPose{};
    empty.label_joint = -1;
    auto bare = (*renderer)->render({empty}, 960, 540, plan->columns());
    ASSERT_TRUE(bare.ok()) << bare.error();
    const auto joints = projected_body(*plan, panel, panel.figures[0].pose, 960, 540);
    int on_bone = 0;
    for (const auto& p : joints) {
      const int x = static_cast<int>(p.x()), y = static_cast<int>(p.y());
      ASSERT_TRUE(x >= 0 && y >= 0 && x < 960 && y < 540) << p.transpose();
      const std::uint8_t *a = image->pixel(x, y), *b = bare->pixel(x, y);
      on_bone += std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]) > 60;
    }
    EXPECT_GE(on_bone, static_cast<int>(joints.size() * 9 / 10)) << "frame " << plan->frames()[i];
  }
}

// Every frame of a video is coloured on one scale: the run's, robust to outliers.
TEST(ColourScale, OneScaleHoldsAcrossEveryFrameOfAVideo) {
  const Clip clip = bandai_walk();
  ComparisonOptions o;
  o.methods = {"slerp", "c2"};
  o.view = View::side;
  o.keep_every = 8;
  o.video = test::fresh_dir("video_scale") / "walk.mp4";
  auto plan = ComparisonPlan::make(clip, o);
  ASSERT_TRUE(plan.ok()) << plan.error();
  ASSERT_EQ(plan->frames().size(), frame_grid(clip).size());
  double scale = -1.0, largest = 0.0;
  for (std::size_t i = 0; i < plan->frames().size(); ++i)
    for (const Panel& p : plan->frame(i).panels) {
      if (scale < 0.0) scale = p.colour_scale_deg;
      EXPECT_EQ(p.colour_scale_deg, scale) << "frame " << i;
      const std::string& title = p.title;
      const double max = std::stod(title.substr(title.find("max ") + 4));
      largest = std::max(largest, max);
    }
  EXPECT_GT(scale, 0.0);
  EXPECT_LE(scale, 180.0);
  EXPECT_LE(scale, largest * 2.5) << "a 1-2-5 step at or above a high percentile, not far above the largest";
}

TEST(ErrorStripAxes, TicksAreAtLeastThreeRoundNumbersInsideTheRange) {
  for (const auto& [lo, hi] : std::vector<std::pair<double, double>>{
           {0, 1}, {0, 50}, {0, 180}, {1.333, 5.333}, {0, 0.2}, {0, 97.5}, {0.4, 0.6}, {12, 4000}}) {
    const std::vector<double> ticks = axis_ticks(lo, hi);
    EXPECT_GE(ticks.size(), 3u) << lo << "…" << hi;
    for (double t : ticks) {
      EXPECT_GE(t, lo - 1e-9) << lo << "…" << hi;
      EXPECT_LE(t, hi + 1e-9) << lo << "…" << hi;
    }
  }
  EXPECT_EQ(axis_ticks(3.0, 3.0), std::vector<double>{3.0});
}

TEST(ErrorStripAxes, TheOverlaysStripHasALinePerMethodOnTheClipsTimeAxis) {
  const Clip clip = bandai_walk();
  ComparisonOptions o = every_frame(clip);
  o.frames = FrameRange{40, 160, 60};
  auto plan = ComparisonPlan::make(clip, o);
  ASSERT_TRUE(plan.ok()) << plan.error();
  const ComparisonPlan::Frame frame = plan->frame(1);
  ASSERT_TRUE(frame.panels[0].strip);
  const ErrorStrip& strip = *frame.panels[0].strip;
  EXPECT_EQ(strip.lines.size(), 3u);
  EXPECT_NE(strip.quantity.find("max over joints"), std::string::npos);
  EXPECT_NEAR(strip.start_s, 40 * 0.0333333, 1e-9);  // the file's frame time
  EXPECT_NEAR(strip.end_s, 160 * 0.0333333, 1e-9);
  EXPECT_EQ(strip.cursor, 60u);
}

}  // namespace
}  // namespace rotinterp::render
