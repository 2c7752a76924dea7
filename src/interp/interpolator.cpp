#include "rotinterp/interp/interpolator.h"

namespace rotinterp {

void Interpolator::evaluate(const double* t, std::size_t n, Quat* out) const {
  for (std::size_t i = 0; i < n; ++i) out[i] = evaluate(t[i]);
}

Vec3 Interpolator::angular_velocity(double) const { return Vec3::Zero(); }

const std::vector<MethodInfo>& methods() {
  // Filled by the interpolator implementations (interp/*.h).
  static const std::vector<MethodInfo> all;
  return all;
}

const MethodInfo* find_method(std::string_view name) {
  for (const MethodInfo& m : methods())
    if (m.name == name) return &m;
  return nullptr;
}

std::string method_names() {
  std::string s;
  for (const MethodInfo& m : methods()) s += (s.empty() ? "" : ", ") + m.name;
  return s;
}

Result<std::unique_ptr<Interpolator>> make_interpolator(std::string_view method, const RotationTrack& track) {
  const MethodInfo* m = find_method(method);
  if (!m) return make_error("unknown method '" + std::string(method) + "' (valid: " + method_names() + ")");
  if (Status s = track.validate(); !s) return make_error(s.error());
  return m->make(track);
}

}  // namespace rotinterp
