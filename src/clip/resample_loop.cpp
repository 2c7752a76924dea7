// resample --loop: every joint rebuilt on its periodic curve, one period out, closing as the input does.
#include "rotinterp/clip/resample_loop.h"

#include "rotinterp/clip/frames.h"
#include "rotinterp/interp/interpolator.h"
#include "rotinterp/interp/periodic.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace rotinterp {

namespace {

constexpr double kDegrees = 180.0 / kPi;
// Key times moved onto the exact frame grid where the clip has one (as resample does).
template <class Track>
Track on_grid(Track track, const FrameGrid& grid) {
  if (!grid.rate) return track;
  for (double& t : track.times)
    if (const std::optional<std::size_t> i = grid.frame_at(t)) t = grid.exact_time(*i);
  return track;
}

// The keys of one period in open form: those before t₀ + P (the closed form's last key repeats the first).
template <class Track>
Track one_period(const Track& track, double t0, double period, double frame) {
  Track open;
  for (std::size_t k = 0; k < track.times.size(); ++k)
    if (track.times[k] < t0 + period - 0.5 * frame) {
      open.times.push_back(track.times[k]);
      open.keys.push_back(track.keys[k]);
    }
  return open;
}

std::string percent(double x) {
  char s[32];
  std::snprintf(s, sizeof s, "%+.2f%%", 100.0 * x);
  return s;
}

}  // namespace

std::string CycleResample::summary() const {
  char head[200];
  std::snprintf(head, sizeof head, "cycle (%s form): %zu → %zu frames per period of %.4g s", loop_form_name(check.form),
                check.period_frames, period_frames, check.period);
  std::string s = head;
  if (stretch != 0.0) {
    char p[120];
    std::snprintf(p, sizeof p, "; period %s (%.4g s) for whole frames at the rate asked", percent(stretch).c_str(),
                  period);
    s += p;
  }
  if (!check.misses.empty()) s += "; " + closure_misses_text(check.misses) + ", kept as it is";
  return s;
}

