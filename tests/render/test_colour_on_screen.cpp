// Errors made visible: the colour map, bones in the colour of their error, the
// worst joint's label and the error strip's cursor.
#include "one_bone_scene.h"
#include "png_pixels.h"

#include "rotinterp/render/colour_map.h"
#include "rotinterp/render/context.h"
#include "rotinterp/render/layout.h"
#include "rotinterp/render/renderer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

namespace rotinterp::render {
namespace {

std::array<int, 3> to_bytes(const Colour& c) {
  return {static_cast<int>(std::lround(c[0] * 255)), static_cast<int>(std::lround(c[1] * 255)),
          static_cast<int>(std::lround(c[2] * 255))};
}

int channel_distance(const std::uint8_t* px, const std::array<int, 3>& c) {
  return std::max({std::abs(px[0] - c[0]), std::abs(px[1] - c[1]), std::abs(px[2] - c[2])});
}

// ---- the colour map -----------------------------------------------------------

TEST(ColourMap, ViridisPassesThroughItsPublishedEntriesAndGetsLighterThroughout) {
  // matplotlib _viridis_data entries 0, 128 and 255.
  EXPECT_EQ(to_bytes(viridis(0.0)), to_bytes({0.267004f, 0.004874f, 0.329415f}));
  EXPECT_EQ(to_bytes(viridis(128.0 / 255.0)), to_bytes({0.127568f, 0.566949f, 0.550556f}));
  EXPECT_EQ(to_bytes(viridis(1.0)), to_bytes({0.993248f, 0.906157f, 0.143936f}));
  // Between control points: entry 100 (0.166617, 0.463708, 0.558119) within 1.7/255.
  const Colour mid = viridis(100.0 / 255.0);
  EXPECT_NEAR(mid[0], 0.166617, 1.7 / 255);
  EXPECT_NEAR(mid[1], 0.463708, 1.7 / 255);
  EXPECT_NEAR(mid[2], 0.558119, 1.7 / 255);
  EXPECT_EQ(to_bytes(viridis(-1.0)), to_bytes(viridis(0.0)));
  EXPECT_EQ(to_bytes(viridis(std::nan(""))), to_bytes(viridis(0.0)));
  EXPECT_EQ(to_bytes(viridis(7.0)), to_bytes(viridis(1.0)));
  double previous = -1.0;
  for (int i = 0; i <= 100; ++i) {
    const Colour c = viridis(i / 100.0);
    const double luma = 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
    EXPECT_GT(luma, previous) << i;
    previous = luma;
  }
}

TEST(ColourMap, ErrorScaleIsTheNext125StepFromOneDegreeTo180) {
  EXPECT_EQ(error_scale(0.0), 1.0);
  EXPECT_EQ(error_scale(0.3), 1.0);
  EXPECT_EQ(error_scale(1.0), 1.0);
  EXPECT_EQ(error_scale(1.01), 2.0);
  EXPECT_EQ(error_scale(4.2), 5.0);
  EXPECT_EQ(error_scale(5.0), 5.0);
  EXPECT_EQ(error_scale(14.54), 20.0);
  EXPECT_EQ(error_scale(101.0), 180.0);  // angles stop at 180°: no bar or strip runs to 200°
  EXPECT_EQ(error_scale(170.0), 180.0);
  EXPECT_EQ(error_scale(180.0), 180.0);
  EXPECT_EQ(error_scale(1e6), 180.0);
  EXPECT_EQ(error_scale(std::nan("")), 1.0);
  EXPECT_EQ(to_bytes(error_colour(5.0, 20.0)), to_bytes(viridis(0.25)));
  EXPECT_EQ(to_bytes(error_colour(30.0, 20.0)), to_bytes(viridis(1.0)));
}

// ---- error colours on screen -----------------------------------------------------


TEST(ErrorColours, ABoneWhoseErrorIsKnownGetsTheColourMapsColour) {
  auto context = create_context(default_backend());
  ASSERT_TRUE(context.ok()) << context.error();
  auto renderer = Renderer::create(std::move(context).value(), test::one_bone_scene());
  ASSERT_TRUE(renderer.ok()) << renderer.error();
  const double scale = 20.0;
  const std::vector<double> errors = {0.0, 5.0, 10.0, 15.0, 20.0};
  for (double error : errors) {
    Panel p;
    p.pose.position = {Vec3(0, 0, 0), Vec3(1, 0, 0)};
    // The root's rotation turns the bone: its error colours it.
    p.joint_colours = {error_colour(error, scale), error_colour(0.0, scale)};
    auto image = (*renderer)->render({p}, 160, 120);
    ASSERT_TRUE(image.ok()) << image.error();
    const PanelLayout layout = panel_layout(160, 120, false);
    // The bone's pixels: the middle rows of the figure, away from the joints.
    const std::array<int, 3> expected = to_bytes(viridis(error / scale));
    int nearest = 255;
    std::array<double, 3> sum = {0, 0, 0};
    int count = 0;
    for (int y = layout.figure.y; y < layout.figure.y + layout.figure.height; ++y)
      for (int x = 60; x < 100; ++x) {
        const std::uint8_t* px = image->pixel(x, y);
        if (channel_distance(px, {40, 42, 47}) < 25) continue;  // background
        nearest = std::min(nearest, channel_distance(px, expected));
        for (int c = 0; c < 3; ++c) sum[c] += px[c];
        ++count;
      }
    ASSERT_GT(count, 50) << error << "°: the bone is drawn";
    EXPECT_LE(nearest, 6) << error << "°: some pixel of the bone shows the map's colour";
    // The bone's mean colour is nearer its own error's colour than any other's.
    auto mean_distance = [&](double e) {
      const auto c = to_bytes(viridis(e / scale));
      double d = 0;
      for (int k = 0; k < 3; ++k) d += std::pow(sum[k] / count - c[k], 2);
      return d;
    };
    for (double other : errors)
      if (other != error) {
        EXPECT_LT(mean_distance(error), mean_distance(other)) << error << "° vs " << other << "°";
      }
  }
}

TEST(ErrorColours, TheWorstJointIsLabelledNextToIt) {
  auto context = create_context(default_backend());
  ASSERT_TRUE(context.ok()) << context.error();
  auto renderer = Renderer::create(std::move(context).value(), test::one_bone_scene());
  ASSERT_TRUE(renderer.ok()) << renderer.error();
  Panel p;
  p.pose.position = {Vec3(0, 0, 0), Vec3(1, 0, 0)};
  auto plain = (*renderer)->render({p}, 240, 160);
  p.label_joint = 1;
  p.joint_label = "Tip 12.3°";
  auto labelled = (*renderer)->render({p}, 240, 160);
  ASSERT_TRUE(plain.ok() && labelled.ok());
  // Text and leader: light pixels that were not there, all in the half of the
  // figure where the tip (x = 1, the right) is.
  int changed = 0, right = 0;
  for (int y = 0; y < 160; ++y)
    for (int x = 0; x < 240; ++x)
      if (const std::uint8_t* before = plain->pixel(x, y);
          channel_distance(labelled->pixel(x, y), {before[0], before[1], before[2]}) > 40) {
        ++changed;
        right += x >= 120;
      }
  EXPECT_GT(changed, 40);
  EXPECT_GT(right, changed * 9 / 10);
}

TEST(ErrorStrip, DrawsTheCursorAtThePanelsFrameOnALinearTimeAxis) {
  auto context = create_context(default_backend());
  ASSERT_TRUE(context.ok()) << context.error();
  auto renderer = Renderer::create(std::move(context).value(), test::one_bone_scene());
  ASSERT_TRUE(renderer.ok()) << renderer.error();
  std::vector<double> at;  // the cursor's mean x at frames 0, 5 and 10
  for (std::size_t cursor : {std::size_t{0}, std::size_t{5}, std::size_t{10}}) {
    auto strip = std::make_shared<ErrorStrip>();
    StripLine line;
    for (int i = 0; i <= 10; ++i) line.deg.push_back(static_cast<float>(i));
    strip->lines = {line};
    strip->end_s = 1.0;
    strip->scale_deg = 10.0;
    strip->cursor = cursor;
    Panel p;
    p.strip = strip;
    auto image = (*renderer)->render({p}, 480, 400);
    ASSERT_TRUE(image.ok()) << image.error();
    const Rect r = panel_layout(480, 400, false, true).strip;
    ASSERT_GT(r.height, 0);
    // The orange cursor's pixels.
    double sum = 0;
    int count = 0;
    for (int y = r.y; y < r.y + r.height; ++y)
      for (int x = r.x; x < r.x + r.width; ++x) {
        const std::uint8_t* px = image->pixel(x, y);
        if (px[0] > 180 && px[1] > 100 && px[1] < 190 && px[2] < 90) {
          sum += x;
          ++count;
        }
      }
    ASSERT_GT(count, 5) << cursor;
    at.push_back(sum / count);
  }
  EXPECT_GT(at[2] - at[0], 0.8 * 480);  // the axis spans the strip but its labels
  EXPECT_NEAR(at[1], 0.5 * (at[0] + at[2]), 1.5);
}

}  // namespace
}  // namespace rotinterp::render
