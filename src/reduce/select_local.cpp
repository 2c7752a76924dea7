// Key insertion for a method of bounded support: only the frames a new key moves are measured again.
#include "select.h"

#include <algorithm>
#include <iterator>
#include <set>

namespace rotinterp::detail {

namespace {

// The per-frame errors `e` of the curve through `keys`, kept exact at every frame, and
// the worst frame over budget of each key interval that has one.
class LocalErrors {
 public:
  LocalErrors(std::vector<std::size_t>& keys, std::vector<double>& e, const ErrorFn& err, std::size_t support)
      : keys_(keys), e_(e), err_(err), s_(support), worst_in_(e.size(), 0) {}

  // Marks the key indices whose curve a key at index i moved (i ± support), for measure().
  void moved_at(std::size_t i) {
    const std::size_t a = i >= s_ ? i - s_ : 0, b = std::min(keys_.size() - 1, i + s_);
    if (!spans_.empty() && a <= spans_.back().second) spans_.back().second = std::max(spans_.back().second, b);
    else spans_.emplace_back(a, b);
  }
  void moved_everywhere() { spans_.assign(1, {0, keys_.size() - 1}); }

  // The marked frames measured again, on a window of keys reaching past them by more
  // than the support (where the curve is the whole track's, bit for bit up to sign);
  // their intervals' worst frames found again.
  Status measure() {
    for (const auto& [a, b] : spans_) {
      const std::size_t reach = s_ + 1, wa = a >= reach ? a - reach : 0, wb = std::min(keys_.size() - 1, b + reach);
      window_.assign(keys_.begin() + static_cast<std::ptrdiff_t>(wa), keys_.begin() + static_cast<std::ptrdiff_t>(wb + 1));
      if (Status s = err_(window_, keys_[a], keys_[b], e_.data() + keys_[a]); !s) return s;
      for (std::size_t i = a; i < b; ++i) find_worst(i);
    }
    spans_.clear();
    return Ok{};
  }

  void find_all_worst() {
    for (std::size_t i = 0; i + 1 < keys_.size(); ++i) find_worst(i);
  }
  // The worst frames of the intervals over budget, in order (worst_frames' answer).
  void worst(std::vector<std::size_t>& add) const {
    add.clear();
    for (std::size_t left : over_) add.push_back(worst_in_[left]);
  }

 private:
  // worst_frames on interval i: the first frame of the largest error above 1, strictly inside.
  void find_worst(std::size_t i) {
    std::size_t worst = 0;
    double w = 1.0;
    for (std::size_t f = keys_[i] + 1; f < keys_[i + 1]; ++f)
      if (e_[f] > w) w = e_[f], worst = f;
    worst_in_[keys_[i]] = worst;
    if (worst) over_.insert(keys_[i]);
    else over_.erase(keys_[i]);
  }

  std::vector<std::size_t>& keys_;
  std::vector<double>& e_;
  const ErrorFn& err_;
  std::size_t s_;
  std::vector<std::pair<std::size_t, std::size_t>> spans_;  // key index ranges to measure, in order
  std::vector<std::size_t> window_;
  std::vector<std::size_t> worst_in_;  // [left key frame]: its interval's worst frame over budget, or 0
  std::set<std::size_t> over_;         // left key frames of the intervals with one
};

}  // namespace

// Step 1 (and 3) as insert_worst does it, for a method whose curve between two keys
// depends on `support` keys on either side (MethodInfo::support): every frame's error
// stays exactly the whole track's when only the frames between the support-th keys
// around a new (or reset) key are measured again, so no pass over every frame follows
// the first (none at all with `known`), and the worst frames come from the intervals
// measured. The same keys and values as insert_worst, found with less work.
Status insert_worst_local(std::vector<std::size_t>& keys, std::size_t frames, const ErrorFn& err, const KeyValues* values,
                          std::vector<double>& e, bool known, std::size_t support) {
  e.resize(frames);
  if (!known)
    if (Status s = err(keys, 0, frames - 1, e.data()); !s) return s;
  LocalErrors errors(keys, e, err, support);
  errors.find_all_worst();
  std::vector<std::size_t> add, merged;
  for (;;) {
    errors.worst(add);
    if (add.empty()) {
      bool reset = false;
      if (values)
        for (std::size_t i = 0; i < keys.size(); ++i)
          if (e[keys[i]] > 1.0 && values->reset(keys[i])) reset = true, errors.moved_at(i);
      if (!reset) return Ok{};
      if (Status s = errors.measure(); !s) return s;
      continue;
    }
    add_keys(keys, add, values, merged);
    for (std::size_t f : add) errors.moved_at(static_cast<std::size_t>(std::lower_bound(keys.begin(), keys.end(), f) - keys.begin()));
    if (Status s = errors.measure(); !s) return s;
  }
}

}  // namespace rotinterp::detail
