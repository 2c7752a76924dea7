// Key selection on a cycle's track: the steps of select.cpp on the periodic curve, checked round the seam.
#include "select.h"

#include <algorithm>
#include <cstddef>
#include <iterator>

namespace rotinterp::detail {

namespace {

// Step 1 (and 3) on a cycle: insert the worst frame of every key interval over budget —
// the last interval runs from the last key to the seam's image — until none is, every
// frame measured on the periodic curve each round (a cycle is short). A key frame over
// budget gets the source's value back; the closed form's last frame is the seam's.
Status insert_cycle(std::vector<std::size_t>& keys, std::size_t frames, const ErrorFn& err, const KeyValues* values,
                    std::vector<double>& e) {
  const std::size_t period = keys.back();
  e.resize(frames);
  std::vector<std::size_t> add, merged;
  for (;;) {
    if (Status s = err(keys, 0, frames - 1, e.data()); !s) return s;
    worst_frames(keys, e, add);
    if (add.empty()) {
      bool reset = false;
      if (values)
        for (std::size_t f : keys)
          if (f < frames && e[f] > 1.0) reset = values->reset(f % period) || reset;
      if (!reset) return Ok{};
      continue;
    }
    add_keys(keys, add, values, merged);
  }
}

// Step 2 on a cycle: drop every key but the seam whose removal leaves every frame of the
// cycle within budget (a frame already over it — one its ancestors put out of reach — no
// further over): the whole periodic curve is checked, a cycle being short and a C²
// curve's change reaching round it; else, at most kRefitReach over, refit its two
// neighbours' values (the seam's too), checked over the whole cycle as well.
Status remove_cycle(std::vector<std::size_t>& keys, std::size_t frames, const ErrorFn& err, const KeyValues* values,
                    std::vector<double>& e) {
  std::vector<std::size_t> window, free;
  std::vector<double> now(frames);
  bool measured = false;
  for (std::size_t i = 1; i + 1 < keys.size();) {
    if (!measured) {
      if (Status s = err(keys, 0, frames - 1, now.data()); !s) return s;
      measured = true;
    }
    window.assign(keys.begin(), keys.end());
    window.erase(window.begin() + static_cast<std::ptrdiff_t>(i));
    e.resize(frames);
    if (Status s = err(window, 0, frames - 1, e.data()); !s) return s;
    double worst = 0.0;
    for (std::size_t f = 0; f < frames; ++f) worst = std::max(worst, e[f] / std::max(1.0, now[f]));
    bool drop = worst <= 1.0;
    if (!drop && values && worst <= kRefitReach) {
      const std::size_t m = keys.size() - 1;  // keys in the period
      auto around = [&](std::size_t back, std::size_t ahead) { return keys[(i + m - back + ahead) % m]; };
      free = {around(1, 0), around(0, 1)};
      std::sort(free.begin(), free.end());
      free.erase(std::unique(free.begin(), free.end()), free.end());
      auto fitted = values->refit(window, free, 0, frames - 1);
      if (!fitted) return fitted.failure();
      drop = *fitted;
    }
    if (drop) {
      keys.erase(keys.begin() + static_cast<std::ptrdiff_t>(i));
      measured = false;
    } else {
      ++i;
    }
  }
  return Ok{};
}

}  // namespace

Status select_cycle_keys(std::vector<std::size_t>& keys, std::size_t frames, const ErrorFn& err, const KeyValues* values,
                         bool removal, std::vector<double>& e) {
  if (Status s = insert_cycle(keys, frames, err, values, e); !s) return s;
  if (!removal) return Ok{};
  if (Status s = remove_cycle(keys, frames, err, values, e); !s) return s;
  return insert_cycle(keys, frames, err, values, e);
}

}  // namespace rotinterp::detail
