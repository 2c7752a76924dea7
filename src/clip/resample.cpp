// resample_clip: every joint rebuilt by its method on the new grid, translations by their curve.
#include "rotinterp/clip/resample.h"

#include "rotinterp/clip/frames.h"
#include "rotinterp/clip/key_limit.h"
#include "rotinterp/core/work_queue.h"
#include "rotinterp/interp/interpolator.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>
#include <thread>

namespace rotinterp {

namespace {


// The time of output frame i in a clip that keeps the source's frame time: what a
// reader of the written file gives (start + i·frame_time), so the output's key
// times sit on its own frame grid.
double label(const FrameGrid& grid, std::size_t i) { return grid.start + static_cast<double>(i) * grid.frame_time; }

// Moves key times onto the exact grid when every key is on it (the frame of each
// key, clip/frames.h, and no two keys on one frame); otherwise leaves them.
template <class Track>
void snap_times(Track& track, const FrameGrid& grid) {
  std::vector<double> snapped(track.times.size());
  std::optional<std::size_t> previous;
  for (std::size_t k = 0; k < track.times.size(); ++k) {
    // A key per frame is the common case: frame k, without a search, when it is within the snap.
    const bool own_frame = k < grid.times.size() && std::abs(grid.times[k] - track.times[k]) <= grid.snap;
    const std::optional<std::size_t> i = own_frame ? std::optional<std::size_t>(k) : grid.frame_at(track.times[k]);
    if (!i || (previous && *i <= *previous)) return;
    snapped[k] = grid.exact_time(*i);
    previous = i;
  }
  track.times = std::move(snapped);
}

// The key at exactly time t, if the track has one.
template <class Track>
const typename decltype(Track::keys)::value_type* key_at(const Track& track, double t) {
  const auto it = std::lower_bound(track.times.begin(), track.times.end(), t);
  if (it == track.times.end() || *it != t) return nullptr;
  return &track.keys[static_cast<std::size_t>(it - track.times.begin())];
}

// Whether the output frames are exactly the track's keys (a same-rate resample):
// then the keys are the output, and no curve is built.
template <class Track>
bool frames_are_keys(const Track& track, const std::vector<double>& eval_times) {
  return track.times == eval_times;
}

// What to compute, shared by all joints.
struct Plan {
  std::vector<double> eval_times;  // where the output frames are sampled (source timeline)
  std::vector<double> out_times;   // their times in the output clip
  // keep-every only: the source frame times that become keys.
  std::vector<double> key_times;
  bool keep_every = false;
};

// With `consumable` (the same clip as `in`, given up by the caller), joint j's
// tracks are moved out of it instead of copied: at the same rate the output then
// takes the source's key arrays as they are, without a first touch of new pages.
Status resample_joint(const Clip& in, Clip* consumable, std::size_t j, const std::string& method,
                      const ResampleOptions& opt, const std::optional<FrameGrid>& grid, const Plan& plan, Clip& out) {
  RotationTrack source = consumable ? std::move(consumable->rotations[j]) : in.rotations[j];
  if (grid) snap_times(source, *grid);

  RotationTrack keys_track;
  const RotationTrack* build_from = &source;
  if (plan.keep_every) {
    std::unique_ptr<Interpolator> source_curve;  // only for keys between source keys
    keys_track.times = plan.key_times;
    keys_track.keys.reserve(plan.key_times.size());
    for (double t : plan.key_times) {
      if (const Quat* q = key_at(source, t)) {
        keys_track.keys.push_back(*q);
        continue;
      }
      if (!source_curve) {
        auto made = make_interpolator(method, source);
        if (!made) return made.failure();
        source_curve = std::move(made.value());
      }
      keys_track.keys.push_back(source_curve->evaluate(t));
    }
    keys_track.make_sign_continuous();
    build_from = &keys_track;
  }

  RotationTrack& rot = out.rotations[j];
  rot.times = plan.out_times;
  rot.keys.resize(plan.eval_times.size());
  if (build_from->keys.size() == 1) {
    std::fill(rot.keys.begin(), rot.keys.end(), build_from->keys.front());
  } else if (frames_are_keys(*build_from, plan.eval_times)) {
    // Not one conditional expression: its mixed const lvalue and xvalue operands make a copy.
    if (build_from == &source) rot.keys = std::move(source.keys);
    else rot.keys = build_from->keys;
  } else {
    auto made = make_interpolator(method, *build_from);
    if (!made) return made.failure();
    made.value()->evaluate(plan.eval_times.data(), plan.eval_times.size(), rot.keys.data());
  }
  rot.make_sign_continuous();

  if (in.translations[j]) {
    TranslationTrack tsource = consumable ? std::move(*consumable->translations[j]) : *in.translations[j];
    if (grid) snap_times(tsource, *grid);
    TranslationTrack tkeys;
    const TranslationTrack* tbuild = &tsource;
    if (plan.keep_every) {
      std::optional<TranslationCurve> source_curve;
      tkeys.times = plan.key_times;
      for (double t : plan.key_times) {
        if (const Vec3* p = key_at(tsource, t)) {
          tkeys.keys.push_back(*p);
          continue;
        }
        if (!source_curve) source_curve.emplace(tsource, opt.translation);
        tkeys.keys.push_back(source_curve->evaluate(t));
      }
      tbuild = &tkeys;
    }
    TranslationTrack& tr = out.translations[j].emplace();
    tr.times = plan.out_times;
    if (frames_are_keys(*tbuild, plan.eval_times)) {
      if (tbuild == &tsource) tr.keys = std::move(tsource.keys);
      else tr.keys = tbuild->keys;
    } else {
      const TranslationCurve curve(*tbuild, opt.translation);
      tr.keys.resize(plan.eval_times.size());
      for (std::size_t k = 0; k < plan.eval_times.size(); ++k) tr.keys[k] = curve.evaluate(plan.eval_times[k]);
    }
  }
  return Ok{};
}

Result<Clip> resample(const Clip& in, Clip* consumable, const ResampleOptions& options) {
  ResampleOptions opt = options;
  if (Status s = in.validate(); !s) return s.failure();
  if (opt.fps && opt.keep_every) return make_error("give either a frame rate or keep-every, not both");
  if (opt.keep_every && *opt.keep_every < 1) return make_error("keep-every must be at least 1");
  if (opt.fps && (opt.fps->num <= 0 || opt.fps->den <= 0)) return make_error("frame rate must be greater than 0");

  // Methods per joint.
  const std::size_t n = in.skeleton.joints.size();
  if (!find_method(opt.method))
    return make_error(unknown_method_message(opt.method));
  std::vector<std::string> method(n, opt.method);
  for (const auto& [joint, name] : opt.method_for) {
    const int j = in.skeleton.find(joint);
    if (j < 0) return make_error("no joint '" + joint + "' in the clip (method override " + joint + "=" + name + ")");
    if (!find_method(name))
      return make_error(unknown_method_message(name) + " for joint '" + joint + "'");
    method[static_cast<std::size_t>(j)] = name;
  }

  // The source grid.
  std::optional<FrameGrid> grid;
  const double start = in.start_time();
  double duration = in.end_time() - start;
  if (FrameGrid g = frame_grid(in); g.rate) {  // keys on a grid of known rate
    grid = std::move(g);
    duration = grid->exact_time(grid->size() - 1) - start;
  }
  // Keys on no grid: the file's own frame rate (FBX GlobalSettings) is the default.
  if (const double stated = stated_rate_hz(in.source_record); !opt.fps && !grid && !opt.keep_every && stated > 0.0) {
    if (const Result<Rate> file_rate = rate_from_frame_time(1.0 / stated)) opt.fps = file_rate.value();
  }
  if (!opt.fps && !grid)
    return make_error(opt.keep_every ? "the clip has no frame rate, so it has no frames to keep (give --fps instead)"
                                     : "the clip has no frame rate; give an output rate (--fps)");

  // The range, in seconds from the first frame.
  double a = 0.0, b = duration;
  if (opt.range) {
    auto r = range_seconds(*opt.range, grid ? grid->rate : std::nullopt, duration);
    if (!r) return r.failure();
    a = r->first;
    b = r->second;
  }

  auto too_many = [n](std::size_t frames) {
    return make_error("resampling would give " + too_many_keys_text(static_cast<double>(frames), n) +
                      "; give a lower --fps or a --range");
  };
  Plan plan;
  Clip out = in.without_tracks();
  out.source_record = in.source_record;
  if (opt.keep_every) {
    const Rate& r = *grid->rate;
    const double fa = a * static_cast<double>(r.num) / static_cast<double>(r.den);
    const double fb = b * static_cast<double>(r.num) / static_cast<double>(r.den);
    const auto i0 = static_cast<std::size_t>(std::max(0.0, std::ceil(fa - 1e-6)));
    const auto i1 = std::min(grid->size() - 1, static_cast<std::size_t>(std::floor(fb + 1e-6)));
    if (i1 < i0) return make_error("range " + seconds_text(a) + ":" + seconds_text(b) + " s holds no frame");
    if (too_many_keys(static_cast<double>(i1 - i0 + 1), n)) return too_many(i1 - i0 + 1);
    plan.keep_every = true;
    for (std::size_t i = i0; i <= i1; ++i) {
      plan.eval_times.push_back(grid->exact_time(i));
      plan.out_times.push_back(label(*grid, i - i0));
    }
    for (std::size_t k : keep_every_indices(i1 - i0 + 1, *opt.keep_every)) plan.key_times.push_back(grid->exact_time(i0 + k));
    out.frame_time = in.frame_time;
  } else {
    const Rate rate = opt.fps ? *opt.fps : *grid->rate;
    TimeGrid g;
    g.start = start;
    g.offset = a;
    g.end = start + b;
    g.rate = rate;
    g.count = (!opt.range && grid) ? sample_count(grid->size(), *grid->rate, rate) : sample_count(b - a, rate);
    if (too_many_keys(static_cast<double>(g.count), n)) return too_many(g.count);
    plan.eval_times = g.times();
    if (opt.fps) {
      TimeGrid o = g;
      o.offset = 0.0;
      o.end = start + (b - a);
      plan.out_times = o.times();
      out.frame_time = rate.period();
      out.source_record = retimed(in.source_record);  // the file's frame time no longer holds
    } else {
      for (std::size_t k = 0; k < g.count; ++k) plan.out_times.push_back(label(*grid, k));
      out.frame_time = in.frame_time;
    }
  }
  // A cut starts at the clip's start: the writers find the source's frames that far on.
  if (!plan.eval_times.empty() && in.frame_time > 0.0)
    out.source_record = cut(out.source_record,
                            static_cast<std::size_t>(std::max(0.0, std::round((plan.eval_times.front() - start) / in.frame_time))));

  out.rotations.resize(n);
  out.translations.resize(n);
  unsigned threads = thread_count(opt.threads);
  threads = static_cast<unsigned>(std::min<std::size_t>(threads, n));
  // Tiny jobs are faster on one thread.
  if (plan.eval_times.size() * n < 20000) threads = 1;
  std::vector<Status> status(n, Status(Ok{}));
  {
    std::atomic<std::size_t> done{0};
    std::atomic<bool> stop{false};  // a joint failed by exception (out of memory): skip the rest
    WorkQueue queue(threads);
    std::vector<std::future<void>> joints;
    for (std::size_t j = 0; j < n; ++j)
      joints.push_back(queue.submit([&, j] {
        if (stop) return;
        try {
          status[j] = resample_joint(in, consumable, j, method[j], opt, grid, plan, out);
        } catch (...) {
          stop = true;
          throw;
        }
        const std::size_t d = ++done;
        if (opt.progress) opt.progress(d, n);
      }));
    for (auto& f : joints) f.get();  // rethrows the first exception, in joint order
  }
  for (std::size_t j = 0; j < n; ++j)
    if (!status[j]) return status[j].failure("joint '" + in.skeleton.joints[j].name + "': ");
  return out;
}

}  // namespace

Result<Clip> resample_clip(const Clip& clip, const ResampleOptions& options) { return resample(clip, nullptr, options); }

Result<Clip> resample_clip(Clip&& clip, const ResampleOptions& options) { return resample(clip, &clip, options); }

}  // namespace rotinterp
