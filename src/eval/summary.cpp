#include "rotinterp/eval/summary.h"

#include "rotinterp/clip/metrics.h"
#include "seam_summary.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>

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

namespace {

// `v` to 4 significant figures in fixed notation; "< 0.001" below, "0" for zero.
std::string sig4(double v) {
  if (v == 0.0 || !std::isfinite(v)) return "0";
  if (std::fabs(v) < 1e-3) return v < 0 ? "> -0.001" : "< 0.001";
  const int digits = static_cast<int>(std::floor(std::log10(std::fabs(v))));
  return fmt::format("{:.{}f}", v, std::max(0, 3 - digits));
}

}  // namespace

std::string format_summary_table(const Summary& s, TableFormat format) {
  const std::vector<std::string> head = {"method", "N", "clips", "mean°", "RMS°", "p95°", "max°",
                                         "median clip RMS°", "pos max %", "extra skate %"};
  std::vector<std::vector<std::string>> body;
  for (const SummaryEntry& e : s.entries)
    body.push_back({e.method, std::to_string(e.keep_every), std::to_string(e.clips), sig4(e.mean_deg),
                    sig4(e.rms_deg), sig4(e.p95_deg), sig4(e.max_deg), sig4(e.clip_rms_median_deg),
                    sig4(e.pos_max_pct),
                    e.skating.feet ? sig4(100.0 * (e.skating.ratio() - e.skating.ratio_ref())) : "–"});
  std::string out;
  if (format == TableFormat::markdown) {
    auto line = [](const std::vector<std::string>& cells) {
      std::string l = "|";
      for (const std::string& c : cells) l += " " + c + " |";
      return l + "\n";
    };
    out += line(head);
    out += "|---|" + std::string() ;
    for (std::size_t i = 1; i < head.size(); ++i) out += "---:|";
    out += "\n";
    for (const auto& b : body) out += line(b);
    return out;
  }
  if (format == TableFormat::latex) {
    auto tex = [](std::string c) {
      std::string o;
      for (char ch : c) {
        if (ch == '_' || ch == '%' || ch == '&' || ch == '#') o += '\\';
        o += ch;
      }
      std::string deg = "°";
      for (std::size_t p; (p = o.find(deg)) != std::string::npos;) o.replace(p, deg.size(), "$^\\circ$");
      std::string lt = "< ";
      for (std::size_t p; (p = o.find(lt)) != std::string::npos;) o.replace(p, lt.size(), "$<$\\,");
      std::string dash = "–";
      for (std::size_t p; (p = o.find(dash)) != std::string::npos;) o.replace(p, dash.size(), "--");
      return o;
    };
    out += "\\begin{tabular}{lrr" + std::string(head.size() - 3, 'r') + "}\n\\hline\n";
    auto line = [&](const std::vector<std::string>& cells) {
      std::string l;
      for (std::size_t i = 0; i < cells.size(); ++i) l += (i ? " & " : "") + tex(cells[i]);
      return l + " \\\\\n";
    };
    out += line(head) + "\\hline\n";
    for (const auto& b : body) out += line(b);
    out += "\\hline\n\\end{tabular}\n";
    return out;
  }
  out = fmt::format("{} clip{}; mean and RMS weight every joint sample alike (clips by their samples), median clip "
                    "RMS counts each clip once\n",
                    s.clips, s.clips == 1 ? "" : "s");
  std::vector<std::size_t> width(head.size(), 0);
  auto display = [](const std::string& t) {  // UTF-8 code points
    std::size_t n = 0;
    for (char c : t) n += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
    return n;
  };
  for (std::size_t i = 0; i < head.size(); ++i) width[i] = display(head[i]);
  for (const auto& b : body)
    for (std::size_t i = 0; i < b.size(); ++i) width[i] = std::max(width[i], display(b[i]));
  auto line = [&](const std::vector<std::string>& cells) {
    std::string l;
    for (std::size_t i = 0; i < cells.size(); ++i) {
      const std::string pad(width[i] - display(cells[i]), ' ');
      l += (i ? "  " : "") + (i == 0 ? cells[i] + pad : pad + cells[i]);
    }
    return l + "\n";
  };
  out += line(head);
  std::string last;
  for (std::size_t k = 0; k < body.size(); ++k) {
    if (!last.empty() && s.entries[k].method != last) out += '\n';
    last = s.entries[k].method;
    out += line(body[k]);
  }
  if (!s.worst_clip.empty()) out += fmt::format("worst clip (RMS at keep {}): {}\n", s.worst_keep_every, s.worst_clip);
  return out;
}

