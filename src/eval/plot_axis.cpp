// Ranges, ticks and texts of eval's plot axes.
#include "rotinterp/eval/plot_axis.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace rotinterp {

namespace {

// More decades than this are labelled every other one (or sparser).
constexpr int kMaxDecadeTicks = 8;

// A value as a short label: 0.05, 2, 180, 1e-5.
std::string value_label(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", v);
  std::string s = text;
  if (const std::size_t e = s.find("e-0"); e != std::string::npos) s.erase(e + 2, 1);
  if (const std::size_t e = s.find("e+0"); e != std::string::npos) s.erase(e + 1, 2);
  return s;
}

// Multiples of the largest round step (1, 2 or 5 × 10ᵏ) of which at least kMinTicks
// lie in [lo, hi] (values, not logs).
std::vector<double> round_values(double lo, double hi) {
  for (double step = std::pow(10.0, std::ceil(std::log10(hi - lo))); step > 0; ) {
    std::vector<double> out;
    for (double k = std::ceil(lo / step - 1e-9); k * step <= hi + 1e-9 * step; ++k) out.push_back(k * step);
    if (static_cast<int>(out.size()) >= kMinTicks) {
      for (double& v : out) v = std::abs(v) < step * 1e-9 ? 0.0 : v;  // -0 and round-off at 0
      return out;
    }
    const double m = step / std::pow(10.0, std::floor(std::log10(step) + 1e-9));
    step *= m > 4.5 ? 0.4 : 0.5;  // 10 → 5 → 2 → 1
  }
  return {lo, hi};
}

std::vector<PlotTick> log_ticks(double lo, double hi) {
  std::vector<PlotTick> ticks;
  const int k0 = static_cast<int>(std::ceil(lo - 1e-9)), k1 = static_cast<int>(std::floor(hi + 1e-9));
  if (k1 - k0 + 1 >= kMinTicks) {  // decades
    const int every = (k1 - k0) / kMaxDecadeTicks + 1;
    for (int k = k0; k <= k1; k += every) ticks.push_back({double(k), value_label(std::pow(10.0, k))});
    return ticks;
  }
  for (int k = k0 - 1; k <= k1; ++k)  // 1-2-5 within decades
    for (double m : {1.0, 2.0, 5.0}) {
      const double at = k + std::log10(m);
      if (at >= lo - 1e-9 && at <= hi + 1e-9) ticks.push_back({at, value_label(m * std::pow(10.0, k))});
    }
  if (static_cast<int>(ticks.size()) >= kMinTicks) return ticks;
  ticks.clear();  // less than a factor of ~2.5: a log axis is nearly linear, so round values
  for (double v : round_values(std::pow(10.0, lo), std::pow(10.0, hi)))
    if (v > 0) ticks.push_back({std::log10(v), value_label(v)});
  return ticks;
}

std::vector<PlotTick> linear_ticks(double lo, double hi) {
  std::vector<PlotTick> ticks;
  for (double v : round_values(lo, hi)) ticks.push_back({v, value_label(v)});
  return ticks;
}

// Shifts [lo, hi] down so that it ends within the pad above `cap` (when the values allow).
void cap_range(double& lo, double& hi, double data_hi, double cap) {
  const double top = std::max(cap, data_hi) + kAxisPad * (hi - lo);
  if (hi > top) lo -= hi - top, hi = top;
}

std::vector<std::size_t> code_points(const std::string& text) {  // byte offset of each
  std::vector<std::size_t> at;
  for (std::size_t i = 0; i < text.size(); ++i)
    if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80) at.push_back(i);
  return at;
}

// Lengthens the limits of entries whose labels collide with a different entry's until
// none do; `make(i, limit)` gives entry i's label at its limit.
template <class Make>
std::vector<std::string> unique_labels(const std::vector<std::string>& names, std::size_t limit, Make make) {
  std::vector<std::size_t> limits(names.size(), limit);
  std::vector<std::string> labels(names.size());
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t i = 0; i < names.size(); ++i) labels[i] = make(i, limits[i]);
    std::map<std::string, std::vector<std::size_t>> by_label;
    for (std::size_t i = 0; i < names.size(); ++i) by_label[labels[i]].push_back(i);
    for (const auto& [label, group] : by_label) {
      bool distinct = false;
      for (std::size_t i : group) distinct |= names[i] != names[group.front()];
      if (!distinct) continue;
      for (std::size_t i : group)
        if (make(i, limits[i] + 1) != labels[i]) ++limits[i], changed = true;
    }
  }
  return labels;
}

}  // namespace

