// summary.json: the run record and the results written, and the record read back (shard merges).
#include "rotinterp/eval/summary.h"
#include "seam_summary.h"
#include "rotinterp/io/files/json_text.h"

#include <nlohmann/json.hpp>

#include <fstream>
#include <iterator>

namespace rotinterp {

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

// Leaves out the values of metrics not chosen (summary_metric).
json chosen_only(json j, MetricSet metrics) {
  if (metrics.is_all()) return j;
  for (auto it = j.begin(); it != j.end();) {
    const std::optional<Metric> m = summary_metric(it.key());
    it = m && !metrics.has(*m) ? j.erase(it) : std::next(it);
  }
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
    clips.back()["results"].back() = chosen_only(clips.back()["results"].back(), s.metrics);
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
  // The metrics a run chose, when not all (so the file of a default run is as before --metrics).
  if (r.options.metrics != "all") j["options"]["metrics"] = r.options.metrics;
  if (r.merged_from.empty()) {
    j["shard"] = {{"index", r.shard_index}, {"count", r.shard_count}};
    j["jobs"] = r.jobs;
  } else {
    j["merged_from"] = r.merged_from;
    j["merge_seconds"] = r.merge_seconds;
  }
  json results = json::array();
  for (const SummaryEntry& e : summary.entries) results.push_back(chosen_only(entry_json(e, summary.seam), summary.metrics));
  j["clips_evaluated"] = summary.clips;
  j["results"] = std::move(results);
  if (summary.metrics.has(*summary_metric("worst_clip")))
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
  return json_text(j, 2) + "\n";
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
    const json& truth = o.at("truth");  // a bool before the truth had a name: true was synth
    r.options.truth = truth.is_boolean() ? (truth.get<bool>() ? "synth" : "frames") : truth.get<std::string>();
    r.options.animation = o.value("anim", "");
    r.options.loop = o.value("loop", "off");
    r.options.metrics = o.value("metrics", "all");
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
