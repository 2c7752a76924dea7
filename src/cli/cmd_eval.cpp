// rotinterp eval PATH... | eval --merge DIR... -o DIR: batch angular-error evaluation.
#include "allocator.h"
#include "common.h"
#include "folder_plan.h"
#include "options.h"
#include "progress_line.h"
#include "rotinterp/clip/units.h"
#include "rotinterp/eval/batch.h"
#include "rotinterp/eval/metric_set.h"
#include "rotinterp/batch/dataset.h"
#include "rotinterp/eval/plots.h"
#include "rotinterp/eval/source_truth.h"
#include "rotinterp/eval/synth_truth.h"
#include "rotinterp/interp/interpolator.h"
#include "rotinterp/io/files/atomic_file.h"
#include "rotinterp/io/files/file_errors.h"

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <new>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace rotinterp::cli {

namespace {

struct EvalArgs {
  std::vector<std::string> paths;
  std::string methods = "all";
  std::string keep_every = "2,4,8,16";
  int jobs = 0;
  std::string output = "eval-out";
  std::string shard;
  std::vector<std::string> merge;
  int subframe = 0;
  // Lengths as the user writes them, their defaults the library's (metres → cm text).
  std::string shell_distance = fmt::format("{}cm", kDefaultShellDistanceMetres * 100);
  bool no_plots = false;
  std::string truth;  // --truth [synth|source] as written; empty: not given
  bool quiet = false;
  std::string anim;
  long long min_frames = 0;
  std::string feet;
  std::string contact_height = fmt::format("{}cm", kDefaultContactHeightMetres * 100);
  std::string contact_speed = fmt::format("{}m/s", kDefaultContactSpeedMps);
  std::string floor, unit;
  bool allow_external_files = false;
  std::string per_frame;
  std::string table = "text";
  std::string loop = "off";  // --loop as written
  std::string metrics = "all";
};

// --per-frame CLIP,METHOD,N (the clip id may itself hold commas: the last two fields are split off).
Result<PerFrameRequest> parse_per_frame(const std::string& text) {
  const std::size_t b = text.rfind(','), a = b == std::string::npos || b == 0 ? std::string::npos : text.rfind(',', b - 1);
  if (a == std::string::npos || a == 0) return make_error("--per-frame: expected CLIP,METHOD,N, got '" + text + "'");
  PerFrameRequest q;
  q.clip = text.substr(0, a);
  q.method = text.substr(a + 1, b - a - 1);
  const MethodInfo* m = find_method(q.method);
  if (!m) return make_error("--per-frame: " + unknown_method_message(q.method));
  q.method = m->name;
  auto n = parse_whole_option("--per-frame", text.substr(b + 1), 1, kMaxKeepEvery);
  if (!n) return n.failure();
  q.keep_every = static_cast<int>(*n);
  return q;
}

int run(const EvalArgs& a) {
  const bool quiet = a.quiet;
  // A file without animation is said at the end: alone, it is the one line of a run
  // that had nothing to evaluate (a static mesh), not an empty table.
  auto print_failure = [quiet](const EvalFailure& f) {
    if (f.kind != file_error::no_animation) print_file_failure(f, quiet);
  };
  Result<EvalReport> report = make_error("");
  // No output file may be one of the inputs (a shard merged into itself, -o where a
  // clip of the same name is read).
  for (const std::string& p : a.paths) protect_input(p);
  for (const std::string& d : a.merge)
    for (const char* name : {kErrorsCsvName, kSummaryJsonName}) protect_input(std::filesystem::path(d) / name);
  std::vector<std::string> outputs = plot_file_names();
  for (const char* name : {kErrorsCsvName, kSummaryJsonName, kClipsCsvName, kPerFrameCsvName}) outputs.push_back(name);
  for (const std::string& name : outputs)
    if (Status s = check_not_an_input(std::filesystem::path(a.output) / name); !s) return fail(s.error());
  TableFormat table = TableFormat::text;
  if (a.table == "md") table = TableFormat::markdown;
  else if (a.table == "latex") table = TableFormat::latex;
  else if (a.table != "text") return fail_usage("--table: expected md, latex or text, got '" + a.table + "'");
  if (!a.merge.empty()) {
    if (!a.paths.empty()) return fail_usage("eval --merge takes directories after --merge, not input paths");
    std::vector<std::filesystem::path> dirs(a.merge.begin(), a.merge.end());
    report = merge_eval(dirs, a.output, !a.no_plots);
    if (report)
      for (const EvalFailure& f : report->failures) print_failure(f);
  } else {
    if (a.paths.empty()) return fail_usage("eval needs at least one input file or directory");
    EvalOptions o;
    o.inputs.assign(a.paths.begin(), a.paths.end());
    o.output_dir = a.output;
    auto names = parse_methods(a.methods, true);
    if (!names) return fail_usage(names.error());
    o.clip.methods = *names;
    for (const std::string& k : split_comma_list(a.keep_every)) {
      auto n = parse_whole_option("--keep-every", k, 1, kMaxKeepEvery);
      if (!n) return fail_usage(n.error());
      o.clip.keep_every.push_back(static_cast<int>(*n));
    }
    std::sort(o.clip.keep_every.begin(), o.clip.keep_every.end());
    o.clip.keep_every.erase(std::unique(o.clip.keep_every.begin(), o.clip.keep_every.end()), o.clip.keep_every.end());
    if (o.clip.keep_every.empty()) return fail_usage("--keep-every needs at least one value");
    auto metrics = parse_metrics(a.metrics);
    if (!metrics) return fail_usage("--metrics: " + metrics.error());
    o.clip.metrics = *metrics;
    o.clip.subframe = a.subframe;
    auto shell = parse_length(a.shell_distance);
    if (!shell) return fail_usage("--shell-distance: " + shell.error());
    o.clip.shell_distance_m = *shell;
    o.jobs = a.jobs;
    if (!a.shard.empty()) {
      auto s = parse_shard(a.shard);
      if (!s) return fail_usage(s.error());
      o.shard_index = s->first;
      o.shard_count = s->second;
    }
    o.plots = !a.no_plots;
    o.animation = a.anim;
    o.clip.min_frames = static_cast<std::size_t>(a.min_frames);
    o.clip.feet.feet = split_comma_list(a.feet);
    auto contact_height = parse_length(a.contact_height);
    if (!contact_height) return fail_usage("--contact-height: " + contact_height.error());
    auto contact_speed = parse_speed(a.contact_speed);
    if (!contact_speed) return fail_usage("--contact-speed: " + contact_speed.error());
    o.clip.feet.contact_height_m = *contact_height;
    o.clip.feet.contact_speed_mps = *contact_speed;
    if (!a.floor.empty()) {
      auto floor = parse_signed_length(a.floor);
      if (!floor) return fail_usage("--floor: " + floor.error());
      o.clip.feet.floor_m = *floor;
    }
    auto unit = parse_unit_option(a.unit);
    if (!unit) return fail_usage(unit.error());
    o.unit = *unit;
    if (!a.per_frame.empty()) {
      auto q = parse_per_frame(a.per_frame);
      if (!q) return fail_usage(q.error());
      o.per_frame = *q;
    }
    auto loop = parse_loop_option(a.loop);
    if (!loop) return fail_usage(loop.error());
    if (*loop) {
      o.clip.loop = true;
      o.clip.loop_form = (*loop)->form;
    }
    if (a.truth == "synth") o.truth = {"synth", synth_truth};
    o.allow_external_files = a.allow_external_files;
    if (a.truth == "source")
      o.truth = {"source", [allow = a.allow_external_files](const std::string& file, const Clip& clip) {
                   return source_truth(file, clip, allow);
                 }};
    keep_freed_memory_for_reuse();
    o.progress = make_progress("eval", quiet, "clips");
    o.on_failure = print_failure;
    report = run_eval(o);
    end_progress(quiet);
  }
  if (!report) return fail(report.error());
  const auto static_files = std::count_if(report->failures.begin(), report->failures.end(),
                                          [](const EvalFailure& f) { return f.kind == file_error::no_animation; });
  if (report->clips_evaluated == 0 && static_files > 0 && static_cast<std::size_t>(static_files) == report->failures.size()) {
    std::string files;
    for (const EvalFailure& f : report->failures) files += (files.empty() ? "" : ", ") + f.file;
    return fail(fmt::format("nothing to evaluate: {} {} no animation (a static mesh or scene); eval needs animated clips",
                            files, static_files == 1 ? "holds" : "hold"));
  }
  for (const EvalFailure& f : report->failures)
    if (f.kind == file_error::no_animation) std::fprintf(stderr, "rotinterp: %s\n", f.message.c_str());
  for (const ShortClip& c : report->too_short) {
    if (quiet) break;
    std::string ns;
    for (int n : c.keep_every) ns += (ns.empty() ? "" : ",") + std::to_string(n);
    std::fprintf(stderr, "rotinterp: note: %s: %zu frames, too few for keep-every %s (needs 2N+1%s); skipped there\n",
                 c.clip.c_str(), c.frames, ns.c_str(), a.min_frames > 0 ? " and --min-frames" : "");
  }
  if (!quiet) {
    if (!report->skipped.empty())
      std::fprintf(stderr, "rotinterp: note: %zu file(s) found in directories hold no animation and were skipped "
                   "(listed in %s/%s)\n", report->skipped.size(), a.output.c_str(), kSummaryJsonName);
    fmt::print("{}", format_summary_table(report->summary, table));
    if (!a.truth.empty())
      fmt::print("truth: {}\n", a.truth == "source" ? "each file's own motion: FBX rotation curves, glTF animation samplers, BVH frames (--truth source)"
                                                    : "each synth clip's analytic motion (--truth)");
    if (table == TableFormat::text)
      fmt::print("wrote {}/{}, {}/{}, {}/{}{}\n", a.output, kErrorsCsvName, a.output, kClipsCsvName, a.output,
                 kSummaryJsonName,
                 a.no_plots || report->summary.clips == 0 || !report->summary.metrics.has(Metric::angle)
                     ? ""
                     : ", and plots (PNG, SVG)");
  }
  if (!report->failures.empty()) {
    std::vector<std::string> bad;
    for (const EvalFailure& f : report->failures)
      if (std::find(bad.begin(), bad.end(), f.file) == bad.end()) bad.push_back(f.file);
    std::fprintf(stderr, "rotinterp: %zu of %zu files had failures (listed above and in %s/%s)\n", bad.size(),
                 report->files, a.output.c_str(), kSummaryJsonName);
    return kExitPartial;
  }
  return kExitOk;
}

}  // namespace

void add_eval_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<EvalArgs>();
  auto* sub = app.add_subcommand(
      "eval", "Decimate clips, rebuild them with each method and measure the error: DIR/errors.csv, clips.csv, summary.json, "
      "plots");
  sub->add_option("paths", args->paths, "Clip files or directories (searched recursively for every format assimp reads)");
  add_method_option(*sub, args->methods, true, "all");
  add_keep_every_option(*sub, args->keep_every, true, "each measured on its own")->capture_default_str();
  add_jobs_option(*sub, args->jobs, "Worker threads over (clip, method) pairs");
  add_output_option(*sub, args->output, "Output directory")->capture_default_str();
  sub->add_option("--shard", args->shard,
                  "Evaluate shard I of N (I/N) of the sorted inputs, for a cluster (default: all)");
  sub->add_option("--merge", args->merge, "Combine the output directories of shard runs into -o DIR (default: off)");
  sub->add_option("--metrics", args->metrics,
                  "Comma list of the metrics to compute and report: " + metric_names() +
                      " (seam with --loop); the others are neither computed nor written, and the plots need angle")
      ->capture_default_str();
  sub->add_option("--subframe", args->subframe,
                  "Also measure K evenly spaced times between frames, against the original's slerp")
      ->capture_default_str()->check(CLI::Range(0, 1000));
  sub->add_option("--shell-distance", args->shell_distance,
                  "Virtual-vertex distance: a length (3cm); a bare number is metres (converted by each clip's unit)")
      ->capture_default_str();
  auto* truth = sub->add_option("--truth", args->truth,
                                "Compare at every frame and subframe with: synth (bare --truth), the analytic motion "
                                "of synth clips (CLIP.synth, from rotinterp synth); or source, the file's own "
                                "motion as resample --method source replays it (an FBX file's rotation curves, a "
                                "glTF file's animation samplers, a BVH's frames). A clip without one fails (default: off, compare with the source frames)")
                    ->expected(0, 1);
  add_anim_option(*sub, args->anim, "a clip per take, named FILE#TAKE");
  sub->add_option("--min-frames", args->min_frames,
                  "Skip clips with fewer frames (listed); spacings N need at least 2N+1 frames in any case")
      ->capture_default_str()->check(CLI::Range(0LL, 1000000000LL));
  sub->add_option("--feet", args->feet,
                  "Comma-separated foot joints for foot skating (default: found by name, CMU/Mixamo/Bandai/Blender rigs)");
  sub->add_option("--floor", args->floor,
                  "Floor height (Y up): a length (-2cm); a bare number is metres (default: the lowest foot height)");
  sub->add_option("--contact-height", args->contact_height,
                  "Foot contact: height above the floor below which a foot may touch it: a length; a bare number is "
                  "metres")
      ->capture_default_str();
  sub->add_option("--contact-speed", args->contact_speed,
                  "Foot skating: horizontal speed of a foot in contact above which it slides: m/s, cm/s or mm/s; a "
                  "bare number is m/s")
      ->capture_default_str();
  add_unit_option(*sub, args->unit);
  add_external_files_option(*sub, args->allow_external_files);
  sub->add_option("--per-frame", args->per_frame,
                  "Also write DIR/per_frame.csv: the angle error of every joint at every sample, for CLIP,METHOD,N "
                  "(CLIP as in errors.csv); default none");
  sub->add_option("--table", args->table, "The results table on stdout: text, md (Markdown) or latex")
      ->capture_default_str();
  add_loop_option(*sub, args->loop,
                  "Each clip is one period: its keys wrap around (every Nth frame inside the period, then frame 0 one "
                  "period later), each method is rebuilt on its periodic curve, and errors.csv, clips.csv and "
                  "summary.json add the seam's angle error, velocity and acceleration jump next to the same inside "
                  "(absent without --loop); a clip that is not a cycle fails.");
  sub->add_flag("--no-plots", args->no_plots, "Skip the plots (default: PNG and SVG plots in -o DIR)");
  add_quiet_option(*sub, args->quiet);
  sub->callback([args, truth, &exit_code] {
    // A bare --truth is synth; a value that is neither name is an input path it took.
    if (truth->count() > 0 && args->truth != "source") {
      if (!args->truth.empty() && args->truth != "synth") args->paths.insert(args->paths.begin(), args->truth);
      args->truth = "synth";
    }
    exit_code = run(*args);
  });
}

}  // namespace rotinterp::cli
