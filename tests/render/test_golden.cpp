// A golden image: one frame of the synthetic clip with a trail inset, compared
// per pixel with tests/render/golden/synthetic_frame20.png on both backends.
// Regenerate (after a deliberate change of look) with
//   ROTINTERP_UPDATE_GOLDEN=1 ./build/tests/test_render --gtest_filter='Golden*'
#include "synthetic_clip.h"

#include "rotinterp/render/context.h"
#include "rotinterp/render/renderer.h"

#include <gtest/gtest.h>
#include <stb_image.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <utility>

namespace rotinterp::render {
namespace {

// Tolerance: a pixel matches when no channel differs by more than kChannelTolerance
// (llvmpipe builds may round a shading term differently); at most kMismatchFraction
// of the pixels may fail that (edge pixels of antialiased geometry).
constexpr int kChannelTolerance = 12;
constexpr double kMismatchFraction = 0.002;

const char* kGolden = ROTINTERP_SOURCE_DIR "/tests/render/golden/synthetic_frame20.png";

WorldPose fk(const Clip& clip, const std::vector<Quat>& local) {
  std::vector<Vec3> translation;
  for (const Joint& j : clip.skeleton.joints) translation.push_back(j.offset);
  WorldPose pose;
  forward_kinematics(clip.skeleton, local, translation, pose);
  return pose;
}

// Two panels of frame 20: the clip itself, and the clip with every other joint
// rotation replaced by its value 3 frames later (a visible error); the trail of
// LeftShoulder's bone direction over all frames.
std::vector<Panel> golden_panels(const Clip& clip) {
  const std::size_t frame = 20, frames = clip.rotations[0].keys.size();
  const int shoulder = clip.skeleton.find("LeftShoulder");
  const Vec3 bone = clip.skeleton.joints[static_cast<std::size_t>(shoulder) + 1].offset.normalized();
  auto local = [&](std::size_t f, bool shifted) {
    std::vector<Quat> q;
    for (std::size_t j = 0; j < clip.rotations.size(); ++j)
      q.push_back(clip.rotations[j].keys[shifted && j % 2 == 0 ? std::min(f + 3, frames - 1) : f]);
    return q;
  };
  auto trail = std::make_shared<Trail>();
  trail->label = "LeftShoulder";
  for (std::size_t f = 0; f < frames; ++f) {
    trail->reference.push_back(local(f, false)[static_cast<std::size_t>(shoulder)] * bone);
    trail->method.push_back(local(f, true)[static_cast<std::size_t>(shoulder)] * bone);
  }
  trail->keys = {0, 10, 20, 30, 40, 50, 60};
  trail->current = frame;
  std::vector<Panel> panels(2);
  panels[0].title = "original  mean 0.00°  max 0.00°";
  panels[0].colour = {0.25f, 0.6f, 0.95f};
  panels[1].title = "shifted  mean 9.9°  max 31.2°";
  for (auto& p : panels) p.ghost = fk(clip, local(frame, false));
  panels[0].pose = fk(clip, local(frame, false));
  panels[1].pose = fk(clip, local(frame, true));
  for (auto& p : panels) p.trail = trail;
  return panels;
}

// Pixels whose worst channel differs from the golden by more than the tolerance;
// SIZE_MAX when the golden cannot be read or has another size.
std::size_t mismatches_against_golden(const Image& image) {
  int w = 0, h = 0, channels = 0;
  std::unique_ptr<stbi_uc, void (*)(void*)> golden(stbi_load(kGolden, &w, &h, &channels, 3), stbi_image_free);
  if (!golden || w != image.width || h != image.height) return SIZE_MAX;
  std::size_t mismatches = 0;
  for (std::size_t i = 0; i < image.rgb.size(); i += 3) {
    int worst = 0;
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(int(image.rgb[i + c]) - int(golden.get()[i + c])));
    mismatches += worst > kChannelTolerance;
  }
  return mismatches;
}

Result<Image> render_golden_frame(Backend backend, bool perturb) {
  const Clip clip = test::synthetic_clip();
  Scene scene;
  scene.skeleton = clip.skeleton;
  for (std::size_t f = 0; f < clip.rotations[0].keys.size(); ++f) {
    std::vector<Quat> q;
    for (const auto& track : clip.rotations) q.push_back(track.keys[f]);
    const WorldPose p = fk(clip, q);
    for (const Vec3& x : p.position) scene.bounds.extend(x);
    for (const Vec3& x : p.end_site_position) scene.bounds.extend(x);
  }
  auto context = create_context(backend);
  if (!context) return context.failure();
  auto renderer = Renderer::create(std::move(context).value(), scene);
  if (!renderer) return renderer.failure();
  auto panels = golden_panels(clip);
  if (perturb) std::swap(panels[0].pose, panels[1].pose);  // each panel shows the other's pose
  return (*renderer)->render(panels, 400, 220);
}

class GoldenImage : public ::testing::TestWithParam<Backend> {};

TEST_P(GoldenImage, FrameMatchesTheCommittedGoldenWithinTolerance) {
  auto image = render_golden_frame(GetParam(), false);
  ASSERT_TRUE(image.ok()) << image.error();

  if (std::getenv("ROTINTERP_UPDATE_GOLDEN") && GetParam() == Backend::osmesa) {
    ASSERT_TRUE(write_png(*image, kGolden).ok());
    GTEST_SKIP() << "golden image rewritten: " << kGolden;
  }
  const std::size_t mismatches = mismatches_against_golden(*image);
  ASSERT_NE(mismatches, SIZE_MAX) << kGolden << ": missing, unreadable or of another size";
  const std::size_t pixels = image->rgb.size() / 3;
  EXPECT_LE(static_cast<double>(mismatches), kMismatchFraction * static_cast<double>(pixels))
      << mismatches << " of " << pixels << " pixels differ by more than " << kChannelTolerance;
}

// The comparison can fail: a frame whose second panel shows the reference pose
// instead of the shifted one is far outside the tolerance.
TEST_P(GoldenImage, AChangedPoseIsFarOutsideTheTolerance) {
  auto image = render_golden_frame(GetParam(), true);
  ASSERT_TRUE(image.ok()) << image.error();
  const std::size_t mismatches = mismatches_against_golden(*image);
  ASSERT_NE(mismatches, SIZE_MAX);
  EXPECT_GT(static_cast<double>(mismatches), 2 * kMismatchFraction * static_cast<double>(image->rgb.size() / 3));
}

INSTANTIATE_TEST_SUITE_P(Backends, GoldenImage, ::testing::Values(Backend::osmesa, Backend::egl),
                         [](const auto& info) { return std::string(backend_name(info.param)); });

}  // namespace
}  // namespace rotinterp::render