Result<CycleResample> resample_cycle(const Clip& in, const ResampleOptions& options, std::optional<LoopForm> form,
                                     const LoopTolerance& tolerance) {
  if (Status s = in.validate(); !s) return s.failure();
  if (options.fps && options.keep_every) return make_error("give either a frame rate or keep-every, not both");
  if (options.keep_every && *options.keep_every < 1) return make_error("keep-every must be at least 1");
  if (options.range) return make_error("a cycle is resampled whole: --range and --loop do not go together");
  const std::size_t n = in.skeleton.joints.size();
  if (!find_method(options.method)) return make_error(unknown_method_message(options.method));
  std::vector<std::string> method(n, options.method);
  for (const auto& [joint, name] : options.method_for) {
    const int j = in.skeleton.find(joint);
    if (j < 0) return make_error("no joint '" + joint + "' in the clip (method override " + joint + "=" + name + ")");
    if (!find_method(name)) return make_error(unknown_method_message(name) + " for joint '" + joint + "'");
    method[static_cast<std::size_t>(j)] = name;
  }

  auto checked = check_loop(in, form, tolerance);
  if (!checked) return checked.failure();
  CycleResample result;
  result.check = *checked;
  const LoopCheck& check = result.check;
  if (!form && !check.looks_like_cycle)
    return make_error("--loop: the clip does not look like a cycle: " + loop_check_text(check) +
                      " (give --loop closed or --loop open to treat it as one)");

  const FrameGrid grid = frame_grid(in);
  if (options.keep_every && !grid.rate)
    return make_error("the clip has no frame rate, so it has no frames to keep (give --fps instead)");
  const double t0 = in.start_time();
  const double source_period = check.period;
  const double source_frame = source_period / static_cast<double>(check.period_frames);
  const bool closed = check.form == LoopForm::closed;

  // Where output frame k is sampled on the source timeline, and its own time.
  std::vector<double> eval_times, out_times, key_times;
  Clip out = in.without_tracks();
  if (options.keep_every) {
    result.period_frames = check.period_frames;
    result.period = source_period;
    for (std::size_t i = 0; i < check.period_frames + (closed ? 1 : 0); ++i) {
      eval_times.push_back(grid.exact_time(i));
      out_times.push_back(grid.start + static_cast<double>(i) * grid.frame_time);
    }
    for (std::size_t i = 0; i < check.period_frames; i += *options.keep_every) key_times.push_back(grid.exact_time(i));
    out.frame_time = in.frame_time;
    out.source_record = in.source_record;
  } else {
    const Result<Rate> own = rate_from_frame_time(source_frame);  // the source's rate: a round trip
    if (!options.fps && !own) return own.failure();
    const Rate rate = options.fps ? *options.fps : own.value();
    const double exact = source_period * rate.hz();
    result.period_frames = static_cast<std::size_t>(std::max(2.0, std::round(exact)));
    result.period = rate.time_of(static_cast<std::int64_t>(result.period_frames));
    result.stretch = std::abs(exact - std::round(exact)) < 1e-9 ? 0.0 : result.period / source_period - 1.0;
    for (std::size_t k = 0; k < result.period_frames + (closed ? 1 : 0); ++k) {
      eval_times.push_back(t0 + source_period * static_cast<double>(k) / static_cast<double>(result.period_frames));
      out_times.push_back(t0 + rate.time_of(static_cast<std::int64_t>(k)));
    }
    if (result.stretch == 0.0) eval_times = out_times;  // k/R exactly, as resample samples
    out.frame_time = rate.period();
    out.source_record = retimed(in.source_record);
  }

  std::vector<bool> loops(n, true);
  for (const ClosureMiss& m : check.misses) {
    loops[m.joint] = false;
    result.not_looped.push_back(m.name);
  }
  // A joint that closes is rebuilt on its periodic curve; one that misses closure as it is.
  auto period_of = [&](std::size_t j) { return loops[j] ? std::optional<double>(source_period) : std::nullopt; };
  out.rotations.resize(n);
  out.translations.resize(n);
  for (std::size_t j = 0; j < n; ++j) {
    const RotationTrack source = on_grid(in.rotations[j], grid);
    RotationTrack keys = loops[j] ? one_period(source, t0, source_period, source_frame) : source;
    if (keys.times.empty()) keys = source;  // a single key past the period: a still joint
    if (options.keep_every && keys.times.size() > 1) {
      auto whole = make_joint_curve(method[j], keys, period_of(j));
      if (!whole) return whole.failure("joint '" + in.skeleton.joints[j].name + "': ");
      RotationTrack sparse;
      sparse.times = key_times;
      if (!loops[j]) sparse.times.push_back(grid.exact_time(eval_times.size() - 1));  // its own last frame
      sparse.times.erase(std::unique(sparse.times.begin(), sparse.times.end()), sparse.times.end());
      for (double t : sparse.times) sparse.keys.push_back((*whole)->evaluate(t));
      sparse.make_sign_continuous();
      keys = std::move(sparse);
    }
    RotationTrack& rot = out.rotations[j];
    rot.times = out_times;
    rot.keys.resize(eval_times.size());
    if (keys.keys.size() == 1) {
      std::fill(rot.keys.begin(), rot.keys.end(), keys.keys.front());
    } else {
      auto curve = make_joint_curve(method[j], keys, period_of(j));
      if (!curve) return curve.failure("joint '" + in.skeleton.joints[j].name + "': ");
      (*curve)->evaluate(eval_times.data(), eval_times.size(), rot.keys.data());
    }
    rot.make_sign_continuous();

    if (!in.translations[j]) continue;
    const TranslationTrack tsource = on_grid(*in.translations[j], grid);
    TranslationTrack& tr = out.translations[j].emplace();
    tr.times = out_times;
    const TranslationTrack open = one_period(tsource, t0, source_period, source_frame);
    if (open.times.empty() || tsource.keys.size() < 2) {
      tr.keys.assign(out_times.size(), tsource.keys.front());
      continue;
    }
    const Vec3 offset = per_cycle_offset(tsource, check.form, source_frame);
    TranslationTrack tkeys = open;
    if (options.keep_every) {  // the kept frames only, read off the source's own periodic curve
      const PeriodicTranslationCurve whole(open, offset, t0, source_period, options.translation);
      tkeys.times = key_times;
      tkeys.keys.clear();
      for (double t : key_times) tkeys.keys.push_back(whole.evaluate(t));
    }
    const PeriodicTranslationCurve curve(tkeys, offset, t0, source_period, options.translation);
    for (double t : eval_times) tr.keys.push_back(curve.evaluate(t));
  }
  if (Status s = out.validate(); !s) return make_error("internal: the looped clip is not valid: " + s.error());
  result.clip = std::move(out);
  return result;
}

}  // namespace rotinterp
