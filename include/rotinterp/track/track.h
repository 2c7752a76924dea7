// Key tracks of one joint: rotation keys and translation keys with their times.
// Plain data and the invariants every layer above relies on (interpolators read
// rotation tracks; the clip holds one of each per joint).
#pragma once

#include "rotinterp/core/result.h"
#include "rotinterp/core/rotation.h"

#include <vector>

namespace rotinterp {

// How far a key's norm may be from 1 (absolute): round-off of the library's own
// arithmetic, far below float32 resolution (6e-8), so rounded input is caught.
inline constexpr double kUnitNormTolerance = 1e-9;

// Rotation keys of one joint.
// Invariants (checked by validate()):
//  1. times.size() == keys.size() ≥ 1;
//  2. times are finite and strictly increasing;
//  3. keys are finite unit quaternions (||q| − 1| ≤ kUnitNormTolerance); the
//     library never normalizes silently: callers holding rounded data (float32,
//     printed decimals) normalize at their boundary (the Python module does);
//  4. sign continuity: keys[k].dot(keys[k−1]) ≥ 0 — interpolators may rely on it.
struct RotationTrack {
  std::vector<double> times;  // seconds
  std::vector<Quat> keys;

  Status validate() const;
  // Normalizes every key and flips signs so that invariant 4 holds.
  void make_sign_continuous();
};

// Translation keys of one joint. Invariants: sizes equal ≥ 1, times finite and
// strictly increasing, keys finite.
struct TranslationTrack {
  std::vector<double> times;  // seconds
  std::vector<Vec3> keys;     // clip units

  Status validate() const;
};

}  // namespace rotinterp