std::string clips_csv(const Summary& s) {
  static const CsvSchema plain = {
      "clip", "method", "keep_every", "frames", "joints", "keys", "motion_deg", "samples", "mean_deg", "rms_deg",
      "p95_deg", "max_deg", "max_joint", "pos_rms_pct", "pos_max_pct", "shell_rms_pct", "shell_max_pct", "feet",
      "contact_frames", "skate_ratio", "skate_speed_mps", "contact_frames_ref", "skate_ratio_ref",
      "skate_speed_ref_mps", "extra_skate_ratio", "extra_skate_speed_mps"};
  static const CsvSchema with_seam = plain + seam_csv_schema();
  const CsvSchema& schema = s.seam ? with_seam : plain;
  const auto n = [](auto v) { return fmt::format("{}", v); };
  std::string out = schema.header();
  for (const ClipResult& c : s.clip_results) {
    CsvRow row(schema);
    row << c.clip << c.method << n(c.keep_every) << n(c.frames) << n(c.joints) << n(c.keys) << n(c.motion_deg)
        << n(c.samples) << n(c.mean_deg) << n(c.rms_deg) << n(c.p95_deg) << n(c.max_deg) << c.max_joint
        << n(c.pos_rms_pct) << n(c.pos_max_pct) << n(c.shell_rms_pct) << n(c.shell_max_pct) << n(c.skating.feet);
    const FootSkating& f = c.skating;
    if (f.feet)
      row << n(f.contact) << n(f.ratio()) << n(f.speed()) << n(f.contact_ref) << n(f.ratio_ref())
          << n(f.speed_ref()) << n(f.ratio() - f.ratio_ref()) << n(f.speed() - f.speed_ref());
    else
      row.skip(8);
    if (s.seam) add_seam_fields(row, c.seam);
    out += row.line();
  }
  return out;
}

