// Camera framing, ground grid, the trail inset's view, and the layout of panels
// and of what is in them: pure geometry, no GL.
#include "rotinterp/render/camera.h"
#include "rotinterp/render/layout.h"
#include "rotinterp/render/renderer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

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

TEST(Framing, PixelsAtTargetScaleWithTheViewportAndTheField) {
  Camera camera;
  camera.eye = Vec3(0, 0, 10);
  camera.fov_y = 2.0 * std::atan(0.5);  // the viewport's half-height is 5 units at the target
  EXPECT_NEAR(pixels_at_target(camera, 5.0, 400), 200.0, 1e-9);
  EXPECT_NEAR(pixels_at_target(camera, 1.0, 400), 40.0, 1e-9);
  camera.eye = Vec3(0, 0, 20);
  EXPECT_NEAR(pixels_at_target(camera, 1.0, 400), 20.0, 1e-9);
}

// The trail's unit vector at p seen by `view` is inside the square inset and between its planes.
void expect_seen(const TrailView& view, const Vec3& p) {
  const Eigen::Vector3d q = ndc(view.camera, unit_or_zero(p));
  EXPECT_LT(std::abs(q.x()), 1.0) << p.transpose();
  EXPECT_LT(std::abs(q.y()), 1.0) << p.transpose();
  EXPECT_GT(q.z(), -1.0);
  EXPECT_LT(q.z(), 1.0);
}

TEST(Framing, TrailViewLooksAlongTheReferencesMeanAndSeesEverySample) {
  const Vec3 centre = Vec3(0.3, 0.5, 0.8).normalized();
  const Vec3 side = centre.cross(Vec3::UnitY()).normalized(), up = side.cross(centre);
  std::vector<Vec3> reference, method;
  for (int i = 0; i <= 40; ++i) {
    const double a = 0.01 * (i - 20);
    reference.push_back(2.0 * (centre + a * side));  // not unit: normalized
    method.push_back(centre + a * side + 0.05 * up);
  }
  const TrailView view = trail_view(reference, method, ViewAngles{});
  EXPECT_GT(view.camera.eye.normalized().dot(centre), 0.9999);
  EXPECT_NEAR(view.camera.target.norm(), 0.0, 1e-12);
  EXPECT_EQ(view.camera.aspect, 1.0) << "the inset is square";
  EXPECT_GT(view.zoom, 0.0);
  EXPECT_LT(view.zoom, 0.5) << "a short trail is zoomed on";
  EXPECT_NEAR(std::tan(0.5 * view.camera.fov_y), view.zoom * std::tan(18.0 * kPi / 180.0), 1e-12);
  for (const auto* curve : {&reference, &method})
    for (const Vec3& p : *curve) expect_seen(view, p);
  // The sphere's front stays between the planes.
  expect_seen(view, centre);
}

TEST(Framing, TrailViewOfATrailThatFillsTheSphereLooksFromTheScenesViewAndSeesAllOfIt) {
  // A tennis ball's seam: around the whole sphere, in no plane.
  std::vector<Vec3> seam;
  for (int i = 0; i < 72; ++i) {
    const double t = i * kPi / 36, lat = 0.6 * std::sin(2 * t);
    seam.push_back(Vec3(std::cos(lat) * std::cos(t), std::sin(lat), std::cos(lat) * std::sin(t)));
  }
  ASSERT_FALSE(trail_plane(seam).has_value());
  ViewAngles angles;
  angles.azimuth_deg = 30.0;
  angles.elevation_deg = 5.0;  // raised to 20°
  const TrailView view = trail_view(seam, seam, angles);
  const double az = 30.0 * kPi / 180.0, el = 20.0 * kPi / 180.0;
  const Vec3 toward(std::sin(az) * std::cos(el), std::sin(el), std::cos(az) * std::cos(el));
  EXPECT_LT((view.camera.eye.normalized() - toward).norm(), 1e-12);
  EXPECT_DOUBLE_EQ(view.zoom, 1.0) << "the whole sphere";
  EXPECT_NEAR(view.camera.fov_y, 36.0 * kPi / 180.0, 1e-12);
}

