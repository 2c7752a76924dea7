#include "rotinterp/reduce/reduce.h"

#include "rotinterp/clip/metrics.h"

#include "rotinterp/core/rotation.h"
#include "rotinterp/core/work_queue.h"
#include "rotinterp/interp/interpolator.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <future>
#include <memory>
#include <thread>

namespace rotinterp {

namespace {

// Keys rebuilt on either side of a key whose removal is checked: squad, expmap,
// clamped and gltf-cubic reach one key beyond a segment, so the frames between the
// removed key's second neighbours see exactly the whole track's curve; c2, bf and
// expmap-c2 are global, but the influence of a key decays by ≈ 0.27 per key, and
// the verification over every frame catches the rest.
constexpr std::size_t kWindow = 4;
// A frame whose error with the joint keyed there is above this fraction of the
// budget is passed up to an ancestor (the joint's own key would leave nothing for
// the interpolator's round-off at keys, ~1e-9 rad).
constexpr double kFloorLimit = 1.0 - 1e-6;
// With a shell budget, a joint also keeps its children's positions (their own
// translation exact) within this share of the children's budget, so that they keep
// room for their own keys instead of passing frames back up. Measured on the shared
// clips at 1 mm at 10 cm (slerp): 2.5 % fewer keys in all than without (0.5: 13 %
// more, 0.8: 1 % fewer).
constexpr double kChildShare = 0.9;
// translation_tolerance's share of the shell budget. Measured at 1 mm at
// 10 cm (slerp, linear translations): CMU 01_01 25 055 → 22 060 keys (0.25: 21 965,
// but more in all over the shared clips in bench_reduce); the Bandai walk and the
// Xbox jump within 0.3 %.
constexpr double kTranslationShare = 0.5;
// A track is keyed at a frame its joint cannot meet only if being exact there lowers
// that joint's error by more than this share of its budget.
constexpr double kUseful = 0.01;

// Normalized error (≤ 1: within budget) of the frames [lo, hi] of a curve rebuilt
// from the sorted key frames `keys` (which span [lo, hi]); out[f − lo].
using ErrorFn = std::function<Status(const std::vector<std::size_t>& keys, std::size_t lo, std::size_t hi, double* out)>;
// Key values that are fitted rather than copied from the source (rotation tracks):
//  * start(f) sets the value of a new key at f;
//  * reset(f) sets the value of a key at f back to the source's, true if it changed;
//  * refit(keys, free, lo, hi) tries values at the key frames `free` that bring the
//    frames [lo, hi] of the curve through `keys` within budget: true (and the values
//    kept) if it found them, false (and the values as they were) if not.
struct KeyValues {
  std::function<void(std::size_t f)> start;
  std::function<bool(std::size_t f)> reset;
  std::function<Result<bool>(const std::vector<std::size_t>& keys, const std::vector<std::size_t>& free, std::size_t lo,
                             std::size_t hi)>
      refit;
};

// A key whose removal leaves its neighbourhood at most this far over budget is
// tried again with its neighbours' values refitted, in at most kRefitIterations
// steps. Measured at 1 mm at 10 cm on CMU 01_01 and the Bandai walk (slerp, c2, bf):
// 1.25 and 2 keep as few keys as 2.0 and 3, within 2 %, in half the time (a refit
// far over budget that succeeds spends the neighbours' room).
constexpr double kRefitReach = 1.25;
constexpr int kRefitIterations = 2;
// A new rotation key starts from the source smoothed over a few milliseconds: a
// Gaussian in time whose neighbour at 1/120 s weighs half the frame itself (at 30 Hz
// a neighbour weighs 2e-5: nothing changes). Capture noise at 100–120 Hz is what it
// removes, which the C² splines would otherwise carry through every key: on CMU
// 01_01 at 1 mm at 10 cm c2 keeps 8 % fewer keys, bf 7 %; slerp as many.
constexpr double kStartSmoothing = 0.0070771;  // s: (1/120) / √(2 ln 2)
// The least weight of a frame in a refit, relative to the worst one's before the 6th
// power: frames within budget still pull (so that the worst one is not traded for them).
constexpr double kRefitWeightFloor = 0.5;

// Step 1 (and 3): insert the worst frame of every key interval over budget until none
// is. After an insertion only the frames between the second neighbours of each new key
// are measured again (the curve rebuilt from the keys around them, as in step 2), or
// every frame when those spans cover most of them; "none over budget" is always
// confirmed over every frame with the whole track. A new key takes its start value
// (rotations: the source smoothed by kStartSmoothing); a key frame over budget (a
// fitted value that its ancestors' later keys moved away from) gets the source's
// value back.
Status insert_worst(std::vector<std::size_t>& keys, std::size_t frames, const ErrorFn& err, const KeyValues* values,
                    std::vector<double>& e) {
  e.resize(frames);
  std::vector<std::size_t> add, merged, window;
  std::vector<std::pair<std::size_t, std::size_t>> spans;  // key index ranges to measure again
  bool full = true;
  for (;;) {
    if (full)
      if (Status s = err(keys, 0, frames - 1, e.data()); !s) return s;
    add.clear();
    for (std::size_t i = 0; i + 1 < keys.size(); ++i) {
      std::size_t worst = 0;
      double w = 1.0;
      for (std::size_t f = keys[i] + 1; f < keys[i + 1]; ++f)
        if (e[f] > w) w = e[f], worst = f;
      if (worst) add.push_back(worst);
    }
    if (add.empty()) {
      if (!full) {
        full = true;  // confirm with the whole track
        continue;
      }
      bool reset = false;
      if (values)
        for (std::size_t f : keys)
          if (e[f] > 1.0) reset = values->reset(f) || reset;
      if (!reset) return Ok{};
      continue;
    }
    if (values)
      for (std::size_t f : add) values->start(f);
    merged.clear();
    std::merge(keys.begin(), keys.end(), add.begin(), add.end(), std::back_inserter(merged));
    keys.swap(merged);
    spans.clear();
    std::size_t covered = 0;
    for (std::size_t f : add) {
      const auto i = static_cast<std::size_t>(std::lower_bound(keys.begin(), keys.end(), f) - keys.begin());
      const std::size_t a = i >= 2 ? i - 2 : 0, b = std::min(keys.size() - 1, i + 2);
      if (!spans.empty() && a <= spans.back().second) spans.back().second = b;
      else spans.emplace_back(a, b);
    }
    for (const auto& [a, b] : spans) covered += keys[b] - keys[a] + 1;
    full = 2 * covered > frames;
    if (full) continue;
    for (const auto& [a, b] : spans) {
      const std::size_t wa = a >= kWindow - 2 ? a - (kWindow - 2) : 0, wb = std::min(keys.size() - 1, b + kWindow - 2);
      window.assign(keys.begin() + static_cast<std::ptrdiff_t>(wa), keys.begin() + static_cast<std::ptrdiff_t>(wb + 1));
      if (Status s = err(window, keys[a], keys[b], e.data() + keys[a]); !s) return s;
    }
  }
}

// Step 2: drop every interior key whose neighbourhood stays within budget without it
// — with the values it has, else (fitted values) with its two neighbours' values
// refitted, checked between its third neighbours (a changed value reaches one key
// further than a removed one for the methods that reach beyond a segment).
Status remove_keys(std::vector<std::size_t>& keys, const ErrorFn& err, const KeyValues* values, std::vector<double>& e) {
  std::vector<std::size_t> window, free;
  for (std::size_t i = 1; i + 1 < keys.size();) {
    const std::size_t a = i >= kWindow ? i - kWindow : 0, b = std::min(keys.size() - 1, i + kWindow);
    window.assign(keys.begin() + static_cast<std::ptrdiff_t>(a), keys.begin() + static_cast<std::ptrdiff_t>(b + 1));
    window.erase(window.begin() + static_cast<std::ptrdiff_t>(i - a));
    const std::size_t lo = keys[i >= 2 ? i - 2 : 0], hi = keys[std::min(keys.size() - 1, i + 2)];
    e.resize(hi - lo + 1);
    if (Status s = err(window, lo, hi, e.data()); !s) return s;
    bool drop = *std::max_element(e.begin(), e.end()) <= 1.0;
    if (!drop && values && *std::max_element(e.begin(), e.end()) <= kRefitReach) {
      free = {keys[i - 1], keys[i + 1]};
      auto fitted = values->refit(window, free, keys[i >= 3 ? i - 3 : 0], keys[std::min(keys.size() - 1, i + 3)]);
      if (!fitted) return fitted.failure();
      drop = *fitted;
    }
    if (drop)
      keys.erase(keys.begin() + static_cast<std::ptrdiff_t>(i));
    else
      ++i;
  }
  return Ok{};
}

Status select_keys(std::vector<std::size_t>& keys, std::size_t frames, const ErrorFn& err, const KeyValues* values,
                   bool removal, std::vector<double>& e) {
  if (frames < 3) return Ok{};
  if (Status s = insert_worst(keys, frames, err, values, e); !s) return s;
  if (!removal) return Ok{};
  if (Status s = remove_keys(keys, err, values, e); !s) return s;
  return insert_worst(keys, frames, err, values, e);
}

std::vector<std::size_t> ends(std::size_t frames) {
  if (frames == 0) return {};
  if (frames == 1) return {0};
  return {0, frames - 1};
}

bool has(const std::vector<std::size_t>& keys, std::size_t f) { return std::binary_search(keys.begin(), keys.end(), f); }
void add_key(std::vector<std::size_t>& keys, std::size_t f) {
  auto it = std::lower_bound(keys.begin(), keys.end(), f);
  if (it == keys.end() || *it != f) keys.insert(it, f);
}

TranslationTrack translation_keys(const std::vector<double>& times, const std::vector<Vec3>& source,
                                  const std::vector<std::size_t>& kept) {
  TranslationTrack t;
  for (std::size_t f : kept) {
    t.times.push_back(times[f]);
    t.keys.push_back(source[f]);
  }
  return t;
}

// shell_error where it exceeds `limit`; below, possibly a bound between it and
// `limit` (|ΔP| + 2d·sin(θ/2), θ the angle between the world rotations, bounds every
// vertex's displacement): enough to tell within-budget frames, at a third of the cost.
double shell_error_above(const Quat& r_ref, const Vec3& p_ref, const Quat& r_test, const Vec3& p_test, double d,
                         double limit) {
  const double bound = (p_ref - p_test).norm() + 2.0 * d * (r_ref.conjugate() * r_test).vec().norm();
  return bound <= limit ? bound : shell_error(r_ref, p_ref, r_test, p_test, d);
}

// Every joint's rotations smoothed by the kStartSmoothing Gaussian over the frames on
// either side, as many on each side (the first and last frames stay as they are),
// weights below 1e-4 left out: the normalized weighted sum of the sign-aligned
// quaternions, which keeps a constant angular velocity on its geodesic.
std::vector<std::vector<Quat>> smoothed(const DenseClip& d) {
  std::vector<std::vector<Quat>> out = d.rotation;
  const std::vector<double>& t = d.grid.times;
  const std::size_t n = t.size();
  for (std::size_t j = 0; j < out.size(); ++j)
    for (std::size_t f = 1; f + 1 < n; ++f) {
      const Quat& centre = d.rotation[j][f];
      Eigen::Vector4d sum = centre.coeffs();
      for (std::size_t k = 1; k <= std::min(f, n - 1 - f); ++k) {
        const double dt = 0.5 * (t[f + k] - t[f - k]);
        const double w = std::exp(-dt * dt / (2.0 * kStartSmoothing * kStartSmoothing));
        if (w < 1e-4) break;
        for (const Quat& q : {d.rotation[j][f - k], d.rotation[j][f + k]})
          sum += (q.dot(centre) < 0.0 ? -w : w) * q.coeffs();
      }
      out[j][f].coeffs() = sum.normalized();
    }
  return out;
}

// The source's frames at their exact times, start + k/rate (BVH "Frame Time:
// 0.0333333" is 1/30 s, not 0.0333333 s): kept keys sit where resample puts frames,
// and a long clip's last key is not 1e-7·k early.
DenseClip exact_dense_clip(const Clip& clip) {
  DenseClip d = dense_clip(clip);
  if (d.grid.rate) {
    for (std::size_t k = 0; k < d.grid.size(); ++k) d.grid.times[k] = d.grid.exact_time(k);
    d.grid.frame_time = d.grid.rate->period();
  }
  return d;
}

class Reducer {
 public:
  Reducer(const Clip& clip, const ReduceOptions& o, std::vector<ReduceBudget> budgets)
      : clip_(clip), o_(o), budget_(std::move(budgets)), dense_(exact_dense_clip(clip)), value_(dense_.rotation),
        start_(smoothed(dense_)) {
    children_.resize(clip.skeleton.joints.size());
    for (std::size_t j = 0; j < clip.skeleton.joints.size(); ++j)
      if (clip.skeleton.joints[j].parent >= 0) children_[static_cast<std::size_t>(clip.skeleton.joints[j].parent)].push_back(j);
    n_ = dense_.grid.size();
    joints_ = clip.skeleton.joints.size();
    for (const ReduceBudget& b : budget_) shell_ = shell_ || b.shell > 0.0;
    rkeys_.assign(joints_, ends(n_));
    tkeys_.assign(joints_, {});
    for (std::size_t j = 0; j < joints_; ++j)
      if (clip.translations[j]) tkeys_[j] = ends(n_);
    out_.assign(joints_, ReducedJoint{});
    test_translation_.resize(joints_);
    if (shell_) {
      ref_rot_.assign(joints_, std::vector<Quat>(n_));
      ref_pos_.assign(joints_, std::vector<Vec3>(n_));
      test_rot_ = ref_rot_;
      test_pos_ = ref_pos_;
      for (std::size_t j = 0; j < joints_; ++j) {
        const int p = clip.skeleton.joints[j].parent;
        for (std::size_t f = 0; f < n_; ++f) {
          const Quat& q = dense_.rotation[j][f];
          const Vec3& t = dense_.translation[j][f];
          if (p < 0) {
            ref_rot_[j][f] = q;
            ref_pos_[j][f] = t;
          } else {
            const auto pu = static_cast<std::size_t>(p);
            ref_rot_[j][f] = ref_rot_[pu][f] * q;
            ref_pos_[j][f] = ref_pos_[pu][f] + ref_rot_[pu][f] * t;
          }
        }
      }
    }
  }

