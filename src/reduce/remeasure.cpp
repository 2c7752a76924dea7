// Later passes of a hierarchical run: the frames a joint's curve or inputs moved at, measured again; the rest kept.
#include "reducer.h"

#include "slerp_window.h"

#include "rotinterp/clip/metrics.h"

#include <algorithm>

namespace rotinterp::detail {

namespace {

// Marks the frames between the s-th keys of `keys` before and after frame c
// (strictly; the track's ends where there are fewer): where a curve of support s
// moves when a key at c is added, removed or changed (MethodInfo::support).
void mark_span(const std::vector<std::size_t>& keys, std::size_t c, std::size_t s, std::vector<char>& mask) {
  const auto below = static_cast<std::size_t>(std::lower_bound(keys.begin(), keys.end(), c) - keys.begin());
  const auto above = static_cast<std::size_t>(std::upper_bound(keys.begin(), keys.end(), c) - keys.begin());
  const std::size_t lo = below >= s ? keys[below - s] : 0;
  const std::size_t hi = above + s - 1 < keys.size() ? keys[above + s - 1] : mask.size() - 1;
  std::fill(mask.begin() + static_cast<std::ptrdiff_t>(lo), mask.begin() + static_cast<std::ptrdiff_t>(std::min(hi, mask.size() - 1) + 1), 1);
}

}  // namespace

int Reducer::support(std::size_t j) const {
  return looped(j) || measure_everything_ ? 0 : find_method(o_.method)->support;
}

std::vector<char> Reducer::to_measure(std::size_t j) const {
  if (measure_everything_) return std::vector<char>(n_, 1);
  const Measured& m = measured_[j];
  std::vector<char> mask = m.moved;
  const std::vector<std::size_t>& now = rkeys_[j];
  const int s = support(j);
  // Both sorted key lists walked: a key in one only, or with another value now, moved the curve.
  for (std::size_t a = 0, b = 0; a < m.rkeys.size() || b < now.size();) {
    std::size_t c;
    if (b == now.size() || (a < m.rkeys.size() && m.rkeys[a] < now[b])) {
      c = m.rkeys[a++];
    } else if (a == m.rkeys.size() || now[b] < m.rkeys[a]) {
      c = now[b++];
    } else {
      c = now[b];
      const bool same = m.values[a].coeffs() == value_[j][key_frame(j, c)].coeffs();
      ++a, ++b;
      if (same) continue;
    }
    if (s == 0) return std::vector<char>(n_, 1);
    mark_span(m.rkeys, c, static_cast<std::size_t>(s), mask);
    mark_span(now, c, static_cast<std::size_t>(s), mask);
  }
  return mask;
}

bool Reducer::keys_unchanged(std::size_t j) const {
  const Measured& m = measured_[j];
  bool same = m.done && m.rkeys == rkeys_[j];
  for (std::size_t i = 0; same && i < m.rkeys.size(); ++i)
    same = m.values[i].coeffs() == value_[j][key_frame(j, m.rkeys[i])].coeffs();
  return same;
}

Result<std::shared_ptr<const Interpolator>> Reducer::current_curve(std::size_t j) const {
  const Measured& m = measured_[j];
  if (m.curve && keys_unchanged(j)) return m.curve;
  auto c = curve(j, rkeys_[j]);
  if (!c) return c.failure();
  return std::shared_ptr<const Interpolator>(std::move(*c));
}

Status Reducer::for_each_rebuilt_run(std::size_t j, const std::vector<char>& mask, bool keep, const RunFn& f) {
  std::shared_ptr<const Interpolator> c;
  std::vector<Quat> keys, q;  // slerp's prepared keys (unless kept); a run's rotations
  const std::vector<Quat>* prepared = &keys;
  if (slerp_ && !looped(j)) {
    if (measured_[j].prepared.empty()) prepare_slerp_keys(value_[j], rkeys_[j], keys);
    else if (keys_unchanged(j)) prepared = &measured_[j].prepared;
    else prepare_slerp_keys_again(value_[j], rkeys_[j], measured_[j].rkeys, measured_[j].values, measured_[j].prepared, keys);
  } else {
    auto made = current_curve(j);
    if (!made) return made.failure();
    c = std::move(*made);
  }
  const Status s = for_each_run(mask, [&](std::size_t lo, std::size_t hi) -> Status {
    q.resize(hi - lo + 1);
    if (c) c->evaluate(times().data() + lo, q.size(), q.data());
    else slerp_frames(times(), rkeys_[j].data(), prepared->data(), prepared->size(), lo, hi, q.data());
    frames_measured_ += hi - lo + 1;
    f(lo, hi, q);
    return Ok{};
  });
  if (s && keep) {
    measured_[j].curve = std::move(c);
    if (prepared == &keys) measured_[j].prepared = std::move(keys);
  }
  return s;
}

Status Reducer::update_translation(std::size_t j, bool first, std::vector<double>& e) {
  Measured& m = measured_[j];
  // The same keys select and rebuild the same translation: nothing to do.
  if (!first && tkeys_[j] == m.tkeys) return Ok{};
  const std::vector<Vec3> before = test_translation_[j];
  if (Status s = select_translation(j, first, e); !s) return s;
  m.tkeys = tkeys_[j];
  if (!first)
    for (std::size_t f = 0; f < n_; ++f)
      if (test_translation_[j][f] != before[f]) m.moved[f] = 1;
  return Ok{};
}

Status Reducer::settle_rotation(std::size_t j, const std::vector<char>& mask) {
  Measured& m = measured_[j];
  if (!m.done) {
    m.angle.assign(n_, 0.0);
    m.shell.assign(n_, 0.0);
  }
  const std::vector<Quat>& src = dense_.rotation[j];
  const Status s = for_each_rebuilt_run(j, mask, true, [&](std::size_t lo, std::size_t hi, const std::vector<Quat>& q) {
    for (std::size_t f = lo; f <= hi; ++f) {
      m.angle[f] = angular_distance(src[f], q[f - lo]);
      Quat r;
      Vec3 p;
      test_world(j, f, q[f - lo], r, p);
      if (r.coeffs() != test_rot_[j][f].coeffs() || p != test_pos_[j][f])
        for (std::size_t k : children_[j]) measured_[k].moved[f] = 1;
      test_rot_[j][f] = r;
      test_pos_[j][f] = p;
      m.shell[f] = shell_error(ref_rot_[j][f], ref_pos_[j][f], r, p, o_.shell_distance);
    }
  });
  if (!s) return s;
  out_[j].max_rotation_error = *std::max_element(m.angle.begin(), m.angle.end());
  out_[j].max_shell_error = *std::max_element(m.shell.begin(), m.shell.end());
  m.rkeys = rkeys_[j];
  m.values.clear();
  for (std::size_t k : m.rkeys) m.values.push_back(value_[j][key_frame(j, k)]);
  std::fill(m.moved.begin(), m.moved.end(), 0);
  m.done = true;
  return Ok{};
}

}  // namespace rotinterp::detail
