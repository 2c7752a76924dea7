#include "rotinterp/render/comparison.h"

#include "rotinterp/clip/frames.h"
#include "rotinterp/core/work_queue.h"
#include "rotinterp/core/rotation.h"
#include "rotinterp/interp/interpolator.h"
#include "rotinterp/render/layout.h"

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

// Solid colours of the methods (then repeating).
constexpr Color kPalette[] = {{0.96f, 0.56f, 0.20f}, {0.26f, 0.62f, 0.96f}, {0.40f, 0.80f, 0.38f},
                              {0.90f, 0.36f, 0.62f}, {0.94f, 0.82f, 0.28f}, {0.36f, 0.84f, 0.84f},
                              {0.66f, 0.52f, 0.94f}, {0.92f, 0.40f, 0.34f}};

// A method's colour follows its place in the registry, so a method looks the same
// in every image, whatever else is compared with it.
Color method_colour(const std::string& method) {
  const auto& all = methods();
  std::size_t i = 0;
  while (i < all.size() && all[i].name != method) ++i;
  return kPalette[i % std::size(kPalette)];
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
        if (!made) return make_error(methods[m] + ", joint " + clip.skeleton.joints[j].name + ": " + made.error());
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

  FrameError method_pose(std::size_t m, std::size_t f, WorldPose& out) const {
    std::vector<Quat> local(dense.rotation.size());
    FrameError error;
    std::size_t counted = 0;
    for (std::size_t j = 0; j < local.size(); ++j) {
      local[j] = interpolators[m][j]->evaluate(time(f));
      if (animated[j] || !any_animated) {
        const double e = angular_distance(dense.rotation[j][f], local[j]) * 180.0 / kPi;
        error.mean += e;
        error.max = std::max(error.max, e);
        ++counted;
      }
    }
    if (counted) error.mean /= static_cast<double>(counted);
    forward_kinematics(clip->skeleton, local, translations(f), out);
    return error;
  }

  // Method m's trail of `joint`'s bone direction over frames first…last.
  std::shared_ptr<const Trail> trail(std::size_t m, int joint, std::size_t first, std::size_t last,
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
  if (!start) return make_error(start.error());
  r.start = r.end = *start;
  if (parts.size() > 1) {
    auto end = parse_count(parts[1], "--frames end");
    if (!end) return make_error(end.error());
    r.end = *end;
  }
  if (parts.size() > 2) {
    auto step = parse_count(parts[2], "--frames step");
    if (!step) return make_error(step.error());
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

Result<std::vector<FrameError>> comparison_errors(const Clip& clip, const std::string& method, std::size_t keep_every) {
  if (Status s = clip.validate(); !s) return make_error(s.error());
  if (!find_method(method)) return make_error("unknown method '" + method + "' (valid: " + method_names() + ")");
  auto rebuild = Rebuild::build(clip, {method}, std::max<std::size_t>(keep_every, 1));
  if (!rebuild) return make_error(rebuild.error());
  std::vector<FrameError> errors(rebuild->frames());
  WorldPose pose;
  for (std::size_t f = 0; f < errors.size(); ++f) errors[f] = rebuild->method_pose(0, f, pose);
  return errors;
}

Result<std::vector<std::size_t>> comparison_frames(const Clip& clip, const ComparisonOptions& options) {
  const std::size_t count = frame_grid(clip).size();
  if (count == 0) return make_error("the clip has no frames");
  std::vector<std::size_t> frames;
  if (options.frames) {
    const FrameRange& r = *options.frames;
    if (r.end >= count)
      return make_error(fmt::format("--frames {}:{}:{} is outside the clip (frames 0…{})", r.start, r.end, r.step,
                                    count - 1));
    for (std::size_t k = r.start; k <= r.end; k += r.step) frames.push_back(k);
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

Result<ComparisonResult> render_comparison(const Clip& clip, const fs::path& out_dir, const ComparisonOptions& options) {
  // ---- validate everything before drawing anything ----
  if (Status s = clip.validate(); !s) return make_error(s.error());
  if (options.methods.empty()) return make_error("no methods to compare");
  for (const std::string& m : options.methods)
    if (!find_method(m)) return make_error("unknown method '" + m + "' (valid: " + method_names() + ")");
  if (options.keep_every < 1) return make_error("--keep-every must be at least 1");
  const int methods = static_cast<int>(options.methods.size());
  if (Status s = check_image_size(options.width, options.height, methods); !s) return make_error(s.error());
  int trail_joint = -1;
  if (!options.trail_joint.empty()) {
    trail_joint = clip.skeleton.find(options.trail_joint);
    if (trail_joint < 0) return make_error("--trail: no joint '" + options.trail_joint + "' in the clip");
  }
  auto selected = comparison_frames(clip, options);
  if (!selected) return make_error(selected.error());
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
  if (!built) return make_error(built.error());
  const Rebuild& rebuild = *built;
  const std::size_t frame_count = rebuild.frames();

  // Trails and camera bounds cover the frames drawn; the whole clip for one frame.
  const bool one_frame = frames.front() == frames.back();
  const std::size_t first = one_frame ? 0 : frames.front(), last = one_frame ? frame_count - 1 : frames.back();
  std::vector<std::shared_ptr<const Trail>> trails(options.methods.size());
  if (trail_joint >= 0)
    for (std::size_t m = 0; m < options.methods.size(); ++m)
      trails[m] = rebuild.trail(m, trail_joint, first, last, options.trail_joint + " bone direction");
  Scene scene;
  scene.skeleton = clip.skeleton;
  {
    WorldPose pose;
    for (std::size_t f = first; f <= last; ++f) {
      rebuild.reference_pose(f, pose);
      for (const Vec3& p : pose.position) scene.bounds.extend(p);
      for (const Vec3& p : pose.end_site_position) scene.bounds.extend(p);
    }
  }

  std::error_code ec;
  fs::create_directories(out_dir, ec);
  if (ec || !fs::is_directory(out_dir)) return make_error(out_dir.string() + ": cannot create the output directory");

  auto context = create_context(backend);
  if (!context) return make_error(context.error());
  auto renderer = Renderer::create(std::move(context).value(), std::move(scene));
  if (!renderer) return make_error(renderer.error());

  ComparisonResult result;
  result.gl = (*renderer)->gl_description();
  const std::size_t total = frames.size() + (options.sheet ? 1 : 0);
  PngWriters writers(options.progress, total);
  bool writing = true;  // no write has failed yet
  std::vector<Panel> sheet(options.sheet ? frames.size() * options.methods.size() : 0);
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const std::size_t f = frames[i];
    WorldPose ghost;
    rebuild.reference_pose(f, ghost);
    const bool is_key = std::binary_search(rebuild.keys.begin(), rebuild.keys.end(), f);
    std::vector<Panel> panels(options.methods.size());
    for (std::size_t m = 0; m < options.methods.size(); ++m) {
      Panel& p = panels[m];
      const FrameError error = rebuild.method_pose(m, f, p.pose);
      p.title = fmt::format("{}  mean {:.2f}°  max {:.2f}°{}", options.methods[m], error.mean, error.max,
                            is_key ? "  (key)" : "");
      p.color = method_colour(options.methods[m]);
      p.ghost = ghost;
      if (trails[m]) {
        auto trail = std::make_shared<Trail>(*trails[m]);
        trail->current = f - first;
        p.trail = std::move(trail);
      }
      if (options.sheet) {
        Panel cell = p;
        cell.title = fmt::format("{} #{}  {:.2f}° / {:.2f}°", options.methods[m], f, error.mean, error.max);
        sheet[m * frames.size() + i] = std::move(cell);
      }
    }
    auto image = (*renderer)->render(panels, options.width, options.height, columns);
    if (!image) return make_error(image.error());
    fs::path path = out_dir / fmt::format("frame_{:06d}.png", f);
    result.files.push_back(path);
    if (!writers.push(std::move(path), std::move(image).value())) {
      writing = false;
      break;
    }
  }
  if (options.sheet && writing) {
    auto image = (*renderer)->render(sheet, cell_w * sheet_columns, cell_h * methods, sheet_columns);
    if (!image) return make_error(image.error());
    result.files.push_back(out_dir / "sheet.png");
    (void)writers.push(result.files.back(), std::move(image).value());
  }
  if (Status s = writers.finish(); !s) return make_error(s.error());
  return result;
}

}  // namespace rotinterp::render
