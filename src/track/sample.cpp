// The one track sampler: keys where they lie, slerp or lerp between, held outside.
#include "rotinterp/track/sample.h"

#include "rotinterp/core/geodesic.h"

#include <cmath>
#include <cstddef>

namespace rotinterp {

namespace {

template <class Track, class Value, class Blend>
void sample_track(const Track& track, const std::vector<double>& times, double snap, Value* out, Blend blend) {
  const std::size_t n = track.times.size();
  std::size_t i = 0;  // the last key at or before t + snap
  for (std::size_t m = 0; m < times.size(); ++m) {
    const double t = times[m];
    while (i + 1 < n && track.times[i + 1] <= t + snap) ++i;
    if (std::abs(track.times[i] - t) <= snap || i + 1 >= n) {
      out[m] = track.keys[i];
    } else if (t < track.times[i]) {  // before the first key
      out[m] = track.keys[0];
    } else {
      const double u = (t - track.times[i]) / (track.times[i + 1] - track.times[i]);
      out[m] = blend(track.keys[i], track.keys[i + 1], u);
    }
  }
}

Quat rotation_blend(const Quat& a, const Quat& b, double u) { return slerp(a, b, u); }
Vec3 translation_blend(const Vec3& a, const Vec3& b, double u) { return a + u * (b - a); }

}  // namespace

void sample_rotations(const RotationTrack& track, const std::vector<double>& times, double snap, Quat* out) {
  sample_track(track, times, snap, out, rotation_blend);
}

void sample_translations(const TranslationTrack& track, const std::vector<double>& times, double snap, Vec3* out) {
  sample_track(track, times, snap, out, translation_blend);
}

Quat sample_rotation(const RotationTrack& track, double t) {
  Quat q;
  sample_rotations(track, {t}, 0.0, &q);
  return q;
}

Vec3 sample_translation(const TranslationTrack& track, double t) {
  Vec3 v;
  sample_translations(track, {t}, 0.0, &v);
  return v;
}

}  // namespace rotinterp