  Result<ReduceResult> run() {
    if (n_ >= 2) {
      if (Status s = shell_ ? run_hierarchical() : run_independent(); !s) return s.failure();
    } else {
      for (std::size_t j = 0; j < joints_; ++j) out_[j].budget = budget_[j];
    }
    ReduceResult r;
    r.reduced = clip_;
    r.source_keys = 0;
    for (std::size_t j = 0; j < joints_; ++j) {
      out_[j].rotation_frames = rkeys_[j];
      out_[j].translation_frames = tkeys_[j];
      r.reduced.rotations[j] = decimated_track(dense_.grid.times, value_[j], rkeys_[j]);
      r.source_keys += n_;
      r.kept_keys += rkeys_[j].size();
      if (clip_.translations[j]) {
        r.reduced.translations[j] = translation_keys(dense_.grid.times, dense_.translation[j], tkeys_[j]);
        r.source_keys += n_;
        r.kept_keys += tkeys_[j].size();
      }
    }
    r.joints = std::move(out_);
    r.grid = std::move(dense_.grid);
    return r;
  }

 private:
  const std::vector<double>& times() const { return dense_.grid.times; }
  int parent(std::size_t j) const { return clip_.skeleton.joints[j].parent; }

  // The translation track of j: keys, then its rebuilt values at every frame.
  Status select_translation(std::size_t j, bool removal, std::vector<double>& e) {
    if (!clip_.translations[j]) return Ok{};
    const double tol = budget_[j].translation;
    const std::vector<Vec3>& src = dense_.translation[j];
    ErrorFn err = [&](const std::vector<std::size_t>& keys, std::size_t lo, std::size_t hi, double* out) -> Status {
      const TranslationCurve curve(translation_keys(times(), src, keys), o_.translation);
      for (std::size_t f = lo; f <= hi; ++f) out[f - lo] = (curve.evaluate(times()[f]) - src[f]).norm() / tol;
      return Ok{};
    };
    if (Status s = select_keys(tkeys_[j], n_, err, nullptr, removal, e); !s) return s;
    const TranslationCurve curve(translation_keys(times(), src, tkeys_[j]), o_.translation);
    std::vector<Vec3>& t = test_translation_[j];
    t.resize(n_);
    double worst = 0.0;
    for (std::size_t f = 0; f < n_; ++f) {
      t[f] = curve.evaluate(times()[f]);
      worst = std::max(worst, (t[f] - src[f]).norm());
    }
    out_[j].max_translation_error = worst;
    return Ok{};
  }
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

