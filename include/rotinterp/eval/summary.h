// Aggregates of errors.csv rows per method × keep_every, over all clips and
// joints. Built from the rows alone, clip by clip in the order of errors.csv, so a
// merge of shard outputs gives the same numbers as a single run. And summary.json,
// written and read here alone: the aggregates with the record of the run.
#pragma once

#include "rotinterp/core/result.h"
#include "rotinterp/eval/error_row.h"
#include "rotinterp/batch/folder_run.h"  // FileFailure

#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace rotinterp {

// Foot skating summed over feet (and clips): eval/foot_skating.h. Counts are frame
// intervals; speeds summed in m/s over the contact intervals.
struct FootSkating {
  std::size_t feet = 0;         // foot tracks (clip × foot)
  double intervals = 0;         // frame intervals of all foot tracks
  double contact = 0, skating = 0, speed_sum = 0;              // the rebuilt motion
  double contact_ref = 0, skating_ref = 0, speed_sum_ref = 0;  // the reference
  void add(const ErrorRow& foot_row);
  void add(const FootSkating& other);
  // Share of the foot intervals spent sliding in contact, and mean horizontal speed
  // over the contact intervals (m/s); "extra": rebuilt − reference.
  double ratio() const { return intervals > 0 ? skating / intervals : 0.0; }
  double ratio_ref() const { return intervals > 0 ? skating_ref / intervals : 0.0; }
  double speed() const { return contact > 0 ? speed_sum / contact : 0.0; }
  double speed_ref() const { return contact_ref > 0 ? speed_sum_ref / contact_ref : 0.0; }
};

// eval --loop (eval/seam.h): the seam against the inside, over the joint rows rebuilt
// on their periodic curves (looped); the rows of joints that miss closure are counted
// apart (their pop is in errors.csv). Largest values; degrees, deg/s, deg/s².
struct SeamSummary {
  double angle_deg = 0, inner_angle_deg = 0;
  double vel_jump = 0, inner_vel_jump = 0;
  double acc_jump = 0, inner_acc_jump = 0;
  std::size_t looped = 0, not_looped = 0;  // joint rows
  void add(const ErrorRow& joint_row);     // a row with seam columns
  void add(const SeamSummary& other);
};

// One clip × method × keep_every: the aggregates of its rows (clips.csv, and the
// "clips" section of summary.json). Angles in degrees, "_pct" in % of its height.
struct ClipResult {
  std::string clip, method;
  int keep_every = 1;
  std::size_t frames = 0, joints = 0, samples = 0;
  double metres_per_unit = 1;      // the clip's unit (clip/units.h) …
  std::string unit;                // … its name and where it came from
  double keys = 0;                 // largest key count of any joint in the source
  double motion_deg = 0;           // largest angle any joint turns from the first frame (0: static)
  double mean_deg = 0, rms_deg = 0;  // over all its joint samples
  double p95_deg = 0;              // 95th percentile of the per-joint p95
  double max_deg = 0;
  std::string max_joint;           // where max_deg occurs
  double pos_rms_pct = 0, pos_max_pct = 0, shell_rms_pct = 0, shell_max_pct = 0;
  FootSkating skating;
  SeamSummary seam;  // with --loop (Summary::seam)
};

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
  // Each clip counted once: the median over clips of the clip's RMS, p95 and max
  // (ClipResult), beside the sample-weighted values above.
  double clip_rms_median_deg = 0, clip_p95_median_deg = 0, clip_max_median_deg = 0;
  FootSkating skating;                          // summed over the clips with feet
  SeamSummary seam;                             // over the clips, with --loop
};

