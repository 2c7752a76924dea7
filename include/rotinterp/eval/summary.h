// Aggregates of errors.csv rows per method × keep_every, over all clips and
// joints. Built from the rows alone, clip by clip in the order of errors.csv, so a
// merge of shard outputs gives the same numbers as a single run.
#pragma once

#include "rotinterp/eval/error_row.h"

#include <cstddef>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace rotinterp {

// One method × keep_every. Angles in degrees; "_pct" in % of each clip's skeleton
// height; accelerations in deg/s², velocities in deg/s.
struct SummaryEntry {
  std::string method;
  int keep_every = 1;
  std::size_t clips = 0;
  std::size_t joints = 0;   // joint rows (clip × joint)
  std::size_t samples = 0;  // joint samples compared
  double mean_deg = 0;      // sample-weighted mean over all joints
  double rms_deg = 0;       // sample-weighted RMS over all joints
  double p95_deg = 0;       // 95th percentile of the per-joint p95
  double max_deg = 0;       // largest over all joints
  double swing_rms_deg = 0, twist_rms_deg = 0;
  double pos_rms_pct = 0, pos_max_pct = 0;      // joints and End Sites
  double shell_rms_pct = 0, shell_max_pct = 0;  // joints
  double acc_rms = 0, acc_rms_ref = 0;          // sample-weighted RMS
  double vel_jump_max = 0, acc_jump_max = 0;    // largest
  std::string worst_clip, worst_joint;          // where max_deg occurs
};

struct Summary {
  std::vector<SummaryEntry> entries;  // in order of first appearance in the rows
  std::size_t clips = 0;
  // The clip with the largest RMS angle (over its joints and all methods) at the
  // largest keep_every, and its rows at that spacing, for the per-joint plot.
  std::string worst_clip;
  int worst_keep_every = 0;
  std::vector<ErrorRow> worst_clip_rows;
};

// Feed the rows of one clip at a time, in file order; then finish().
class SummaryBuilder {
 public:
  void add_clip(const std::vector<ErrorRow>& rows);
  Summary finish() const;

 private:
  struct Acc {
    SummaryEntry entry;
    double w_mean = 0, w_sq = 0, w_swing = 0, w_twist = 0, w_acc = 0, w_acc_ref = 0;
    double pos_samples = 0, w_pos = 0, w_shell = 0;
    std::vector<double> p95;
    std::string last_clip;
  };
  std::vector<std::pair<std::string, int>> order_;
  std::map<std::pair<std::string, int>, Acc> acc_;
  std::size_t clips_ = 0;
  std::vector<ErrorRow> worst_rows_;
  int worst_keep_ = 0;
  double worst_score_ = -1.0;
};

// The stdout table: one line per method × keep_every.
std::string format_summary_table(const Summary& summary);

}  // namespace rotinterp
