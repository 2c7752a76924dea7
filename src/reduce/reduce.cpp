#include "rotinterp/reduce/reduce.h"

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

// Normalized error (≤ 1: within budget) of the frames [lo, hi] of a curve rebuilt
// from the sorted key frames `keys` (which span [lo, hi]); out[f − lo].
using ErrorFn = std::function<Status(const std::vector<std::size_t>& keys, std::size_t lo, std::size_t hi, double* out)>;

// Step 1 (and 3): insert the worst frame of every key interval over budget until none
// is. After an insertion only the frames between the second neighbours of each new key
// are measured again (the curve rebuilt from the keys around them, as in step 2), or
// every frame when those spans cover most of them; "none over budget" is always
// confirmed over every frame with the whole track.
Status insert_worst(std::vector<std::size_t>& keys, std::size_t frames, const ErrorFn& err, std::vector<double>& e) {
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
      if (full) return Ok{};
      full = true;  // confirm with the whole track
      continue;
    }
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

// Step 2: drop every interior key whose neighbourhood stays within budget without it.
Status remove_keys(std::vector<std::size_t>& keys, const ErrorFn& err, std::vector<double>& e) {
  std::vector<std::size_t> window;
  for (std::size_t i = 1; i + 1 < keys.size();) {
    const std::size_t a = i >= kWindow ? i - kWindow : 0, b = std::min(keys.size() - 1, i + kWindow);
    window.assign(keys.begin() + static_cast<std::ptrdiff_t>(a), keys.begin() + static_cast<std::ptrdiff_t>(b + 1));
    window.erase(window.begin() + static_cast<std::ptrdiff_t>(i - a));
    const std::size_t lo = keys[i >= 2 ? i - 2 : 0], hi = keys[std::min(keys.size() - 1, i + 2)];
    e.resize(hi - lo + 1);
    if (Status s = err(window, lo, hi, e.data()); !s) return s;
    if (*std::max_element(e.begin(), e.end()) <= 1.0)
      keys.erase(keys.begin() + static_cast<std::ptrdiff_t>(i));
    else
      ++i;
  }
  return Ok{};
}

