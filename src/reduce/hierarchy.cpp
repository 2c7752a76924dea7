// Joints in order: independent ones in parallel, or parents first with frames a joint cannot meet passed up.
#include "reducer.h"

#include "rotinterp/clip/metrics.h"
#include "rotinterp/core/work_queue.h"

#include <algorithm>
#include <atomic>
#include <future>
#include <thread>

namespace rotinterp::detail {

Status Reducer::run_independent() {
  unsigned threads = thread_count(o_.threads);
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

// Whether a track is exact at f: keyed there, and a rotation key with the source's
// value (not a fitted one). In a closed cycle a looped track's last frame is keyed by the seam.
bool Reducer::exact_at(const Track& t, std::size_t f) const {
  const std::size_t k = key_frame(t.joint, f);
  if (t.translation) return !clip_.translations[t.joint] || has(tkeys_[t.joint], k);
  return has(rkeys_[t.joint], k) && value_[t.joint][k].coeffs() == dense_.rotation[t.joint][k].coeffs();
}

// j's shell error at f with its own rotation exact and the tracks in `exact` exact
// too (as if keyed at f); the others rebuilt.
double Reducer::floor_with_exact(std::size_t j, std::size_t f, const std::vector<Track>& exact,
                                 const std::vector<std::size_t>& chain) const {
  auto is_exact = [&](std::size_t k, bool translation) {
    return std::find(exact.begin(), exact.end(), Track{k, translation}) != exact.end();
  };
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
std::vector<Reducer::Track> Reducer::tracks_to_key(std::size_t j, std::size_t f) const {
  const double limit = kFloorLimit * budget_[j].shell;
  std::vector<Track> candidates, exact;
  candidates.push_back({j, true});
  for (int a = parent(j); a >= 0; a = parent(static_cast<std::size_t>(a)))
    for (bool translation : {false, true}) candidates.push_back({static_cast<std::size_t>(a), translation});
  candidates.erase(std::remove_if(candidates.begin(), candidates.end(), [&](const Track& t) { return exact_at(t, f); }),
                   candidates.end());
  std::vector<std::size_t> chain;  // j's ancestors, root first
  for (int a = parent(j); a >= 0; a = parent(static_cast<std::size_t>(a))) chain.push_back(static_cast<std::size_t>(a));
  std::reverse(chain.begin(), chain.end());
  double err = floor_with_exact(j, f, exact, chain);
  for (const Track& t : candidates) {
    if (err <= limit) return exact;
    exact.push_back(t);
    const double e = floor_with_exact(j, f, exact, chain);
    if (e < err - kUseful * budget_[j].shell) err = e;
    else exact.pop_back();
  }
  return err <= limit ? exact : candidates;
}

// Frames over budget at j even with j's own rotation exact (its translation and
// its ancestors rebuilt): measured at every frame the first time, then only where
// those moved.
std::vector<std::size_t> Reducer::floor_frames(std::size_t j) {
  std::vector<std::size_t> out;
  if (!(budget_[j].shell > 0.0)) return out;
  Measured& m = measured_[j];
  const bool all = m.floor.empty() || measure_everything_;
  if (m.floor.empty()) m.floor.assign(n_, 0);
  std::size_t measured = 0;
  for (std::size_t f = 0; f < n_; ++f) {
    if (all || m.moved[f]) {
      ++measured;
      Quat r;
      Vec3 p;
      test_world(j, f, dense_.rotation[j][f], r, p);
      const double limit = kFloorLimit * budget_[j].shell;
      m.floor[f] = shell_error_above(ref_rot_[j][f], ref_pos_[j][f], r, p, o_.shell_distance, limit) > limit;
    }
    if (m.floor[f]) out.push_back(f);
  }
  frames_measured_ += measured;
  return out;
}

// Passes, parents first (the joints of one depth in parallel: each reads only its
// ancestors' rebuilt motion). A joint with frames it cannot meet (floor_frames)
// passes them up — to its own translation track, else to the nearest ancestor not
// keyed there — and waits, with its subtree, for the next pass; the changed
// joints' subtrees are verified again then (insertion only: keys only grow, so it
// ends).
Status Reducer::run_hierarchical() {
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
    status[j] = update_translation(j, !translated[j], e);
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
  unsigned threads = thread_count(o_.threads);
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
        const std::size_t k = key_frame(t.joint, f);
        add_key(t.translation ? tkeys_[t.joint] : rkeys_[t.joint], k);
        if (!t.translation) value_[t.joint][k] = dense_.rotation[t.joint][k];
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


}  // namespace rotinterp::detail