TEST(Framing, TrailViewOfAPlanarArcLooksAlongItsPlaneNormalAtItsCentroid) {
  // A hinge: the bone turns 240° about a fixed axis, the bone at 60° to the axis
  // (a small circle), then at 90° (a great circle, through the sphere's centre).
  const Vec3 axis = Vec3(1, 2, 0.5).normalized();
  const Vec3 across = axis.cross(Vec3::UnitZ()).normalized();
  for (double tilt : {60.0, 90.0}) {
    const Vec3 bone = std::cos(tilt * kPi / 180) * axis + std::sin(tilt * kPi / 180) * across;
    std::vector<Vec3> arc;
    for (int i = 0; i <= 60; ++i) arc.push_back(Eigen::AngleAxisd(4.0 * kPi / 3 * i / 60, axis) * bone);
    const auto plane = trail_plane(arc);
    ASSERT_TRUE(plane.has_value()) << tilt;
    EXPECT_GT(std::abs(plane->normal.dot(axis)), 1.0 - 1e-9) << tilt;
    const TrailView view = trail_view(arc, arc, ViewAngles{});
    const Vec3 looking = (view.camera.target - view.camera.eye).normalized();
    EXPECT_GT(std::abs(looking.dot(axis)), 1.0 - 1e-9) << tilt << ": face on";
    EXPECT_LT((view.camera.target - plane->centroid).norm(), 1e-12) << tilt;
    for (const Vec3& p : arc) expect_seen(view, p);
  }
}

TEST(Framing, TrailViewOfOneSampleHasTheNarrowestField) {
  const TrailView view = trail_view({Vec3::UnitY()}, {Vec3::UnitY()}, ViewAngles{});
  EXPECT_NEAR(view.camera.fov_y, 3.0 * kPi / 180.0, 1e-12);
  EXPECT_NEAR(view.zoom, std::tan(1.5 * kPi / 180.0) / std::tan(18.0 * kPi / 180.0), 1e-12);
  const Eigen::Matrix3d r = view.camera.view().block<3, 3>(0, 0);
  EXPECT_TRUE((r * r.transpose()).isApprox(Eigen::Matrix3d::Identity(), 1e-9)) << "looking along +Y needs another up";
  expect_seen(view, Vec3::UnitY());
}

