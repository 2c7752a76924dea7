// The summary of an eval run: per clip and per method × spacing, aggregated from errors.csv rows.
#include "rotinterp/eval/summary.h"

#include "rotinterp/clip/metrics.h"
#include "seam_summary.h"


#include <algorithm>
#include <cmath>
#include <map>

namespace rotinterp {

void FootSkating::add(const ErrorRow& r) {
  ++feet;
  intervals += r.frames > 0 ? static_cast<double>(r.frames - 1) : 0.0;
  contact += r.contact_frames;
  skating += r.skate_frames;
  speed_sum += r.skate_speed * r.contact_frames;
  contact_ref += r.contact_frames_ref;
  skating_ref += r.skate_frames_ref;
  speed_sum_ref += r.skate_speed_ref * r.contact_frames_ref;
}

void FootSkating::add(const FootSkating& o) {
  feet += o.feet;
  intervals += o.intervals;
  contact += o.contact, skating += o.skating, speed_sum += o.speed_sum;
  contact_ref += o.contact_ref, skating_ref += o.skating_ref, speed_sum_ref += o.speed_sum_ref;
}

std::optional<Metric> summary_metric(std::string_view name) {
  static const std::map<std::string_view, Metric> of = {
      {"mean_deg", Metric::angle},           {"rms_deg", Metric::angle},
      {"p95_deg", Metric::angle},            {"max_deg", Metric::angle},
      {"max_joint", Metric::angle},          {"worst", Metric::angle}, {"worst_clip", Metric::angle},
      {"clip_rms_median_deg", Metric::angle}, {"clip_p95_median_deg", Metric::angle},
      {"clip_max_median_deg", Metric::angle}, {"swing_rms_deg", Metric::swing_twist},
      {"twist_rms_deg", Metric::swing_twist}, {"pos_rms_pct", Metric::fk},
      {"pos_max_pct", Metric::fk},           {"shell_rms_pct", Metric::shell},
      {"shell_max_pct", Metric::shell},      {"acc_rms_dps2", Metric::smoothness},
      {"acc_rms_ref_dps2", Metric::smoothness}, {"vel_jump_max_dps", Metric::smoothness},
      {"acc_jump_max_dps2", Metric::smoothness}, {"foot_skating", Metric::foot_skating},
      {"feet", Metric::foot_skating},        {"seam", Metric::seam}};
  if (auto it = of.find(name); it != of.end()) return it->second;
  if (name.find("skate") != std::string_view::npos || name.find("contact_frames") != std::string_view::npos)
    return Metric::foot_skating;  // contact_frames, skate_ratio, … extra_skate_speed_mps
  return std::nullopt;
}

namespace {

// The ClipResults of one clip's rows, per method × keep_every in row order.
std::vector<ClipResult> clip_results_of(const std::vector<ErrorRow>& rows) {
  std::vector<ClipResult> out;
  struct Sums {
    double w = 0, w_mean = 0, w_sq = 0, pos_w = 0, w_pos = 0, w_shell = 0;
    std::vector<double> p95;
  };
  std::vector<Sums> sums;
  for (const ErrorRow& r : rows) {
    if (out.empty() || out.back().method != r.method || out.back().keep_every != r.keep_every) {
      ClipResult c;
      c.clip = r.clip;
      c.method = r.method;
      c.keep_every = r.keep_every;
      c.frames = r.frames;
      c.metres_per_unit = r.metres_per_unit;
      c.unit = r.unit;
      out.push_back(std::move(c));
      sums.emplace_back();
    }
    ClipResult& c = out.back();
    Sums& a = sums.back();
    const double w = static_cast<double>(r.samples), h = r.height > 0 ? r.height : 1.0;
    a.pos_w += w;
    a.w_pos += w * r.pos_rms_pct * r.pos_rms_pct;
    c.pos_max_pct = std::max(c.pos_max_pct, r.pos_max_pct);
    if (r.end_site) continue;
    ++c.joints;
    c.samples += r.samples;
    c.keys = std::max(c.keys, r.keys);
    c.motion_deg = std::max(c.motion_deg, r.motion_deg);
    a.w += w;
    a.w_mean += w * r.mean_deg;
    a.w_sq += w * r.rms_deg * r.rms_deg;
    const double shell_pct = 100.0 * r.shell_rms / h;
    a.w_shell += w * shell_pct * shell_pct;
    c.shell_max_pct = std::max(c.shell_max_pct, 100.0 * r.shell_max / h);
    a.p95.push_back(r.p95_deg);
    if (c.max_joint.empty() || r.max_deg > c.max_deg) c.max_deg = r.max_deg, c.max_joint = r.joint;
    if (r.foot) c.skating.add(r);
    if (r.seam) c.seam.add(r);
  }
  for (std::size_t i = 0; i < out.size(); ++i) {
    ClipResult& c = out[i];
    Sums& a = sums[i];
    if (a.w > 0) {
      c.mean_deg = a.w_mean / a.w;
      c.rms_deg = std::sqrt(a.w_sq / a.w);
      c.shell_rms_pct = std::sqrt(a.w_shell / a.w);
    }
    if (a.pos_w > 0) c.pos_rms_pct = std::sqrt(a.w_pos / a.pos_w);
    c.p95_deg = percentile(a.p95.data(), a.p95.size(), 0.95);
  }
  return out;
}

double median(std::vector<double> v) { return percentile(v.data(), v.size(), 0.5); }

}  // namespace

void SummaryBuilder::add_clip(const std::vector<ErrorRow>& rows) {
  if (rows.empty()) return;
  ++clips_;
  int largest_keep = 0;
  for (const ErrorRow& r : rows) largest_keep = std::max(largest_keep, r.keep_every);
  double score_sq = 0, score_w = 0;
  for (const ErrorRow& r : rows) {
    const auto key = std::make_pair(r.method, r.keep_every);
    auto it = acc_.find(key);
    if (it == acc_.end()) {
      order_.push_back(key);
      it = acc_.emplace(key, Acc{}).first;
      it->second.entry.method = r.method;
      it->second.entry.keep_every = r.keep_every;
    }
    Acc& a = it->second;
    if (a.last_clip != r.clip) {
      a.last_clip = r.clip;
      ++a.entry.clips;
    }
    const double w = static_cast<double>(r.samples);
    const double h = r.height > 0 ? r.height : 1.0;
    a.pos_samples += w;
    a.w_pos += w * r.pos_rms_pct * r.pos_rms_pct;
    a.entry.pos_max_pct = std::max(a.entry.pos_max_pct, r.pos_max_pct);
    if (r.end_site) continue;
    SummaryEntry& e = a.entry;
    ++e.joints;
    e.samples += r.samples;
    a.w_mean += w * r.mean_deg;
    a.w_sq += w * r.rms_deg * r.rms_deg;
    a.w_swing += w * r.swing_rms_deg * r.swing_rms_deg;
    a.w_twist += w * r.twist_rms_deg * r.twist_rms_deg;
    a.w_acc += w * r.acc_rms * r.acc_rms;
    a.w_acc_ref += w * r.acc_rms_ref * r.acc_rms_ref;
    const double shell_pct = 100.0 * r.shell_rms / h;
    a.w_shell += w * shell_pct * shell_pct;
    e.shell_max_pct = std::max(e.shell_max_pct, 100.0 * r.shell_max / h);
    a.p95.push_back(r.p95_deg);
    if (e.worst_clip.empty() || r.max_deg > e.max_deg) {
      e.max_deg = r.max_deg;
      e.worst_clip = r.clip;
      e.worst_joint = r.joint;
    }
    e.vel_jump_max = std::max(e.vel_jump_max, r.vel_jump_max);
    e.acc_jump_max = std::max(e.acc_jump_max, r.acc_jump_max);
    if (r.keep_every == largest_keep) {
      score_sq += w * r.rms_deg * r.rms_deg;
      score_w += w;
    }
  }
  for (ClipResult& c : clip_results_of(rows)) {
    Acc& a = acc_.at({c.method, c.keep_every});
    a.clip_rms.push_back(c.rms_deg);
    a.clip_p95.push_back(c.p95_deg);
    a.clip_max.push_back(c.max_deg);
    a.entry.skating.add(c.skating);
    a.entry.seam.add(c.seam);
    clip_results_.push_back(std::move(c));
  }
  const double score = score_w > 0 ? std::sqrt(score_sq / score_w) : 0.0;
  if (score > worst_score_) {
    worst_score_ = score;
    worst_keep_ = largest_keep;
    worst_rows_.clear();
    for (const ErrorRow& r : rows)
      if (r.keep_every == largest_keep && !r.end_site) worst_rows_.push_back(r);
  }
}

Summary SummaryBuilder::finish() const {
  Summary s;
  s.clips = clips_;
  s.clip_results = clip_results_;
  s.worst_keep_every = worst_keep_;
  s.worst_clip_rows = worst_rows_;
  if (!worst_rows_.empty()) s.worst_clip = worst_rows_.front().clip;
  for (const auto& key : order_) {
    const Acc& a = acc_.at(key);
    SummaryEntry e = a.entry;
    const double w = static_cast<double>(e.samples);
    if (w > 0) {
      e.mean_deg = a.w_mean / w;
      e.rms_deg = std::sqrt(a.w_sq / w);
      e.swing_rms_deg = std::sqrt(a.w_swing / w);
      e.twist_rms_deg = std::sqrt(a.w_twist / w);
      e.acc_rms = std::sqrt(a.w_acc / w);
      e.acc_rms_ref = std::sqrt(a.w_acc_ref / w);
      e.shell_rms_pct = std::sqrt(a.w_shell / w);
    }
    if (a.pos_samples > 0) e.pos_rms_pct = std::sqrt(a.w_pos / a.pos_samples);
    std::vector<double> p95 = a.p95;
    e.p95_deg = percentile(p95.data(), p95.size(), 0.95);
    e.clip_rms_median_deg = median(a.clip_rms);
    e.clip_p95_median_deg = median(a.clip_p95);
    e.clip_max_median_deg = median(a.clip_max);
    s.entries.push_back(std::move(e));
  }
  return s;
}

}  // namespace rotinterp
