// render's comparison planned before any GL: the options checked, the methods rebuilt, the body
// framed, and each frame's panels.
#include "rotinterp/render/comparison.h"

#include "comparison_panels.h"
#include "panel_parts.h"
#include "views.h"

#include "rotinterp/clip/frames.h"
#include "rotinterp/clip/rebuild.h"
#include "rotinterp/interp/interpolator.h"
#include "rotinterp/io/files/source_method.h"
#include "rotinterp/render/layout.h"
#include "rotinterp/render/option_text.h"
#include "rotinterp/render/video.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>

namespace rotinterp::render {

namespace {

// The file's own motion as a curve (render -m source): evaluated, not rebuilt
// from keys.
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

// The methods rebuilt on `clip`'s frames; with `cycle` (--loop), `clip` is its
// two periods and the curves are the cycle's; "source" is `source`'s motion.
Result<RebuiltClip> rebuild_methods(const Clip& clip, const std::vector<std::string>& methods, std::size_t keep_every,
                                    const CyclePlayedTwice* cycle, const SourceMotion& source) {
  if (cycle)
    return RebuiltClip::build(clip, methods, cycle->keys,
                              [cycle](const std::string& m, std::size_t j) { return cycle->curve(m, j); });
  if (std::none_of(methods.begin(), methods.end(), is_source)) return RebuiltClip::build(clip, methods, keep_every);
  // As RebuiltClip::build(clip, methods, keep_every) does, with the source's
  // curves beside.
  keep_every = std::max<std::size_t>(keep_every, 1);
  const DenseClip reference = dense_clip(clip);
  return RebuiltClip::build(clip, methods, keep_every_indices(reference.grid.size(), keep_every),
                            [&](const std::string& m, std::size_t j) -> Result<std::unique_ptr<Interpolator>> {
                              if (is_source(m))
                                return std::unique_ptr<Interpolator>(std::make_unique<SourceCurve>(source, j));
                              auto rebuilt =
                                  rebuild_joint(reference.grid.times, reference.rotation[j], m, keep_every, nullptr, j);
                              if (!rebuilt) return rebuilt.failure();
                              return std::move(rebuilt->curve);
                            });
}

}  // namespace

Result<std::vector<FrameError>> comparison_errors(const Clip& clip, const std::string& method, std::size_t keep_every,
                                                  const std::optional<LoopPlay>& loop, const SourceMotion& source) {
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
// A focus view's box is at least this fraction of the skeleton's height per
// side.
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

}  // namespace

struct ComparisonPlan::Impl {
  ComparisonOptions options;
  std::vector<std::size_t> frames;
  std::optional<CyclePlayedTwice> cycle;  // --loop: the clip is its two periods
  std::unique_ptr<RebuiltClip> rebuild;
  std::vector<WorldPose> reference;  // [f - first]
  Scene scene;
  PanelPlan plan;
  int columns = 1;
  int trail_joint = -1;
  std::size_t first = 0, last = 0;
  bool followed = false;
  double video_fps = 30.0;
};

ComparisonPlan::ComparisonPlan(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
ComparisonPlan::ComparisonPlan(ComparisonPlan&&) noexcept = default;
ComparisonPlan& ComparisonPlan::operator=(ComparisonPlan&&) noexcept = default;
ComparisonPlan::~ComparisonPlan() = default;
const Scene& ComparisonPlan::scene() const { return impl_->scene; }
const std::vector<std::size_t>& ComparisonPlan::frames() const { return impl_->frames; }
int ComparisonPlan::columns() const { return impl_->columns; }
bool ComparisonPlan::followed() const { return impl_->followed; }
double ComparisonPlan::video_fps() const { return impl_->video_fps; }

ComparisonPlan::Frame ComparisonPlan::frame(std::size_t i) const {
  const Impl& in = *impl_;
  const ComparisonOptions& options = in.options;
  const RebuiltClip& rebuild = *in.rebuild;
  const std::size_t f = in.frames[i], first = in.first, last = in.last, frame_count = rebuild.frames();
  const int trail_joint = in.trail_joint;
  FramePanels frame = frame_panels(rebuild, in.plan, f, in.reference[f - first]);
  if (trail_joint >= 0) {
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
                                  static_cast<float>(std::min(
                                      1.0, std::abs(rebuild.time(k) - rebuild.time(f)) / options.trail_window)));
    for (std::size_t m = 0; m < frame.panels.size(); ++m) {
      auto trail = make_trail(rebuild, m, trail_joint, lo, hi, options.trail_joint + " bone direction");
      trail->current = f - lo;
      trail->fade = fade;
      frame.panels[m].trail = std::move(trail);
    }
  }
  return Frame{frame.panels, options.sheet ? sheet_cells(in.plan, frame, f) : std::vector<Panel>{}};
}

Result<ComparisonPlan> ComparisonPlan::plan(const Clip& given, const ComparisonOptions& options,
                                            std::optional<CyclePlayedTwice> cycle_played) {
  auto impl = std::make_unique<Impl>();
  impl->cycle = std::move(cycle_played);
  const CyclePlayedTwice* cycle = impl->cycle ? &*impl->cycle : nullptr;
  const Clip& clip = cycle ? cycle->clip : given;  // the rebuild keeps pointing at its skeleton
  // ---- validate everything before drawing anything ----
  if (Status s = clip.validate(); !s) return s.failure();
  if (options.methods.empty()) return make_error("no methods to compare");
  if (Status s = check_methods(options.methods, options.source, cycle != nullptr); !s) return s.failure();
  if (options.keep_every < 1) return make_error("--keep-every must be at least 1");
  if (!options.pngs && options.video.empty()) return make_error("nothing to write: no frame images and no video");
  if (!options.pngs && options.sheet) return make_error("--sheet needs an output directory");
  const bool overlay = options.view == View::overlay;
  const int panel_count = overlay ? 1 : static_cast<int>(options.methods.size());
  if (Status s = check_image_size(options.width, options.height, panel_count); !s) return s.failure();
  int trail_joint = -1;
  if (!options.trail_joint.empty()) {
    trail_joint = clip.skeleton.find(options.trail_joint);
    if (trail_joint < 0) return make_error("--trail: no joint '" + options.trail_joint + "' in the clip");
  }
  if (!(options.trail_window >= 0.0) || !std::isfinite(options.trail_window))
    return make_error("--trail-window must be a number of seconds ≥ 0");
  if (Status s = check_view_options(options.view, false, trail_joint >= 0); !s) return s.failure();
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
  impl->options = options;
  impl->frames = std::move(selected).value();
  const std::vector<std::size_t>& frames = impl->frames;

  // Sheet cells: the frame images' panels, shrunk to fit kMaxImageSide.
  impl->columns = automatic_columns(panel_count, options.width, options.height);
  if (options.sheet) {
    const Rect sheet = sheet_size(grid_layout(panel_count, impl->columns, options.width, options.height).front(),
                                  frames.size(), panel_count);
    if (Status s = check_image_size(sheet.width, sheet.height, static_cast<int>(frames.size()) * panel_count,
                                    static_cast<int>(frames.size()));
        !s)
      return make_error(fmt::format(
          "--sheet: {} frames × {} panels do not fit {}x{} at a legible size; select fewer frames with --frames",
          frames.size(), panel_count, kMaxImageSide, kMaxImageSide));
  }
  const Backend backend = options.backend ? *options.backend : default_backend();
  if (options.backend && !backend_available(backend)) {
    auto probe = create_context(backend);
    return make_error(probe ? std::string(backend_name(backend)) + " is not available" : probe.error());
  }

  auto built = rebuild_methods(clip, options.methods, options.keep_every, cycle, options.source);
  if (!built) return built.failure();
  impl->rebuild = std::make_unique<RebuiltClip>(std::move(built).value());
  const RebuiltClip& rebuild = *impl->rebuild;
  const std::size_t frame_count = rebuild.frames();

  // Camera, trails (with no window) and strips cover the frames drawn; the
  // whole clip for one frame.
  const bool one_frame = frames.front() == frames.back();
  const std::size_t first = one_frame ? 0 : frames.front(), last = one_frame ? frame_count - 1 : frames.back();
  std::vector<WorldPose>& reference = impl->reference;
  reference.resize(last - first + 1);
  for (std::size_t f = first; f <= last; ++f) rebuild.reference_pose(f, reference[f - first]);
  const Body body = find_body(clip.skeleton, reference);
  Scene& scene = impl->scene;
  scene.skeleton = clip.skeleton;
  scene.thin = body.marker;
  for (const WorldPose& pose : reference)
    for_each_point(clip.skeleton, pose, body.kept, [&](const Vec3& p) { scene.bounds.extend(p); });
  scene.axes = draws_axes(options.axes, clip);

  // Follow: as asked, or (automatic) when the pelvis travels farther than the
  // skeleton is high; a focus joint is followed unless the camera is fixed.
  const double height = std::max(skeleton_height(rest_pose(clip.skeleton)), 1e-9);
  bool follow = options.camera == CameraMode::follow;
  if (options.camera == CameraMode::automatic) {
    if (focus_joint >= 0) {
      follow = true;
    } else {
      Bounds travel;
      const auto pelvis = static_cast<std::size_t>(body.pelvis);
      for (const WorldPose& pose : reference)
        if (pelvis < pose.position.size())
          travel.extend(Vec3(pose.position[pelvis].x(), 0.0, pose.position[pelvis].z()));
      follow = !travel.empty() && travel.size().norm() > height;
    }
  }
  Framing framing{body.kept, body.pelvis, false, kFollowSmoothing, 0.0};
  if (focus_joint >= 0)
    framing = Framing{subtree(clip.skeleton, focus_joint), focus_joint, true, kFocusSmoothing, kFocusMinimum * height};
  const Views views = camera_views(rebuild, reference, first, framing, follow);
  follow = follow && !views.moving.empty();  // nothing to follow: the fixed view
  if (focus_joint >= 0)                      // bones as thick for the limb as for a whole figure in its place
    scene.bone_radius = scene_bone_radius(clip.skeleton, follow ? views.moving.front() : views.fixed);

  PanelPlan& plan = impl->plan;
  plan.methods = options.methods;
  plan.overlay = overlay;
  plan.error_colours = !overlay && options.colouring == Colouring::error;
  for (const std::string& m : options.methods) plan.colours.push_back(method_colour(m));
  if (plan.error_colours) plan.scale = run_colour_scale(rebuild, plan.methods.size(), frames);
  if (follow)
    plan.moving = views.moving;
  else
    plan.view = views.fixed;
  plan.first = first;
  if (options.strip) plan.strips = error_strips(rebuild, plan, first, last);

  impl->followed = follow;
  impl->trail_joint = trail_joint;
  impl->first = first;
  impl->last = last;
  impl->video_fps = default_video_fps(clip, rebuild, frames);
  return ComparisonPlan(std::move(impl));
}

Result<ComparisonPlan> ComparisonPlan::make(const Clip& clip, const ComparisonOptions& options) {
  if (!options.loop) return plan(clip, options, std::nullopt);
  if (Status s = clip.validate(); !s) return s.failure();
  if (options.keep_every < 1) return make_error("--keep-every must be at least 1");
  auto cycle = play_cycle_twice(clip, *options.loop, options.keep_every);
  if (!cycle) return cycle.failure();
  ComparisonOptions twice = options;
  if (!twice.frames && twice.video.empty()) {  // the seam, one key interval
                                               // either side, at most 8 frames
    const std::size_t n = cycle->period_frames, k = options.keep_every;
    const std::size_t first = n > k ? n - k : 0, last = std::min(n + k, frame_grid(cycle->clip).size() - 1);
    twice.frames = FrameRange{first, last, std::max<std::size_t>(1, (last - first + 6) / 7)};
  }
  return plan(clip, twice, std::move(cycle).value());
}

}  // namespace rotinterp::render
