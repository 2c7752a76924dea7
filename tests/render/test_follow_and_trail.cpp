// Where the eye is led: a camera that follows a travelling figure, the hinge
// trail seen face on, the trail's window of time, and time on every frame.
#include "one_bone_scene.h"
#include "png_pixels.h"
#include "support/run_cli.h"
#include "synthetic_clip.h"

#include "rotinterp/render/comparison.h"
#include "rotinterp/render/context.h"
#include "rotinterp/render/layout.h"
#include "rotinterp/render/renderer.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <vector>

namespace rotinterp::render {
namespace {

namespace fs = std::filesystem;
using test::fresh_dir;

// ---- the follow camera -----------------------------------------------------------

// One method's panels at `width` × `height`, coloured by method (the figure's
// pixels are the saturated ones: squad's vermillion stays saturated in shade, where a
// light blue's shaded side would not count), no strip.
ComparisonOptions one_method(FrameRange frames, int width, int height) {
  ComparisonOptions o;
  o.methods = {"squad"};
  o.view = View::side;
  o.frames = frames;
  o.width = width;
  o.height = height;
  o.colouring = Colouring::method;
  o.strip = false;
  return o;
}

// The centre x of the saturated (method-coloured) pixels of the first panel, as
// a fraction of its width; -1 when there are none.
double figure_centre(const fs::path& png, const Rect& panel) {
  const test::Pixels p = test::read_png(png);
  if (!p.ok()) return -1;
  double sum = 0;
  int count = 0;
  const PanelLayout layout = panel_layout(panel.width, panel.height, false);
  for (int y = panel.y + layout.figure.y; y < panel.y + layout.figure.y + layout.figure.height; ++y)
    for (int x = panel.x; x < panel.x + panel.width; ++x) {
      const std::uint8_t* px = p.rgb.data() + (static_cast<std::size_t>(y) * p.width + x) * 3;
      if (std::max({px[0], px[1], px[2]}) - std::min({px[0], px[1], px[2]}) > 60) {
        sum += x - panel.x;
        ++count;
      }
    }
  return count ? sum / count / panel.width : -1;
}

TEST(FollowCamera, KeepsTheRootInTheMiddleThirdOfATravellingClip) {
  const Clip clip = test::synthetic_clip(61, 30.0, 1.5);  // 3 units in 2 s; the figure is 1.9 high
  ComparisonOptions o = one_method(FrameRange{0, 60, 30}, 240, 160);
  const Rect panel{0, 0, 240, 160};
  std::map<CameraMode, std::vector<double>> centres;
  for (CameraMode mode : {CameraMode::automatic, CameraMode::fixed}) {
    o.camera = mode;
    const fs::path dir = fresh_dir("follow");
    auto result = render_comparison(clip, dir, o);
    ASSERT_TRUE(result.ok()) << result.error();
    EXPECT_EQ(result->followed, mode == CameraMode::automatic) << "the root travels farther than the figure is high";
    for (const fs::path& f : result->files) centres[mode].push_back(figure_centre(f, panel));
    fs::remove_all(dir);
  }
  for (double c : centres[CameraMode::automatic]) {
    EXPECT_GT(c, 1.0 / 3) << "following";
    EXPECT_LT(c, 2.0 / 3) << "following";
  }
  // A fixed camera sees the figure walk from one side to the other (so the test can fail).
  EXPECT_LT(centres[CameraMode::fixed].front(), 1.0 / 3);
  EXPECT_GT(centres[CameraMode::fixed].back(), 2.0 / 3);
}

TEST(FollowCamera, IsNotTheDefaultForAClipThatStaysInPlaceAndFocusZoomsOnTheLimb) {
  const Clip clip = test::synthetic_clip();
  ComparisonOptions o = one_method(FrameRange{15, 15, 1}, 240, 160);
  const fs::path dir = fresh_dir("focus");
  auto whole = render_comparison(clip, dir / "whole", o);
  ASSERT_TRUE(whole.ok()) << whole.error();
  EXPECT_FALSE(whole->followed);
  o.focus_joint = "LeftElbow";
  auto focused = render_comparison(clip, dir / "focus", o);
  ASSERT_TRUE(focused.ok()) << focused.error();
  EXPECT_TRUE(focused->followed) << "a focus joint is followed";
  // Zoomed on the forearm, the solid figure covers more of the panel.
  auto coloured = [](const fs::path& f) {
    const test::Pixels p = test::read_png(f);
    std::size_t n = 0;
    for (std::size_t i = 0; i + 2 < p.rgb.size(); i += 3)
      n += std::max({p.rgb[i], p.rgb[i + 1], p.rgb[i + 2]}) - std::min({p.rgb[i], p.rgb[i + 1], p.rgb[i + 2]}) > 60;
    return n;
  };
  EXPECT_GT(coloured(focused->files[0]), 2 * coloured(whole->files[0]));
  o.focus_joint = "Nope";
  auto bad = render_comparison(clip, dir / "bad", o);
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.error(), "--focus: no joint 'Nope' in the clip");
  fs::remove_all(dir);
}

// ---- the trail ----------------------------------------------------------------

TEST(TrailInset, AHingesArcIsSeenFaceOnNotEdgeOn) {
  // An elbow: the forearm turns 240° about the hinge axis, perpendicular to it
  // (a great-circle arc, which the reference's mean direction sees as a line).
  const Vec3 axis = Vec3(0.3, 1.0, 0.2).normalized();
  const Vec3 bone = axis.cross(Vec3::UnitX()).normalized();
  auto trail = std::make_shared<Trail>();
  for (int i = 0; i <= 80; ++i) {
    const Vec3 d = Eigen::AngleAxisd(4.0 * kPi / 3 * i / 80 - 2.0 * kPi / 3, axis) * bone;
    trail->reference.push_back(d);
    trail->method.push_back(d);
  }
  trail->current = 40;
  Scene scene = test::one_bone_scene();
  auto context = create_context(default_backend());
  ASSERT_TRUE(context.ok()) << context.error();
  auto renderer = Renderer::create(std::move(context).value(), scene);
  ASSERT_TRUE(renderer.ok()) << renderer.error();
  Panel p;
  p.colour = {1.0f, 0.0f, 0.0f};
  p.trail = trail;
  auto image = (*renderer)->render({p}, 320, 200);
  ASSERT_TRUE(image.ok()) << image.error();
  const Rect inset = panel_layout(320, 200, true).inset;
  // The method's red tube in the inset: its extent along its principal axes.
  std::vector<Eigen::Vector2d> red;
  for (int y = inset.y; y < inset.y + inset.height; ++y)
    for (int x = inset.x; x < inset.x + inset.width; ++x) {
      const std::uint8_t* px = image->pixel(x, y);
      if (px[0] > 110 && px[1] < 70 && px[2] < 70) red.emplace_back(x, y);
    }
  ASSERT_GT(red.size(), 100u);
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const auto& q : red) mean += q;
  mean /= static_cast<double>(red.size());
  Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
  for (const auto& q : red) cov += (q - mean) * (q - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(cov);
  double extent[2] = {0, 0};
  for (int a = 0; a < 2; ++a) {
    double lo = 1e9, hi = -1e9;
    for (const auto& q : red) {
      const double t = (q - mean).dot(eigen.eigenvectors().col(a));
      lo = std::min(lo, t);
      hi = std::max(hi, t);
    }
    extent[a] = hi - lo;
  }
  EXPECT_GE(extent[0], 0.5 * extent[1]) << "width " << extent[0] << " px, height " << extent[1] << " px";
}

TEST(TrailInset, ShowsAWindowOfTimeThatFades) {
  const Clip clip = test::synthetic_clip();
  ComparisonOptions o = one_method(FrameRange{30, 30, 1}, 320, 200);
  o.trail_joint = "LeftShoulder";
  const fs::path dir = fresh_dir("window");
  std::vector<std::vector<std::uint8_t>> insets;
  for (double window : {0.0, 0.3}) {
    o.trail_window = window;
    auto result = render_comparison(clip, dir / std::to_string(window), o);
    ASSERT_TRUE(result.ok()) << result.error();
    const test::Pixels p = test::read_png(result->files[0]);
    insets.push_back(test::crop(p, panel_layout(320, 200, true).inset));
  }
  // 0 draws the whole 2 s clip (one frame drawn); 0.3 s draws frames 21…39 only.
  EXPECT_GT(test::differing_pixels(insets[0], insets[1]), 300u);
  o.trail_window = -1;
  EXPECT_FALSE(render_comparison(clip, dir / "bad", o).ok());
  fs::remove_all(dir);
}

// ---- time on every frame ------------------------------------------------------------

TEST(FrameText, EveryFrameShowsItsNumberAndTimeInACorner) {
  const Clip clip = test::synthetic_clip();
  const ComparisonOptions o = one_method(FrameRange{14, 16, 2}, 320, 200);
  const fs::path dir = fresh_dir("time");
  auto result = render_comparison(clip, dir, o);
  ASSERT_TRUE(result.ok()) << result.error();
  const PanelLayout layout = panel_layout(320, 200, false);
  const Rect corner{0, layout.figure.y, 120, 16};
  const auto a = test::crop(test::read_png(result->files[0]), corner);
  const auto b = test::crop(test::read_png(result->files[1]), corner);
  std::size_t light = 0;
  for (std::size_t i = 0; i + 2 < a.size(); i += 3) light += a[i] > 140 && a[i + 1] > 140 && a[i + 2] > 140;
  EXPECT_GT(light, 20u) << "text in the corner";
  EXPECT_GT(test::differing_pixels(a, b), 10u) << "frame 14 at 0.467 s and frame 16 at 0.533 s read differently";
  fs::remove_all(dir);
}
}  // namespace
}  // namespace rotinterp::render
