// rotinterp eval PATH... | eval --merge DIR... -o DIR: batch angular-error evaluation.
#include "common.h"
#include "rotinterp/eval/batch.h"
#include "rotinterp/eval/inputs.h"
#include "rotinterp/eval/plots.h"
#include "rotinterp/eval/synth_truth.h"
#include "rotinterp/interp/interpolator.h"
#include "rotinterp/io/atomic_file.h"

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
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
  double shell_m = kDefaultShellDistanceMetres;
  bool no_plots = false;
  bool truth = false;
  bool quiet = false;
};

int run(const EvalArgs& a) {
  const bool quiet = a.quiet;
  auto print_failure = [](const EvalFailure& f) { std::fprintf(stderr, "rotinterp: %s\n", f.message.c_str()); };
  Result<EvalReport> report = make_error("");
  // No output file may be one of the inputs (a shard merged into itself, -o where a
  // clip of the same name is read).
  for (const std::string& p : a.paths) protect_input(p);
  for (const std::string& d : a.merge)
    for (const char* name : {kErrorsCsvName, kSummaryJsonName}) protect_input(std::filesystem::path(d) / name);
  for (const char* name : {kErrorsCsvName, kSummaryJsonName, kSpacingPlotName, kWorstClipPlotName})
    if (Status s = check_not_an_input(std::filesystem::path(a.output) / name); !s) return fail(s.error());
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
    if (a.methods == "all") {
      for (const MethodInfo& m : methods()) o.clip.methods.push_back(m.name);
    } else {
      for (const std::string& m : split_comma_list(a.methods)) {
        if (!find_method(m)) return fail_usage("--methods: unknown method '" + m + "' (valid: " + method_names() + ")");
        if (std::find(o.clip.methods.begin(), o.clip.methods.end(), m) == o.clip.methods.end())
          o.clip.methods.push_back(m);
      }
    }
    if (o.clip.methods.empty()) return fail("no methods to evaluate");
    for (const std::string& k : split_comma_list(a.keep_every)) {
      auto n = parse_whole_option("--keep-every", k, 1, kMaxKeepEvery);
      if (!n) return fail_usage(n.error());
      o.clip.keep_every.push_back(static_cast<int>(*n));
    }
    std::sort(o.clip.keep_every.begin(), o.clip.keep_every.end());
    o.clip.keep_every.erase(std::unique(o.clip.keep_every.begin(), o.clip.keep_every.end()), o.clip.keep_every.end());
    if (o.clip.keep_every.empty()) return fail_usage("--keep-every needs at least one value");
    o.clip.subframe = a.subframe;
    o.clip.shell_distance_m = a.shell_m;
    o.jobs = a.jobs;
    if (!a.shard.empty()) {
      auto s = parse_shard(a.shard);
      if (!s) return fail_usage(s.error());
      o.shard_index = s->first;
      o.shard_count = s->second;
    }
    o.plots = !a.no_plots;
    if (a.truth) o.truth_for = synth_truth;
    o.progress = make_progress("eval", quiet);
    o.on_failure = print_failure;
    report = run_eval(o);
    end_progress(quiet);
  }
  if (!report) return fail(report.error());
  if (!quiet) {
    if (!report->skipped.empty())
      std::fprintf(stderr, "rotinterp: note: %zu file(s) found in directories hold no animation and were skipped "
                   "(listed in %s/%s)\n", report->skipped.size(), a.output.c_str(), kSummaryJsonName);
    fmt::print("{}", format_summary_table(report->summary));
    fmt::print("wrote {}/{}, {}/{}{}\n", a.output, kErrorsCsvName, a.output, kSummaryJsonName,
               a.no_plots || report->summary.clips == 0 ? "" : ", and PNG plots");
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
      "eval", "Decimate clips, rebuild them with each method and measure the error: DIR/errors.csv, summary.json, plots");
  sub->add_option("paths", args->paths, "Clip files or directories (searched recursively for every format assimp reads)");
  sub->add_option("--methods", args->methods, "Comma-separated methods, or 'all'")->capture_default_str();
  sub->add_option("--keep-every", args->keep_every, "Comma-separated key spacings N: keys at every Nth frame and the last")
      ->capture_default_str();
  sub->add_option("-j,--jobs", args->jobs, "Worker threads over (clip, method) pairs (0 = all cores)")->capture_default_str()
      ->check(CLI::Range(0, 4096));
  sub->add_option("-o,--output", args->output, "Output directory")->capture_default_str();
  sub->add_option("--shard", args->shard, "Evaluate shard I of N (I/N) of the sorted inputs, for a cluster");
  sub->add_option("--merge", args->merge, "Combine the output directories of shard runs into -o DIR");
  sub->add_option("--subframe", args->subframe,
                  "Also measure K evenly spaced times between frames, against the original's slerp")
      ->capture_default_str()->check(CLI::Range(0, 1000));
  sub->add_option("--shell-distance", args->shell_m,
                  "Virtual-vertex distance in metres (converted by each clip's unit scale)")
      ->capture_default_str()->check(CLI::PositiveNumber);
  sub->add_flag("--truth", args->truth,
                "Compare with the analytic motion of synth clips (CLIP.synth, from rotinterp synth) at every "
                "frame and subframe; a clip without one fails");
  sub->add_flag("--no-plots", args->no_plots, "Skip the PNG plots");
  sub->add_flag("-q,--quiet", args->quiet, "No progress and no table on stdout");
  sub->callback([args, &exit_code] { exit_code = run(*args); });
}

}  // namespace rotinterp::cli
