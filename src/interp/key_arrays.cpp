// Keys as flat numeric arrays: made unit, and every joint interpolated at once.
#include "rotinterp/interp/key_arrays.h"

#include "rotinterp/interp/continued.h"
#include "rotinterp/interp/interpolator.h"

#include <algorithm>
#include <memory>
#include <utility>
#include <vector>

namespace rotinterp {

namespace {

bool curve_is_its_keys(const std::string& method) {
  const MethodInfo* m = find_method(method);
  return m && (m->name == "slerp" || m->name == "nlerp");
}

// The first key of joint j that unit_quat refuses, as an error.
template <class Component>
Status bad_key(const KeyArrays<Component>& keys, std::size_t j) {
  Eigen::Vector4d unused = Eigen::Vector4d::Zero();
  for (std::size_t i = 0; i < keys.keys; ++i) {
    const Component* p = keys.quats + 4 * (i * keys.joints + j);
    const double raw[4] = {p[0], p[1], p[2], p[3]};
    if (!unit_quat(raw, unused))
      return make_error("joint " + std::to_string(j) + ", key " + std::to_string(i) +
                        " is not a finite non-zero quaternion");
  }
  return Ok{};
}

}  // namespace

template <class Component>
std::size_t unit_tracks(const KeyArrays<Component>& keys, std::size_t first, std::size_t count,
                        RotationTrack* tracks) {
  for (std::size_t c = 0; c < count; ++c) {
    tracks[c].times.assign(keys.times, keys.times + keys.keys);
    tracks[c].keys.resize(keys.keys);
  }
  std::size_t bad = count;
  Eigen::Vector4d u = Eigen::Vector4d::Zero();
  for (std::size_t i = 0; i < keys.keys; ++i) {
    const Component* row = keys.quats + 4 * (i * keys.joints + first);
    for (std::size_t c = 0; c < count; ++c) {
      const Component* p = row + 4 * c;
      const double raw[4] = {p[0], p[1], p[2], p[3]};
      if (unit_quat(raw, u))
        tracks[c].keys[i] = quat_at(u.data(), keys.scalar_first);
      else
        bad = std::min(bad, c);
    }
  }
  return bad;
}

template <class Component>
Status interpolate_key_arrays(const KeyArrays<Component>& keys, const double* at, std::size_t n,
                              const KeyArraysCurve& curve, double* out) {
  constexpr std::size_t kBlock = 64;  // output times per evaluate call (measured: 64 to 1024 alike)
  constexpr std::size_t kGather = 8;  // joints gathered per pass when curves are built one at a time
  const std::size_t joints = keys.joints;
  const std::size_t group = curve_is_its_keys(curve.method) ? std::max<std::size_t>(joints, 1) : 1;
  std::vector<std::unique_ptr<Interpolator>> curves(group);
  // Keys are gathered a pass per `gather` joints; waiting as keys, tracks cost far less
  // than built curves.
  const std::size_t gather = group > 1 ? group : kGather;
  std::vector<RotationTrack> tracks;
  std::size_t bad = 0;  // offset in `tracks` of the first joint with a refused key
  std::vector<Quat> samples(kBlock);
  for (std::size_t j0 = 0; j0 < joints; j0 += group) {
    const std::size_t g = std::min(group, joints - j0);
    if (j0 % gather == 0) {
      tracks.resize(std::min(gather, joints - j0));
      bad = unit_tracks(keys, j0, tracks.size(), tracks.data());
    }
    for (std::size_t c = 0; c < g; ++c) {
      curves[c].reset();
      const std::size_t t = j0 % gather + c;
      if (t == bad) return bad_key(keys, j0 + c);
      auto built = make_interpolator(curve.method, std::move(tracks[t]));
      if (!built) return joints > 1 ? built.failure("joint " + std::to_string(j0 + c) + ": ") : built.failure();
      curves[c] = curve.continued
                      ? continue_at_end_velocity(std::move(*built), keys.times[0], keys.times[keys.keys - 1])
                      : std::move(*built);
    }
    for (std::size_t i0 = 0; i0 < n; i0 += kBlock) {
      const std::size_t m = std::min(kBlock, n - i0);
      for (std::size_t c = 0; c < g; ++c) {
        curves[c]->evaluate(at + i0, m, samples.data());
        for (std::size_t i = 0; i < m; ++i)
          put_quat(samples[i], out + 4 * ((i0 + i) * joints + j0 + c), curve.out_scalar_first);
      }
    }
  }
  return Ok{};
}

template std::size_t unit_tracks(const KeyArrays<double>&, std::size_t, std::size_t, RotationTrack*);
template std::size_t unit_tracks(const KeyArrays<float>&, std::size_t, std::size_t, RotationTrack*);
template Status interpolate_key_arrays(const KeyArrays<double>&, const double*, std::size_t, const KeyArraysCurve&,
                                       double*);
template Status interpolate_key_arrays(const KeyArrays<float>&, const double*, std::size_t, const KeyArraysCurve&,
                                       double*);

}  // namespace rotinterp
