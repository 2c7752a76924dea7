// glTF animation samplers evaluated as the glTF 2.0 spec's Appendix C defines them
// (io/gltf/gltf_source.h has the formulas).
#include "rotinterp/core/geodesic.h"
#include "rotinterp/io/gltf/gltf_source.h"

#include "rotinterp/core/geodesic.h"
#include "rotinterp/io/files/key_checks.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace rotinterp {

namespace {

// Where t falls: the key interval [k, k + 1] and u ∈ [0, 1) in it; `held` when t lies
// at or outside the ends (k is then the key that holds: the first or the last).
struct Interval {
  std::size_t k = 0;
  double u = 0.0;
  bool held = true;
};

Interval interval_of(const std::vector<double>& times, double t) {
  const std::size_t n = times.size();
  if (n == 1 || !(t > times.front())) return {0, 0.0, true};  // NaN holds the first key
  if (t >= times.back()) return {n - 1, 0.0, true};
  const auto hi = std::upper_bound(times.begin(), times.end(), t);
  const std::size_t k = static_cast<std::size_t>(hi - times.begin()) - 1;
  return {k, (t - times[k]) / (times[k + 1] - times[k]), false};
}

// Component c of key k's value (CUBICSPLINE: the middle of its three elements) …
double value(const GltfSampler& s, std::size_t k, std::size_t c) {
  const std::size_t per_key = s.interpolation == GltfInterpolation::cubic_spline ? 3 : 1;
  return s.values[(k * per_key + (per_key == 3 ? 1 : 0)) * s.width + c];
}
// … and of its in-tangent aₖ (element 0) and out-tangent bₖ (element 2).
double in_tangent(const GltfSampler& s, std::size_t k, std::size_t c) { return s.values[(3 * k) * s.width + c]; }
double out_tangent(const GltfSampler& s, std::size_t k, std::size_t c) { return s.values[(3 * k + 2) * s.width + c]; }

// Component c of the cubic Hermite segment k at u (the spec's p₀, m₀, p₁, m₁).
double hermite(const GltfSampler& s, std::size_t k, double u, std::size_t c) {
  const double dt = s.times[k + 1] - s.times[k];
  const double u2 = u * u, u3 = u2 * u;
  return (2 * u3 - 3 * u2 + 1) * value(s, k, c) + (u3 - 2 * u2 + u) * dt * out_tangent(s, k, c) +
         (-2 * u3 + 3 * u2) * value(s, k + 1, c) + (u3 - u2) * dt * in_tangent(s, k + 1, c);
}

Quat key_rotation(const GltfSampler& s, std::size_t k) {
  return normalized_or_identity(Quat(value(s, k, 3), value(s, k, 0), value(s, k, 1), value(s, k, 2)));
}

}  // namespace

Status validate_gltf_sampler(const GltfSampler& s) {
  // One CUBICSPLINE key, which the spec forbids, is still a constant: our own writer
  // wrote such samplers for tracks of one key (reduce's .glb), so they read.
  if (s.times.empty()) return make_error("a sampler has no key");
  const bool cubic = s.interpolation == GltfInterpolation::cubic_spline;
  const std::size_t per_key = s.width * (cubic ? 3 : 1);
  if (s.width == 0 || s.values.size() != s.times.size() * per_key)
    return make_error("a sampler's output holds " + std::to_string(s.values.size()) + " numbers for " +
                      std::to_string(s.times.size()) + " keys");
  Result<std::vector<std::size_t>> repeated = check_keys(s.times, s.values, per_key, "a sampler");
  if (!repeated) return repeated.failure();
  if (!repeated->empty()) return make_error("a sampler's key times do not increase at key " + std::to_string(repeated->front()));
  return Ok{};
}

Quat gltf_rotation_at(const GltfSampler& s, double t) {
  const Interval at = interval_of(s.times, t);
  if (at.held || s.interpolation == GltfInterpolation::step) return key_rotation(s, at.k);
  if (s.interpolation == GltfInterpolation::linear)
    return slerp(key_rotation(s, at.k), key_rotation(s, at.k + 1), at.u);  // shortest path (core/geodesic.h)
  const Quat q(hermite(s, at.k, at.u, 3), hermite(s, at.k, at.u, 0), hermite(s, at.k, at.u, 1),
               hermite(s, at.k, at.u, 2));
  return normalized_or_identity(q);
}

Vec3 gltf_vector_at(const GltfSampler& s, double t) {
  const Interval at = interval_of(s.times, t);
  Vec3 out;
  for (int c = 0; c < 3; ++c) {
    const auto i = static_cast<std::size_t>(c);
    if (at.held || s.interpolation == GltfInterpolation::step)
      out[c] = value(s, at.k, i);
    else if (s.interpolation == GltfInterpolation::linear)
      out[c] = (1.0 - at.u) * value(s, at.k, i) + at.u * value(s, at.k + 1, i);
    else
      out[c] = hermite(s, at.k, at.u, i);
  }
  return out;
}

}  // namespace rotinterp
