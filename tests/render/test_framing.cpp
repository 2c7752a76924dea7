// Camera framing, ground grid and panel layout: pure geometry, no GL.
#include "rotinterp/render/camera.h"
#include "rotinterp/render/layout.h"
#include "rotinterp/render/renderer.h"

#include <gtest/gtest.h>

#include <cmath>

namespace rotinterp::render {
namespace {

// Normalized device coordinates of p seen by camera.
Eigen::Vector3d ndc(const Camera& camera, const Vec3& p) {
  const Eigen::Vector4d clip = camera.projection() * camera.view() * Eigen::Vector4d(p.x(), p.y(), p.z(), 1.0);
  return clip.head<3>() / clip.w();
}

Bounds box(const Vec3& a, const Vec3& b) {
  Bounds bounds;
  bounds.extend(a);
  bounds.extend(b);
  return bounds;
}

TEST(Framing, EveryCornerOfTheBoundsIsInsideTheViewAndOneSideTouchesTheMargin) {
  for (double aspect : {0.5, 1.0, 16.0 / 9.0, 3.0}) {
    const Bounds b = box(Vec3(-30, 0, -200), Vec3(40, 170, 350));  // a long walk, in cm
    const ViewAngles angles;
    const Camera camera = frame_bounds(b, aspect, angles);
    double largest = 0;
    for (int i = 0; i < 8; ++i) {
      const Vec3 corner((i & 1) ? b.max.x() : b.min.x(), (i & 2) ? b.max.y() : b.min.y(), (i & 4) ? b.max.z() : b.min.z());
      const Eigen::Vector3d p = ndc(camera, corner);
      EXPECT_LE(std::abs(p.x()), 1.0 - angles.margin + 1e-9) << "aspect " << aspect;
      EXPECT_LE(std::abs(p.y()), 1.0 - angles.margin + 1e-9) << "aspect " << aspect;
      EXPECT_GT(p.z(), -1.0);
      EXPECT_LT(p.z(), 1.0);
      largest = std::max({largest, std::abs(p.x()), std::abs(p.y())});
    }
    EXPECT_NEAR(largest, 1.0 - angles.margin, 1e-9) << "the closest camera touches the margin";
  }
}

TEST(Framing, EmptyAndDegenerateBoundsStillGiveAFiniteCamera) {
  for (const Bounds& b : {Bounds{}, box(Vec3(1, 2, 3), Vec3(1, 2, 3))}) {
    const Camera camera = frame_bounds(b, 1.5);
    EXPECT_TRUE(camera.eye.allFinite());
    EXPECT_TRUE((camera.projection() * camera.view()).allFinite());
    EXPECT_GT(camera.far_plane, camera.near_plane);
    EXPECT_GT(camera.near_plane, 0.0);
  }
}

TEST(Framing, GroundGridUsesA125StepAndCoversTheBoxOnTheFloor) {
  const Bounds b = box(Vec3(-0.3, 0.02, -1.7), Vec3(0.4, 1.8, 2.9));
  const GroundGrid g = ground_grid(b);
  EXPECT_DOUBLE_EQ(g.y, 0.02);
  EXPECT_DOUBLE_EQ(g.step, 1.0);  // 4.6 / 8 = 0.575 → 1
  EXPECT_LE(g.x0, b.min.x() - g.step + 1e-12);
  EXPECT_GE(g.x1, b.max.x() + g.step - 1e-12);
  EXPECT_LE(g.z0, b.min.z() - g.step + 1e-12);
  EXPECT_GE(g.z1, b.max.z() + g.step - 1e-12);
  EXPECT_DOUBLE_EQ(ground_grid(box(Vec3(0, 0, 0), Vec3(120, 10, 30))).step, 20.0);  // 15 → 20
  EXPECT_DOUBLE_EQ(ground_grid(box(Vec3(0, 0, 0), Vec3(0.3, 1, 0.1))).step, 0.05);  // 0.0375 → 0.05
}

TEST(Layout, PanelsAreEqualAndTileWithinTheImage) {
  for (int count = 1; count <= 9; ++count) {
    const int columns = automatic_columns(count, 961, 541);
    const auto rects = grid_layout(count, columns, 961, 541);
    ASSERT_EQ(static_cast<int>(rects.size()), count);
    for (const Rect& r : rects) {
      EXPECT_EQ(r.width, rects[0].width);
      EXPECT_EQ(r.height, rects[0].height);
      EXPECT_LE(r.x + r.width, 961);
      EXPECT_LE(r.y + r.height, 541);
    }
    for (std::size_t i = 1; i < rects.size(); ++i)  // no overlap in row-major order
      EXPECT_TRUE(rects[i].x >= rects[i - 1].x + rects[i - 1].width || rects[i].y >= rects[i - 1].y + rects[i - 1].height);
  }
}

TEST(Layout, ThreeMethodsInAWideFrameSitSideBySide) {
  EXPECT_EQ(automatic_columns(3, 960, 540), 3);
  EXPECT_EQ(automatic_columns(4, 960, 540), 2);  // 2×2: 480×270 beats 240×540
  EXPECT_EQ(automatic_columns(2, 400, 900), 1);
}

TEST(ImageSize, LimitsAreCheckedWithOneLineNamingTheProblem) {
  EXPECT_TRUE(check_image_size(960, 540, 3).ok());
  EXPECT_TRUE(check_image_size(kMaxImageSide, kMaxImageSide, 1).ok());
  const auto huge = check_image_size(kMaxImageSide + 1, 100, 1);
  ASSERT_FALSE(huge.ok());
  EXPECT_NE(huge.error().find("8192"), std::string::npos);
  const auto small = check_image_size(150, 40, 3);
  ASSERT_FALSE(small.ok());
  EXPECT_NE(small.error().find("too small for 3 panels"), std::string::npos) << small.error();
  EXPECT_FALSE(check_image_size(0, 100, 1).ok());
  EXPECT_FALSE(check_image_size(100, 100, 0).ok());
}

}  // namespace
}  // namespace rotinterp::render
