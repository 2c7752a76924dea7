// Random rotations for property tests: a uniformly random axis and a uniformly
// random unit quaternion (normal components, normalized), from the test's own engine.
#pragma once

#include "rotinterp/core/rotation.h"

#include <random>

namespace rotinterp::test {

inline Vec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  Vec3 v;
  do v = Vec3(n(rng), n(rng), n(rng));
  while (v.norm() < 1e-6);
  return v.normalized();
}

inline Quat random_quat(std::mt19937_64& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  return Quat(n(rng), n(rng), n(rng), n(rng)).normalized();
}

}  // namespace rotinterp::test