  Result<std::vector<Quat>> rebuild(std::size_t j, const std::vector<std::size_t>& keys, std::size_t lo, std::size_t hi) const {
    auto curve = make_interpolator(o_.method, decimated_track(times(), value_[j], keys));
    if (!curve) return curve.failure();
    std::vector<Quat> q(hi - lo + 1);
    (*curve)->evaluate(times().data() + lo, q.size(), q.data());
    return q;
  }

  // Values at the key frames `free` of j's curve through `keys` that bring the frames
  // [lo, hi] within budget: Gauss–Newton on the residuals (`residual(f, q, out)`
  // fills 3·blocks numbers and returns the frame's error, the largest block norm),
  // each frame weighted by its error to the 6th power relative to the worst (Lawson's
  // reweighting: the sum of squares leans towards the largest error, the bound that
  // matters). Jacobians by forward differences of rotations of the values about their
  // own axes. True with the values stored if it gets there; else they are restored.
  template <class Residual>
  Result<bool> refit_values(std::size_t j, const std::vector<std::size_t>& keys, const std::vector<std::size_t>& free,
                            std::size_t lo, std::size_t hi, int blocks, const Residual& residual) {
    const std::size_t frames = hi - lo + 1, rows = 3 * static_cast<std::size_t>(blocks), params = 3 * free.size();
    std::vector<Quat> start(free.size());
    for (std::size_t k = 0; k < free.size(); ++k) start[k] = value_[j][free[k]];
    // Residuals and frame errors of the values as they are now; the worst error.
    Eigen::VectorXd r(frames * rows), rp(frames * rows), err(frames), errp(frames);
    Eigen::MatrixXd jac(frames * rows, params);
    auto measure = [&](Eigen::VectorXd& out, Eigen::VectorXd& e) -> Result<double> {
      auto q = rebuild(j, keys, lo, hi);
      if (!q) return q.failure();
      for (std::size_t f = 0; f < frames; ++f)
        e[static_cast<Eigen::Index>(f)] = residual(lo + f, (*q)[f], out.data() + f * rows);
      return e.maxCoeff();
    };
    auto first = measure(r, err);
    if (!first) return first.failure();
    double worst = *first;
    constexpr double kStep = 1e-6;  // rad: the forward difference
    for (int iteration = 0; iteration < kRefitIterations; ++iteration) {
      for (std::size_t p = 0; p < params; ++p) {
        Quat& v = value_[j][free[p / 3]];
        const Quat keep = v;
        v = apply_moving(keep, RotVec(Vec3::Unit(static_cast<Eigen::Index>(p % 3)) * kStep));
        if (auto m = measure(rp, errp); !m) return m.failure();
        v = keep;
        jac.col(static_cast<Eigen::Index>(p)) = (rp - r) / kStep;
      }
      Eigen::MatrixXd normal = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(params), static_cast<Eigen::Index>(params));
      Eigen::VectorXd g = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(params));
      for (std::size_t f = 0; f < frames; ++f) {
        const double w = std::pow(std::max(err[static_cast<Eigen::Index>(f)] / worst, kRefitWeightFloor), 6);
        const auto rows_f = static_cast<Eigen::Index>(rows), at = static_cast<Eigen::Index>(f * rows);
        normal.noalias() += w * jac.middleRows(at, rows_f).transpose() * jac.middleRows(at, rows_f);
        g.noalias() += w * jac.middleRows(at, rows_f).transpose() * r.segment(at, rows_f);
      }
      normal.diagonal().array() += 1e-9 * normal.diagonal().maxCoeff() + 1e-300;
      const Eigen::VectorXd step = -normal.ldlt().solve(g);
      if (!step.allFinite()) break;
      // The step, else a half, a quarter, … of it: the first that lowers the worst error.
      std::vector<Quat> before(free.size());
      for (std::size_t k = 0; k < free.size(); ++k) before[k] = value_[j][free[k]];
      bool better = false;
      for (double t = 1.0; t >= 1.0 / 16 && !better; t *= 0.5) {
        for (std::size_t k = 0; k < free.size(); ++k)
          value_[j][free[k]] = apply_moving(before[k], RotVec(t * step.segment<3>(static_cast<Eigen::Index>(3 * k))));
        auto now = measure(rp, errp);
        if (!now) return now.failure();
        if (*now <= 1.0) return true;
        if (*now < worst) better = true, worst = *now;
      }
      if (!better) break;
      r.swap(rp);
      err.swap(errp);
    }
    for (std::size_t k = 0; k < free.size(); ++k) value_[j][free[k]] = start[k];
    return false;
  }

