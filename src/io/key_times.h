// The key times the exporters put every joint on (private to src/io).
#pragma once

#include "rotinterp/clip/clip.h"

#include <vector>

namespace rotinterp {

// The sorted union of every rotation and translation key time of the clip.
std::vector<double> all_key_times(const Clip& clip);

}  // namespace rotinterp
