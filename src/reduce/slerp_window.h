// slerp through a few of a track's frames, evaluated in place (not installed): the
// selection builds such a curve tens of thousands of times per clip, each to measure a
// few dozen frames. Every function gives, bit for bit, what make_slerp's curve through
// decimated_track(times, value, keys) gives, for times that strictly increase and
// values of about unit norm.
#pragma once

#include "rotinterp/core/rotation.h"

#include <cstddef>
#include <vector>

namespace rotinterp::detail {

// make_slerp's prepared keys (detail::prepare) of the track through `value` at the
// sorted frames `keys`.
void prepare_slerp_keys(const std::vector<Quat>& value, const std::vector<std::size_t>& keys, std::vector<Quat>& q);
// The same, reusing `old_prepared` (prepared for `old_keys` with the values `old_values`)
// for each key at the same frame with the same value.
void prepare_slerp_keys_again(const std::vector<Quat>& value, const std::vector<std::size_t>& keys,
                              const std::vector<std::size_t>& old_keys, const std::vector<Quat>& old_values,
                              const std::vector<Quat>& old_prepared, std::vector<Quat>& q);
// The curve through the `n` sorted key frames `keys` with prepared values `prepared`
// at the frames [lo, hi] (times: every frame's), into out[0 .. hi − lo].
void slerp_frames(const std::vector<double>& times, const std::size_t* keys, const Quat* prepared, std::size_t n,
                  std::size_t lo, std::size_t hi, Quat* out);
// prepare_slerp_keys then slerp_frames, preparing only the keys of the segments [lo, hi] falls in.
void slerp_window(const std::vector<double>& times, const std::vector<Quat>& value, const std::vector<std::size_t>& keys,
                  std::size_t lo, std::size_t hi, Quat* out);

}  // namespace rotinterp::detail
