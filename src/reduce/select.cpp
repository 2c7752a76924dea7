// Key selection on one track: insert the worst frames, remove the keys not needed, verify.
#include "select.h"

#include <algorithm>
#include <iterator>

namespace rotinterp::detail {

// Step 1 (and 3): insert the worst frame of every key interval over budget until none
// is. After an insertion only the frames between the second neighbours of each new key
// are measured again (the curve rebuilt from the keys around them, as in step 2), or
// every frame when those spans cover most of them; "none over budget" is always
// confirmed over every frame with the whole track. A new key takes its start value
// (rotations: the source smoothed by kStartSmoothing, reducer.h); a key frame over budget (a
// fitted value that its ancestors' later keys moved away from) gets the source's
// value back. With `known`, `e` holds every frame's error already.
Status insert_worst(std::vector<std::size_t>& keys, std::size_t frames, const ErrorFn& err, const KeyValues* values,
                    std::vector<double>& e, bool known = false) {
  e.resize(frames);
  std::vector<std::size_t> add, merged, window;
  std::vector<std::pair<std::size_t, std::size_t>> spans;  // key index ranges to measure again
  bool full = true;
  for (;;) {
    if (full && !known)
      if (Status s = err(keys, 0, frames - 1, e.data()); !s) return s;
    known = false;
    worst_frames(keys, e, add);
    if (add.empty()) {
      if (!full) {
        full = true;  // confirm with the whole track
        continue;
      }
      bool reset = false;
      if (values)
        for (std::size_t f : keys)
          if (e[f] > 1.0) reset = values->reset(f) || reset;
      if (!reset) return Ok{};
      continue;
    }
    add_keys(keys, add, values, merged);
    spans.clear();
    std::size_t covered = 0;
    for (std::size_t f : add) {
      const auto i = static_cast<std::size_t>(std::lower_bound(keys.begin(), keys.end(), f) - keys.begin());
      const std::size_t a = i >= 2 ? i - 2 : 0, b = std::min(keys.size() - 1, i + 2);
      if (!spans.empty() && a <= spans.back().second) spans.back().second = b;
      else spans.emplace_back(a, b);
    }
    for (const auto& [a, b] : spans) covered += keys[b] - keys[a] + 1;
    full = 2 * covered > frames;
    if (full) continue;
    for (const auto& [a, b] : spans) {
      const std::size_t wa = a >= kWindow - 2 ? a - (kWindow - 2) : 0, wb = std::min(keys.size() - 1, b + kWindow - 2);
      window.assign(keys.begin() + static_cast<std::ptrdiff_t>(wa), keys.begin() + static_cast<std::ptrdiff_t>(wb + 1));
      if (Status s = err(window, keys[a], keys[b], e.data() + keys[a]); !s) return s;
    }
  }
}

// Step 2: drop every interior key whose neighbourhood stays within budget without it
// — with the values it has, else (fitted values) with its two neighbours' values
// refitted, checked between its third neighbours (a changed value reaches one key
// further than a removed one for the methods that reach beyond a segment).
Status remove_keys(std::vector<std::size_t>& keys, const ErrorFn& err, const KeyValues* values, std::vector<double>& e,
                   std::size_t support) {
  std::vector<std::size_t> window, free;
  for (std::size_t i = 1; i + 1 < keys.size();) {
    const std::size_t a = i >= kWindow ? i - kWindow : 0, b = std::min(keys.size() - 1, i + kWindow);
    window.assign(keys.begin() + static_cast<std::ptrdiff_t>(a), keys.begin() + static_cast<std::ptrdiff_t>(b + 1));
    window.erase(window.begin() + static_cast<std::ptrdiff_t>(i - a));
    const std::size_t lo = keys[i >= 2 ? i - 2 : 0], hi = keys[std::min(keys.size() - 1, i + 2)];
    e.resize(hi - lo + 1);
    // Support 1 (slerp, nlerp): between the neighbours first, the only frames whose curve
    // changes and so where a removal fails; the rest of [lo, hi] only if that part leaves
    // the key worth dropping or refitting. (Others: one measure, one curve built.)
    const std::size_t mid_lo = support == 1 ? keys[i - 1] : lo, mid_hi = support == 1 ? keys[i + 1] : hi;
    // The largest error of the frames [from, to) (none if empty), measured into e.
    auto worst = [&](std::size_t from, std::size_t to) -> Result<double> {
      if (from >= to) return 0.0;
      if (Status s = err(window, from, to - 1, e.data() + (from - lo)); !s) return s.failure();
      return *std::max_element(e.begin() + static_cast<std::ptrdiff_t>(from - lo), e.begin() + static_cast<std::ptrdiff_t>(to - lo));
    };
    auto mid = worst(mid_lo, mid_hi + 1);
    if (!mid) return mid.failure();
    double max = *mid;
    if (max <= (values ? kRefitReach : 1.0)) {
      auto left = worst(lo, mid_lo), right = worst(mid_hi + 1, hi + 1);
      if (!left) return left.failure();
      if (!right) return right.failure();
      max = std::max({max, *left, *right});
    }
    bool drop = max <= 1.0;
    if (!drop && values && max <= kRefitReach) {
      free = {keys[i - 1], keys[i + 1]};
      auto fitted = values->refit(window, free, keys[i >= 3 ? i - 3 : 0], keys[std::min(keys.size() - 1, i + 3)]);
      if (!fitted) return fitted.failure();
      drop = *fitted;
    }
    if (drop)
      keys.erase(keys.begin() + static_cast<std::ptrdiff_t>(i));
    else
      ++i;
  }
  return Ok{};
}

Status select_keys(std::vector<std::size_t>& keys, std::size_t frames, const ErrorFn& err, const KeyValues* values,
                   bool removal, std::vector<double>& e, bool known, std::size_t support) {
  if (frames < 3) return Ok{};
  auto insert = [&](bool e_known) {
    return support > 0 ? insert_worst_local(keys, frames, err, values, e, e_known, support)
                       : insert_worst(keys, frames, err, values, e, e_known);
  };
  if (Status s = insert(known); !s) return s;
  if (!removal) return Ok{};
  if (Status s = remove_keys(keys, err, values, e, support); !s) return s;
  return insert(false);
}

std::vector<std::size_t> ends(std::size_t frames) {
  if (frames == 0) return {};
  if (frames == 1) return {0};
  return {0, frames - 1};
}

void worst_frames(const std::vector<std::size_t>& keys, const std::vector<double>& e, std::vector<std::size_t>& add) {
  add.clear();
  for (std::size_t i = 0; i + 1 < keys.size(); ++i) {
    std::size_t worst = 0;
    double w = 1.0;
    for (std::size_t f = keys[i] + 1; f < keys[i + 1]; ++f)
      if (e[f] > w) w = e[f], worst = f;
    if (worst) add.push_back(worst);
  }
}

bool has(const std::vector<std::size_t>& keys, std::size_t f) { return std::binary_search(keys.begin(), keys.end(), f); }
void add_key(std::vector<std::size_t>& keys, std::size_t f) {
  auto it = std::lower_bound(keys.begin(), keys.end(), f);
  if (it == keys.end() || *it != f) keys.insert(it, f);
}

}  // namespace rotinterp::detail