  // The rotation keys of j (its translation chosen, its ancestors rebuilt).
  Status select_rotation(std::size_t j, bool removal, std::vector<double>& e) {
    const ReduceBudget& b = budget_[j];
    const double tol_rot = b.rotation_deg * kPi / 180.0, d = o_.shell_distance;
    const std::vector<Quat>& src = dense_.rotation[j];
    const bool shell = b.shell > 0.0;
    auto frame_error = [&](std::size_t f, const Quat& q) {
      double v = 0.0;
      if (tol_rot > 0.0) v = angular_distance(src[f], q) / tol_rot;
      if (shell) {
        Quat r;
        Vec3 p;
        test_world(j, f, q, r, p);
        v = std::max(v, shell_error_above(ref_rot_[j][f], ref_pos_[j][f], r, p, d, b.shell) / b.shell);
        // Headroom for the children: their positions (their own translation exact)
        // within a share of their budget.
        for (std::size_t c : children_[j]) {
          const double limit = kChildShare * budget_[c].shell;
          if (!(limit > 0.0)) continue;
          const Vec3 pc = p + r * dense_.translation[c][f];
          v = std::max(v, (ref_pos_[c][f] - pc).norm() / limit);
        }
      }
      return v;
    };
    ErrorFn err = [&](const std::vector<std::size_t>& keys, std::size_t lo, std::size_t hi, double* out) -> Status {
      auto q = rebuild(j, keys, lo, hi);
      if (!q) return q.failure();
      for (std::size_t f = lo; f <= hi; ++f) out[f - lo] = frame_error(f, (*q)[f - lo]);
      return Ok{};
    };
    // The residuals behind frame_error, each block normalized by its budget (the
    // error is the largest block norm): the local rotation error vector; the three
    // shell vertices' displacements; each child's displacement.
    std::vector<std::size_t> kids;
    for (std::size_t c : children_[j])
      if (budget_[c].shell > 0.0) kids.push_back(c);
    const int blocks = (tol_rot > 0.0 ? 1 : 0) + (shell ? 3 + static_cast<int>(kids.size()) : 0);
    auto residual = [&](std::size_t f, const Quat& q, double* out) {
      double worst = 0.0;
      auto put = [&](const Vec3& v) {
        std::copy(v.data(), v.data() + 3, out);
        out += 3;
        worst = std::max(worst, v.squaredNorm());
      };
      if (tol_rot > 0.0) put(displacement_moving(src[f], q).vec() / tol_rot);
      if (shell) {
        Quat r;
        Vec3 p;
        test_world(j, f, q, r, p);
        const Mat3 dr = (d / b.shell) * (ref_rot_[j][f].toRotationMatrix() - r.toRotationMatrix());
        const Vec3 dp = (ref_pos_[j][f] - p) / b.shell;
        for (int a = 0; a < 3; ++a) put(dp + dr.col(a));
        for (std::size_t c : kids)
          put((ref_pos_[c][f] - (p + r * dense_.translation[c][f])) / (kChildShare * budget_[c].shell));
      }
      return std::sqrt(worst);
    };
    KeyValues values;
    values.start = [&](std::size_t f) { value_[j][f] = start_[j][f]; };
    values.reset = [&](std::size_t f) {
      if (value_[j][f].coeffs() == src[f].coeffs()) return false;
      value_[j][f] = src[f];
      return true;
    };
    values.refit = [&](const std::vector<std::size_t>& keys, const std::vector<std::size_t>& free, std::size_t lo,
                       std::size_t hi) -> Result<bool> {
      return refit_values(j, keys, free, lo, hi, blocks, residual);
    };
    if (Status s = select_keys(rkeys_[j], n_, err, &values, removal, e); !s) return s;
    auto q = rebuild(j, rkeys_[j], 0, n_ - 1);
    if (!q) return q.failure();
    ReducedJoint& out = out_[j];
    out.budget = b;
    out.max_rotation_error = out.max_shell_error = 0.0;
    for (std::size_t f = 0; f < n_; ++f) {
      out.max_rotation_error = std::max(out.max_rotation_error, angular_distance(src[f], (*q)[f]));
      if (shell_) {
        test_world(j, f, (*q)[f], test_rot_[j][f], test_pos_[j][f]);
        out.max_shell_error = std::max(out.max_shell_error, shell_error(ref_rot_[j][f], ref_pos_[j][f], test_rot_[j][f], test_pos_[j][f], d));
      }
    }
    return Ok{};
  }

