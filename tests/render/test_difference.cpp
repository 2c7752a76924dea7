// What makes a difference visible at a glance: bones in the colour map's colour
// of their error, a camera that follows a travelling figure, the hinge trail
// seen face on, time on every frame, the trail's window, and the video.
#include "png_pixels.h"
#include "support/run_cli.h"
#include "synthetic_clip.h"

#include "rotinterp/render/colour_map.h"
#include "rotinterp/render/comparison.h"
#include "rotinterp/render/context.h"
#include "rotinterp/render/layout.h"
#include "rotinterp/render/renderer.h"
#include "rotinterp/render/video.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>

#include <unistd.h>

namespace rotinterp::render {
namespace {

namespace fs = std::filesystem;
using test::fresh_dir;
using test::run_cli;

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

// A two-joint skeleton: one bone from (0,0,0) to (1,0,0), seen from the front.
Scene one_bone_scene() {
  Scene scene;
  Joint root;
  root.name = "Root";
  Joint tip;
  tip.name = "Tip";
  tip.parent = 0;
  tip.offset = Vec3(1, 0, 0);
  scene.skeleton.joints = {root, tip};
  scene.bounds.extend(Vec3(-0.1, -0.3, -0.1));
  scene.bounds.extend(Vec3(1.1, 0.3, 0.1));
  scene.bone_radius = 0.08;
  scene.view.azimuth_deg = 0.0;
  scene.view.elevation_deg = 0.0;
  return scene;
}

TEST(ErrorColours, ABoneWhoseErrorIsKnownGetsTheColourMapsColour) {
  auto context = create_context(default_backend());
  ASSERT_TRUE(context.ok()) << context.error();
  auto renderer = Renderer::create(std::move(context).value(), one_bone_scene());
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
  auto renderer = Renderer::create(std::move(context).value(), one_bone_scene());
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

TEST(ErrorStrip, DrawsTheCursorAtThePanelsFrame) {
  auto context = create_context(default_backend());
  ASSERT_TRUE(context.ok()) << context.error();
  auto renderer = Renderer::create(std::move(context).value(), one_bone_scene());
  ASSERT_TRUE(renderer.ok()) << renderer.error();
  for (std::size_t cursor : {std::size_t{2}, std::size_t{8}}) {
    auto strip = std::make_shared<ErrorStrip>();
    for (int i = 0; i <= 10; ++i) {
      strip->max_deg.push_back(static_cast<float>(i));
      strip->mean_deg.push_back(static_cast<float>(i) / 2);
    }
    strip->scale_deg = 10.0;
    strip->cursor = cursor;
    Panel p;
    p.strip = strip;
    auto image = (*renderer)->render({p}, 240, 200);
    ASSERT_TRUE(image.ok()) << image.error();
    const Rect r = panel_layout(240, 200, false, true).strip;
    ASSERT_GT(r.height, 0);
    // The orange cursor's pixels: their mean x is the cursor's place on the time axis.
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
    const double pad = std::max(3, r.height / 8);
    const double expected = r.x + pad + (r.width - 2 * pad) * static_cast<double>(cursor) / 10.0;
    EXPECT_NEAR(sum / count, expected, 2.0) << cursor;
  }
}

// ---- the follow camera -----------------------------------------------------------

// One method's panels at `width` × `height`, coloured by method (the figure's
// pixels are the saturated ones: squad's vermillion stays saturated in shade, where a
// light blue's shaded side would not count), no strip.
ComparisonOptions one_method(FrameRange frames, int width, int height) {
  ComparisonOptions o;
  o.methods = {"squad"};
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
  Scene scene = one_bone_scene();
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

// ---- video --------------------------------------------------------------------------

std::string probe(const fs::path& video, const std::string& entries) {
  const std::string cmd = "ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=" + entries +
                          " -of csv=p=0 " + video.string();
  std::string out;
  if (std::FILE* pipe = ::popen(cmd.c_str(), "r")) {
    char buf[256];
    while (std::fgets(buf, sizeof buf, pipe)) out += buf;
    ::pclose(pipe);
  }
  while (!out.empty() && (out.back() == '\n' || out.back() == ',')) out.pop_back();
  return out;
}

const std::string kSample = std::string(ROTINTERP_SOURCE_DIR) + "/samples/walk.bvh";  // 121 frames at 30 Hz

TEST(Video, Mp4HasTheFramesSizeAndRateAskedNoPngsAndTheSameBytesEachTime) {
  const fs::path dir = fresh_dir("mp4");
  fs::create_directories(dir);
  const fs::path video = dir / "walk.mp4";
  auto r = run_cli("render " + kSample + " --video " + video.string() +
                   " --methods slerp,squad --frames 10:45 --size 320x180 -q");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(probe(video, "width,height,r_frame_rate,nb_read_frames,codec_name"), "h264,320,180,30/1,36");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1) << "only the video";
  const std::string first = test::slurp(video);
  r = run_cli("render " + kSample + " --video " + video.string() + " --methods slerp,squad --frames 10:45 --size 320x180 -q");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(test::slurp(video), first) << "the same command gives the same bytes";
  // --video-fps, and every frame of the clip by default.
  r = run_cli("render " + kSample + " --video " + video.string() + " --methods slerp --size 160x90 --video-fps 12 -q");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(probe(video, "width,height,r_frame_rate,nb_read_frames"), "160,90,12/1,121");
  fs::remove_all(dir);
}

TEST(Video, GifAndPngsTogetherAndTheSameCommandGivesTheSameBytes) {
  const fs::path dir = fresh_dir("gif");
  const std::string args = "render " + kSample + " -o " + (dir / "png").string() + " --video " +
                           (dir / "walk.gif").string() + " --methods slerp --frames 20:29 --size 160x90 -q";
  auto r = run_cli(args);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(probe(dir / "walk.gif", "codec_name,width,height,nb_read_frames"), "gif,160,90,10");
  EXPECT_TRUE(fs::exists(dir / "png" / "frame_000020.png"));
  const std::string gif = test::slurp(dir / "walk.gif"), png = test::slurp(dir / "png" / "frame_000025.png");
  r = run_cli(args);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(test::slurp(dir / "walk.gif"), gif);
  EXPECT_EQ(test::slurp(dir / "png" / "frame_000025.png"), png);
  fs::remove_all(dir);
}

TEST(Video, AFailingFfmpegGivesOneLineAndLeavesThePreviousFileAndNoTemporary) {
  const fs::path dir = fresh_dir("ffmpeg_fails");
  fs::create_directories(dir / "bin");
  {
    std::ofstream fake(dir / "bin" / "ffmpeg");
    fake << "#!/bin/sh\ncat >/dev/null\necho 'libx264: out of cheese' >&2\nexit 1\n";
  }
  fs::permissions(dir / "bin" / "ffmpeg", fs::perms::owner_all);
  std::ofstream(dir / "old.mp4") << "previous";
  const fs::path err = dir / "err.txt";
  const std::string cmd = "PATH=" + (dir / "bin").string() + ":$PATH " + ROTINTERP_CLI + " render " + kSample +
                          " --video " + (dir / "old.mp4").string() + " --methods slerp --frames 0:3 --size 64x48 -q 2>" +
                          err.string();
  const int status = std::system(cmd.c_str());
  EXPECT_EQ(WEXITSTATUS(status), 1);
  EXPECT_EQ(test::slurp(err), "rotinterp: " + kSample + ": " + (dir / "old.mp4").string() +
                                  ": ffmpeg failed: libx264: out of cheese\n");
  EXPECT_EQ(test::slurp(dir / "old.mp4"), "previous");
  std::size_t files = 0;
  for (const auto& e : fs::directory_iterator(dir)) files += e.is_regular_file();
  EXPECT_EQ(files, 2u) << "old.mp4 and err.txt: no temporary left";
  fs::remove_all(dir);
}

TEST(Video, BadRequestsAreUsageErrorsWithOneLine) {
  const fs::path dir = fresh_dir("video_usage");
  struct Case {
    std::string args;
    int code;
    std::string message;
  };
  const std::vector<Case> cases = {
      {"--video " + (dir / "a.avi").string(), 2, "--video '" + (dir / "a.avi").string() + "': unknown format (use .mp4 or .gif)"},
      {"--video " + (dir / "a.mp4").string() + " --size 161x90", 2, "--video: H.264 (.mp4) needs an even width and height, not 161x90"},
      {"", 2, "render: give -o DIR (frame PNGs), --video FILE, or both"},
      {"--video " + (dir / "a.mp4").string() + " --sheet", 2, "--sheet needs -o DIR"},
      {"--video " + (dir / "a.mp4").string() + " --anim 5", 1, "there is no animation '5'"},
  };
  for (const Case& c : cases) {
    const auto r = run_cli("render " + kSample + " --methods slerp --frames 0:3 -q " + c.args);
    EXPECT_EQ(r.exit_code, c.code) << c.args << ": " << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  EXPECT_FALSE(fs::exists(dir / "a.mp4"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rotinterp::render
