// The selection of keys on one track (not installed): select.cpp, select_local.cpp and
// select_cycle.cpp run it, the reducer (reducer.h) gives it each track's error and key values.
#pragma once

#include "rotinterp/core/result.h"

#include <algorithm>
#include <cstddef>
#include <functional>
#include <iterator>
#include <vector>

namespace rotinterp::detail {

// Keys rebuilt on either side of a key whose removal is checked: squad, expmap,
// clamped and gltf-cubic reach one key beyond a segment, so the frames between the
// removed key's second neighbours see exactly the whole track's curve; c2, bf and
// expmap-c2 are global, but the influence of a key decays by ≈ 0.27 per key, and
// the verification over every frame catches the rest.
inline constexpr std::size_t kWindow = 4;
// A key whose removal leaves its neighbourhood at most this far over budget is
// tried again with its neighbours' values refitted, in at most kRefitIterations
// steps. Measured at 1 mm at 10 cm on CMU 01_01 and the Bandai walk (slerp, c2, bf):
// 1.25 and 2 keep as few keys as 2.0 and 3, within 2 %, in half the time (a refit
// far over budget that succeeds spends the neighbours' room).
inline constexpr double kRefitReach = 1.25;
inline constexpr int kRefitIterations = 2;

// Normalized error (≤ 1: within budget) of the frames [lo, hi] of a curve rebuilt
// from the sorted key frames `keys` (which span [lo, hi] outside a cycle); out[f − lo].
using ErrorFn = std::function<Status(const std::vector<std::size_t>& keys, std::size_t lo, std::size_t hi, double* out)>;
// Key values that are fitted rather than copied from the source (rotation tracks):
//  * start(f) sets the value of a new key at f;
//  * reset(f) sets the value of a key at f back to the source's, true if it changed;
//  * refit(keys, free, lo, hi) tries values at the key frames `free` that bring the
//    frames [lo, hi] of the curve through `keys` within budget: true (and the values
//    kept) if it found them, false (and the values as they were) if not.
struct KeyValues {
  std::function<void(std::size_t f)> start;
  std::function<bool(std::size_t f)> reset;
  std::function<Result<bool>(const std::vector<std::size_t>& keys, const std::vector<std::size_t>& free, std::size_t lo,
                             std::size_t hi)>
      refit;
};
// Merges the sorted new key frames `add` into the sorted `keys` (`scratch`: reused
// storage), each new key's value started first where values are fitted.
inline void add_keys(std::vector<std::size_t>& keys, const std::vector<std::size_t>& add, const KeyValues* values,
                     std::vector<std::size_t>& scratch) {
  if (values)
    for (std::size_t f : add) values->start(f);
  scratch.clear();
  std::merge(keys.begin(), keys.end(), add.begin(), add.end(), std::back_inserter(scratch));
  keys.swap(scratch);
}

// The selection on one track of `frames` frames: insertion, then (with `removal`) removal
// and insertion again (reduce/reduce.h, steps 1–3). `keys` holds the start keys, and the kept
// ones on return; `e` holds every frame's error of the kept keys on return (frames ≥ 3) and,
// with `known`, already on entry (the first measure over every frame is skipped). A
// `support` > 0 (MethodInfo::support of the curve `err` rebuilds) measures only the
// frames a new key moves (select_local.cpp); 0, every frame when the new keys' spans
// cover most of them and once more at the end.
Status select_keys(std::vector<std::size_t>& keys, std::size_t frames, const ErrorFn& err, const KeyValues* values,
                   bool removal, std::vector<double>& e, bool known = false, std::size_t support = 0);
Status insert_worst_local(std::vector<std::size_t>& keys, std::size_t frames, const ErrorFn& err, const KeyValues* values,
                          std::vector<double>& e, bool known, std::size_t support);
// The same on a cycle of `frames` frames (select_cycle.cpp): keys[0] = 0 is the seam, the
// one key the cycle keeps; the last key is its image one period on (closed: frames − 1,
// open: frames), no key of its own. The last interval runs round the seam, and removals
// and refits are checked on the whole periodic curve.
Status select_cycle_keys(std::vector<std::size_t>& keys, std::size_t frames, const ErrorFn& err, const KeyValues* values,
                         bool removal, std::vector<double>& e);
// The first and last of `frames` frames (one for one frame, none for none).
std::vector<std::size_t> ends(std::size_t frames);
// The worst frame over budget (error `e` above 1) inside each key interval, into `add`.
void worst_frames(const std::vector<std::size_t>& keys, const std::vector<double>& e, std::vector<std::size_t>& add);
// Whether the sorted `keys` hold `f`; `f` added to them in order (once).
bool has(const std::vector<std::size_t>& keys, std::size_t f);
void add_key(std::vector<std::size_t>& keys, std::size_t f);

}  // namespace rotinterp::detail
