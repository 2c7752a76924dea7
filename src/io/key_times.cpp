// The union of a clip's key times, for the exporters.
#include "key_times.h"

#include <algorithm>

namespace rotinterp {

std::vector<double> all_key_times(const Clip& clip) {
  std::vector<double> times;
  for (const RotationTrack& r : clip.rotations) times.insert(times.end(), r.times.begin(), r.times.end());
  for (const auto& tr : clip.translations)
    if (tr) times.insert(times.end(), tr->times.begin(), tr->times.end());
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  return times;
}

}  // namespace rotinterp