  Status run_independent() {
    unsigned threads = o_.threads ? o_.threads : std::max(1u, std::thread::hardware_concurrency());
    threads = static_cast<unsigned>(std::min<std::size_t>(threads, joints_));
    std::vector<Status> status(joints_, Status(Ok{}));
    std::atomic<std::size_t> done{0};
    {
      WorkQueue queue(threads);
      std::vector<std::future<void>> jobs;
      for (std::size_t j = 0; j < joints_; ++j)
        jobs.push_back(queue.submit([&, j] {
          std::vector<double> e;
          status[j] = select_translation(j, true, e);
          if (status[j]) status[j] = select_rotation(j, true, e);
          const std::size_t d = ++done;
          if (o_.progress) o_.progress(d, joints_);
        }));
      for (auto& f : jobs) f.get();
    }
    for (std::size_t j = 0; j < joints_; ++j)
      if (!status[j]) return status[j].failure("joint '" + clip_.skeleton.joints[j].name + "': ");
    return Ok{};
  }

  // One track of a joint: its rotation, or its translation.
  struct Track {
    std::size_t joint;
    bool translation;
    bool operator==(const Track& o) const { return joint == o.joint && translation == o.translation; }
  };
  // Whether a track is exact at f: keyed there, and a rotation key with the source's
  // value (not a fitted one).
  bool exact_at(const Track& t, std::size_t f) const {
    if (t.translation) return !clip_.translations[t.joint] || has(tkeys_[t.joint], f);
    return has(rkeys_[t.joint], f) && value_[t.joint][f].coeffs() == dense_.rotation[t.joint][f].coeffs();
  }

