#include "rotinterp/render/comparison.h"

#include "rotinterp/clip/frames.h"
#include "rotinterp/core/work_queue.h"
#include "rotinterp/core/rotation.h"
#include "rotinterp/interp/interpolator.h"
#include "rotinterp/interp/method_style.h"
#include "rotinterp/clip/metrics.h"
#include "rotinterp/render/colour_map.h"
#include "rotinterp/render/layout.h"
#include "rotinterp/render/video.h"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <charconv>
#include <cmath>
#include <deque>
#include <future>
#include <memory>

namespace rotinterp::render {

namespace fs = std::filesystem;

namespace {

Result<std::size_t> parse_count(std::string_view text, const char* what) {
  std::size_t value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size())
    return make_error(std::string(what) + " '" + std::string(text) + "' is not a non-negative integer");
  return value;
}

// A method's colour: its registry slot's (interp/method_style.h), as in eval's plots.
Color method_colour(const std::string& method) {
  const auto& rgb = method_style(method_slot(method)).rgb;
  return {rgb[0] / 255.0f, rgb[1] / 255.0f, rgb[2] / 255.0f};
}

// The clip's frames (clip/frames.h, as eval measures them), and every method
// rebuilt from its keys.
struct Rebuild {
  const Clip* clip = nullptr;
  DenseClip dense;                            // the reference at every frame
  std::vector<Vec3> bone_axis;                // [joint]
  std::vector<std::size_t> keys;              // frames kept as keys
  std::vector<bool> animated;                 // [joint]: more than one key in the source
  bool any_animated = false;
  std::vector<std::vector<std::unique_ptr<Interpolator>>> interpolators;  // [method][joint]

  static Result<Rebuild> build(const Clip& clip, const std::vector<std::string>& methods, std::size_t keep_every) {
    Rebuild r;
    r.clip = &clip;
    r.dense = dense_clip(clip);
    r.bone_axis = bone_axes(clip.skeleton);
    const std::size_t joints = clip.skeleton.joints.size();
    r.keys = keep_every_indices(r.frames(), keep_every);
    r.interpolators.resize(methods.size());
    r.animated.resize(joints);
    for (std::size_t j = 0; j < joints; ++j) {
      r.animated[j] = clip.rotations[j].keys.size() > 1;
      r.any_animated = r.any_animated || r.animated[j];
      const RotationTrack track =
          decimated_track(r.dense.grid.times, r.dense.rotation[j], r.animated[j] ? r.keys : std::vector<std::size_t>{0});
      for (std::size_t m = 0; m < methods.size(); ++m) {
        auto made = make_interpolator(methods[m], track);
        if (!made) return made.failure(methods[m] + ", joint " + clip.skeleton.joints[j].name + ": ");
        r.interpolators[m].push_back(std::move(made).value());
      }
    }
    return r;
  }

  std::size_t frames() const { return dense.grid.size(); }
  double time(std::size_t f) const { return dense.grid.times[f]; }

  // Translations are the reference's for every method (only rotations are rebuilt).
  std::vector<Vec3> translations(std::size_t f) const {
    std::vector<Vec3> t(dense.translation.size());
    for (std::size_t j = 0; j < t.size(); ++j) t[j] = dense.translation[j][f];
    return t;
  }

  void reference_pose(std::size_t f, WorldPose& out) const {
    std::vector<Quat> local(dense.rotation.size());
    for (std::size_t j = 0; j < local.size(); ++j) local[j] = dense.rotation[j][f];
    forward_kinematics(clip->skeleton, local, translations(f), out);
  }

  // Method m's rotations at frame f into `local`, its error (as eval measures it)
  // returned; with `joint_error`, every joint's error in degrees, and `worst` the
  // counted joint that errs most (-1 when none is counted).
  FrameError method_rotations(std::size_t m, std::size_t f, std::vector<Quat>& local,
                              std::vector<double>* joint_error = nullptr, int* worst = nullptr) const {
    local.resize(dense.rotation.size());
    if (joint_error) joint_error->assign(local.size(), 0.0);
    if (worst) *worst = -1;
    FrameError error;
    std::size_t counted = 0;
    for (std::size_t j = 0; j < local.size(); ++j) {
      local[j] = interpolators[m][j]->evaluate(time(f));
      const double e = angular_distance(dense.rotation[j][f], local[j]) * 180.0 / kPi;
      if (joint_error) (*joint_error)[j] = e;
      if (animated[j] || !any_animated) {
        error.mean += e;
        if (worst && (*worst < 0 || e > error.max)) *worst = static_cast<int>(j);
        error.max = std::max(error.max, e);
        ++counted;
      }
    }
    if (counted) error.mean /= static_cast<double>(counted);
    return error;
  }

