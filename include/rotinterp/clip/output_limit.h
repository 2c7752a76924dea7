// The one limit on what a command may make from a clip: frames × joints (or samples ×
// curves) of output. Resample refuses a --fps or --range past it, info --curves a
// --sample rate; the readers' own limits are io/files/limits.h.
#pragma once

#include <cstddef>

namespace rotinterp {

// 100 million keys, about 4 GB at 40 bytes a key: far past any real take (an hour
// of a 100-joint skeleton at 120 Hz is 43 million), and refused before allocating.
inline constexpr std::size_t kMaxOutputKeys = 100000000;

}  // namespace rotinterp
