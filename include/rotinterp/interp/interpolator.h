// The interpolator interface and the registry of methods.
//
// An interpolator is built once from one joint's RotationTrack (strictly
// increasing times, unit keys — see clip/clip.h) and evaluated at any time; times
// outside [t₀, tₙ] (and NaN) are clamped. Every method passes through every key
// (< 1e-9 rad), returns unit quaternions and never NaN. One method per header:
// slerp.h, squad.h, expmap.h, nlerp.h, bf.h, c2.h, clamped.h, gltf_cubic.h.
#pragma once

#include "rotinterp/track/track.h"
#include "rotinterp/core/result.h"
#include "rotinterp/core/rotation.h"

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace rotinterp {

class Interpolator {
 public:
  virtual ~Interpolator() = default;

  // Orientation at time t (seconds), clamped to the key range.
  virtual Quat evaluate(double t) const = 0;
  // Batch form: out[i] = evaluate(t[i]). Methods override it when a sorted batch
  // can be done faster (segment search once per run of times).
  virtual void evaluate(const double* t, std::size_t n, Quat* out) const;

  // Fixed-frame angular velocity (rad/s) at t, where the method has it in closed form.
  virtual bool has_angular_velocity() const { return false; }
  virtual Vec3 angular_velocity(double t) const;
  // Fixed-frame angular acceleration dω/dt (rad/s²) at t, where the method has it:
  // within the segment holding t (at a key, the segment starting there; zero
  // outside [t₀, tₙ], where the curve is clamped). The body-frame acceleration is
  // q(t)⁻¹·α(t): the frame's own turning adds ω × ω = 0.
  virtual bool has_angular_acceleration() const { return false; }
  virtual Vec3 angular_acceleration(double t) const;
};

struct MethodInfo {
  std::string name;         // what --method takes
  std::string description;  // one line
  int continuity;           // 0, 1 or 2: C⁰, C¹, C² (in orientation, at keys)
  bool coordinate_invariant;  // left/right multiplying all keys by a fixed rotation maps the curve alike
  bool exact_on_constant_velocity;  // keys of exp(ωt)·q₀ give exactly that curve, at any spacing
  bool preserves_holds;             // a segment between two equal keys is exactly still
  // Keys on each side of a segment that its curve depends on, bit for bit up to the
  // sign of the result (segment i is a function of keys i−support+1 … i+support): a
  // key added, removed or changed moves only the curve between the support-th keys
  // before and after it. 0: every key (a global spline, or a method whose values
  // carry a chain from the first key).
  int support;
  std::function<Result<std::unique_ptr<Interpolator>>(RotationTrack)> make;
};

// All methods, in a stable order: slerp, squad, expmap, nlerp, bf, c2, expmap-c2, clamped,
// gltf-cubic.
const std::vector<MethodInfo>& methods();
// The method called `name`, ignoring ASCII case ("SLERP" is slerp), or nullptr.
// Callers that keep the name keep MethodInfo::name, the one spelling.
const MethodInfo* find_method(std::string_view name);
// Comma-separated names of all methods, for error messages.
std::string method_names();
// The one error line for a name find_method does not know: "unknown method 'slrep'
// (did you mean slerp? valid: slerp, squad, …)"; the guess is the nearest name by
// edit distance, given only when it is within a third of the name's length (≥ 2).
std::string unknown_method_message(std::string_view name);
// Builds `method` on `track`. The track must satisfy rules 1–3 of RotationTrack
// (times strictly increasing, finite unit keys); rule 4 (sign continuity) is not
// required: every method aligns neighbouring keys to one hemisphere itself and
// so always takes the short way (a key pair 338° apart "as stored" is followed
// as the 22° it is). The track is taken by value and its storage becomes the
// interpolator's keys: pass std::move(track) to build without copying it.
Result<std::unique_ptr<Interpolator>> make_interpolator(std::string_view method, RotationTrack track);

}  // namespace rotinterp
