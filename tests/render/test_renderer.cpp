// The renderer library on a synthetic clip: images of the right size, not blank,
// panels that differ where poses differ and only there, determinism, a golden
// image, and both context backends.
#include "synthetic_clip.h"

#include "rotinterp/render/context.h"
#include "rotinterp/render/layout.h"
#include "rotinterp/render/renderer.h"

#include <gtest/gtest.h>
#include <stb_image.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>

namespace rotinterp::render {
namespace {

namespace fs = std::filesystem;

WorldPose pose_at(const Clip& clip, std::size_t frame, const Quat& extra_left_elbow = Quat::Identity()) {
  std::vector<Quat> local;
  std::vector<Vec3> translation;
  for (std::size_t j = 0; j < clip.skeleton.joints.size(); ++j) {
    Quat q = clip.rotations[j].keys[frame];
    if (clip.skeleton.joints[j].name == "LeftElbow") q = q * extra_left_elbow;
    local.push_back(q);
    translation.push_back(clip.skeleton.joints[j].offset);
  }
  WorldPose pose;
  forward_kinematics(clip.skeleton, local, translation, pose);
  return pose;
}

Bounds clip_bounds(const Clip& clip) {
  Bounds b;
  for (std::size_t f = 0; f < clip.rotations[0].keys.size(); ++f) {
    const WorldPose p = pose_at(clip, f);
    for (const Vec3& x : p.position) b.extend(x);
    for (const Vec3& x : p.end_site_position) b.extend(x);
  }
  return b;
}

// Three panels: the original, the same again, and one with the left elbow bent 60°
// more; all over the original as ghost.
std::vector<Panel> three_panels(const Clip& clip, std::size_t frame) {
  const WorldPose original = pose_at(clip, frame);
  const WorldPose bent = pose_at(clip, frame, exp(RotVec(0, 1.05, 0)));
  std::vector<Panel> panels(3);
  panels[0].title = "same  mean 0.00°  max 0.00°";
  panels[1].title = "same  mean 0.00°  max 0.00°";
  panels[2].title = "bent  mean 4.62°  max 60.00°";
  for (auto& p : panels) p.ghost = original;
  panels[0].pose = original;
  panels[1].pose = original;
  panels[2].pose = bent;
  return panels;
}

std::unique_ptr<Renderer> make_renderer(const Clip& clip, Backend backend) {
  auto context = create_context(backend);
  EXPECT_TRUE(context.ok()) << context.error();
  if (!context) return nullptr;
  Scene scene;
  scene.skeleton = clip.skeleton;
  scene.bounds = clip_bounds(clip);
  auto renderer = Renderer::create(std::move(context).value(), scene);
  EXPECT_TRUE(renderer.ok()) << renderer.error();
  return renderer ? std::move(renderer).value() : nullptr;
}

// Pixels of `rect` in `image`, row by row.
std::vector<std::uint8_t> crop(const Image& image, const Rect& rect) {
  std::vector<std::uint8_t> out;
  for (int y = rect.y; y < rect.y + rect.height; ++y)
    out.insert(out.end(), image.pixel(rect.x, y), image.pixel(rect.x, y) + 3 * rect.width);
  return out;
}

std::size_t distinct_colours(const std::vector<std::uint8_t>& rgb) {
  std::set<std::uint32_t> colours;
  for (std::size_t i = 0; i + 2 < rgb.size(); i += 3)
    colours.insert((std::uint32_t(rgb[i]) << 16) | (std::uint32_t(rgb[i + 1]) << 8) | rgb[i + 2]);
  return colours.size();
}

class RendererOnBothBackends : public ::testing::TestWithParam<Backend> {};

TEST_P(RendererOnBothBackends, PanelsAreNotBlankAndDifferExactlyWhereThePosesDiffer) {
  const Clip clip = test::synthetic_clip();
  auto renderer = make_renderer(clip, GetParam());
  ASSERT_TRUE(renderer);
  auto image = renderer->render(three_panels(clip, 20), 480, 200);
  ASSERT_TRUE(image.ok()) << image.error();
  ASSERT_EQ(image->width, 480);
  ASSERT_EQ(image->height, 200);
  const auto rects = grid_layout(3, automatic_columns(3, 480, 200), 480, 200);
  const auto a = crop(*image, rects[0]), b = crop(*image, rects[1]), c = crop(*image, rects[2]);
  // Shaded, antialiased bones, a grid and text give many colours; a blank panel one.
  EXPECT_GT(distinct_colours(a), 200u);
  EXPECT_EQ(a, b) << "panels with identical content must be pixel-identical";
  std::size_t differing = 0;
  for (std::size_t i = 0; i < a.size(); i += 3)
    differing += a[i] != c[i] || a[i + 1] != c[i + 1] || a[i + 2] != c[i + 2];
  EXPECT_GT(differing, 100u) << "a 60° elbow bend must show";
}

TEST_P(RendererOnBothBackends, SameInputGivesTheSamePixels) {
  const Clip clip = test::synthetic_clip();
  auto renderer = make_renderer(clip, GetParam());
  ASSERT_TRUE(renderer);
  auto first = renderer->render(three_panels(clip, 33), 300, 160);
  auto second = renderer->render(three_panels(clip, 33), 300, 160);
  ASSERT_TRUE(first.ok() && second.ok());
  EXPECT_EQ(first->rgb, second->rgb);
}

INSTANTIATE_TEST_SUITE_P(Backends, RendererOnBothBackends, ::testing::Values(Backend::osmesa, Backend::egl),
                         [](const auto& info) { return std::string(backend_name(info.param)); });

TEST(Renderer, TooSmallAndTooLargeImagesAreRefusedWithAClearLine) {
  const Clip clip = test::synthetic_clip();
  auto renderer = make_renderer(clip, default_backend());
  ASSERT_TRUE(renderer);
  auto small = renderer->render(three_panels(clip, 0), 150, 40);
  ASSERT_FALSE(small.ok());
  EXPECT_NE(small.error().find("too small"), std::string::npos) << small.error();
  auto huge = renderer->render(three_panels(clip, 0), 8193, 100);
  ASSERT_FALSE(huge.ok());
  EXPECT_NE(huge.error().find("8192"), std::string::npos) << huge.error();
}

}  // namespace
}  // namespace rotinterp::render
