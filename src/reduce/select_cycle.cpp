// Key selection on a cycle's track: the same steps as select.cpp, with every interval, window and refit wrapping round the seam.
#include "reducer.h"

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
    add.clear();
    for (std::size_t i = 0; i + 1 < keys.size(); ++i) {
      std::size_t worst = 0;
      double w = 1.0;
      for (std::size_t f = keys[i] + 1; f < keys[i + 1]; ++f)
        if (e[f] > w) w = e[f], worst = f;
      if (worst) add.push_back(worst);
    }
    if (add.empty()) {
      bool reset = false;
      if (values)
        for (std::size_t f : keys)
          if (f < frames && e[f] > 1.0) reset = values->reset(f % period) || reset;
      if (!reset) return Ok{};
      continue;
    }
    if (values)
      for (std::size_t f : add) values->start(f);
    merged.clear();
    std::merge(keys.begin(), keys.end(), add.begin(), add.end(), std::back_inserter(merged));
    keys.swap(merged);
  }
}

// Step 2 on a cycle: drop every key but the seam whose neighbourhood — from its second
// neighbour before to its second after, round the seam — stays within budget on the
// periodic curve without it; else refit its two neighbours' values (the seam's too),
// checked between its third neighbours. Where the neighbourhood goes round the whole
// cycle, every frame is checked.
Status remove_cycle(std::vector<std::size_t>& keys, std::size_t frames, const ErrorFn& err, const KeyValues* values,
                    std::vector<double>& e) {
  const bool closed = keys.back() + 1 == frames;
  std::vector<std::size_t> window, free;
  for (std::size_t i = 1; i + 1 < keys.size();) {
    const std::size_t m = keys.size() - 1;  // keys in the period
    auto around = [&](std::size_t back, std::size_t ahead) { return keys[(i + m - back + ahead) % m]; };
    // The frames from the key `reach` before i to the key `reach` after it; a span that
    // starts at the seam of a closed cycle starts at its image, the last frame.
    auto span = [&](std::size_t reach, std::size_t& lo, std::size_t& hi) {
      if (2 * reach >= m) {
        lo = 0, hi = frames - 1;
        return;
      }
      lo = around(reach, 0), hi = around(0, reach);
      if (lo == 0 && closed) lo = frames - 1;
    };
    window.assign(keys.begin(), keys.end());
    window.erase(window.begin() + static_cast<std::ptrdiff_t>(i));
    std::size_t lo = 0, hi = 0;
    span(2, lo, hi);
    e.resize(span_frames(lo, hi, frames));
    if (Status s = err(window, lo, hi, e.data()); !s) return s;
    const double worst = *std::max_element(e.begin(), e.end());
    bool drop = worst <= 1.0;
    if (!drop && values && worst <= kRefitReach) {
      free = {around(1, 0), around(0, 1)};
      std::sort(free.begin(), free.end());
      free.erase(std::unique(free.begin(), free.end()), free.end());
      span(3, lo, hi);
      auto fitted = values->refit(window, free, lo, hi);
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

}  // namespace

Status select_cycle_keys(std::vector<std::size_t>& keys, std::size_t frames, const ErrorFn& err, const KeyValues* values,
                         bool removal, std::vector<double>& e) {
  if (Status s = insert_cycle(keys, frames, err, values, e); !s) return s;
  if (!removal) return Ok{};
  if (Status s = remove_cycle(keys, frames, err, values, e); !s) return s;
  return insert_cycle(keys, frames, err, values, e);
}

}  // namespace rotinterp::detail
