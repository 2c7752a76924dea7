// The invariants of rotation and translation tracks (validate) and sign continuity.
#include "rotinterp/track/track.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace rotinterp {

namespace {

template <class Keys>
Status validate_times(const std::vector<double>& times, const Keys& keys) {
  if (times.empty()) return make_error("track has no keys");
  if (times.size() != keys.size()) return make_error("track has different numbers of times and keys");
  for (std::size_t k = 0; k < times.size(); ++k) {
    if (!std::isfinite(times[k])) return make_error("key " + std::to_string(k) + " has a non-finite time");
    if (k > 0 && !(times[k] > times[k - 1]))
      return make_error("key times are not strictly increasing at key " + std::to_string(k));
  }
  return Ok{};
}

}  // namespace

Status RotationTrack::validate() const {
  if (Status s = validate_times(times, keys); !s) return s;
  for (std::size_t k = 0; k < keys.size(); ++k) {
    if (!keys[k].coeffs().allFinite()) return make_error("rotation key " + std::to_string(k) + " is not finite");
    // The message says by how much, so that a caller can tell rounding (float32,
    // printed decimals: normalize at the boundary) from a wrong value.
    if (const double norm = keys[k].norm(); std::abs(norm - 1.0) > kUnitNormTolerance) {
      char text[96];
      std::snprintf(text, sizeof text, " is not unit (|q| = %.9g, off by %.2g; the tolerance is %g)", norm,
                    std::abs(norm - 1.0), kUnitNormTolerance);
      return make_error("rotation key " + std::to_string(k) + text);
    }
    if (k > 0 && keys[k].dot(keys[k - 1]) < 0.0)
      return make_error("rotation key " + std::to_string(k) + " is not sign-continuous with the previous key");
  }
  return Ok{};
}

void RotationTrack::make_sign_continuous() {
  for (std::size_t k = 0; k < keys.size(); ++k) {
    keys[k] = normalized_or_identity(keys[k]);
    if (k > 0) keys[k] = align_to(keys[k], keys[k - 1]);
  }
}

Status TranslationTrack::validate() const {
  if (Status s = validate_times(times, keys); !s) return s;
  for (std::size_t k = 0; k < keys.size(); ++k)
    if (!keys[k].allFinite()) return make_error("translation key " + std::to_string(k) + " is not finite");
  return Ok{};
}

}  // namespace rotinterp
