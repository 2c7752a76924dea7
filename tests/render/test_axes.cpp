// Joint axes as RGB triads (render/axes.h): drawn by default for a one-joint clip,
// and the one thing that shows a bone's twist about its own axis.
#include "png_pixels.h"
#include "support/run_cli.h"

#include "rotinterp/render/axes.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace rotinterp::render {
namespace {

namespace fs = std::filesystem;
using test::fresh_dir;
using test::run_cli;

// Pixels where one channel stands out as the axis colours do: 0 red, 1 green, 2 blue.
std::size_t pixels_of(const test::Pixels& p, int channel) {
  std::size_t n = 0;
  for (std::size_t i = 0; i + 2 < p.rgb.size(); i += 3) {
    const int c = p.rgb[i + static_cast<std::size_t>(channel)];
    const int o1 = p.rgb[i + static_cast<std::size_t>((channel + 1) % 3)], o2 = p.rgb[i + static_cast<std::size_t>((channel + 2) % 3)];
    if (c > 120 && c > 2 * o1 && c > 2 * o2) ++n;
  }
  return n;
}

test::Pixels render_frame(const fs::path& clip, const fs::path& out, const std::string& flags) {
  const auto r = run_cli("render " + clip.string() + " -o " + out.string() +
                         " --methods slerp --keep-every 1 --frames 1 --size 240x180 --view side -q " + flags);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return test::read_png(out / "frame_000001.png");
}

TEST(RenderAxes, AOneJointClipShowsRedGreenAndBlueAxesByDefault) {
  const fs::path dir = fresh_dir("axes_one_joint");
  fs::create_directories(dir);
  const fs::path clip = dir / "box.bvh";
  std::ofstream(clip) << "HIERARCHY\nROOT Box\n{\n  OFFSET 0 0 0\n  CHANNELS 3 Zrotation Xrotation Yrotation\n"
                         "  End Site\n  {\n    OFFSET 0 0 0\n  }\n}\nMOTION\nFrames: 3\nFrame Time: 0.1\n"
                         "0 0 0\n10 20 30\n20 40 60\n";
  const test::Pixels on = render_frame(clip, dir / "auto", ""), off = render_frame(clip, dir / "off", "--axes off");
  ASSERT_TRUE(on.ok() && off.ok());
  for (int channel = 0; channel < 3; ++channel)
    EXPECT_GT(pixels_of(on, channel), pixels_of(off, channel) + 30) << "channel " << channel;
  fs::remove_all(dir);
}

TEST(RenderAxes, TwistOfABoneAboutItsOwnAxisShowsWithAxesOnAndNotOff) {
  const fs::path dir = fresh_dir("axes_twist");
  fs::create_directories(dir);
  // A bone along +Y from A to B; the twisted clip turns A 50° about Y (the bone's axis).
  auto write = [&](const fs::path& path, int twist) {
    std::ofstream(path) << "HIERARCHY\nROOT A\n{\n  OFFSET 0 0 0\n  CHANNELS 3 Zrotation Xrotation Yrotation\n"
                           "  JOINT B\n  {\n    OFFSET 0 10 0\n    CHANNELS 3 Zrotation Xrotation Yrotation\n"
                           "    End Site\n    {\n      OFFSET 0 10 0\n    }\n  }\n}\nMOTION\nFrames: 3\n"
                           "Frame Time: 0.1\n"
                        << "0 0 " << twist << " 0 0 0\n0 0 " << twist << " 0 0 0\n0 0 " << twist << " 0 0 0\n";
  };
  const fs::path straight = dir / "straight.bvh", twisted = dir / "twisted.bvh";
  write(straight, 0);
  write(twisted, 50);
  const test::Pixels off_a = render_frame(straight, dir / "off_a", "--axes off"),
                     off_b = render_frame(twisted, dir / "off_b", "--axes off");
  const test::Pixels on_a = render_frame(straight, dir / "on_a", "--axes on"),
                     on_b = render_frame(twisted, dir / "on_b", "--axes on");
  ASSERT_TRUE(off_a.ok() && off_b.ok() && on_a.ok() && on_b.ok());
  EXPECT_EQ(test::differing_pixels(off_a.rgb, off_b.rgb), 0u) << "a bone line cannot show its twist";
  EXPECT_GT(test::differing_pixels(on_a.rgb, on_b.rgb), 50u) << "the triads turn with the twist";
  fs::remove_all(dir);
}

TEST(RenderAxes, EachJointGetsThreeAxesAlongItsWorldRotationSizedToTheBox) {
  Skeleton skeleton;
  skeleton.joints.push_back(Joint{});
  skeleton.joints[0].name = "A";
  WorldPose pose;
  pose.position = {Vec3(1, 2, 3)};
  pose.rotation = {Quat(Eigen::AngleAxisd(0.5, Vec3::UnitZ()))};
  Batch batch;
  Bounds box;
  box.extend(Vec3(0, 0, 0));
  box.extend(Vec3(10, 4, 2));
  const double length = axes_length(box, 0.01);
  EXPECT_DOUBLE_EQ(length, 1.0);
  add_axes(skeleton, pose, length, batch);
  ASSERT_EQ(batch.cylinders.size(), 3u);
  const Mat3 r = pose.rotation[0].toRotationMatrix();
  for (int axis = 0; axis < 3; ++axis) {
    const float* m = batch.cylinders[static_cast<std::size_t>(axis)].model;  // column-major; column 2 = the axis
    EXPECT_NEAR((Vec3(m[8], m[9], m[10]) - length * r.col(axis)).norm(), 0.0, 1e-6);
    EXPECT_NEAR((Vec3(m[12], m[13], m[14]) - pose.position[0]).norm(), 0.0, 1e-6);
  }
  Bounds point;
  point.extend(Vec3(5, 5, 5));
  EXPECT_DOUBLE_EQ(axes_length(point, 0.0), 0.4) << "a point is framed as a unit cube";
  EXPECT_DOUBLE_EQ(axes_length(point, 1.0), 4.0) << "never hidden in the joint's sphere";
}

}  // namespace
}  // namespace rotinterp::render
