// Frames per second of `rotinterp render`'s work: a 3-method, 960×540 comparison
// of a 31-joint clip.
//  * BM_DrawFrame: drawing one frame (3 panels, ghost + solid, grid, titles) and
//    reading it back, on each backend;
//  * BM_DrawAndEncodeFrame: the same plus writing the PNG (atomically), sequentially;
//  * BM_RenderComparison: the whole pipeline of render_comparison (keys every 10
//    frames, 3 interpolators, FK, error colouring with its colour bar and worst
//    joint label, the error strip, drawing, then PNG writing on worker threads —
//    or H.264 encoding through ffmpeg, no PNGs) over 48 frames of the synthetic
//    humanoid and of CMU 01_01 (31 joints), reported as frames per second
//    (items/s), context creation (and ffmpeg's start and finish) included.
#include "rotinterp/clip/clip.h"
#include "rotinterp/interp/interpolator.h"
#include "rotinterp/io/read.h"
#include "rotinterp/render/comparison.h"
#include "rotinterp/render/context.h"
#include "rotinterp/render/renderer.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

namespace {

using namespace rotinterp;
using namespace rotinterp::render;

// A 31-joint humanoid (CMU-like topology: hips, spine ×3, neck ×2, head, two arms
// of 7 and two legs of 5), 240 frames at 120 Hz of swinging limbs.
struct JointSpec {
  const char* name;
  int parent;
  double x, y, z;  // rest offset
};
constexpr JointSpec kHumanoid[] = {
    {"Hips", -1, 0, 17, 0},          {"LowerBack", 0, 0, 2, 0},        {"Spine", 1, 0, 2, 0},
    {"Spine1", 2, 0, 2, 0},          {"Neck", 3, 0, 1.5, 0},           {"Neck1", 4, 0, 1.5, 0},
    {"Head", 5, 0, 1.5, 0},          {"LeftShoulder", 3, 1.5, 1, 0},   {"LeftArm", 7, 3, 0, 0},
    {"LeftForeArm", 8, 5, 0, 0},     {"LeftHand", 9, 4.5, 0, 0},       {"LeftThumb", 10, 0.6, 0, 0.6},
    {"LeftFingers", 10, 0.8, 0, 0},  {"LeftFingerTip", 12, 0.7, 0, 0}, {"RightShoulder", 3, -1.5, 1, 0},
    {"RightArm", 14, -3, 0, 0},      {"RightForeArm", 15, -5, 0, 0},   {"RightHand", 16, -4.5, 0, 0},
    {"RightThumb", 17, -0.6, 0, 0.6}, {"RightFingers", 17, -0.8, 0, 0}, {"RightFingerTip", 19, -0.7, 0, 0},
    {"LeftHipJoint", 0, 1.5, -1, 0}, {"LeftUpLeg", 21, 0, -7, 0},      {"LeftLeg", 22, 0, -7, 0},
    {"LeftFoot", 23, 0, -1, 1.5},    {"LeftToeBase", 24, 0, 0, 1},     {"RightHipJoint", 0, -1.5, -1, 0},
    {"RightUpLeg", 26, 0, -7, 0},    {"RightLeg", 27, 0, -7, 0},       {"RightFoot", 28, 0, -1, 1.5},
    {"RightToeBase", 29, 0, 0, 1},
};

Clip humanoid_clip() {
  Clip clip;
  clip.name = "bench";
  clip.frame_time = 1.0 / 120.0;
  for (const JointSpec& spec : kHumanoid) {
    Joint j;
    j.name = spec.name;
    j.parent = spec.parent;
    j.offset = Vec3(spec.x, spec.y, spec.z);
    clip.skeleton.joints.push_back(j);
  }
  const std::size_t joints = clip.skeleton.joints.size();  // 31
  clip.rotations.resize(joints);
  clip.translations.resize(joints);
  for (std::size_t j = 0; j < joints; ++j) {
    for (int f = 0; f < 240; ++f) {
      const double t = f * clip.frame_time;
      const double w = 2.0 + 0.37 * static_cast<double>(j);
      clip.rotations[j].times.push_back(t);
      clip.rotations[j].keys.push_back(
          j == 0 ? Quat::Identity() : exp(RotVec(0.5 * std::sin(w * t), 0.3 * std::cos(1.3 * w * t), 0.4 * std::sin(0.7 * w * t + 1))));
    }
    clip.rotations[j].make_sign_continuous();
  }
  return clip;
}

WorldPose pose(const Clip& clip, std::size_t frame, double lag) {
  std::vector<Quat> local;
  std::vector<Vec3> translation;
  for (std::size_t j = 0; j < clip.skeleton.joints.size(); ++j) {
    const auto& keys = clip.rotations[j].keys;
    local.push_back(keys[frame].slerp(lag, keys[std::min(frame + 5, keys.size() - 1)]));
    translation.push_back(clip.skeleton.joints[j].offset);
  }
  WorldPose out;
  forward_kinematics(clip.skeleton, local, translation, out);
  return out;
}

struct Fixture {
  Clip clip = humanoid_clip();
  std::vector<std::vector<Panel>> frames;
  std::unique_ptr<Renderer> renderer;