PlotAxis angle_axis(const std::vector<double>& deg, AxisScale scale) {
  PlotAxis a;
  double mn = INFINITY, mx = -INFINITY;
  bool zero = false;
  for (double v : deg) {
    if (!std::isfinite(v)) continue;
    if (v > kZeroDeg) mn = std::min(mn, v), mx = std::max(mx, v);
    else zero = true;
  }
  a.any = std::isfinite(mn);
  if (!a.any) {  // nothing to scale: 0 to 1°, zeros on the line at 0
    a.lo = -kAxisPad, a.hi = 1;
    a.ticks = linear_ticks(0, 1);
    return a;
  }
  a.log = scale == AxisScale::log || mx >= 10 * mn;
  if (a.log) {
    double lo = std::log10(mn), hi = std::log10(mx);
    if (hi - lo < kMinLogSpan) lo = 0.5 * (lo + hi) - 0.5 * kMinLogSpan, hi = lo + kMinLogSpan;
    const double pad = kAxisPad * (hi - lo);
    a.lo = lo - pad, a.hi = hi + pad;
    cap_range(a.lo, a.hi, std::log10(mx), std::log10(kMaxDeg));
    a.data_lo = zero ? a.lo : std::log10(mn), a.data_hi = std::log10(mx);
    a.ticks = log_ticks(a.lo, a.hi);
    return a;
  }
  double lo = zero || mn <= 0.5 * mx ? 0.0 : mn, hi = mx;
  if (hi - lo < kMinLinearSpan * mx) {  // all near one value: a span around it
    const double mid = 0.5 * (lo + hi);
    lo = std::max(0.0, mid - 0.5 * kMinLinearSpan * mx), hi = lo + kMinLinearSpan * mx;
  }
  const double pad = kAxisPad * (hi - lo);
  a.lo = lo - pad, a.hi = hi + pad;
  cap_range(a.lo, a.hi, mx, kMaxDeg);
  a.data_lo = zero ? 0.0 : mn, a.data_hi = mx;
  a.ticks = linear_ticks(std::max(a.lo, lo == 0 ? 0.0 : a.lo), a.hi);
  return a;
}

PlotAxis spacing_axis(const std::vector<int>& keep_every) {
  PlotAxis a;
  a.log = true;
  double mn = INFINITY, mx = -INFINITY;
  for (int n : keep_every) {
    const double x = std::log2(std::max(1, n));
    mn = std::min(mn, x), mx = std::max(mx, x);
  }
  a.any = std::isfinite(mn);
  if (!a.any) mn = 1, mx = 2;
  a.data_lo = mn, a.data_hi = mx;
  // Half a doubling each side: room for the methods' sideways offsets.
  a.lo = mn - 0.5, a.hi = mx + 0.5;
  for (bool up = true; std::floor(a.hi) - std::ceil(a.lo) + 1 < kMinTicks; up = !up)
    (up || a.lo < 0.5 ? a.hi : a.lo) += up || a.lo < 0.5 ? 1.0 : -1.0;
  for (double k = std::ceil(a.lo); k <= a.hi; ++k) a.ticks.push_back({k, value_label(std::pow(2.0, k))});
  return a;
}

std::size_t text_chars(const std::string& text) { return code_points(text).size(); }

std::string middle_ellipsis(const std::string& text, std::size_t max_chars) {
  const std::vector<std::size_t> at = code_points(text);
  if (at.size() <= max_chars) return text;
  const std::size_t keep = std::max<std::size_t>(max_chars, 3) - 1;
  const std::size_t head = (keep + 1) / 2, tail = keep - head;
  return text.substr(0, at[head]) + "…" + text.substr(at[at.size() - tail]);
}

std::vector<std::string> short_labels(const std::vector<std::string>& names, std::size_t max_chars) {
  return unique_labels(names, max_chars, [&](std::size_t i, std::size_t limit) { return middle_ellipsis(names[i], limit); });
}

std::string clip_file_name(const std::string& clip) {
  // A take follows the file's name after '#': the file is the first '#'-ended component
  // that looks like a file name (has a '.'); a '#' in a directory does not count.
  for (std::size_t p = clip.find('#'); p != std::string::npos; p = clip.find('#', p + 1)) {
    const std::size_t slash = clip.rfind('/', p);
    const std::size_t start = slash == std::string::npos ? 0 : slash + 1;
    if (clip.find('.', start) < p) return clip.substr(start);
  }
  const std::size_t slash = clip.rfind('/');
  return slash == std::string::npos ? clip : clip.substr(slash + 1);
}

std::vector<std::string> clip_labels(const std::vector<std::string>& clips) {
  // Entry i at "limit" L: its file name and L − 1 parent directories.
  auto with_parents = [&](std::size_t i, std::size_t limit) {
    const std::string name = clip_file_name(clips[i]);
    std::size_t start = clips[i].size() - name.size();
    for (std::size_t up = 1; up < limit && start > 1; ++up) {
      const std::size_t slash = clips[i].rfind('/', start - 2);
      start = slash == std::string::npos ? 0 : slash + 1;
    }
    return clips[i].substr(start);
  };
  return unique_labels(clips, 1, with_parents);
}

}  // namespace rotinterp
