// One row of DIR/errors.csv: the error of one joint (or End Site) of one clip,
// rebuilt by one method from every keep_every-th frame. Plain data plus the CSV
// form, written and read back exactly (numbers in the shortest form that reads
// back as the same double), so shard outputs merge into the same files.
#pragma once

#include "rotinterp/core/result.h"
#include "rotinterp/eval/metric_set.h"
#include "rotinterp/io/files/csv.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rotinterp {

struct ErrorRow {
  std::string clip;    // the input path as discovered
  std::string method;  // interpolator name
  int keep_every = 1;  // keys at every keep_every-th frame and the last
  std::string joint;   // joint or End Site name
  bool end_site = false;  // End Site rows carry only position columns
  std::size_t frames = 0;   // frames of the original clip
  std::size_t samples = 0;  // times compared: frames + (frames − 1)·subframe

  // Geodesic angle, degrees (joints only).
  double mean_deg = 0, rms_deg = 0, p95_deg = 0, max_deg = 0;
  double swing_rms_deg = 0, twist_rms_deg = 0;
  // World position error by forward kinematics, metres and % of skeleton height.
  double pos_rms = 0, pos_max = 0, pos_rms_pct = 0, pos_max_pct = 0;
  // Virtual-vertex (shell) error at the shell distance, metres (joints only).
  double shell_rms = 0, shell_max = 0;
  // Smoothness (joints only): RMS angular acceleration of the rebuilt and of the
  // original curve (deg/s²), largest velocity (deg/s) and acceleration (deg/s²) jump at keys.
  double acc_rms = 0, acc_rms_ref = 0, vel_jump_max = 0, acc_jump_max = 0;
  double height = 0;  // skeleton height used for the percentages, metres
  // The source (joints only): its largest key count, and the largest angle (degrees)
  // the joint turns away from its first frame — 0 for a joint that never moves.
  double keys = 0, motion_deg = 0;
  // Foot contact (eval/foot_skating.h; foot joints only, `foot` true): frame intervals
  // in contact with the floor and those of them sliding, and the mean horizontal
  // speed over the contact intervals (m/s), of the rebuilt motion and of the reference.
  bool foot = false;
  double contact_frames = 0, skate_frames = 0, skate_speed = 0;
  double contact_frames_ref = 0, skate_frames_ref = 0, skate_speed_ref = 0;
  // The clip's unit (clip/units.h): metres per unit, and its name and reason.
  double metres_per_unit = 1;
  std::string unit;
  // eval --loop (eval/seam.h; joint rows, `seam` true): the largest angle error at the
  // frames of the two key intervals meeting at the seam and at the other frames (degrees),
  // the velocity (deg/s) and acceleration (deg/s²) jump at the seam, and whether the
  // joint was rebuilt on its periodic curve (1) or misses closure and kept its ends (0).
  bool seam = false;
  double seam_angle_deg = 0, inner_angle_deg = 0, seam_vel_jump = 0, seam_acc_jump = 0, looped = 0;
};

// A measured (floating-point) column of errors.csv: its name, the ErrorRow field
// it holds, whether End Site rows leave it empty, whether rows of joints that
// are not feet leave it empty, and the metric that fills it (none: always there).
struct ErrorValueColumn {
  const char* name;
  double ErrorRow::*field;
  bool joint_only;
  bool foot_only;
  std::optional<Metric> metric;
};
// mean_deg … acc_jump_max_dps2, height_m, keys … skate_speed_ref_mps, metres_per_unit, in file order.
const std::vector<ErrorValueColumn>& error_value_columns();

// The metrics whose columns errors.csv carries: those chosen, and seam only with
// eval --loop (a run without it has no seam to measure).
MetricSet csv_metrics(MetricSet chosen, bool loop);

// errors.csv's columns for `columns` (from csv_metrics): clip,method,keep_every,joint,
// frames, then each measured column of a metric in the set (angle: mean_deg … max_deg,
// swing-twist, fk: pos_*, shell, smoothness: acc_* and the jumps), samples,height_m,
// kind,keys,motion_deg, foot-skating's columns, metres_per_unit,unit, then seam's
// seam_angle_deg … looped. With every metric but seam: the file as before --metrics.
const CsvSchema& error_csv_schema(MetricSet columns = csv_metrics(MetricSet::all(), false));
// One CSV line, with its '\n'. Text fields are quoted when they hold a comma, quote or
// line break; End Site rows leave the joint-only columns empty, and the seam columns
// are empty where the row has none.
std::string format_error_row(const ErrorRow& row, MetricSet columns = csv_metrics(MetricSet::all(), false));

// Reads CSV lines back. Construct from the header line; columns are found by name.
class ErrorRowParser {
 public:
  // The metrics' columns are read when the header has them (each metric's all or
  // none), the seam columns too (an eval --loop run).
  static Result<ErrorRowParser> from_header(std::string_view header);
  bool has_seam_columns() const { return !seam_column_.empty(); }
  MetricSet metrics() const { return metrics_; }  // as csv_metrics gives them
  // `line` is one data line; the error names the problem (the caller adds file:line).
  Result<ErrorRow> parse(std::string_view line) const;

 private:
  std::vector<int> column_;       // field index per known column, −1 when absent
  std::vector<int> seam_column_;  // field index per seam column; empty when the file has none
  MetricSet metrics_ = MetricSet::none();
};

}  // namespace rotinterp