  // j's shell error at f with its own rotation exact and the tracks in `exact` exact
  // too (as if keyed at f); the others rebuilt.
  double floor_with_exact(std::size_t j, std::size_t f, const std::vector<Track>& exact) const {
    auto is_exact = [&](std::size_t k, bool translation) {
      return std::find(exact.begin(), exact.end(), Track{k, translation}) != exact.end();
    };
    std::vector<std::size_t> chain;  // j's ancestors, root first
    for (int a = parent(j); a >= 0; a = parent(static_cast<std::size_t>(a))) chain.insert(chain.begin(), static_cast<std::size_t>(a));
    Quat r = Quat::Identity();
    Vec3 p = Vec3::Zero();
    for (std::size_t k : chain) {
      const int pk = parent(k);
      const Quat local = is_exact(k, false) ? dense_.rotation[k][f]
                         : (pk < 0 ? test_rot_[k][f] : Quat(test_rot_[static_cast<std::size_t>(pk)][f].conjugate() * test_rot_[k][f]));
      p += r * (is_exact(k, true) ? dense_.translation[k][f] : test_translation(k, f));
      r = r * local;
    }
    p += r * (is_exact(j, true) ? dense_.translation[j][f] : test_translation(j, f));
    r = r * dense_.rotation[j][f];
    return shell_error(ref_rot_[j][f], ref_pos_[j][f], r, p, o_.shell_distance);
  }

