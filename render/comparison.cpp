// render's comparison: the frames selected, each drawn as one panel per method, the sheet and the video.
#include "rotinterp/render/comparison.h"

#include "panel_parts.h"
#include "png_writers.h"
#include "views.h"

#include "rotinterp/clip/frames.h"
#include "rotinterp/clip/rebuild.h"
#include "rotinterp/interp/interpolator.h"
#include "rotinterp/io/files/source_method.h"
#include "rotinterp/render/colour_map.h"
#include "rotinterp/render/layout.h"
#include "rotinterp/render/video.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>

namespace rotinterp::render {

namespace fs = std::filesystem;

namespace {

// The file's own motion as a curve (render -m source): evaluated, not rebuilt from keys.
class SourceCurve final : public Interpolator {
 public:
  SourceCurve(SourceMotion source, std::size_t joint) : source_(std::move(source)), joint_(joint) {}
  Quat evaluate(double t) const override { return source_(joint_, t); }

 private:
  SourceMotion source_;
  std::size_t joint_;
};

bool is_source(const std::string& method) { return method == kSourceMethodName; }

// Every method is a registry's, or "source" with the file's motion at hand.
Status check_methods(const std::vector<std::string>& methods, const SourceMotion& source, bool loop) {
  for (const std::string& m : methods) {
    if (!is_source(m)) {
      if (!find_method(m)) return make_error(unknown_method_message(m));
    } else if (!source) {
      return make_error("--method source needs the file's own curves (an FBX file with rotation curves)");
    } else if (loop) {
      return make_error("--method source draws the file's own motion, which --loop cannot play as a cycle");
    }
  }
  return Ok{};
}

// The methods rebuilt on `clip`'s frames; with `cycle` (--loop), `clip` is its two
// periods and the curves are the cycle's; "source" is `source`'s motion.
Result<RebuiltClip> rebuild_methods(const Clip& clip, const std::vector<std::string>& methods, std::size_t keep_every,
                                    const CyclePlayedTwice* cycle, const SourceMotion& source) {
  if (cycle) return RebuiltClip::build(clip, methods, cycle->keys,
                                       [cycle](const std::string& m, std::size_t j) { return cycle->curve(m, j); });
  if (std::none_of(methods.begin(), methods.end(), is_source)) return RebuiltClip::build(clip, methods, keep_every);
  // As RebuiltClip::build(clip, methods, keep_every) does, with the source's curves beside.
  keep_every = std::max<std::size_t>(keep_every, 1);
  const DenseClip reference = dense_clip(clip);
  return RebuiltClip::build(
      clip, methods, keep_every_indices(reference.grid.size(), keep_every),
      [&](const std::string& m, std::size_t j) -> Result<std::unique_ptr<Interpolator>> {
        if (is_source(m)) return std::unique_ptr<Interpolator>(std::make_unique<SourceCurve>(source, j));
        auto rebuilt = rebuild_joint(reference.grid.times, reference.rotation[j], m, keep_every, nullptr, j);
        if (!rebuilt) return rebuilt.failure();
        return std::move(rebuilt->curve);
      });
}

}  // namespace

Result<std::vector<FrameError>> comparison_errors(const Clip& clip, const std::string& method, std::size_t keep_every,
                                                  const std::optional<LoopPlay>& loop,
                                                  const SourceMotion& source) {
  if (Status s = clip.validate(); !s) return s.failure();
  if (Status s = check_methods({method}, source, loop.has_value()); !s) return s.failure();
  keep_every = std::max<std::size_t>(keep_every, 1);
  std::optional<CyclePlayedTwice> cycle;
  if (loop) {
    auto twice = play_cycle_twice(clip, *loop, keep_every);
    if (!twice) return twice.failure();
    cycle = std::move(*twice);
  }
  auto rebuild = rebuild_methods(cycle ? cycle->clip : clip, {method}, keep_every, cycle ? &*cycle : nullptr, source);
  if (!rebuild) return rebuild.failure();
  std::vector<FrameError> errors(rebuild->frames());
  std::vector<Quat> local;
  for (std::size_t f = 0; f < errors.size(); ++f) errors[f] = rebuild->method_rotations(0, f, local);
  return errors;
}

Result<std::vector<std::size_t>> comparison_frames(const Clip& clip, const ComparisonOptions& options) {
  const std::size_t count = frame_grid(clip).size();
  if (count == 0) return make_error("the clip has no frames");
  std::vector<std::size_t> frames;
  if (options.frames) {
    const FrameRange& r = *options.frames;
    if (r.end >= count)
      return make_error(fmt::format("--frames {}:{}:{} runs past the clip's end (ends at frame {}, {:g} s)", r.start,
                                    r.end, r.step, count - 1, clip.end_time() - clip.start_time()));
    for (std::size_t k = r.start; k <= r.end; k += r.step) frames.push_back(k);
    return frames;
  }
  if (!options.video.empty()) {
    for (std::size_t k = 0; k < count; ++k) frames.push_back(k);
    return frames;
  }
  constexpr std::size_t kDefaultFrames = 8;
  const auto keys = keep_every_indices(count, std::max<std::size_t>(1, options.keep_every));
  std::vector<std::size_t> midpoints;
  for (std::size_t i = 0; i + 1 < keys.size(); ++i)
    if (keys[i + 1] - keys[i] >= 2) midpoints.push_back((keys[i] + keys[i + 1]) / 2);
  std::vector<std::size_t> pool = midpoints;
  if (pool.empty())
    for (std::size_t k = 0; k < count; ++k) pool.push_back(k);
  if (pool.size() <= kDefaultFrames) return pool;
  for (std::size_t i = 0; i < kDefaultFrames; ++i) {
    const std::size_t k = pool[(i * (pool.size() - 1) + (kDefaultFrames - 1) / 2) / (kDefaultFrames - 1)];
    if (frames.empty() || frames.back() != k) frames.push_back(k);
  }
  return frames;
}

namespace {

// Seconds of the centred moving average a following camera smooths its target
// with: the root's (steps, sway) and a focus joint's (faster, so shorter).
constexpr double kFollowSmoothing = 0.5;
constexpr double kFocusSmoothing = 0.1;
// A focus view's box is at least this fraction of the skeleton's height per side.
constexpr double kFocusMinimum = 0.2;
// A trail sample at the window's edge keeps this much of its colour.
constexpr float kTrailEdgeFade = 0.15f;

// Frames per second of the video: the source's rate over the frame step.
double default_video_fps(const Clip& clip, const RebuiltClip& rebuild, const std::vector<std::size_t>& frames) {
  double hz = 0.0;
  if (auto rate = clip_rate(clip)) hz = rate->hz();
  const std::size_t n = rebuild.frames();
  if (!(hz > 0.0) && n > 1 && rebuild.time(n - 1) > rebuild.time(0))
    hz = static_cast<double>(n - 1) / (rebuild.time(n - 1) - rebuild.time(0));
  if (!(hz > 0.0)) hz = 30.0;
  const std::size_t step = frames.size() > 1 ? frames[1] - frames[0] : 1;
  return std::clamp(hz / static_cast<double>(step), 0.01, 1000.0);
}

// render_comparison's work; `cycle`: --loop, `clip` being its two periods.
Result<ComparisonResult> render_frames(const Clip& clip, const fs::path& out_dir, const ComparisonOptions& options,
                                       const CyclePlayedTwice* cycle) {
  // ---- validate everything before drawing anything ----
  if (Status s = clip.validate(); !s) return s.failure();
  if (options.methods.empty()) return make_error("no methods to compare");
  if (Status s = check_methods(options.methods, options.source, cycle != nullptr); !s) return s.failure();
  if (options.keep_every < 1) return make_error("--keep-every must be at least 1");
  if (!options.pngs && options.video.empty()) return make_error("nothing to write: no frame images and no video");
  if (!options.pngs && options.sheet) return make_error("--sheet needs an output directory");
  const int methods = static_cast<int>(options.methods.size());
  if (Status s = check_image_size(options.width, options.height, methods); !s) return s.failure();
  int trail_joint = -1;
  if (!options.trail_joint.empty()) {
    trail_joint = clip.skeleton.find(options.trail_joint);
    if (trail_joint < 0) return make_error("--trail: no joint '" + options.trail_joint + "' in the clip");
  }
  if (!(options.trail_window >= 0.0) || !std::isfinite(options.trail_window))
    return make_error("--trail-window must be a number of seconds ≥ 0");
  int focus_joint = -1;
  if (!options.focus_joint.empty()) {
    focus_joint = clip.skeleton.find(options.focus_joint);
    if (focus_joint < 0) return make_error("--focus: no joint '" + options.focus_joint + "' in the clip");
  }
  if (!options.video.empty()) {
    auto format = video_format(options.video);
    if (!format) return format.failure();
    if (Status s = check_video_size(*format, options.width, options.height); !s) return s.failure();
    if (options.video_fps < 0.0 || options.video_fps > 1000.0 || !std::isfinite(options.video_fps))
      return make_error("--video-fps must be within (0, 1000]");
  }
  auto selected = comparison_frames(clip, options);
  if (!selected) return selected.failure();
  const std::vector<std::size_t>& frames = *selected;

  // Sheet cells: the frame images' panels, shrunk to fit kMaxImageSide.
  const int columns = automatic_columns(methods, options.width, options.height);
  const Rect panel = grid_layout(methods, columns, options.width, options.height).front();
  int cell_w = panel.width, cell_h = panel.height;
  const int sheet_columns = static_cast<int>(frames.size());
  if (options.sheet) {
    const double scale = std::min({1.0, static_cast<double>(kMaxImageSide) / (static_cast<double>(cell_w) * sheet_columns),
                                   static_cast<double>(kMaxImageSide) / (static_cast<double>(cell_h) * methods)});
    cell_w = static_cast<int>(std::floor(cell_w * scale));
    cell_h = static_cast<int>(std::floor(cell_h * scale));
    if (Status s = check_image_size(cell_w * sheet_columns, cell_h * methods, sheet_columns * methods, sheet_columns); !s)
      return make_error(fmt::format("--sheet: {} frames × {} methods do not fit {}x{} at a legible size; select "
                                    "fewer frames with --frames",
                                    frames.size(), methods, kMaxImageSide, kMaxImageSide));
  }
  const Backend backend = options.backend ? *options.backend : default_backend();
  if (options.backend && !backend_available(backend)) {
    auto probe = create_context(backend);
    return make_error(probe ? std::string(backend_name(backend)) + " is not available" : probe.error());
  }

  auto built = rebuild_methods(clip, options.methods, options.keep_every, cycle, options.source);
  if (!built) return built.failure();
  const RebuiltClip& rebuild = *built;
  const std::size_t frame_count = rebuild.frames();

  // Camera, trails (with no window) and strips cover the frames drawn; the whole
  // clip for one frame.
  const bool one_frame = frames.front() == frames.back();
  const std::size_t first = one_frame ? 0 : frames.front(), last = one_frame ? frame_count - 1 : frames.back();
  std::vector<WorldPose> reference(last - first + 1);
  for (std::size_t f = first; f <= last; ++f) rebuild.reference_pose(f, reference[f - first]);
  Scene scene;
  scene.skeleton = clip.skeleton;
  for (const WorldPose& pose : reference)
    for_each_point(clip.skeleton, pose, {}, [&](const Vec3& p) { scene.bounds.extend(p); });
  scene.axes = draws_axes(options.axes, clip);

  // Follow: as asked, or (automatic) when the root travels farther than the
  // skeleton is high; a focus joint is followed unless the camera is fixed.
  const double height = std::max(skeleton_height(rest_pose(clip.skeleton)), 1e-9);
  bool follow = options.camera == CameraMode::follow;
  if (options.camera == CameraMode::automatic) {
    if (focus_joint >= 0) {
      follow = true;
    } else {
      Bounds travel;
      for (const WorldPose& pose : reference)
        if (!pose.position.empty()) travel.extend(Vec3(pose.position[0].x(), 0.0, pose.position[0].z()));
      follow = !travel.empty() && travel.size().norm() > height;
    }
  }
  const std::vector<bool> limb = focus_joint >= 0 ? subtree(clip.skeleton, focus_joint) : std::vector<bool>{};
  const Views views = camera_views(rebuild, reference, first, std::max(focus_joint, 0), limb, follow,
                                   focus_joint >= 0 ? kFocusSmoothing : kFollowSmoothing,
                                   focus_joint >= 0 ? kFocusMinimum * height : 0.0);
  follow = follow && !views.moving.empty();  // nothing to follow: the fixed view
  const bool own_view = follow || focus_joint >= 0;
  if (focus_joint >= 0) {  // bones as thick for the limb as for a whole figure in its place
    const Bounds& limb_box = follow ? views.moving.front() : views.fixed;
    scene.bone_radius = scene_bone_radius(clip.skeleton, limb_box);
  }

  std::vector<std::shared_ptr<ErrorStrip>> strips(options.methods.size());
  if (options.strip) strips = error_strips(rebuild, options.methods.size(), first, last);

  std::error_code ec;
  if (options.pngs) {
    if (fs::exists(out_dir, ec) && !fs::is_directory(out_dir, ec))
      return make_error(out_dir.string() + ": is an existing file, not a directory for the frames");
  }

  auto context = create_context(backend);
  if (!context) return context.failure();
  auto renderer = Renderer::create(std::move(context).value(), std::move(scene));
  if (!renderer) return renderer.failure();

  ComparisonResult result;
  result.gl = (*renderer)->gl_description();
  result.followed = follow;
  std::unique_ptr<VideoWriter> video;
  if (!options.video.empty()) {
    result.video_fps = options.video_fps > 0.0 ? options.video_fps : default_video_fps(clip, rebuild, frames);
    auto opened = VideoWriter::open(options.video, options.width, options.height, result.video_fps);
    if (!opened) return opened.failure();
    video = std::move(opened).value();
  }
  const std::size_t total = frames.size() + (options.sheet ? 1 : 0);
  PngWriters writers(options.pngs ? options.progress : ProgressFn{}, total);
  bool writing = true;  // no write has failed yet
  std::vector<Panel> sheet(options.sheet ? frames.size() * options.methods.size() : 0);
  // The sheet's cells are coloured on one scale, its largest error, once all are known
  // (a frame's own scale made colours incomparable from column to column).
  std::vector<std::vector<double>> sheet_errors(sheet.size());
  double sheet_max = 0.0;
  std::vector<std::vector<double>> joint_error(options.methods.size());
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const std::size_t f = frames[i];
    const WorldPose& ghost = reference[f - first];
    const bool is_key = std::binary_search(rebuild.keys().begin(), rebuild.keys().end(), f);
    // The trail's window of frames around f, and how each fades.
    std::size_t lo = first, hi = last;
    if (options.trail_window > 0.0) {
      lo = f;
      while (lo > 0 && rebuild.time(f) - rebuild.time(lo - 1) <= options.trail_window) --lo;
      hi = f;
      while (hi + 1 < frame_count && rebuild.time(hi + 1) - rebuild.time(f) <= options.trail_window) ++hi;
    }
    std::vector<float> fade;
    if (options.trail_window > 0.0)
      for (std::size_t k = lo; k <= hi; ++k)
        fade.push_back(1.0f - (1.0f - kTrailEdgeFade) *
                                  static_cast<float>(std::min(1.0, std::abs(rebuild.time(k) - rebuild.time(f)) / options.trail_window)));
    std::vector<Panel> panels(options.methods.size());
    std::vector<FrameError> errors(panels.size());
    std::vector<int> worst(panels.size(), -1);
    double frame_max = 0.0;
    for (std::size_t m = 0; m < panels.size(); ++m) {
      errors[m] = rebuild.method_pose(m, f, panels[m].pose, &joint_error[m], &worst[m]);
      frame_max = std::max(frame_max, errors[m].max);
    }
    const double scale = error_scale(frame_max);  // one colour scale for every panel of the frame
    const std::string corner = fmt::format("frame {}   {:.3f} s", f, rebuild.time(f) - rebuild.time(0));
    for (std::size_t m = 0; m < panels.size(); ++m) {
      Panel& p = panels[m];
      const FrameError& error = errors[m];
      p.title = fmt::format("{}  mean {:.2f}°  max {:.2f}°{}", options.methods[m], error.mean, error.max,
                            is_key ? "  (key)" : "");
      p.colour = method_colour(options.methods[m]);
      p.ghost = ghost;
      p.corner = corner;
      if (options.colouring == Colouring::error) {
        p.colour_scale_deg = scale;
        for (double e : joint_error[m]) p.joint_colours.push_back(error_colour(e, scale));
        if (worst[m] >= 0 && error.max > 0.0) {
          p.label_joint = worst[m];
          p.joint_label = fmt::format("{} {:.1f}°", clip.skeleton.joints[static_cast<std::size_t>(worst[m])].name, error.max);
        }
      }
      if (own_view) p.view = follow ? views.moving[f - first] : views.fixed;
      if (trail_joint >= 0) {
        auto trail = make_trail(rebuild, m, trail_joint, lo, hi, options.trail_joint + " bone direction");
        trail->current = f - lo;
        trail->fade = fade;
        p.trail = std::move(trail);
      }
      if (strips[m]) {
        auto strip = std::make_shared<ErrorStrip>(*strips[m]);
        strip->cursor = f - first;
        p.strip = std::move(strip);
      }
      if (options.sheet) {
        Panel cell = p;
        cell.title = fmt::format("{} #{}  {:.2f}° / {:.2f}°", options.methods[m], f, error.mean, error.max);
        cell.corner.clear();
        sheet[m * frames.size() + i] = std::move(cell);
        sheet_errors[m * frames.size() + i] = joint_error[m];
        sheet_max = std::max(sheet_max, frame_max);
      }
    }
    auto image = (*renderer)->render(panels, options.width, options.height, columns);
    if (!image) return image.failure();
    if (video) {
      if (Status s = video->write(*image); !s) return s.failure();
      if (!options.pngs && options.progress) options.progress(i + 1, frames.size());
    }
    if (!options.pngs) continue;
    fs::path path = out_dir / fmt::format("frame_{:06d}.png", f);
    result.files.push_back(path);
    if (!writers.push(std::move(path), std::move(image).value())) {
      writing = false;
      break;
    }
  }
  if (options.sheet && options.colouring == Colouring::error) {
    const double scale = error_scale(sheet_max);
    for (std::size_t c = 0; c < sheet.size(); ++c) {
      sheet[c].colour_scale_deg = scale;
      sheet[c].joint_colours.clear();
      for (double e : sheet_errors[c]) sheet[c].joint_colours.push_back(error_colour(e, scale));
    }
  }
  if (options.sheet && writing) {
    auto image = (*renderer)->render(sheet, cell_w * sheet_columns, cell_h * methods, sheet_columns);
    if (!image) return image.failure();
    result.files.push_back(out_dir / "sheet.png");
    (void)writers.push(result.files.back(), std::move(image).value());
  }
  if (Status s = writers.finish(); !s) return s.failure();
  if (video) {
    if (Status s = video->finish(); !s) return s.failure();
    result.video_frames = video->frames();
    result.files.push_back(options.video);
  }
  return result;
}

}  // namespace

Result<ComparisonResult> render_comparison(const Clip& clip, const fs::path& out_dir, const ComparisonOptions& options) {
  if (!options.loop) return render_frames(clip, out_dir, options, nullptr);
  if (Status s = clip.validate(); !s) return s.failure();
  if (options.keep_every < 1) return make_error("--keep-every must be at least 1");
  auto cycle = play_cycle_twice(clip, *options.loop, options.keep_every);
  if (!cycle) return cycle.failure();
  ComparisonOptions twice = options;
  if (!twice.frames && twice.video.empty()) {  // the seam, one key interval either side, at most 8 frames
    const std::size_t n = cycle->period_frames, k = options.keep_every;
    const std::size_t first = n > k ? n - k : 0, last = std::min(n + k, frame_grid(cycle->clip).size() - 1);
    twice.frames = FrameRange{first, last, std::max<std::size_t>(1, (last - first + 6) / 7)};
  }
  return render_frames(cycle->clip, out_dir, twice, &*cycle);
}

}  // namespace rotinterp::render
