// The method registry, name lookup with suggestions, and make_interpolator.
#include "rotinterp/interp/interpolator.h"

#include "rotinterp/core/nearest_name.h"

#include "rotinterp/interp/bf.h"
#include "rotinterp/interp/c2.h"
#include "rotinterp/interp/clamped.h"
#include "rotinterp/interp/expmap.h"
#include "rotinterp/interp/gltf_cubic.h"
#include "rotinterp/interp/nlerp.h"
#include "rotinterp/interp/slerp.h"
#include "rotinterp/interp/squad.h"

#include <algorithm>
#include <utility>

namespace rotinterp {

void Interpolator::evaluate(const double* t, std::size_t n, Quat* out) const {
  for (std::size_t i = 0; i < n; ++i) out[i] = evaluate(t[i]);
}

Vec3 Interpolator::angular_velocity(double) const { return Vec3::Zero(); }
Vec3 Interpolator::angular_acceleration(double) const { return Vec3::Zero(); }

const std::vector<MethodInfo>& methods() {
  using Made = Result<std::unique_ptr<Interpolator>>;
  static const std::vector<MethodInfo> all = {
      {"slerp", "piecewise geodesic (shortest arc) between neighbouring keys", 0, true, true, true,
       1, [](RotationTrack t) -> Made { return make_slerp(std::move(t)); }},
      {"squad", "Shoemake's spherical quadrangle, control points scaled for non-uniform times", 1, true, true, false,
       2, [](RotationTrack t) -> Made { return make_squad(std::move(t)); }},
      {"expmap", "Catmull-Rom spline of the unwrapped rotation vectors (Grassia), mapped back with exp", 1, false, false, false,
       0, [](RotationTrack t) -> Made { return make_expmap(std::move(t)); }},
      {"nlerp", "normalized linear blend of neighbouring keys (not constant speed)", 0, true, false, true,
       1, [](RotationTrack t) -> Made { return make_nlerp(std::move(t)); }},
      {"bf", "Buss-Fillmore spherical cubic B-spline through the keys (weighted spherical averages)", 2, true, true, false,
       0, [](RotationTrack t) -> Made { return make_bf(std::move(t)); }},
      {"c2", "cubic in the local rotation vector with continuous angular acceleration (as scipy RotationSpline)", 2,
       true, true, false, 0, [](RotationTrack t) -> Made { return make_c2(std::move(t)); }},
      {"expmap-c2", "natural cubic spline of the unwrapped rotation vectors, mapped back with exp", 2, false, false, false,
       0, [](RotationTrack t) -> Made {
         ExpmapOptions o;
         o.spline = ExpmapOptions::Spline::natural;
         return make_expmap(std::move(t), o);
       }},
      {"clamped", "shape-preserving C1 cubic (Steffen's limiter on SO(3)): holds stay still, no overshoot at stops", 1,
       true, true, true, 2, [](RotationTrack t) -> Made { return make_clamped(std::move(t)); }},
      {"gltf-cubic", "glTF CUBICSPLINE: Hermite cubic of the quaternion components, normalized (clamped's key rates)", 1,
       true, false, true, 2, [](RotationTrack t) -> Made { return make_gltf_cubic(std::move(t)); }},
  };
  return all;
}

namespace {

char lower(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; }

bool equal_ignoring_case(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (lower(a[i]) != lower(b[i])) return false;
  return true;
}

}  // namespace

const MethodInfo* find_method(std::string_view name) {
  for (const MethodInfo& m : methods())
    if (equal_ignoring_case(m.name, name)) return &m;
  return nullptr;
}

std::string unknown_method_message(std::string_view name) {
  std::vector<std::string> names;
  for (const MethodInfo& m : methods()) names.push_back(m.name);
  const auto best = nearest_name(name, names);
  const std::string guess = best ? "did you mean " + *best + "? " : "";
  return "unknown method '" + std::string(name) + "' (" + guess + "valid: " + method_names() + ")";
}

std::string method_names() {
  std::string s;
  for (const MethodInfo& m : methods()) s += (s.empty() ? "" : ", ") + m.name;
  return s;
}

Result<std::unique_ptr<Interpolator>> make_interpolator(std::string_view method, RotationTrack track) {
  const MethodInfo* m = find_method(method);
  if (!m) return make_error(unknown_method_message(method));
  // Every method validates the track itself (rules 1–3 of RotationTrack; signs
  // are aligned there, so keys may come in either hemisphere).
  return m->make(std::move(track));
}

}  // namespace rotinterp