  // The tracks to key at a frame f that j cannot meet: of the tracks not keyed there
  // — j's translation, then its ancestors' rotations and translations, nearest first
  // — those that lower j's error at f when exact (keying a track already right at f,
  // a constant offset say, buys nothing), as many as it takes to bring f within the
  // limit: one pass instead of one per level. Where that is not enough, all of them.
  std::vector<Track> tracks_to_key(std::size_t j, std::size_t f) const {
    const double limit = kFloorLimit * budget_[j].shell;
    std::vector<Track> candidates, exact;
    candidates.push_back({j, true});
    for (int a = parent(j); a >= 0; a = parent(static_cast<std::size_t>(a)))
      for (bool translation : {false, true}) candidates.push_back({static_cast<std::size_t>(a), translation});
    candidates.erase(std::remove_if(candidates.begin(), candidates.end(), [&](const Track& t) { return exact_at(t, f); }),
                     candidates.end());
    double err = floor_with_exact(j, f, exact);
    for (const Track& t : candidates) {
      if (err <= limit) return exact;
      exact.push_back(t);
      const double e = floor_with_exact(j, f, exact);
      if (e < err - kUseful * budget_[j].shell) err = e;
      else exact.pop_back();
    }
    return err <= limit ? exact : candidates;
  }

  // Frames over budget at j even with j's own rotation exact (its translation and
  // its ancestors rebuilt).
  std::vector<std::size_t> floor_frames(std::size_t j) const {
    std::vector<std::size_t> out;
    if (!(budget_[j].shell > 0.0)) return out;
    for (std::size_t f = 0; f < n_; ++f) {
      Quat r;
      Vec3 p;
      test_world(j, f, dense_.rotation[j][f], r, p);
      const double limit = kFloorLimit * budget_[j].shell;
      if (shell_error_above(ref_rot_[j][f], ref_pos_[j][f], r, p, o_.shell_distance, limit) > limit)
        out.push_back(f);
    }
    return out;
  }

  // Passes, parents first (the joints of one depth in parallel: each reads only its
  // ancestors' rebuilt motion). A joint with frames it cannot meet (floor_frames)
  // passes them up — to its own translation track, else to the nearest ancestor not
  // keyed there — and waits, with its subtree, for the next pass; the changed
  // joints' subtrees are verified again then (insertion only: keys only grow, so it
  // ends).
  Status run_hierarchical() {
    std::vector<std::size_t> depth(joints_, 0);
    std::vector<std::vector<std::size_t>> levels;
    for (std::size_t j = 0; j < joints_; ++j) {
      const int p = parent(j);
      depth[j] = p < 0 ? 0 : depth[static_cast<std::size_t>(p)] + 1;
      if (levels.size() <= depth[j]) levels.resize(depth[j] + 1);
      levels[depth[j]].push_back(j);
    }
    std::vector<char> dirty(joints_, 1), blocked(joints_, 0), translated(joints_, 0), rotated(joints_, 0);
    std::vector<std::vector<std::pair<Track, std::size_t>>> escalate(joints_);  // (track, frame) to key
    std::vector<Status> status(joints_, Status(Ok{}));
    std::atomic<std::size_t> finished{0};
    auto process = [&](std::size_t j) {
      std::vector<double> e;
      escalate[j].clear();
      status[j] = select_translation(j, !translated[j], e);
      if (!status[j]) return;
      translated[j] = 1;
      for (std::size_t f : floor_frames(j))
        for (const Track& t : tracks_to_key(j, f)) escalate[j].push_back({t, f});
      if (!escalate[j].empty()) {
        blocked[j] = 1;
        return;
      }
      status[j] = select_rotation(j, !rotated[j], e);
      rotated[j] = 1;
      dirty[j] = 0;
      const std::size_t done = ++finished;
      if (o_.progress) o_.progress(std::min(done, joints_), joints_);
    };
    unsigned threads = o_.threads ? o_.threads : std::max(1u, std::thread::hardware_concurrency());
    WorkQueue queue(static_cast<unsigned>(std::min<std::size_t>(threads, joints_)));
    for (;;) {
      std::fill(blocked.begin(), blocked.end(), 0);
      bool any = false;
      for (const std::vector<std::size_t>& level : levels) {
        std::vector<std::future<void>> jobs;
        for (std::size_t j : level) {
          const int p = parent(j);
          if (p >= 0 && blocked[static_cast<std::size_t>(p)]) {
            blocked[j] = 1;
            continue;
          }
          if (!dirty[j]) continue;
          any = true;
          jobs.push_back(queue.submit([&process, j] { process(j); }));
        }
        for (auto& f : jobs) f.get();
        for (std::size_t j : level)
          if (!status[j]) return status[j].failure("joint '" + clip_.skeleton.joints[j].name + "': ");
      }
      if (!any) return Ok{};
      // Key the escalated frames; verify each changed joint's subtree again.
      std::vector<char> changed(joints_, 0);
      for (const auto& list : escalate)
        for (const auto& [t, f] : list) {
          add_key(t.translation ? tkeys_[t.joint] : rkeys_[t.joint], f);
          if (!t.translation) value_[t.joint][f] = dense_.rotation[t.joint][f];
          changed[t.joint] = 1;
        }
      for (auto& list : escalate) list.clear();
      for (std::size_t k = 0; k < joints_; ++k) {
        const int p = parent(k);
        if (p >= 0 && changed[static_cast<std::size_t>(p)]) changed[k] = 1;
        if (changed[k]) dirty[k] = 1;
      }
    }
  }