struct Summary {
  std::vector<SummaryEntry> entries;  // in order of first appearance in the rows
  std::vector<ClipResult> clip_results;  // per clip, in row order
  std::size_t clips = 0;
  // The clip with the largest RMS angle (over its joints and all methods) at the
  // largest keep_every, and its rows at that spacing, for the per-joint plot.
  std::string worst_clip;
  int worst_keep_every = 0;
  std::vector<ErrorRow> worst_clip_rows;
  bool seam = false;  // the rows carry seam columns (eval --loop): clips.csv and summary.json report them
  // The metrics the rows carry (csv_metrics): the table, clips.csv, summary.json and
  // the plots report only these.
  MetricSet metrics = MetricSet::all();
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
    std::vector<double> clip_rms, clip_p95, clip_max;
    std::string last_clip;
  };
  std::vector<std::pair<std::string, int>> order_;
  std::map<std::pair<std::string, int>, Acc> acc_;
  std::vector<ClipResult> clip_results_;
  std::size_t clips_ = 0;
  std::vector<ErrorRow> worst_rows_;
  int worst_keep_ = 0;
  double worst_score_ = -1.0;
};

// The metric a value of the summary belongs to, by its name in summary.json and
// clips.csv (mean_deg and worst: angle, pos_max_pct: fk, foot_skating and skate_*:
// foot-skating, …); none for names and counts. Values of metrics not chosen are left out.
std::optional<Metric> summary_metric(std::string_view name);

// The results table: one line per method × keep_every — clips, mean, RMS, p95 and
// max angle, the median clip RMS, position max and the extra skating, those of the
// summary's metrics — as plain
// text (stdout), Markdown or LaTeX. Values to 4 significant figures in fixed
// notation; below 0.001 "< 0.001", exact zeros "0".
enum class TableFormat { text, markdown, latex };
std::string format_summary_table(const Summary& summary, TableFormat format = TableFormat::text);

// clips.csv: its header and one line per ClipResult (numbers as in errors.csv).
std::string clips_csv(const Summary& summary);

// A file that failed to load or evaluate (batch/folder_run.h: the kind kept).
using EvalFailure = FileFailure;

// A clip evaluated at fewer spacings than asked, or at none: too few frames
// (skipped_spacings in evaluate_clip.h).
struct ShortClip {
  std::string clip;
  std::size_t frames = 0;
  std::vector<int> keep_every;  // the spacings skipped
};

// The options a run evaluated with: shard runs merge only when theirs are equal.
struct RunOptions {
  std::vector<std::string> methods;
  std::vector<int> keep_every;
  int subframe = 0;
  double shell_distance_m = 0;
  std::string truth = "frames";     // EvalOptions::Truth::name: frames, synth or source
  std::string animation;            // --anim: empty (the first), a name or index, or "all"
  std::size_t min_frames = 0;
  std::vector<std::string> feet;    // --feet; empty: by name
  double contact_height_m = 0, contact_speed_mps = 0;
  std::optional<double> floor_m;
  std::optional<double> unit;       // --unit, metres per unit of files that state none
  std::string loop = "off";         // --loop: off, auto, closed or open
  std::string metrics = "all";      // --metrics as metrics_text() writes it
  friend bool operator==(const RunOptions& a, const RunOptions& b) {
    return a.methods == b.methods && a.metrics == b.metrics && a.keep_every == b.keep_every && a.subframe == b.subframe && a.loop == b.loop &&
           a.shell_distance_m == b.shell_distance_m && a.truth == b.truth && a.animation == b.animation &&
           a.min_frames == b.min_frames && a.feet == b.feet && a.contact_height_m == b.contact_height_m &&
           a.contact_speed_mps == b.contact_speed_mps && a.floor_m == b.floor_m && a.unit == b.unit;
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
  std::vector<ShortClip> too_short;
};

// summary.json's text: the record, then the summary's results.
std::string summary_json(const RunRecord& record, const Summary& summary);

// The record of a summary.json (its results are rebuilt from errors.csv instead).
// Errors name the file: unreadable, not JSON, not a rotinterp eval summary.
Result<RunRecord> read_summary_json(const std::filesystem::path& file);

}  // namespace rotinterp
