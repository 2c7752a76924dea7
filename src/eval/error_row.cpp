// errors.csv rows: written against their schema, and parsed back to the same doubles.
#include "rotinterp/eval/error_row.h"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <iterator>
#include <cmath>
#include <cstdlib>
#include <optional>

namespace rotinterp {

namespace {

// Columns in file order. The first thirteen are the documented minimum.
enum Col {
  kClip, kMethod, kKeepEvery, kJoint, kFrames, kMeanDeg, kRmsDeg, kP95Deg, kMaxDeg, kSwingRmsDeg, kTwistRmsDeg,
  kPosRms, kPosMax, kPosRmsPct, kPosMaxPct, kShellRms, kShellMax, kAccRms, kAccRmsRef, kVelJumpMax, kAccJumpMax,
  kSamples, kHeight, kKind, kKeys, kMotionDeg, kContactFrames, kSkateFrames, kSkateSpeed, kContactFramesRef,
  kSkateFramesRef, kSkateSpeedRef, kMetresPerUnit, kUnit, kColumnCount
};

constexpr const char* kColumnNames[kColumnCount] = {
    "clip", "method", "keep_every", "joint", "frames", "mean_deg", "rms_deg", "p95_deg", "max_deg",
    "swing_rms_deg", "twist_rms_deg", "pos_rms_m", "pos_max_m", "pos_rms_pct", "pos_max_pct", "shell_rms_m",
    "shell_max_m", "acc_rms_dps2", "acc_rms_ref_dps2", "vel_jump_max_dps", "acc_jump_max_dps2", "samples",
    "height_m", "kind", "keys", "motion_deg", "contact_frames", "skate_frames", "skate_speed_mps",
    "contact_frames_ref", "skate_frames_ref", "skate_speed_ref_mps", "metres_per_unit", "unit"};

bool is_joint_only(int c) {
  return (c >= kMeanDeg && c <= kTwistRmsDeg) || (c >= kShellRms && c <= kAccJumpMax) || c == kKeys ||
         c == kMotionDeg;
}
// Foot-contact columns: filled on the rows of foot joints only.
bool is_foot_only(int c) { return c >= kContactFrames && c <= kSkateSpeedRef; }
// The metric that fills column `c`; none for the columns every file has.
std::optional<Metric> metric_of(int c) {
  if (c >= kMeanDeg && c <= kMaxDeg) return Metric::angle;
  if (c == kSwingRmsDeg || c == kTwistRmsDeg) return Metric::swing_twist;
  if (c >= kPosRms && c <= kPosMaxPct) return Metric::fk;
  if (c == kShellRms || c == kShellMax) return Metric::shell;
  if (c >= kAccRms && c <= kAccJumpMax) return Metric::smoothness;
  if (is_foot_only(c)) return Metric::foot_skating;
  return std::nullopt;
}
bool has_column(MetricSet columns, int c) {
  const std::optional<Metric> m = metric_of(c);
  return !m || columns.has(*m);
}
// Whether row `r` leaves column `c` empty.
bool is_empty_for(const ErrorRow& r, int c) { return (r.end_site && is_joint_only(c)) || (!r.foot && is_foot_only(c)); }

// The measured columns and the ErrorRow fields they hold.
struct Measured {
  Col col;
  double ErrorRow::*field;
};
constexpr Measured kMeasured[] = {
    {kMeanDeg, &ErrorRow::mean_deg},         {kRmsDeg, &ErrorRow::rms_deg},
    {kP95Deg, &ErrorRow::p95_deg},           {kMaxDeg, &ErrorRow::max_deg},
    {kSwingRmsDeg, &ErrorRow::swing_rms_deg}, {kTwistRmsDeg, &ErrorRow::twist_rms_deg},
    {kPosRms, &ErrorRow::pos_rms},           {kPosMax, &ErrorRow::pos_max},
    {kPosRmsPct, &ErrorRow::pos_rms_pct},    {kPosMaxPct, &ErrorRow::pos_max_pct},
    {kShellRms, &ErrorRow::shell_rms},       {kShellMax, &ErrorRow::shell_max},
    {kAccRms, &ErrorRow::acc_rms},           {kAccRmsRef, &ErrorRow::acc_rms_ref},
    {kVelJumpMax, &ErrorRow::vel_jump_max},  {kAccJumpMax, &ErrorRow::acc_jump_max},
    {kHeight, &ErrorRow::height},            {kKeys, &ErrorRow::keys},
    {kMotionDeg, &ErrorRow::motion_deg},     {kContactFrames, &ErrorRow::contact_frames},
    {kSkateFrames, &ErrorRow::skate_frames}, {kSkateSpeed, &ErrorRow::skate_speed},
    {kContactFramesRef, &ErrorRow::contact_frames_ref}, {kSkateFramesRef, &ErrorRow::skate_frames_ref},
    {kSkateSpeedRef, &ErrorRow::skate_speed_ref}, {kMetresPerUnit, &ErrorRow::metres_per_unit}};

// eval --loop's columns, after `unit`: written and read only when the run had --loop.
struct SeamColumn {
  const char* name;
  double ErrorRow::*field;
};
constexpr SeamColumn kSeamColumns[] = {{"seam_angle_deg", &ErrorRow::seam_angle_deg},
                                       {"inner_angle_deg", &ErrorRow::inner_angle_deg},
                                       {"seam_vel_jump_dps", &ErrorRow::seam_vel_jump},
                                       {"seam_acc_jump_dps2", &ErrorRow::seam_acc_jump},
                                       {"looped", &ErrorRow::looped}};

// Shortest text that reads back as the same double; finite by construction.
std::string number(double v) { return fmt::format("{}", std::isfinite(v) ? v : 0.0); }

Result<double> to_double(const std::string& s, const char* column) {
  if (s.empty()) return make_error(std::string("empty ") + column);
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(s.c_str(), &end);
  if (end != s.c_str() + s.size() || errno == ERANGE || !std::isfinite(v))
    return make_error(std::string("bad number '") + s + "' in column " + column);
  return v;
}

}  // namespace

const std::vector<ErrorValueColumn>& error_value_columns() {
  static const std::vector<ErrorValueColumn> columns = [] {
    std::vector<ErrorValueColumn> v;
    for (const Measured& m : kMeasured)
      v.push_back({kColumnNames[m.col], m.field, is_joint_only(m.col), is_foot_only(m.col), metric_of(m.col)});
    return v;
  }();
  return columns;
}

MetricSet csv_metrics(MetricSet chosen, bool loop) {
  MetricSet out = MetricSet::none();
  for (int m = 0; m < kMetricCount; ++m)
    if (chosen.has(static_cast<Metric>(m)) && (loop || static_cast<Metric>(m) != Metric::seam))
      out.add(static_cast<Metric>(m));
  return out;
}

const CsvSchema& error_csv_schema(MetricSet columns) {
  // One schema per set of metrics, built once (2⁷ small schemas).
  static const std::vector<CsvSchema> schemas = [] {
    std::vector<CsvSchema> v;
    for (unsigned bits = 0; bits < (1u << kMetricCount); ++bits) {
      std::vector<std::string> names;
      for (int c = 0; c < kColumnCount; ++c)
        if (has_column(MetricSet::of_bits(bits), c)) names.emplace_back(kColumnNames[c]);
      if (MetricSet::of_bits(bits).has(Metric::seam))
        for (const SeamColumn& c : kSeamColumns) names.emplace_back(c.name);
      v.emplace_back(std::move(names));
    }
    return v;
  }();
  return schemas[columns.bits()];
}

std::string format_error_row(const ErrorRow& r, MetricSet columns) {
  double values[kColumnCount] = {};
  for (const Measured& m : kMeasured) values[m.col] = r.*m.field;
  CsvRow row(error_csv_schema(columns));
  row << r.clip << r.method << std::to_string(r.keep_every) << r.joint << std::to_string(r.frames);
  for (int c = kMeanDeg; c < kSamples; ++c)
    if (has_column(columns, c)) row << (is_empty_for(r, c) ? "" : number(values[c]));
  row << std::to_string(r.samples) << number(r.height) << (r.end_site ? "end_site" : "joint");
  for (int c = kKind + 1; c < kUnit; ++c)
    if (has_column(columns, c)) row << (is_empty_for(r, c) ? "" : number(values[c]));
  row << r.unit;
  if (columns.has(Metric::seam))
    for (const SeamColumn& c : kSeamColumns) row << (r.seam && !r.end_site ? number(r.*c.field) : "");
  return row.line();
}

Result<ErrorRowParser> ErrorRowParser::from_header(std::string_view header) {
  auto fields = split_csv_line(header);
  if (!fields) return fields.failure("header: ");
  ErrorRowParser p;
  p.column_.assign(kColumnCount, -1);
  for (std::size_t i = 0; i < fields->size(); ++i)
    for (int c = 0; c < kColumnCount; ++c)
      if ((*fields)[i] == kColumnNames[c]) p.column_[c] = static_cast<int>(i);
  // Each metric's columns all or none; the others always.
  for (int c = 0; c < kColumnCount; ++c) {
    const std::optional<Metric> m = metric_of(c);
    if (p.column_[c] >= 0 && m) p.metrics_.add(*m);
  }
  for (int c = 0; c < kColumnCount; ++c)
    if (p.column_[c] < 0 && has_column(p.metrics_, c))
      return make_error(std::string("header has no column '") + kColumnNames[c] + "'" +
                        (metric_of(c) ? std::string(" (metric ") + metric_name(*metric_of(c)) + ")" : ""));
  for (const SeamColumn& c : kSeamColumns) {
    const auto at = std::find(fields->begin(), fields->end(), c.name);
    if (at != fields->end()) p.seam_column_.push_back(static_cast<int>(at - fields->begin()));
  }
  if (!p.seam_column_.empty() && p.seam_column_.size() != std::size(kSeamColumns))
    return make_error("header has some of the seam columns (seam_angle_deg … looped), not all");
  if (!p.seam_column_.empty()) p.metrics_.add(Metric::seam);
  return p;
}

Result<ErrorRow> ErrorRowParser::parse(std::string_view line) const {
  auto fields = split_csv_line(line);
  if (!fields) return fields.failure();
  auto field = [&](int c) -> const std::string& {
    static const std::string empty;
    const int i = column_[c];
    return i >= 0 && i < static_cast<int>(fields->size()) ? (*fields)[static_cast<std::size_t>(i)] : empty;
  };
  ErrorRow r;
  r.clip = field(kClip);
  r.method = field(kMethod);
  r.joint = field(kJoint);
  r.unit = field(kUnit);
  if (r.clip.empty() || r.method.empty() || r.joint.empty()) return make_error("empty clip, method or joint");
  const std::string& kind = field(kKind);
  if (kind != "joint" && kind != "end_site") return make_error("kind is '" + kind + "', not joint or end_site");
  r.end_site = kind == "end_site";
  r.foot = !r.end_site && !field(kContactFrames).empty();
  for (const Measured& m : kMeasured) {
    if (is_empty_for(r, m.col) || !has_column(metrics_, m.col)) continue;
    auto v = to_double(field(m.col), kColumnNames[m.col]);
    if (!v) return v.failure();
    r.*m.field = *v;
  }
  r.seam = !r.end_site && !seam_column_.empty() && seam_column_[0] < static_cast<int>(fields->size()) &&
           !(*fields)[static_cast<std::size_t>(seam_column_[0])].empty();
  for (std::size_t i = 0; r.seam && i < seam_column_.size(); ++i) {
    const auto at = static_cast<std::size_t>(seam_column_[i]);
    auto v = to_double(at < fields->size() ? (*fields)[at] : std::string(), kSeamColumns[i].name);
    if (!v) return v.failure();
    r.*kSeamColumns[i].field = *v;
  }
  for (int c : {kKeepEvery, kFrames, kSamples}) {
    auto v = to_double(field(c), kColumnNames[c]);
    if (!v) return v.failure();
    const double limit = c == kKeepEvery ? 1e9 : 1e15;  // keep_every is an int
    if (*v < 0 || *v != std::floor(*v) || *v > limit)
      return make_error(std::string("column ") + kColumnNames[c] + " is not a count");
    if (c == kKeepEvery) r.keep_every = static_cast<int>(*v);
    if (c == kFrames) r.frames = static_cast<std::size_t>(*v);
    if (c == kSamples) r.samples = static_cast<std::size_t>(*v);
  }
  return r;
}

}  // namespace rotinterp