  FrameError method_pose(std::size_t m, std::size_t f, WorldPose& out, std::vector<double>* joint_error = nullptr,
                         int* worst = nullptr) const {
    std::vector<Quat> local;
    const FrameError error = method_rotations(m, f, local, joint_error, worst);
    forward_kinematics(clip->skeleton, local, translations(f), out);
    return error;
  }

  // Method m's trail of `joint`'s bone direction over frames first…last.
  std::shared_ptr<Trail> trail(std::size_t m, int joint, std::size_t first, std::size_t last,
                               std::string label) const {
    const auto j = static_cast<std::size_t>(joint);
    const Vec3& axis = bone_axis[j];
    auto t = std::make_shared<Trail>();
    t->label = std::move(label);
    for (std::size_t f = first; f <= last; ++f) {
      t->reference.push_back(dense.rotation[j][f] * axis);
      t->method.push_back(interpolators[m][j]->evaluate(time(f)) * axis);
    }
    if (animated[j])
      for (std::size_t k : keys)
        if (k >= first && k <= last) t->keys.push_back(k - first);
    return t;
  }
};

// Writes PNGs on the work queue while the GL thread draws the next frame, at most
// kInFlight images at a time (bounded memory); the first failure stops it.
class PngWriters {
 public:
  PngWriters(ProgressFn progress, std::size_t total) : progress_(std::move(progress)), total_(total), queue_(2) {}

  // Blocks while kInFlight images wait. False once a write has failed.
  bool push(fs::path path, Image image) {
    while (writes_.size() >= kInFlight) collect_one();
    if (!error_.empty()) return false;
    writes_.push_back(queue_.submit([this, path = std::move(path), image = std::move(image)]() -> Status {
      if (failed_) return Ok{};
      Status s = write_png(image, path);
      if (!s) {
        failed_ = true;
        return s;
      }
      if (progress_) progress_(++done_, total_);
      return Ok{};
    }));
    return true;
  }
  // Waits for every image; the first error, if any.
  Status finish() {
    while (!writes_.empty()) collect_one();
    if (!error_.empty()) return make_error(error_);
    return Ok{};
  }

 private:
  static constexpr std::size_t kInFlight = 4;
  void collect_one() {
    Status s = writes_.front().get();
    writes_.pop_front();
    if (!s && error_.empty()) error_ = s.error();
  }

  ProgressFn progress_;
  std::size_t total_;
  std::atomic<std::size_t> done_{0};
  std::atomic<bool> failed_{false};
  std::deque<std::future<Status>> writes_;
  std::string error_;
  WorkQueue queue_;  // last: destroyed first, so its jobs finish while the members they use live
};

}  // namespace

Result<FrameRange> parse_frame_range(std::string_view text) {
  std::vector<std::string_view> parts;
  for (std::size_t begin = 0;;) {
    const std::size_t colon = text.find(':', begin);
    parts.push_back(text.substr(begin, colon == std::string_view::npos ? std::string_view::npos : colon - begin));
    if (colon == std::string_view::npos) break;
    begin = colon + 1;
  }
  if (parts.size() > 3) return make_error("--frames '" + std::string(text) + "' is not START[:END[:STEP]]");
  FrameRange r;
  auto start = parse_count(parts[0], "--frames start");
  if (!start) return start.failure();
  r.start = r.end = *start;
  if (parts.size() > 1) {
    auto end = parse_count(parts[1], "--frames end");
    if (!end) return end.failure();
    r.end = *end;
  }
  if (parts.size() > 2) {
    auto step = parse_count(parts[2], "--frames step");
    if (!step) return step.failure();
    r.step = *step;
  }
  if (r.end < r.start) return make_error("--frames '" + std::string(text) + "': END is before START");
  if (r.step == 0) return make_error("--frames '" + std::string(text) + "': STEP must be at least 1");
  return r;
}

Result<std::pair<int, int>> parse_size(std::string_view text) {
  const std::size_t x = text.find_first_of("xX");
  if (x == std::string_view::npos) return make_error("--size '" + std::string(text) + "' is not WxH (e.g. 960x540)");
  auto w = parse_count(text.substr(0, x), "--size width");
  auto h = parse_count(text.substr(x + 1), "--size height");
  if (!w || !h) return make_error("--size '" + std::string(text) + "' is not WxH (e.g. 960x540)");
  if (*w > 1000000 || *h > 1000000 || *w == 0 || *h == 0)
    return make_error("--size '" + std::string(text) + "' is outside 1…" + std::to_string(kMaxImageSide) + " per side");
  return std::pair<int, int>(static_cast<int>(*w), static_cast<int>(*h));
}

