// The most keys (frames × joints) one call makes at once: resample's output clip, a
// Python call's output array, a clip's frames. Refused before anything is allocated,
// with one line naming what asked for them, rather than running out of memory
// part-way (a clip key costs about 40 bytes with its time: 4 GB at the limit).
#pragma once

#include <cstddef>
#include <string>

namespace rotinterp {

inline constexpr std::size_t kMaxKeys = 100000000;

// Whether `frames` × `joints` keys pass kMaxKeys (no overflow for any sizes; a count
// given as a double, such as a duration over a frame time, as it is before rounding).
bool too_many_keys(double frames, std::size_t joints);
// "1500000001 frames × 3 joints, more than 100000000 keys": what a refusal says.
std::string too_many_keys_text(double frames, std::size_t joints);

}  // namespace rotinterp
