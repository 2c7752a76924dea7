// slerp on a window of keys, evaluated in place (slerp_window.h).
#include "slerp_window.h"

#include "rotinterp/core/geodesic.h"
#include "rotinterp/core/slerp_kernel.h"

#include <algorithm>
#include <cmath>

namespace rotinterp::detail {

// make_slerp's keys for decimated_track(times, value, keys): decimated_track and
// detail::prepare normalize each key twice and align signs three times; only the last
// alignment decides, as align_pair(a, ±b) is the same quaternion for either sign, and
// normalizing commutes with negation. (Validation cannot fail: the grid's times strictly
// increase, the keys are normalized.)
void prepare_slerp_keys(const std::vector<Quat>& value, const std::vector<std::size_t>& keys, std::vector<Quat>& q) {
  q.resize(keys.size());
  for (std::size_t k = 0; k < keys.size(); ++k) {
    q[k] = normalized_or_identity(normalized_or_identity(value[keys[k]]));
    if (k > 0) q[k] = align_pair(q[k - 1], q[k]);
  }
}

// A key at the same frame with the same value as before keeps its normalized value: the
// alignment with its neighbour gives it the same sign from either. The unchanged keys
// before the first change are the old ones as they are; after the last change, all
// negated or none (align_pair(−a, b) = −align_pair(a, b)). Only the span between is
// aligned key by key. (The first key is never flipped.)
void prepare_slerp_keys_again(const std::vector<Quat>& value, const std::vector<std::size_t>& keys,
                              const std::vector<std::size_t>& old_keys, const std::vector<Quat>& old_values,
                              const std::vector<Quat>& old_prepared, std::vector<Quat>& q) {
  const std::size_t n = keys.size(), m = old_keys.size();
  auto same = [&](std::size_t k, std::size_t a) {
    return old_keys[a] == keys[k] && old_values[a].coeffs() == value[keys[k]].coeffs();
  };
  std::size_t head = 0, tail = 0;  // unchanged keys at the start and at the end
  while (head < std::min(n, m) && same(head, head)) ++head;
  while (tail < std::min(n, m) - head && same(n - 1 - tail, m - 1 - tail)) ++tail;
  q.resize(n);
  std::copy(old_prepared.begin(), old_prepared.begin() + static_cast<std::ptrdiff_t>(head), q.begin());
  for (std::size_t k = head, a = head; k < n - tail; ++k) {
    const std::size_t c = keys[k];
    while (a < m && old_keys[a] < c) ++a;
    q[k] = k > 0 && a < m && same(k, a) ? old_prepared[a] : normalized_or_identity(normalized_or_identity(value[c]));
    if (k > 0) q[k] = align_pair(q[k - 1], q[k]);
  }
  if (tail == 0) return;
  const std::size_t first = n - tail, old_first = m - tail;
  q[first] = first > 0 ? align_pair(q[first - 1], old_prepared[old_first])
                       : normalized_or_identity(normalized_or_identity(value[keys[0]]));
  const bool flip = q[first].coeffs() != old_prepared[old_first].coeffs();
  for (std::size_t i = 1; i < tail; ++i) {
    const Quat& o = old_prepared[old_first + i];
    q[first + i] = flip ? Quat(-o.coeffs()) : o;
  }
}

// SlerpInterpolator::segment at each frame's segment and u: a key frame's time is its
// key's, so u = 0 there (the key itself); clamped outside the keys; between keys the
// polynomial kernel, whose value is a sample's own whatever its batch (slerp_kernel.h).
void slerp_frames(const std::vector<double>& t, const std::size_t* keys, const Quat* q, std::size_t n, std::size_t lo,
                  std::size_t hi, Quat* out) {
  std::size_t f = lo;
  for (; f <= hi && f <= keys[0]; ++f) out[f - lo] = q[0];
  // The segment of the first frame after the first key.
  auto i = static_cast<std::size_t>(std::upper_bound(keys, keys + n, f) - keys);
  for (i = i > 0 ? i - 1 : 0; i + 1 < n && f <= hi; ++i) {
    if (f >= keys[i + 1]) continue;
    if (f == keys[i] && f + 1 == keys[i + 1]) {  // adjacent keys: the first one's frame alone, u = 0
      out[f++ - lo] = q[i];
      continue;
    }
    const double t0 = t[keys[i]], t1 = t[keys[i + 1]];
    // The segment's frames in blocks, the kernel's arrays holding its two keys.
    constexpr std::size_t kBlock = 64;
    double a[4][kBlock], b[4][kBlock], u[kBlock], r[4][kBlock];
    std::size_t at[kBlock];
    const double ka[4] = {q[i].w(), q[i].x(), q[i].y(), q[i].z()};
    const double kb[4] = {q[i + 1].w(), q[i + 1].x(), q[i + 1].y(), q[i + 1].z()};
    for (int c = 0; c < 4; ++c) std::fill_n(a[c], kBlock, ka[c]), std::fill_n(b[c], kBlock, kb[c]);
    while (f < keys[i + 1] && f <= hi) {
      std::size_t m = 0;
      for (; f < keys[i + 1] && f <= hi && m < kBlock; ++f) {
        const double s = std::clamp((t[f] - t0) / (t1 - t0), 0.0, 1.0);
        if (s <= 0.0 || s >= 1.0) {
          out[f - lo] = s <= 0.0 ? q[i] : q[i + 1];
        } else {
          u[m] = s;
          at[m++] = f - lo;
        }
      }
      slerp_arrays({a[0], a[1], a[2], a[3]}, {b[0], b[1], b[2], b[3]}, u, m, {r[0], r[1], r[2], r[3]});
      for (std::size_t j = 0; j < m; ++j) out[at[j]] = Quat(r[0][j], r[1][j], r[2][j], r[3][j]);
    }
  }
  for (; f <= hi; ++f) out[f - lo] = q[n - 1];  // at and after the last key
}

// Only the keys of the segments [lo, hi] falls in are prepared: the window's keys before
// them decide only the sign the chain of alignments reaches them with, and the sign of
// two neighbours' dot product is their values' own while it is well away from zero
// (the normalizations move it by ~1e-16), so that no normalization is needed there.
void slerp_window(const std::vector<double>& times, const std::vector<Quat>& v, const std::vector<std::size_t>& keys,
                  std::size_t lo, std::size_t hi, Quat* out) {
  thread_local std::vector<Quat> q;  // prepared keys, reused by every call on this thread
  const std::size_t n = keys.size();
  auto ia = static_cast<std::size_t>(std::upper_bound(keys.begin(), keys.end(), lo) - keys.begin());
  ia = ia > 0 ? ia - 1 : 0;
  const std::size_t ib = std::min(n - 1, static_cast<std::size_t>(std::lower_bound(keys.begin(), keys.end(), hi) - keys.begin()));
  auto near_unit = [](const Quat& x) { return std::abs(x.squaredNorm() - 1.0) < 0.5; };
  bool flip = false, sure = true;
  for (std::size_t k = 1; k <= ia && sure; ++k) {
    const double d = v[keys[k - 1]].dot(v[keys[k]]);
    sure = std::abs(d) >= 1e-6 && near_unit(v[keys[k - 1]]) && near_unit(v[keys[k]]);
    flip = flip != (d < 0.0);
  }
  if (!sure) {  // a pair near 90° apart in 4-D: the whole chain
    prepare_slerp_keys(v, keys, q);
    slerp_frames(times, keys.data(), q.data(), n, lo, hi, out);
    return;
  }
  q.resize(ib - ia + 1);
  for (std::size_t k = ia; k <= ib; ++k) {
    Quat& x = q[k - ia];
    x = normalized_or_identity(normalized_or_identity(v[keys[k]]));
    if (k == ia && flip) x = Quat(-x.coeffs());
    if (k > ia) x = align_pair(q[k - ia - 1], x);
  }
  slerp_frames(times, keys.data() + ia, q.data(), q.size(), lo, hi, out);
}

}  // namespace rotinterp::detail