Result<Colouring> parse_colouring(std::string_view name) {
  if (name == "error") return Colouring::error;
  if (name == "method") return Colouring::method;
  return make_error("--colour '" + std::string(name) + "' is not error or method");
}

Result<CameraMode> parse_camera(std::string_view name) {
  if (name == "fixed") return CameraMode::fixed;
  if (name == "follow") return CameraMode::follow;
  return make_error("--camera '" + std::string(name) + "' is not fixed or follow");
}

Result<std::vector<FrameError>> comparison_errors(const Clip& clip, const std::string& method, std::size_t keep_every) {
  if (Status s = clip.validate(); !s) return s.failure();
  if (!find_method(method)) return make_error(unknown_method_message(method));
  auto rebuild = Rebuild::build(clip, {method}, std::max<std::size_t>(keep_every, 1));
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
// The fraction of frames a following view's box (and the error strip's scale)
// holds entirely: outliers — a reference pose in frame 0, a flip — do not shrink
// everything else.
constexpr double kRobustFraction = 0.98;

// The value below which `fraction` of `values` lie (nearest rank); 0 when empty.
double quantile(std::vector<double> values, double fraction) {
  if (values.empty()) return 0.0;
  const auto k = static_cast<std::size_t>(std::ceil(fraction * static_cast<double>(values.size()))) - 1;
  const auto at = values.begin() + static_cast<std::ptrdiff_t>(std::min(k, values.size() - 1));
  std::nth_element(values.begin(), at, values.end());
  return *at;
}
// A focus view's box is at least this fraction of the skeleton's height per side.
constexpr double kFocusMinimum = 0.2;
// A trail sample at the window's edge keeps this much of its colour.
constexpr float kTrailEdgeFade = 0.15f;

// Joint `joint` and every joint below it.
std::vector<bool> subtree(const Skeleton& skeleton, int joint) {
  std::vector<bool> in(skeleton.joints.size(), false);
  for (std::size_t j = 0; j < in.size(); ++j)
    for (int k = static_cast<int>(j); k >= 0; k = skeleton.joints[static_cast<std::size_t>(k)].parent)
      if (k == joint) {
        in[j] = true;
        break;
      }
  return in;
}

// The points of `pose` a view frames: every joint and End Site, or those of
// `limb` (subtree()) when it is not empty.
template <typename F>
void for_each_point(const Skeleton& skeleton, const WorldPose& pose, const std::vector<bool>& limb, F&& f) {
  for (std::size_t j = 0; j < pose.position.size(); ++j)
    if (limb.empty() || limb[j]) f(pose.position[j]);
  if (pose.end_site_position.size() != skeleton.end_sites.size()) return;
  for (std::size_t e = 0; e < skeleton.end_sites.size(); ++e)
    if (limb.empty() || limb[static_cast<std::size_t>(skeleton.end_sites[e].parent)]) f(pose.end_site_position[e]);
}

// What the camera frames over frames first…last (poses[f - first]): one box
// (fixed), or a box per frame that moves with the followed point, smoothed over
// `smoothing` seconds (follow). Following the root the box moves horizontally
// only (the ground stays put); following a focus joint it moves in 3-D.
struct Views {
  Bounds fixed;
  std::vector<Bounds> moving;  // [f - first]; empty when fixed
};

Views camera_views(const Rebuild& rebuild, const std::vector<WorldPose>& poses, std::size_t first, int followed,
                   const std::vector<bool>& limb, bool follow, double smoothing, double min_side) {
  const Skeleton& skeleton = rebuild.clip->skeleton;
  Views v;
  for (const WorldPose& pose : poses) for_each_point(skeleton, pose, limb, [&](const Vec3& p) { v.fixed.extend(p); });
  if (!follow || poses.empty()) return v;
  const bool focus = !limb.empty();
  const std::size_t n = poses.size();
  // The smoothing window in frames, from the mean frame spacing.
  const double span = rebuild.time(first + n - 1) - rebuild.time(first);
  const double spacing = n > 1 && span > 0.0 ? span / static_cast<double>(n - 1) : 1.0;
  const auto half = static_cast<std::size_t>(std::lround(smoothing / spacing));
  std::vector<Vec3> path(n), prefix(n + 1, Vec3::Zero());
  for (std::size_t i = 0; i < n; ++i) prefix[i + 1] = prefix[i] + poses[i].position[static_cast<std::size_t>(followed)];
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t lo = i >= half ? i - half : 0, hi = std::min(n - 1, i + half);
    path[i] = (prefix[hi + 1] - prefix[lo]) / static_cast<double>(hi - lo + 1);
    if (!focus) path[i].y() = 0.0;
  }
  // Each side of the box: where that side of the figure's own box lies, relative
  // to the path, in all but the most outlying frames.
  std::vector<double> sides[6];
  for (std::size_t i = 0; i < n; ++i) {
    Bounds b;
    for_each_point(skeleton, poses[i], limb, [&](const Vec3& p) { b.extend(p - path[i]); });
    if (b.empty()) continue;
    for (int a = 0; a < 3; ++a) {
      sides[a].push_back(-b.min(a));
      sides[3 + a].push_back(b.max(a));
    }
  }
  if (sides[0].empty()) return v;
  Bounds relative;
  for (int a = 0; a < 3; ++a) {
    relative.min(a) = -quantile(sides[a], kRobustFraction);
    relative.max(a) = quantile(sides[3 + a], kRobustFraction);
  }
  const Vec3 grow = (Vec3::Constant(min_side) - relative.size()).cwiseMax(0.0) * 0.5;
  relative.min -= grow;
  relative.max += grow;
  v.moving.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    v.moving[i].extend(relative.min + path[i]);
    v.moving[i].extend(relative.max + path[i]);
  }
  return v;
}

