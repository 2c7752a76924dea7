// Aggregates of errors.csv rows per method × keep_every, over all clips and
// joints. Built from the rows alone, clip by clip in the order of errors.csv, so a
// merge of shard outputs gives the same numbers as a single run. And summary.json,
// written and read here alone: the aggregates with the record of the run.
#pragma once

#include "rotinterp/core/result.h"
#include "rotinterp/eval/error_row.h"

#include <cstddef>
#include <filesystem>
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

struct EvalFailure {
  std::string file;
  std::string message;  // one line, names the file
};

// The options a run evaluated with: shard runs merge only when theirs are equal.
struct RunOptions {
  std::vector<std::string> methods;
  std::vector<int> keep_every;
  int subframe = 0;
  double shell_distance_m = 0;
  bool truth = false;
  friend bool operator==(const RunOptions& a, const RunOptions& b) {
    return a.methods == b.methods && a.keep_every == b.keep_every && a.subframe == b.subframe &&
           a.shell_distance_m == b.shell_distance_m && a.truth == b.truth;
  }
};

// What summary.json records of a run besides its results: a run of one shard, or
// a merge of shard runs (merged_from non-empty).
struct RunRecord {
  std::string version;
  std::vector<std::string> inputs;
  std::size_t files = 0;
  RunOptions options;
  int shard_index = 1, shard_count = 1;  // a run
  std::size_t jobs = 0;                  // a run
  std::vector<std::string> merged_from;  // a merge
  std::string started;                   // UTC, ISO 8601
  double seconds = 0;                    // a run's wall time; a merge: its shards' summed
  double merge_seconds = 0;              // a merge
  std::vector<EvalFailure> failed;
  std::vector<std::string> skipped;
};

// summary.json's text: the record, then the summary's results.
std::string summary_json(const RunRecord& record, const Summary& summary);

// The record of a summary.json (its results are rebuilt from errors.csv instead).
// Errors name the file: unreadable, not JSON, not a rotinterp eval summary.
Result<RunRecord> read_summary_json(const std::filesystem::path& file);

}  // namespace rotinterp
