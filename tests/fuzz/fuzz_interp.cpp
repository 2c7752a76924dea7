// Fuzz target: every registered interpolator fed an arbitrary key track.
// The bytes decode to (time, w, x, y, z) records — NaN, inf, duplicates and
// unsorted times included. Tracks that fail validation must be refused with an
// error; accepted tracks must give finite unit quaternions at every time tried.
#include "rotinterp/interp/interpolator.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace {

double take(const std::uint8_t*& p, std::size_t& n) {
  double d = 0.0;
  if (n >= sizeof d) {
    std::memcpy(&d, p, sizeof d);
    p += sizeof d;
    n -= sizeof d;
  }
  return d;
}

void check(bool ok) {
  if (!ok) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace rotinterp;
  // Byte 0 chooses whether to clean the track (sort, normalize, fix signs) so the
  // fuzzer reaches the interpolators' numerics as well as the validation.
  if (size < 1) return 0;
  const bool clean = data[0] & 1;
  ++data;
  --size;
  RotationTrack track;
  while (size >= 5 * sizeof(double) && track.times.size() < 64) {
    const double t = take(data, size);
    const double w = take(data, size), x = take(data, size), y = take(data, size), z = take(data, size);
    track.times.push_back(t);
    track.keys.emplace_back(w, x, y, z);
  }
  if (clean) {
    RotationTrack c;
    double last = -INFINITY;
    for (std::size_t k = 0; k < track.times.size(); ++k) {
      const double t = track.times[k];
      if (!std::isfinite(t) || !(t > last) || std::abs(t) > 1e12) continue;
      c.times.push_back(t);
      c.keys.push_back(normalized_or_identity(track.keys[k]));
      last = t;
    }
    c.make_sign_continuous();
    track = std::move(c);
  }
  // Rules 1–3 of RotationTrack decide acceptance. Rule 4 (sign continuity) is not
  // required: every method aligns neighbouring keys itself (interpolator.h).
  RotationTrack signs_aligned = track;
  for (std::size_t k = 1; k < signs_aligned.keys.size(); ++k)
    signs_aligned.keys[k] = align_to(signs_aligned.keys[k], signs_aligned.keys[k - 1]);
  const bool valid = signs_aligned.validate().ok();
  for (const MethodInfo& m : methods()) {
    auto interp = make_interpolator(m.name, track);
    check(interp.ok() == valid);
    if (!interp.ok()) continue;
    const double t0 = track.times.front(), t1 = track.times.back();
    for (int i = -2; i <= 34; ++i) {
      const double t = t0 + (t1 - t0) * (i / 32.0);
      const Quat q = (*interp)->evaluate(t);
      check(q.coeffs().allFinite());
      check(std::abs(q.norm() - 1.0) < 1e-6);
    }
    for (std::size_t k = 0; k < track.times.size(); ++k) check((*interp)->evaluate(track.times[k]).coeffs().allFinite());
  }
  return 0;
}
