// rotinterp render IN [-o DIR] [--video FILE] …: comparison frames of several interpolators, drawn
// offscreen (render/comparison.h does the work). Built only with the renderer.
#if ROTINTERP_HAVE_RENDER
#include "common.h"
#include "options.h"
#include "progress_line.h"
#include "rotinterp/clip/frames.h"
#include "rotinterp/clip/metrics.h"
#include "rotinterp/interp/interpolator.h"
#include "rotinterp/io/files/atomic_file.h"
#include "rotinterp/io/files/formats.h"
#include "rotinterp/io/read.h"
#include "rotinterp/io/source_motion.h"
#include "rotinterp/render/comparison.h"
#include "rotinterp/render/option_text.h"
#include "rotinterp/render/context.h"
#include "rotinterp/render/video.h"
#include "rotinterp/io/files/file_errors.h"

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rotinterp::cli {

namespace {

// Whether every joint lies at one point (within 1e-6 units) at rest and in the
// first frame: such a skeleton draws as nothing but the grid (a reader that lost
// the offsets, e.g. to helper nodes).
bool degenerate(const Clip& clip) {
  if (skeleton_height(rest_pose(clip.skeleton)) > 1e-6) return false;
  std::vector<Quat> rotation;
  std::vector<Vec3> translation;
  for (std::size_t j = 0; j < clip.skeleton.joints.size(); ++j) {
    rotation.push_back(clip.rotations[j].keys.front());
    translation.push_back(clip.translations[j] ? clip.translations[j]->keys.front() : clip.skeleton.joints[j].offset);
  }
  WorldPose first;
  forward_kinematics(clip.skeleton, rotation, translation, first);
  return skeleton_height(first) <= 1e-6;
}

// -o is the directory the frame PNGs go in: a name that reads as a file (out.png,
// walk.bvh, clip.mp4) or an existing file is refused with why, before anything is drawn.
Status check_output_directory(const std::string& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
    return make_error("-o '" + dir + "' is an existing file; -o names the directory the frame PNGs go in");
  std::string ext = fs::path(dir).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  static const char* const kFileExtensions[] = {".png", ".jpg", ".jpeg", ".gif", ".bmp", ".tif", ".tiff", ".webp", ".mp4",
                                                ".mov", ".mkv", ".webm", ".avi"};
  if (!fs::is_directory(dir, ec))
    for (const char* e : kFileExtensions)
      if (ext == e || format_named(ext))
        return make_error("-o '" + dir + "' looks like a file name (" + ext +
                          "); -o names the directory the frame PNGs go in (e.g. -o frames), --video FILE writes one "
                          "clip");
  return Ok{};
}

// Frames that are all keys show the source itself in every panel ("0.00° (key)"): say why.
void warn_if_only_keys(const Clip& clip, const render::ComparisonOptions& options) {
  auto frames = render::comparison_frames(clip, options);
  if (!frames || frames->empty()) return;  // render_comparison reports it
  const std::size_t count = frame_grid(clip).size(), n = options.keep_every, last = count - 1;
  const auto keys = keep_every_indices(count, n);
  for (std::size_t f : *frames)
    if (!std::binary_search(keys.begin(), keys.end(), f)) return;
  const std::string what = n == 1 ? "--keep-every 1 keeps every frame" : fmt::format("--keep-every {} keeps frames 0, {}, {}, …", n, n, 2 * n);
  const std::string fix = n == 1 ? "give --keep-every 2 or more"
                                 : fmt::format("draw frames between keys (e.g. --frames {}:{}:{}) or change --keep-every",
                                               std::min(frames->front() + n / 2, last),
                                               frames->back() + n / 2 <= last ? frames->back() + n / 2 : frames->back() - n / 2,
                                               options.frames->step);
  warn("every frame drawn is a key frame (" + what + "), so every method shows the source exactly (0° error); " + fix);
}

struct RenderArgs {
  std::string input;
  std::string out_dir;
  std::string methods = "all";
  std::string keep_every = "10";
  std::string frames;
  std::string size = "960x540";
  std::string trail;
  double trail_window = 1.0;
  bool sheet = false;
  std::string backend;
  std::string anim, unit;
  bool allow_external_files = false;
  std::string view = "overlay";
  std::string colour;  // empty: error (side)
  std::string camera;
  std::string focus;
  std::string axes = "auto";
  bool no_strip = false;
  std::string video;
  std::optional<double> video_fps;  // unset: the clip's rate over the frame step
  bool quiet = false;
  std::string loop = "off";  // --loop as written
};

int run_render(const RenderArgs& a) {
  render::ComparisonOptions options;
  if (a.out_dir.empty() && a.video.empty()) return fail_usage("render: give -o DIR (frame PNGs), --video FILE, or both");
  // Repeats stay: the same method twice draws two identical panels (a check of determinism).
  bool source = false;  // -m source: the file's own curves, a panel beside the methods
  for (const std::string& m : split_comma_list(a.methods)) {
    if (is_source_method(m)) {
      source = true;
      options.methods.push_back(kSourceMethodName);
      continue;
    }
    auto one = parse_methods(m, true);
    if (!one) return fail_usage(one.error());
    options.methods.insert(options.methods.end(), one->begin(), one->end());
  }
  if (options.methods.empty()) return fail_usage("--method '" + a.methods + "' names no method (valid: " + method_names() + ")");
  auto keep_every = parse_whole_option("--keep-every", a.keep_every, 1, kMaxKeepEvery);
  if (!keep_every) return fail_usage(keep_every.error());
  options.keep_every = static_cast<std::size_t>(*keep_every);
  if (!a.frames.empty()) {
    auto range = render::parse_frame_range(a.frames);
    if (!range) return fail_usage(range.error());
    options.frames = *range;
  }
  auto view = render::parse_view(a.view);
  if (!view) return fail_usage(view.error());
  options.view = *view;
  auto size = render::parse_size(a.size);
  if (!size) return fail_usage(size.error());
  options.width = size->first;
  options.height = size->second;
  const bool side = options.view == render::View::side;
  if (Status s = render::check_image_size(options.width, options.height, side ? static_cast<int>(options.methods.size()) : 1);
      !s)
    return fail_usage("--size: " + s.error());
  if (!a.backend.empty()) {
    auto backend = render::parse_backend(a.backend);
    if (!backend) return fail_usage("--backend: " + backend.error());
    if (!render::backend_available(*backend)) {
      auto probe = render::create_context(*backend);
      return fail(probe ? std::string(render::backend_name(*backend)) + " is not available" : probe.error());
    }
    options.backend = *backend;
  }
  options.trail_joint = a.trail;
  if (!(a.trail_window >= 0.0) || !std::isfinite(a.trail_window))
    return fail_usage("--trail-window must be a number of seconds ≥ 0");
  options.trail_window = a.trail_window;
  options.sheet = a.sheet;
  if (a.sheet && a.out_dir.empty()) return fail_usage("--sheet needs -o DIR");
  if (Status s = render::check_view_options(options.view, !a.colour.empty(), !a.trail.empty()); !s)
    return fail_usage(s.error());
  if (!a.colour.empty()) {
    auto colouring = render::parse_colouring(a.colour);
    if (!colouring) return fail_usage(colouring.error());
    options.colouring = *colouring;
  }
  if (!a.camera.empty()) {
    auto camera = render::parse_camera(a.camera);
    if (!camera) return fail_usage(camera.error());
    options.camera = *camera;
  }
  options.focus_joint = a.focus;
  auto axes = render::parse_axes(a.axes);
  if (!axes) return fail_usage(axes.error());
  options.axes = *axes;
  options.strip = !a.no_strip;
  options.pngs = !a.out_dir.empty();
  if (!a.video.empty()) {
    auto format = render::video_format(a.video);
    if (!format) return fail_usage(format.error());
    if (Status s = render::check_video_size(*format, options.width, options.height); !s) return fail_usage(s.error());
    // 0 is refused like -5: it would otherwise mean "unset" and write 30 fps without a word.
    if (a.video_fps && !(*a.video_fps > 0.0 && *a.video_fps <= 1000.0))
      return fail_usage(fmt::format("--video-fps {:g} must be within (0, 1000] frames per second", *a.video_fps));
    options.video = a.video;
    options.video_fps = a.video_fps.value_or(0.0);
  } else if (a.video_fps) {
    return fail_usage("--video-fps needs --video FILE");
  }
  if (!a.out_dir.empty())
    if (Status s = check_output_directory(a.out_dir); !s) return fail_usage(s.error());
  auto loop = parse_loop_option(a.loop);
  if (!loop) return fail_usage(loop.error());
  if (*loop) options.loop = render::LoopPlay{(*loop)->form};
  if (source && options.loop)
    return fail_usage("--method source draws the file's own motion, which --loop cannot play as a cycle");

  protect_input(a.input);  // no frame written may replace it
  ReadOptions read_options;
  read_options.animation = a.anim;
  auto unit = parse_unit_option(a.unit);
  if (!unit) return fail_usage(unit.error());
  read_options.unit = *unit;
  read_options.allow_external_files = a.allow_external_files;
  read_options.on_warning = warn;
  auto clip = source ? read_clip_with_source_motion(a.input, read_options, options.source) : read_clip(a.input, read_options);
  if (!clip) return fail(clip.error());
  if (clip->skeleton.joints.size() > 1 && degenerate(*clip))
    warn(fmt::format("{}: all {} joints lie within 1e-6 units of one point; the frames will show {}", a.input,
                     clip->skeleton.joints.size(),
                     render::draws_axes(options.axes, *clip) ? "each joint's axes there (--axes)"
                                                             : "only the grid (--axes on draws each joint's axes)"));
  if (options.frames && !options.loop) warn_if_only_keys(*clip, options);
  options.progress = make_progress("render", a.quiet, "frames");
  auto result = render::render_comparison(*clip, a.out_dir, options);
  end_progress(a.quiet);
  // An output's error names the output; the others are about the input.
  if (!result) return fail(result.error_kind() == file_error::cannot_write ? result.error() : a.input + ": " + result.error());
  if (!a.quiet) {
    const std::size_t images = result->files.size() - (a.video.empty() ? 0 : 1);
    const std::string camera = result->followed ? "camera following" : "fixed camera";
    if (!a.out_dir.empty()) fmt::print(stderr, "wrote {} image(s) to {} ({}, {})\n", images, a.out_dir, camera, result->gl);
    if (!a.video.empty())
      fmt::print(stderr, "wrote {} ({} frames at {:g} fps, {}, {})\n", a.video, result->video_frames, result->video_fps,
                 camera, result->gl);
  }
  for (const auto& f : result->files) fmt::print("{}\n", f.string());
  return kExitOk;
}

}  // namespace

void add_render_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<RenderArgs>();
  auto* sub = app.add_subcommand(
      "render", "Draw comparison frames offscreen: the clip rebuilt by several interpolators, side by side, as PNGs");
  sub->add_option("input", args->input, "Clip to read (BVH, FBX, glTF, Collada, …)")->required();
  add_output_option(*sub, args->out_dir,
                    "Output directory for frame_NNNNNN.png (created if missing); default none, then --video is needed");
  add_method_option(*sub, args->methods, true,
                    "all, one panel each; 'source' adds a panel of the file's own motion (FBX curves, glTF "
                    "samplers, BVH frames: the animator's motion, not rebuilt from keys)");
  add_keep_every_option(*sub, args->keep_every, false, "default 10");
  sub->add_option("--frames", args->frames,
                  "Frames to draw, START:END:STEP (END included; frame 0 = first frame). Default: 8 frames spread "
                  "over the clip, each halfway between two keys");
  sub->add_option("--size", args->size, "Image size WxH in pixels, at most 8192 per side")->default_val("960x540");
  sub->add_option("--trail", args->trail,
                  "Also draw this joint's bone direction over the frames on a unit sphere (reference vs method); "
                  "default: no trail");
  sub->add_option("--trail-window", args->trail_window,
                  "Seconds either side of the frame drawn on the trail, fading with distance in time; 0 = all the "
                  "frames drawn")
      ->default_val(1.0);
  sub->add_flag("--sheet", args->sheet, "Also write sheet.png: a column per frame, a row per method (--view side) or one row of overlays "
                "(default: off)");
  add_anim_option(*sub, args->anim, nullptr);
  add_unit_option(*sub, args->unit);
  add_external_files_option(*sub, args->allow_external_files);
  sub->add_option("--view", args->view,
                  "overlay: one panel, the truth as a pale ghost and each method over it in its own colour, named "
                  "in a legend (a 2° difference shows as a gap between bones); side: a panel per method, side by side")
      ->default_val("overlay")
      ->check(CLI::IsMember({"overlay", "side"}));
  sub->add_option("--colour", args->colour,
                  "With --view side. error (default): each bone coloured by its joint's angular error (viridis, one "
                  "scale for the whole run: every frame, video frame and sheet cell); method: one colour per method")
      ->check(CLI::IsMember({"error", "method"}));
  sub->add_option("--camera", args->camera,
                  "fixed or follow (default: follow the body's pelvis when it travels farther than the skeleton's "
                  "height over the frames drawn, or the joint with --focus)")
      ->check(CLI::IsMember({"fixed", "follow"}));
  sub->add_option("--focus", args->focus,
                  "Frame this joint and the joints below it (a hand, a foot), following it (default: the whole figure)");
  sub->add_option("--axes", args->axes,
                  "auto, on or off: each joint's axes as a small RGB triad (x red, y green, z blue), which shows "
                  "twist about a bone. Default auto: on when the clip has one joint or all its joints lie at one point")
      ->default_val("auto")
      ->check(CLI::IsMember({"auto", "on", "off"}));
  sub->add_flag("--no-strip", args->no_strip, "No error-over-time strip under the panels (default: drawn)");
  sub->add_option("--video", args->video,
                  "Also (or, without -o, only) encode the frames into FILE.mp4 (H.264) or FILE.gif through ffmpeg; "
                  "default frames: every frame of the clip");
  sub->add_option("--video-fps", args->video_fps,
                  "Video frame rate, (0, 1000] (default: the clip's rate over the frame step)");
  add_loop_option(*sub, args->loop,
                  "The cycle is played twice, time running on and the root moved on by its per-cycle offset, so the "
                  "seam is seen; each method is rebuilt on its periodic curve; --frames counts over both periods, and "
                  "without it (and without --video) the frames drawn run from one key interval before the seam to "
                  "one after.");
  sub->add_option("--backend", args->backend, "OpenGL context: osmesa or egl (default: osmesa where present)")
      ->check(CLI::IsMember({"osmesa", "egl"}));
  add_quiet_option(*sub, args->quiet);
  sub->callback([args, &exit_code] { exit_code = run_render(*args); });
}

}  // namespace rotinterp::cli

#endif  // ROTINTERP_HAVE_RENDER
