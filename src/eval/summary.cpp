#include "rotinterp/eval/summary.h"

#include "rotinterp/clip/metrics.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>

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

namespace {

using nlohmann::json;

json entry_json(const SummaryEntry& e) {
  return {{"method", e.method},
          {"keep_every", e.keep_every},
          {"clips", e.clips},
          {"joints", e.joints},
          {"samples", e.samples},
          {"mean_deg", e.mean_deg},
          {"rms_deg", e.rms_deg},
          {"p95_deg", e.p95_deg},
          {"max_deg", e.max_deg},
          {"swing_rms_deg", e.swing_rms_deg},
          {"twist_rms_deg", e.twist_rms_deg},
          {"pos_rms_pct", e.pos_rms_pct},
          {"pos_max_pct", e.pos_max_pct},
          {"shell_rms_pct", e.shell_rms_pct},
          {"shell_max_pct", e.shell_max_pct},
          {"acc_rms_dps2", e.acc_rms},
          {"acc_rms_ref_dps2", e.acc_rms_ref},
          {"vel_jump_max_dps", e.vel_jump_max},
          {"acc_jump_max_dps2", e.acc_jump_max},
          {"worst", {{"clip", e.worst_clip}, {"joint", e.worst_joint}}}};
}

}  // namespace

std::string summary_json(const RunRecord& r, const Summary& summary) {
  json failed = json::array();
  for (const EvalFailure& f : r.failed) failed.push_back({{"file", f.file}, {"error", f.message}});
  json j = {{"tool", "rotinterp eval"},
            {"version", r.version},
            {"inputs", r.inputs},
            {"files", r.files},
            {"options",
             {{"methods", r.options.methods},
              {"keep_every", r.options.keep_every},
              {"subframe", r.options.subframe},
              {"shell_distance_m", r.options.shell_distance_m},
              {"truth", r.options.truth}}},
            {"started", r.started},
            {"seconds", r.seconds},
            {"failed", failed},
            {"skipped", r.skipped}};
  if (r.merged_from.empty()) {
    j["shard"] = {{"index", r.shard_index}, {"count", r.shard_count}};
    j["jobs"] = r.jobs;
  } else {
    j["merged_from"] = r.merged_from;
    j["merge_seconds"] = r.merge_seconds;
  }
  json results = json::array();
  for (const SummaryEntry& e : summary.entries) results.push_back(entry_json(e));
  j["clips_evaluated"] = summary.clips;
  j["results"] = std::move(results);
  j["worst_clip"] = {{"clip", summary.worst_clip}, {"keep_every", summary.worst_keep_every}};
  j["units"] = {{"angles", "degrees"},
                {"pct", "percent of each clip's skeleton height"},
                {"acc", "deg/s^2"},
                {"vel", "deg/s"}};
  return j.dump(2) + "\n";
}

Result<RunRecord> read_summary_json(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) return make_error(file.string() + ": cannot read");
  json j;
  try {
    j = json::parse(in);
  } catch (const std::exception& e) {
    return make_error(file.string() + ": not JSON (" + std::string(e.what()) + ")");
  }
  if (!j.is_object() || !j.contains("options") || !j.contains("failed") || !j.contains("files"))
    return make_error(file.string() + ": not a rotinterp eval summary");
  RunRecord r;
  try {
    const json& o = j["options"];
    r.options.methods = o.at("methods").get<std::vector<std::string>>();
    r.options.keep_every = o.at("keep_every").get<std::vector<int>>();
    r.options.subframe = o.at("subframe").get<int>();
    r.options.shell_distance_m = o.at("shell_distance_m").get<double>();
    r.options.truth = o.at("truth").get<bool>();
    r.inputs = j.value("inputs", std::vector<std::string>{});
    r.skipped = j.value("skipped", std::vector<std::string>{});
    for (const auto& f : j["failed"]) r.failed.push_back({f.at("file").get<std::string>(), f.at("error").get<std::string>()});
    r.files = j["files"].get<std::size_t>();
    r.seconds = j.value("seconds", 0.0);
    r.version = j.value("version", "");
    r.started = j.value("started", "");
  } catch (const std::exception& e) {
    return make_error(file.string() + ": malformed summary (" + std::string(e.what()) + ")");
  }
  return r;
}

}  // namespace rotinterp