TEST(Framing, UnitOrZeroNormalizesDirectionsOnly) {
  EXPECT_LT((unit_or_zero(Vec3(0, 3, 4)) - Vec3(0, 0.6, 0.8)).norm(), 1e-15);
  EXPECT_EQ(unit_or_zero(Vec3::Zero()), Vec3::Zero());
  EXPECT_EQ(unit_or_zero(Vec3(std::nan(""), 1, 0)), Vec3::Zero());
  EXPECT_EQ(unit_or_zero(Vec3(HUGE_VAL, 1, 0)), Vec3::Zero());
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

bool overlap(const Rect& a, const Rect& b) {
  return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;
}

TEST(Layout, WithoutATrailTheFigureFillsThePanelUnderTheTitle) {
  const PanelLayout l = panel_layout(320, 240, false);
  EXPECT_EQ(l.title_height, 18);  // 0.075 × 240
  EXPECT_EQ(l.figure.x, 0);
  EXPECT_EQ(l.figure.y, 18);
  EXPECT_EQ(l.figure.width, 320);
  EXPECT_EQ(l.figure.height, 222);
  EXPECT_EQ(l.inset.width, 0);
  EXPECT_EQ(panel_layout(320, 100, false).title_height, 14);
  EXPECT_EQ(panel_layout(320, 2000, false).title_height, 40);
}

TEST(Layout, TheTrailInsetIsASquareInsideThePanelBesideOrBelowTheFigure) {
  for (const auto& [width, height] : std::vector<std::pair<int, int>>{{320, 240}, {480, 270}, {200, 400}, {960, 1080}, {64, 48}, {1000, 90}}) {
    const PanelLayout l = panel_layout(width, height, true);
    const Rect& f = l.figure;
    const Rect& i = l.inset;
    const int scene_height = height - l.title_height;
    SCOPED_TRACE(std::to_string(width) + "x" + std::to_string(height));
    EXPECT_EQ(i.width, i.height);
    EXPECT_GT(i.width, 0);
    EXPECT_GE(i.x, 0);
    EXPECT_LE(i.x + i.width, width);
    EXPECT_GE(i.y, l.title_height);
    EXPECT_LE(i.y + i.height, height);
    EXPECT_GE(f.y, l.title_height);
    EXPECT_LE(f.x + f.width, width);
    EXPECT_LE(f.y + f.height, height);
    EXPECT_FALSE(overlap(f, i));
    if (width * 5 <= scene_height * 6) {  // tall: the inset below the figure, at the bottom right
      EXPECT_EQ(f.width, width);
      EXPECT_LE(f.y + f.height, i.y);
      EXPECT_GT(i.y + i.height, height - i.height / 4);
    } else {  // wide: beside it, at the top right
      EXPECT_EQ(f.height, scene_height);
      EXPECT_LE(f.x + f.width, i.x);
      EXPECT_LT(i.y, l.title_height + i.height / 4);
    }
    EXPECT_GT(i.x + i.width, width - i.width / 4) << "at the right";
  }
}

// A text whose glyphs are all 0.6 of the pixel height wide.
TextWidth glyphs(std::size_t count) {
  return [count](int pixel_height) { return 0.6f * static_cast<float>(pixel_height) * static_cast<float>(count); };
}

TEST(Layout, TextShrinksUntilItFitsButNotBelowEightPixels) {
  EXPECT_EQ(fitting_height(glyphs(10), 30, 100.0f), 16);  // 0.6 × 16 × 10 = 96
  EXPECT_EQ(fitting_height(glyphs(10), 12, 100.0f), 12);
  EXPECT_EQ(fitting_height(glyphs(10), 30, 1.0f), 8);
  EXPECT_EQ(fitting_height(glyphs(10), 6, 1.0f), 6);
}

TEST(Layout, TitleIsCentredInItsStripAndFitsThePanel) {
  const PanelLayout l = panel_layout(320, 240, true);
  const std::string title = "slerp  mean 1.23°  max 4.56°";
  const TextItem t = title_text(title, l, 320, glyphs(10));
  EXPECT_EQ(t.text, title);
  EXPECT_EQ(t.pixel_height, 11);  // 0.62 × 18
  EXPECT_EQ(t.x, 6.0f);
  const float line = 1.15f * static_cast<float>(t.pixel_height);
  EXPECT_GE(t.top, 0.0f);
  EXPECT_LE(t.top + line, static_cast<float>(l.title_height));
  EXPECT_NEAR(t.top, static_cast<float>(l.title_height) - (t.top + line), 1.0f) << "centred";
  const TextItem long_title = title_text(title, l, 320, glyphs(50));
  EXPECT_LT(long_title.pixel_height, 11);
  EXPECT_LE(glyphs(50)(long_title.pixel_height), 320.0f - 2 * long_title.x);
}

TEST(Layout, InsetLabelIsInsideTheInsetAndFitsIt) {
  const Rect inset{200, 100, 110, 110};
  const TextItem t = inset_label("LeftElbow", inset, glyphs(9));
  EXPECT_GT(t.x, static_cast<float>(inset.x));
  EXPECT_GT(t.top, static_cast<float>(inset.y));
  EXPECT_LT(t.top + static_cast<float>(t.pixel_height), static_cast<float>(inset.y + inset.height));
  EXPECT_EQ(t.pixel_height, 10);  // 110 / 11
  EXPECT_LE(t.x + glyphs(9)(t.pixel_height), static_cast<float>(inset.x + inset.width));
  const TextItem wide = inset_label(std::string(40, 'x'), inset, glyphs(40));
  EXPECT_LT(wide.pixel_height, 10);
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
