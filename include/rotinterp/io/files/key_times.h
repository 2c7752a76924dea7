// The key times the exporters put every joint on (private to src/io).
#pragma once

#include "rotinterp/clip/clip.h"

#include <vector>

namespace rotinterp {

// The sorted union of every rotation and translation key time of the clip.
std::vector<double> all_key_times(const Clip& clip);

// Seconds per frame of the uniform grid every time in `seconds` lies on (within 1e-3
// of a step), the step found from the smallest gap and the whole span, and taken as
// an integer or NTSC (n·1000/1001) rate where within 1e-5 of one; 0 where the times
// lie on no grid. Readers that see no stated rate (glTF, Collada, an FBX without
// TimeMode) keep the rate of their keys this way.
double uniform_frame_time(std::vector<double> seconds);

}  // namespace rotinterp
