// A track's value at any time, as every importer reads keyed tracks: its key where
// it has one, slerp (rotations) or lerp (translations) between keys, clamped
// outside. The exporters use it to put every joint on one set of key times
// (private to src/io).
#pragma once

#include "rotinterp/clip/clip.h"

#include <algorithm>
#include <cstddef>

namespace rotinterp {

template <class Track, class Mix>
auto sample_track(const Track& track, double t, Mix mix) {
  const auto& ts = track.times;
  if (t <= ts.front()) return track.keys.front();
  if (t >= ts.back()) return track.keys.back();
  const auto hi = static_cast<std::size_t>(std::upper_bound(ts.begin(), ts.end(), t) - ts.begin());
  if (ts[hi - 1] == t) return track.keys[hi - 1];
  return mix(track.keys[hi - 1], track.keys[hi], (t - ts[hi - 1]) / (ts[hi] - ts[hi - 1]));
}

inline Quat sample_rotation(const RotationTrack& r, double t) {
  return sample_track(r, t, [](const Quat& a, const Quat& b, double u) { return Quat(a.slerp(u, b).normalized()); });
}

inline Vec3 sample_translation(const TranslationTrack& tr, double t) {
  return sample_track(tr, t, [](const Vec3& a, const Vec3& b, double u) { return Vec3((1 - u) * a + u * b); });
}

// The sorted union of every rotation and translation key time of the clip.
std::vector<double> all_key_times(const Clip& clip);

}  // namespace rotinterp