  explicit Fixture(Backend backend) {
    Scene scene;
    scene.skeleton = clip.skeleton;
    for (std::size_t f = 0; f < 240; ++f)
      for (const Vec3& p : pose(clip, f, 0).position) scene.bounds.extend(p);
    for (std::size_t f = 0; f < 240; f += 4) {
      std::vector<Panel> panels(3);
      for (int m = 0; m < 3; ++m) {
        panels[m].title = "method " + std::to_string(m) + "  mean 1.23°  max 4.56°";
        panels[m].ghost = pose(clip, f, 0);
        panels[m].pose = pose(clip, f, 0.1 * m);
      }
      frames.push_back(std::move(panels));
    }
    auto context = create_context(backend);
    if (!context) return;
    auto r = Renderer::create(std::move(context).value(), std::move(scene));
    if (!r) return;
    renderer = std::move(r).value();
    (void)renderer->render(frames[0], 960, 540);  // warm-up: glyph atlases, framebuffers, shader variants
  }
};

void BM_DrawFrame(benchmark::State& state) {
  const Backend backend = state.range(0) == 0 ? Backend::osmesa : Backend::egl;
  Fixture fx(backend);
  if (!fx.renderer) {
    state.SkipWithError("no context for this backend");
    return;
  }
  std::size_t i = 0;
  for (auto _ : state) {
    auto image = fx.renderer->render(fx.frames[i++ % fx.frames.size()], 960, 540);
    benchmark::DoNotOptimize(image);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
  state.SetLabel(backend_name(backend));
}
BENCHMARK(BM_DrawFrame)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_DrawAndEncodeFrame(benchmark::State& state) {
  Fixture fx(default_backend());
  if (!fx.renderer) {
    state.SkipWithError("no context");
    return;
  }
  const auto path = std::filesystem::temp_directory_path() / "rotinterp_bench_frame.png";
  std::size_t i = 0;
  for (auto _ : state) {
    auto image = fx.renderer->render(fx.frames[i++ % fx.frames.size()], 960, 540);
    if (Status s = write_png(*image, path); !s) {
      state.SkipWithError(s.error().c_str());
      break;
    }
  }
  std::filesystem::remove(path);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}
BENCHMARK(BM_DrawAndEncodeFrame)->Unit(benchmark::kMillisecond)->UseRealTime();

// The whole pipeline over 48 frames: first arg 0 = the synthetic humanoid (frames
// 0…235 step 5), 1 = the real CMU 01_01 clip (31 joints, frames 100…570 step 10);
// second arg 0 = PNGs, 1 = an MP4 video only.
void BM_RenderComparison(benchmark::State& state) {
  if (methods().size() < 3) {
    state.SkipWithError("fewer than 3 interpolation methods are registered");
    return;
  }
  Clip clip;
  ComparisonOptions options;
  if (state.range(0) == 0) {
    clip = humanoid_clip();
    options.frames = FrameRange{0, 235, 5};
  } else {
    auto read = read_clip(std::string(ROTINTERP_SHARED_DATA) + "/bvh/cmu_01_01.bvh");
    if (!read) {
      state.SkipWithError(read.error().c_str());
      return;
    }
    clip = std::move(read).value();
    options.frames = FrameRange{100, 570, 10};
  }
  for (std::size_t m = 0; m < 3; ++m) options.methods.push_back(methods()[m].name);
  options.keep_every = 10;
  const auto dir = std::filesystem::temp_directory_path() / "rotinterp_bench_render";
  const bool video = state.range(1) == 1;
  if (video) {
    std::filesystem::create_directories(dir);
    options.pngs = false;
    options.video = dir / "bench.mp4";
  }
  for (auto _ : state) {
    auto result = render_comparison(clip, dir, options);
    if (!result) {
      state.SkipWithError(result.error().c_str());
      break;
    }
  }
  std::filesystem::remove_all(dir);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * 48);
  state.SetLabel(std::string(state.range(0) == 0 ? "synthetic humanoid" : "cmu_01_01.bvh") +
                 (video ? ", mp4" : ", png") + "; items/s = frames/s");
}
BENCHMARK(BM_RenderComparison)
    ->ArgsProduct({{0, 1}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(3);

}  // namespace

BENCHMARK_MAIN();
