// The reducer (not installed): its constants and the class that runs the selection on one
// track (select.h) over a clip's joints (reduce/reduce.h says what it does).
#pragma once

#include "select.h"
#include "rotinterp/clip/loop.h"
#include "rotinterp/clip/metrics.h"
#include "rotinterp/interp/interpolator.h"
#include "rotinterp/reduce/reduce.h"

#include <atomic>
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace rotinterp::detail {

// A frame whose error with the joint keyed there is above this fraction of the
// budget is passed up to an ancestor (the joint's own key would leave nothing for
// the interpolator's round-off at keys, ~1e-9 rad).
inline constexpr double kFloorLimit = 1.0 - 1e-6;
// With a shell budget, a joint also keeps its children's positions (their own
// translation exact) within this share of the children's budget, so that they keep
// room for their own keys instead of passing frames back up. Measured on the shared
// clips at 1 mm at 10 cm (slerp): 2.5 % fewer keys in all than without (0.5: 13 %
// more, 0.8: 1 % fewer).
inline constexpr double kChildShare = 0.9;
// translation_tolerance's share of the shell budget. Measured at 1 mm at
// 10 cm (slerp, linear translations): CMU 01_01 25 055 → 22 060 keys (0.25: 21 965,
// but more in all over the shared clips in bench_reduce); the Bandai walk and the
// Xbox jump within 0.3 %.
inline constexpr double kTranslationShare = 0.5;
// A track is keyed at a frame its joint cannot meet only if being exact there lowers
// that joint's error by more than this share of its budget.
inline constexpr double kUseful = 0.01;

// A new rotation key starts from the source smoothed over a few milliseconds: a
// Gaussian in time whose neighbour at 1/120 s weighs half the frame itself (at 30 Hz
// a neighbour weighs 2e-5: nothing changes). Capture noise at 100–120 Hz is what it
// removes, which the C² splines would otherwise carry through every key: on CMU
// 01_01 at 1 mm at 10 cm c2 keeps 8 % fewer keys, bf 7 %; slerp as many.
inline constexpr double kStartSmoothing = 0.0070771;  // s: (1/120) / √(2 ln 2)
// The least weight of a frame in a refit, relative to the worst one's before the 6th
// power: frames within budget still pull (so that the worst one is not traded for them).
inline constexpr double kRefitWeightFloor = 0.5;

// The residuals of a frame with value q (see Reducer::refit_values).
using ResidualFn = std::function<double(std::size_t f, const Quat& q, double* out)>;

// f(lo, hi) for each run [lo, hi] of set frames in `mask`.
template <class F>
Status for_each_run(const std::vector<char>& mask, const F& f) {
  for (std::size_t lo = 0; lo < mask.size(); ++lo) {
    if (!mask[lo]) continue;
    std::size_t hi = lo;
    while (hi + 1 < mask.size() && mask[hi + 1]) ++hi;
    if (Status s = f(lo, hi); !s) return s;
    lo = hi;
  }
  return Ok{};
}
TranslationTrack translation_keys(const std::vector<double>& times, const std::vector<Vec3>& source,
                                  const std::vector<std::size_t>& kept);
// shell_error where it exceeds `limit`; below, possibly a bound between it and
// `limit` (|ΔP| + 2d·sin(θ/2), θ the angle between the world rotations, bounds every
// vertex's displacement): enough to tell within-budget frames, at a third of the cost.
// Inline: every frame measured runs it.
inline double shell_error_above(const Quat& r_ref, const Vec3& p_ref, const Quat& r_test, const Vec3& p_test, double d,
                                 double limit) {
  const double bound = (p_ref - p_test).norm() + 2.0 * d * (r_ref.conjugate() * r_test).vec().norm();
  return bound <= limit ? bound : shell_error(r_ref, p_ref, r_test, p_test, d);
}

class Reducer {
 public:
  // `cycle`: the clip's cycle check (reduce --loop), whose closing joints are looped.
  Reducer(const Clip& clip, const ReduceOptions& o, std::vector<ReduceBudget> budgets, std::optional<LoopCheck> cycle);
  Result<ReduceResult> run();
  // For the tests: measure every frame again in every pass, and after every new key
  // (the selection without remeasure.cpp and select_local.cpp: the same result); the
  // frames at which a rotation's error, floor or final pose was measured.
  void measure_everything() { measure_everything_ = true; }
  std::size_t frames_measured() const { return frames_measured_; }

 private:
  // A cycle's frames: keys lie in [0, frames) — the period, the seam's image (closed: the
  // last frame; open: one past it) left out; looped joints are rebuilt periodically.
  struct Cycle {
    LoopCheck check;
    std::size_t frames = 0;
    double period = 0.0;     // seconds
    std::vector<char> looped;  // [joint]: closes (not a miss of the check)
    std::vector<Vec3> offset;  // [joint]: its translation's per-cycle offset
  };
  Status set_cycle(LoopCheck check);
  bool looped(std::size_t j) const { return cycle_ && cycle_->looped[j]; }
  // The key frame a frame falls on: the seam for a looped joint's last frame of a closed cycle.
  std::size_t key_frame(std::size_t j, std::size_t f) const { return looped(j) && f >= cycle_->frames ? f - cycle_->frames : f; }
  // A looped joint's keys without the seam's image.
  std::vector<std::size_t> in_period(const std::vector<std::size_t>& keys) const {
    return std::vector<std::size_t>(keys.begin(), keys.end() - 1);
  }
  // The time of the seam's image: the closing key a looped track is written with.
  double closing_time() const {
    return cycle_->check.form == LoopForm::closed ? dense_.grid.times[n_ - 1] : dense_.grid.times[0] + cycle_->period;
  }
  Status select_track_keys(std::size_t j, std::vector<std::size_t>& keys, const ErrorFn& err, const KeyValues* values,
                           bool removal, std::vector<double>& e, bool known = false, std::size_t support = 0) {
    return looped(j) ? select_cycle_keys(keys, n_, err, values, removal, e)
                     : select_keys(keys, n_, err, values, removal, e, known, support);
  }

  const std::vector<double>& times() const { return dense_.grid.times; }
  int parent(std::size_t j) const { return clip_.skeleton.joints[j].parent; }

  // The translation track of j: keys, then its rebuilt values at every frame.
  Status select_translation(std::size_t j, bool removal, std::vector<double>& e);
  const Vec3& test_translation(std::size_t j, std::size_t f) const {
    return clip_.translations[j] ? test_translation_[j][f] : dense_.translation[j][f];
  }

  // World transform of j at f with local rotation q, its ancestors rebuilt.
  void test_world(std::size_t j, std::size_t f, const Quat& q, Quat& r, Vec3& p) const {
    const int pa = parent(j);
    if (pa < 0) {
      r = q;
      p = test_translation(j, f);
      return;
    }
    const auto pu = static_cast<std::size_t>(pa);
    r = test_rot_[pu][f] * q;
    p = test_pos_[pu][f] + test_rot_[pu][f] * test_translation(j, f);
  }

  // j's rotation curve through its keys at the frames `keys`.
  Result<std::unique_ptr<Interpolator>> curve(std::size_t j, const std::vector<std::size_t>& keys) const;
  // j's rotation at the frames [lo, hi], rebuilt through its keys at the frames `keys`, into q
  // (slerp outside a cycle: slerp_window.h, without building the curve).
  Status rebuild(std::size_t j, const std::vector<std::size_t>& keys, std::size_t lo, std::size_t hi, std::vector<Quat>& q) const;
  // Fitted values at the key frames `free` (refit.cpp).
  Result<bool> refit_values(std::size_t j, const std::vector<std::size_t>& keys, const std::vector<std::size_t>& free,
                            std::size_t lo, std::size_t hi, int blocks, const ResidualFn& residual);
  // The rotation keys of j (its translation chosen, its ancestors rebuilt).
  Status select_rotation(std::size_t j, bool removal, std::vector<double>& e);

  Status run_independent();

  // One track of a joint: its rotation, or its translation.
  struct Track {
    std::size_t joint;
    bool translation;
    bool operator==(const Track& o) const { return joint == o.joint && translation == o.translation; }
  };
  bool exact_at(const Track& t, std::size_t f) const;
  // (`chain`: j's ancestors, root first.)
  double floor_with_exact(std::size_t j, std::size_t f, const std::vector<Track>& exact,
                          const std::vector<std::size_t>& chain) const;
  std::vector<Track> tracks_to_key(std::size_t j, std::size_t f) const;
  std::vector<std::size_t> floor_frames(std::size_t j);
  Status run_hierarchical();

  // What a joint's last evaluation left (hierarchical runs), so that a later pass
  // measures again only the frames that moved since (remeasure.cpp).
  struct Measured {
    bool done = false;                      // its rotation selected once
    std::vector<std::size_t> rkeys, tkeys;  // the keys its curves were built through
    std::vector<Quat> values;               // the rotation keys' values then
    std::shared_ptr<const Interpolator> curve;  // the rotation curve through them
    std::vector<Quat> prepared;             // slerp: instead, its keys as make_slerp prepares them
    std::vector<double> error;              // [frame] the selection's rotation error
    std::vector<double> angle, shell;       // [frame] the result's local angle and shell error
    std::vector<char> floor;                // [frame] over budget with its own rotation exact
    std::vector<char> moved;                // [frame] its parent's pose or its translation moved since
  };
  // The method's support (interpolator.h); 0 (every frame) for a looped joint.
  int support(std::size_t j) const;
  // Frames where j's rotation curve through its keys now can differ from the measured
  // one's, and those whose inputs moved.
  std::vector<char> to_measure(std::size_t j) const;
  // j's rotation curve through its keys: the measured one while they are unchanged
  // (a global spline's whole-track build is the costly part of a later pass).
  Result<std::shared_ptr<const Interpolator>> current_curve(std::size_t j) const;
  bool keys_unchanged(std::size_t j) const;  // j's keys and their values as last measured
  // j's rotation through its keys at each run [lo, hi] of `mask`, handed to f(lo, hi, q):
  // current_curve's (kept in measured_[j] with `keep`), or slerp's evaluated in place.
  using RunFn = std::function<void(std::size_t lo, std::size_t hi, const std::vector<Quat>& q)>;
  Status for_each_rebuilt_run(std::size_t j, const std::vector<char>& mask, bool keep, const RunFn& f);
  // j's translation selected again if its keys changed (or never selected); the frames
  // where its rebuilt translation moved marked.
  Status update_translation(std::size_t j, bool first, std::vector<double>& e);
  // j's rebuilt rotation, world pose and errors at the frames `mask` (every frame the
  // first time); the children's frames whose parent pose moved marked; the maxima.
  Status settle_rotation(std::size_t j, const std::vector<char>& mask);

  const Clip& clip_;
  const ReduceOptions& o_;
  std::vector<ReduceBudget> budget_;
  DenseClip dense_;
  std::vector<std::vector<Quat>> value_;  // [joint][frame]: the value of a key there
  std::vector<std::vector<Quat>> start_;  // [joint][frame]: the value a new key there starts from
  std::size_t n_ = 0, joints_ = 0;
  bool shell_ = false;
  bool slerp_ = false;  // the method is slerp and the grid's times strictly increase: slerp_window.h
  std::vector<std::vector<std::size_t>> rkeys_, tkeys_;
  std::vector<ReducedJoint> out_;
  std::vector<std::vector<std::size_t>> children_;
  std::vector<std::vector<Vec3>> test_translation_;
  std::vector<std::vector<Quat>> ref_rot_, test_rot_;
  std::vector<std::vector<Vec3>> ref_pos_, test_pos_;
  std::vector<Measured> measured_;  // [joint], hierarchical runs
  bool measure_everything_ = false;
  std::atomic<std::size_t> frames_measured_{0};
  std::optional<Cycle> cycle_;
  Status setup_ = Ok{};  // an error found building the cycle, returned by run()
};

}  // namespace rotinterp::detail
