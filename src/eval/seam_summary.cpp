// The seam figures of eval --loop summed over joints and clips, and their clips.csv and summary.json form.
#include "seam_summary.h"

#include <fmt/format.h>

#include <algorithm>

namespace rotinterp {

void SeamSummary::add(const ErrorRow& r) {
  if (r.end_site || !r.seam) return;
  if (r.looped == 0.0) {
    ++not_looped;
    return;
  }
  ++looped;
  angle_deg = std::max(angle_deg, r.seam_angle_deg);
  inner_angle_deg = std::max(inner_angle_deg, r.inner_angle_deg);
  vel_jump = std::max(vel_jump, r.seam_vel_jump);
  inner_vel_jump = std::max(inner_vel_jump, r.vel_jump_max);
  acc_jump = std::max(acc_jump, r.seam_acc_jump);
  inner_acc_jump = std::max(inner_acc_jump, r.acc_jump_max);
}

void SeamSummary::add(const SeamSummary& o) {
  angle_deg = std::max(angle_deg, o.angle_deg);
  inner_angle_deg = std::max(inner_angle_deg, o.inner_angle_deg);
  vel_jump = std::max(vel_jump, o.vel_jump);
  inner_vel_jump = std::max(inner_vel_jump, o.inner_vel_jump);
  acc_jump = std::max(acc_jump, o.acc_jump);
  inner_acc_jump = std::max(inner_acc_jump, o.inner_acc_jump);
  looped += o.looped;
  not_looped += o.not_looped;
}

const CsvSchema& seam_csv_schema() {
  static const CsvSchema schema = {"looped_joints",     "not_looped_joints",  "seam_angle_deg",
                                   "inner_angle_deg",   "seam_vel_jump_dps",  "inner_vel_jump_dps",
                                   "seam_acc_jump_dps2", "inner_acc_jump_dps2"};
  return schema;
}

void add_seam_fields(CsvRow& row, const SeamSummary& s) {
  for (double v : {double(s.looped), double(s.not_looped), s.angle_deg, s.inner_angle_deg, s.vel_jump,
                   s.inner_vel_jump, s.acc_jump, s.inner_acc_jump})
    row << fmt::format("{}", v);
}

nlohmann::json seam_json(const SeamSummary& s) {
  return {{"looped_joints", s.looped},
          {"not_looped_joints", s.not_looped},
          {"seam_angle_deg", s.angle_deg},
          {"inner_angle_deg", s.inner_angle_deg},
          {"seam_vel_jump_dps", s.vel_jump},
          {"inner_vel_jump_dps", s.inner_vel_jump},
          {"seam_acc_jump_dps2", s.acc_jump},
          {"inner_acc_jump_dps2", s.inner_acc_jump}};
}

}  // namespace rotinterp