// Frames per second of the video: the source's rate over the frame step.
double default_video_fps(const Clip& clip, const Rebuild& rebuild, const std::vector<std::size_t>& frames) {
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

Result<ComparisonResult> render_comparison(const Clip& clip, const fs::path& out_dir, const ComparisonOptions& options) {
  // ---- validate everything before drawing anything ----
  if (Status s = clip.validate(); !s) return s.failure();
  if (options.methods.empty()) return make_error("no methods to compare");
  for (const std::string& m : options.methods)
    if (!find_method(m)) return make_error(unknown_method_message(m));
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

  auto built = Rebuild::build(clip, options.methods, options.keep_every);
  if (!built) return built.failure();
  const Rebuild& rebuild = *built;
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

  // Error strips: every method's error at every frame of the range, one scale.
  std::vector<std::shared_ptr<ErrorStrip>> strips(options.methods.size());
  if (options.strip) {
    std::vector<std::size_t> strip_keys;
    for (std::size_t k : rebuild.keys)
      if (k >= first && k <= last) strip_keys.push_back(k - first);
    std::vector<Quat> local;
    std::vector<double> maxima;
    for (std::size_t m = 0; m < strips.size(); ++m) {
      auto strip = std::make_shared<ErrorStrip>();
      for (std::size_t f = first; f <= last; ++f) {
        const FrameError e = rebuild.method_rotations(m, f, local);
        strip->max_deg.push_back(static_cast<float>(e.max));
        strip->mean_deg.push_back(static_cast<float>(e.mean));
        maxima.push_back(e.max);
      }
      strip->keys = strip_keys;
      strips[m] = std::move(strip);
    }
    // Spikes above the scale are clipped at the strip's top.
    for (auto& strip : strips) strip->scale_deg = error_scale(quantile(maxima, kRobustFraction));
  }

  std::error_code ec;
  if (options.pngs) {
    if (fs::exists(out_dir, ec) && !fs::is_directory(out_dir, ec))
      return make_error(out_dir.string() + ": is an existing file, not a directory for the frames");
    fs::create_directories(out_dir, ec);
    if (ec || !fs::is_directory(out_dir))
      return make_error(out_dir.string() + ": cannot create the output directory" + (ec ? ": " + ec.message() : ""));
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
    const bool is_key = std::binary_search(rebuild.keys.begin(), rebuild.keys.end(), f);
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
      p.color = method_colour(options.methods[m]);
      p.ghost = ghost;
      p.corner = corner;
      if (options.colouring == Colouring::error) {
        p.colour_scale_deg = scale;
        for (double e : joint_error[m]) p.joint_colors.push_back(error_colour(e, scale));
        if (worst[m] >= 0 && error.max > 0.0) {
          p.label_joint = worst[m];
          p.joint_label = fmt::format("{} {:.1f}°", clip.skeleton.joints[static_cast<std::size_t>(worst[m])].name, error.max);
        }
      }
      if (own_view) p.view = follow ? views.moving[f - first] : views.fixed;
      if (trail_joint >= 0) {
        auto trail = rebuild.trail(m, trail_joint, lo, hi, options.trail_joint + " bone direction");
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
      sheet[c].joint_colors.clear();
      for (double e : sheet_errors[c]) sheet[c].joint_colors.push_back(error_colour(e, scale));
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

}  // namespace rotinterp::render
