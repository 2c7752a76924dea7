#include "rotinterp/eval/summary.h"

#include "rotinterp/clip/metrics.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace rotinterp {

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
    s.entries.push_back(std::move(e));
  }
  return s;
}

std::string format_summary_table(const Summary& s) {
  std::string out = fmt::format("{} clip{}\n", s.clips, s.clips == 1 ? "" : "s");
  out += fmt::format("{:<10} {:>5} {:>10} {:>10} {:>10} {:>10} {:>10} {:>10} {:>12}\n", "method", "keep", "rms°",
                     "p95°", "max°", "swing°", "twist°", "pos max%", "acc rms°/s²");
  std::string last;
  for (const SummaryEntry& e : s.entries) {
    if (!last.empty() && e.method != last) out += '\n';
    last = e.method;
    out += fmt::format("{:<10} {:>5} {:>10.4g} {:>10.4g} {:>10.4g} {:>10.4g} {:>10.4g} {:>10.4g} {:>12.4g}\n", e.method,
                       e.keep_every, e.rms_deg, e.p95_deg, e.max_deg, e.swing_rms_deg, e.twist_rms_deg,
                       e.pos_max_pct, e.acc_rms);
  }
  if (!s.worst_clip.empty()) out += fmt::format("worst clip (RMS at keep {}): {}\n", s.worst_keep_every, s.worst_clip);
  return out;
}

}  // namespace rotinterp