namespace {

using nlohmann::json;

json skating_json(const FootSkating& f) {
  if (!f.feet) return nullptr;
  return {{"feet", f.feet},
          {"contact_frames", f.contact},
          {"skate_ratio", f.ratio()},
          {"skate_speed_mps", f.speed()},
          {"contact_frames_ref", f.contact_ref},
          {"skate_ratio_ref", f.ratio_ref()},
          {"skate_speed_ref_mps", f.speed_ref()},
          {"extra_skate_ratio", f.ratio() - f.ratio_ref()},
          {"extra_skate_speed_mps", f.speed() - f.speed_ref()}};
}

json entry_json(const SummaryEntry& e, bool seam) {
  json j = {{"method", e.method},
          {"keep_every", e.keep_every},
          {"clips", e.clips},
          {"joints", e.joints},
          {"samples", e.samples},
          {"mean_deg", e.mean_deg},
          {"rms_deg", e.rms_deg},
          {"p95_deg", e.p95_deg},
          {"max_deg", e.max_deg},
          {"clip_rms_median_deg", e.clip_rms_median_deg},
          {"clip_p95_median_deg", e.clip_p95_median_deg},
          {"clip_max_median_deg", e.clip_max_median_deg},
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
          {"foot_skating", skating_json(e.skating)},
          {"worst", {{"clip", e.worst_clip}, {"joint", e.worst_joint}}}};
  if (seam) j["seam"] = seam_json(e.seam);
  return j;
}

// The "clips" section: one object per clip, its results per method × keep_every.
json clips_json(const Summary& s) {
  json clips = json::array();
  for (const ClipResult& c : s.clip_results) {
    if (clips.empty() || clips.back()["clip"] != c.clip)
      clips.push_back({{"clip", c.clip},
                       {"frames", c.frames},
                       {"joints", c.joints},
                       {"metres_per_unit", c.metres_per_unit},
                       {"unit", c.unit},
                       {"keys", c.keys},
                       {"motion_deg", c.motion_deg},
                       {"results", json::array()}});
    clips.back()["results"].push_back({{"method", c.method},
                                       {"keep_every", c.keep_every},
                                       {"mean_deg", c.mean_deg},
                                       {"rms_deg", c.rms_deg},
                                       {"p95_deg", c.p95_deg},
                                       {"max_deg", c.max_deg},
                                       {"max_joint", c.max_joint},
                                       {"pos_rms_pct", c.pos_rms_pct},
                                       {"pos_max_pct", c.pos_max_pct},
                                       {"shell_rms_pct", c.shell_rms_pct},
                                       {"shell_max_pct", c.shell_max_pct},
                                       {"foot_skating", skating_json(c.skating)}});
    if (s.seam) clips.back()["results"].back()["seam"] = seam_json(c.seam);
  }
  return clips;
}

}  // namespace
std::string summary_json(const RunRecord& r, const Summary& summary) {
  json failed = json::array();
  for (const EvalFailure& f : r.failed) failed.push_back({{"file", f.file}, {"error", f.message}});
  json too_short = json::array();
  for (const ShortClip& c : r.too_short)
    too_short.push_back({{"clip", c.clip}, {"frames", c.frames}, {"keep_every_skipped", c.keep_every}});
  json j = {{"tool", "rotinterp eval"},
            {"version", r.version},
            {"inputs", r.inputs},
            {"files", r.files},
            {"options",
             {{"methods", r.options.methods},
              {"keep_every", r.options.keep_every},
              {"subframe", r.options.subframe},
              {"shell_distance_m", r.options.shell_distance_m},
              {"truth", r.options.truth},
              {"anim", r.options.animation},
              {"min_frames", r.options.min_frames},
              {"feet", r.options.feet},
              {"contact_height_m", r.options.contact_height_m},
              {"contact_speed_mps", r.options.contact_speed_mps},
              {"floor_m", r.options.floor_m ? json(*r.options.floor_m) : json(nullptr)},
              {"unit_metres_per_unit", r.options.unit ? json(*r.options.unit) : json(nullptr)},
              {"loop", r.options.loop}}},
            {"started", r.started},
            {"seconds", r.seconds},
            {"failed", failed},
            {"skipped", r.skipped},
            {"too_short", too_short}};
  if (r.merged_from.empty()) {
    j["shard"] = {{"index", r.shard_index}, {"count", r.shard_count}};
    j["jobs"] = r.jobs;
  } else {
    j["merged_from"] = r.merged_from;
    j["merge_seconds"] = r.merge_seconds;
  }
  json results = json::array();
  for (const SummaryEntry& e : summary.entries) results.push_back(entry_json(e, summary.seam));
  j["clips_evaluated"] = summary.clips;
  j["results"] = std::move(results);
  j["worst_clip"] = {{"clip", summary.worst_clip}, {"keep_every", summary.worst_keep_every}};
  j["weighting"] =
      "mean_deg, rms_deg, swing/twist, pos/shell RMS and smoothness weight every joint sample alike, so a clip "
      "counts by its samples x joints; p95_deg is the 95th percentile of the per-joint p95; clip_*_median_deg "
      "count each clip once (the median of the per-clip values in \"clips\"); foot_skating sums frame "
      "intervals over all feet of all clips";
  j["clips"] = clips_json(summary);
  j["units"] = {{"angles", "degrees"},
                {"distances", "metres, through each clip's unit (clips[].unit)"},
                {"pct", "percent of each clip's skeleton height"},
                {"acc", "deg/s^2"},
                {"vel", "deg/s"},
                {"skate_ratio", "share of foot frame intervals in contact and sliding faster than contact_speed_mps"},
                {"skate_speed", "m/s, mean horizontal foot speed over the contact intervals"}};
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
    r.options.animation = o.value("anim", "");
    r.options.loop = o.value("loop", "off");
    r.options.min_frames = o.value("min_frames", std::size_t{0});
    r.options.feet = o.value("feet", std::vector<std::string>{});
    r.options.contact_height_m = o.value("contact_height_m", 0.0);
    r.options.contact_speed_mps = o.value("contact_speed_mps", 0.0);
    if (o.contains("floor_m") && !o["floor_m"].is_null()) r.options.floor_m = o["floor_m"].get<double>();
    if (o.contains("unit_metres_per_unit") && !o["unit_metres_per_unit"].is_null())
      r.options.unit = o["unit_metres_per_unit"].get<double>();
    for (const auto& c : j.value("too_short", json::array()))
      r.too_short.push_back({c.at("clip").get<std::string>(), c.at("frames").get<std::size_t>(),
                             c.at("keep_every_skipped").get<std::vector<int>>()});
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