Status select_keys(std::vector<std::size_t>& keys, std::size_t frames, const ErrorFn& err, bool removal,
                   std::vector<double>& e) {
  if (frames < 3) return Ok{};
  if (Status s = insert_worst(keys, frames, err, e); !s) return s;
  if (!removal) return Ok{};
  if (Status s = remove_keys(keys, err, e); !s) return s;
  return insert_worst(keys, frames, err, e);
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

// The largest side of a shell vertex's displacement: max over the local axes a of
// |ΔP + d·(R_ref − R_test)·e_a|.
double shell_error(const Quat& r_ref, const Vec3& p_ref, const Quat& r_test, const Vec3& p_test, double d) {
  const Mat3 dr = d * (r_ref.toRotationMatrix() - r_test.toRotationMatrix());
  const Vec3 dp = p_ref - p_test;
  double worst = 0.0;
  for (int a = 0; a < 3; ++a) worst = std::max(worst, (dp + dr.col(a)).squaredNorm());
  return std::sqrt(worst);
}

// shell_error where it exceeds `limit`; below, possibly a bound between it and
// `limit` (|ΔP| + 2d·sin(θ/2), θ the angle between the world rotations, bounds every
// vertex's displacement): enough to tell within-budget frames, at a third of the cost.
double shell_error_above(const Quat& r_ref, const Vec3& p_ref, const Quat& r_test, const Vec3& p_test, double d,
                         double limit) {
  const double bound = (p_ref - p_test).norm() + 2.0 * d * (r_ref.conjugate() * r_test).vec().norm();
  return bound <= limit ? bound : shell_error(r_ref, p_ref, r_test, p_test, d);
}

class Reducer {
 public:
  Reducer(const Clip& clip, const ReduceOptions& o, std::vector<ReduceBudget> budgets)
      : clip_(clip), o_(o), budget_(std::move(budgets)), dense_(dense_clip(clip)) {
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
      if (Status s = shell_ ? run_hierarchical() : run_independent(); !s) return make_error(s.error());
    } else {
      for (std::size_t j = 0; j < joints_; ++j) out_[j].budget = budget_[j];
    }
    ReduceResult r;
    r.reduced = clip_;
    r.source_keys = 0;
    for (std::size_t j = 0; j < joints_; ++j) {
      out_[j].rotation_frames = rkeys_[j];
      out_[j].translation_frames = tkeys_[j];
      r.reduced.rotations[j] = decimated_track(dense_.grid.times, dense_.rotation[j], rkeys_[j]);
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
    std::vector<Vec3> buf;
    ErrorFn err = [&](const std::vector<std::size_t>& keys, std::size_t lo, std::size_t hi, double* out) -> Status {
      const TranslationCurve curve(translation_keys(times(), src, keys), o_.translation);
      for (std::size_t f = lo; f <= hi; ++f) out[f - lo] = (curve.evaluate(times()[f]) - src[f]).norm() / tol;
      return Ok{};
    };
    if (Status s = select_keys(tkeys_[j], n_, err, removal, e); !s) return s;
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
    auto curve = make_interpolator(o_.method, decimated_track(times(), dense_.rotation[j], keys));
    if (!curve) return make_error(curve.error());
    std::vector<Quat> q(hi - lo + 1);
    (*curve)->evaluate(times().data() + lo, q.size(), q.data());
    return q;
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
      if (!q) return make_error(q.error());
      for (std::size_t f = lo; f <= hi; ++f) out[f - lo] = frame_error(f, (*q)[f - lo]);
      return Ok{};
    };
    if (Status s = select_keys(rkeys_[j], n_, err, removal, e); !s) return s;
    auto q = rebuild(j, rkeys_[j], 0, n_ - 1);
    if (!q) return make_error(q.error());
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
      if (!status[j]) return make_error("joint '" + clip_.skeleton.joints[j].name + "': " + status[j].error());
    return Ok{};
  }

  // j's shell error at f with its own rotation exact and the ancestors in `exact`
  // exact too (as if keyed at f); the others rebuilt.
  double floor_with_exact(std::size_t j, std::size_t f, const std::vector<std::size_t>& exact) const {
    std::vector<std::size_t> chain;  // j's ancestors, root first
    for (int a = parent(j); a >= 0; a = parent(static_cast<std::size_t>(a))) chain.insert(chain.begin(), static_cast<std::size_t>(a));
    Quat r = Quat::Identity();
    Vec3 p = Vec3::Zero();
    for (std::size_t k : chain) {
      const int pk = parent(k);
      const bool is_exact = std::find(exact.begin(), exact.end(), k) != exact.end();
      const Quat local = is_exact ? dense_.rotation[k][f]
                                  : (pk < 0 ? test_rot_[k][f] : Quat(test_rot_[static_cast<std::size_t>(pk)][f].conjugate() * test_rot_[k][f]));
      const Vec3& t = is_exact ? dense_.translation[k][f] : test_translation(k, f);
      p += r * t;
      r = r * local;
    }
    p += r * test_translation(j, f);
    r = r * dense_.rotation[j][f];
    return shell_error(ref_rot_[j][f], ref_pos_[j][f], r, p, o_.shell_distance);
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
    std::vector<std::vector<std::pair<std::size_t, std::size_t>>> escalate(joints_);  // (joint, frame) to key
    std::vector<Status> status(joints_, Status(Ok{}));
    std::atomic<std::size_t> finished{0};
    auto process = [&](std::size_t j) {
      std::vector<double> e;
      escalate[j].clear();
      status[j] = select_translation(j, !translated[j], e);
      if (!status[j]) return;
      translated[j] = 1;
      for (std::size_t f : floor_frames(j)) {
        if (clip_.translations[j] && !has(tkeys_[j], f)) {
          escalate[j].emplace_back(j, f);
          continue;
        }
        // The nearest ancestors not keyed at f, as many as it takes (a keyed joint is
        // exact there) to bring f within the limit: one pass instead of one per level.
        std::vector<std::size_t> exact;
        for (int a = parent(j); a >= 0; a = parent(static_cast<std::size_t>(a))) {
          const auto au = static_cast<std::size_t>(a);
          if (has(rkeys_[au], f) && (!clip_.translations[au] || has(tkeys_[au], f))) continue;
          exact.push_back(au);
          escalate[j].emplace_back(au, f);
          if (floor_with_exact(j, f, exact) <= kFloorLimit * budget_[j].shell) break;
        }
      }
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
          if (!status[j]) return make_error("joint '" + clip_.skeleton.joints[j].name + "': " + status[j].error());
      }
      if (!any) return Ok{};
      // Key the escalated frames; verify each changed joint's subtree again.
      std::vector<char> changed(joints_, 0);
      for (const auto& list : escalate)
        for (const auto& [a, f] : list) {
          add_key(rkeys_[a], f);
          if (clip_.translations[a]) add_key(tkeys_[a], f);
          changed[a] = 1;
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

Result<std::vector<Quat>> rebuild_rotations(const std::string& method, const std::vector<double>& times,
                                            const std::vector<Quat>& source, const std::vector<std::size_t>& kept) {
  auto curve = make_interpolator(method, decimated_track(times, source, kept));
  if (!curve) return make_error(curve.error());
  std::vector<Quat> q(times.size());
  (*curve)->evaluate(times.data(), times.size(), q.data());
  return q;
}

Result<ReduceResult> reduce_clip(const Clip& clip, const ReduceOptions& o) {
  if (Status s = clip.validate(); !s) return make_error(s.error());
  if (!find_method(o.method)) return make_error("unknown method '" + o.method + "' (valid: " + method_names() + ")");
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
  return Reducer(clip, o, std::move(budgets)).run();
}

}  // namespace rotinterp