  const Clip& clip_;
  const ReduceOptions& o_;
  std::vector<ReduceBudget> budget_;
  DenseClip dense_;
  std::vector<std::vector<Quat>> value_;  // [joint][frame]: the value of a key there
  std::vector<std::vector<Quat>> start_;  // [joint][frame]: the value a new key there starts from
  std::size_t n_ = 0, joints_ = 0;
  bool shell_ = false;
  std::vector<std::vector<std::size_t>> rkeys_, tkeys_;
  std::vector<ReducedJoint> out_;
  std::vector<std::vector<std::size_t>> children_;
  std::vector<std::vector<Vec3>> test_translation_;
  std::vector<std::vector<Quat>> ref_rot_, test_rot_;
  std::vector<std::vector<Vec3>> ref_pos_, test_pos_;
};

bool valid_budget_value(double v) { return std::isfinite(v) && v >= 0.0; }

}  // namespace

double translation_tolerance(const ReduceBudget& b) {
  return b.shell > 0.0 ? std::min(b.translation, kTranslationShare * b.shell) : b.translation;
}

Result<ReduceResult> reduce_clip(const Clip& clip, const ReduceOptions& o) {
  if (Status s = clip.validate(); !s) return s.failure();
  if (!find_method(o.method)) return make_error(unknown_method_message(o.method));
  const std::size_t n = clip.skeleton.joints.size();
  std::vector<ReduceBudget> budgets(n, o.budget);
  for (const auto& [name, b] : o.budget_for) {
    const int j = clip.skeleton.find(name);
    if (j < 0) return make_error("no joint named '" + name + "' for its budget");
    ReduceBudget& to = budgets[static_cast<std::size_t>(j)];
    if (b.rotation_deg > 0.0) to.rotation_deg = b.rotation_deg;
    if (b.shell > 0.0) to.shell = b.shell;
    if (b.translation > 0.0) to.translation = b.translation;
  }
  for (std::size_t j = 0; j < n; ++j) {
    const ReduceBudget& b = budgets[j];
    const std::string& name = clip.skeleton.joints[j].name;
    if (!valid_budget_value(b.rotation_deg) || !valid_budget_value(b.shell) || !valid_budget_value(b.translation))
      return make_error("joint '" + name + "': a budget is not a finite number ≥ 0");
    if (!(b.rotation_deg > 0.0) && !(b.shell > 0.0)) return make_error("joint '" + name + "' has no rotation or shell budget");
    if (clip.translations[j] && !(b.translation > 0.0))
      return make_error("joint '" + name + "' has a translation track but no translation budget");
    if (b.shell > 0.0 && !(std::isfinite(o.shell_distance) && o.shell_distance > 0.0))
      return make_error("a shell budget needs a shell distance > 0");
  }
  for (ReduceBudget& b : budgets) b.translation = translation_tolerance(b);
  return Reducer(clip, o, std::move(budgets)).run();
}

}  // namespace rotinterp
