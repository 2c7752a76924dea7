// The one track sampler: a track's value at any time, as every reader and the
// frame grid read keyed tracks.
#pragma once

#include "rotinterp/track/track.h"

#include <vector>

namespace rotinterp {

// A track at sorted `times`: its key where one lies within `snap` seconds of the
// time (readers' times differ from a frame grid by round-off, float key times by
// more), else the shortest-arc slerp (core/geodesic.h; translations: linear) of the
// two neighbouring keys; held constant outside the keys. `out` holds times.size().
void sample_rotations(const RotationTrack& track, const std::vector<double>& times, double snap, Quat* out);
void sample_translations(const TranslationTrack& track, const std::vector<double>& times, double snap, Vec3* out);

// The same at one time, exact (no snap).
Quat sample_rotation(const RotationTrack& track, double t);
Vec3 sample_translation(const TranslationTrack& track, double t);

}  // namespace rotinterp
