// The metrics eval computes (eval --metrics, Python evaluate's `metrics`): their names,
// declared here once, and the set a run chose. Each metric fills its own columns of
// errors.csv (error_row.h says which); a metric not chosen is not computed at all —
// no forward kinematics unless fk, shell or foot-skating is chosen, no key-jump
// stencil without smoothness — and its columns are left out of every output.
#pragma once

#include "rotinterp/core/result.h"

#include <cstdint>
#include <string>
#include <string_view>

namespace rotinterp {

enum class Metric : std::uint8_t {
  angle,         // geodesic angle: mean, RMS, p95, max (deg)
  swing_twist,   // RMS swing and twist about the bone (deg)
  fk,            // world position by forward kinematics (m, % of height), End Site rows
  shell,         // virtual-vertex error at the shell distance (m)
  smoothness,    // RMS angular acceleration, velocity and acceleration jumps at keys
  foot_skating,  // foot contact and sliding (eval/foot_skating.h)
  seam,          // the seam of a cycle (eval/seam.h; with --loop only)
};
constexpr int kMetricCount = 7;

// A metric's name as the user writes it: angle, swing-twist, fk, shell, smoothness,
// foot-skating, seam.
const char* metric_name(Metric m);

class MetricSet {
 public:
  static MetricSet all() { return MetricSet((1u << kMetricCount) - 1); }
  static MetricSet none() { return MetricSet(0); }
  bool has(Metric m) const { return (bits_ >> static_cast<int>(m)) & 1u; }
  MetricSet& add(Metric m) { bits_ |= 1u << static_cast<int>(m); return *this; }
  bool is_all() const { return bits_ == all().bits_; }
  // The world poses of the rebuilt motion (and of the reference) are needed.
  bool needs_poses() const { return has(Metric::fk) || has(Metric::shell) || has(Metric::foot_skating); }
  // The set as bits (bit i: Metric i), for tables indexed by set.
  unsigned bits() const { return bits_; }
  static MetricSet of_bits(unsigned bits) { return MetricSet(bits & all().bits_); }
  friend bool operator==(MetricSet a, MetricSet b) { return a.bits_ == b.bits_; }
  friend bool operator!=(MetricSet a, MetricSet b) { return a.bits_ != b.bits_; }

 private:
  explicit MetricSet(unsigned bits) : bits_(bits) {}
  unsigned bits_;
};

// Every name, ", "-separated in the order of Metric (for help and error texts).
std::string metric_names();

// "all", or a comma list of metric names (order and repeats do not matter). An
// unknown or empty name is an error that lists the valid ones.
Result<MetricSet> parse_metrics(std::string_view list);
// "all", or the chosen names, comma-separated in the order of Metric: what
// parse_metrics reads back, and what summary.json records.
std::string metrics_text(MetricSet set);

}  // namespace rotinterp
