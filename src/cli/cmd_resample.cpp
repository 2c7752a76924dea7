// rotinterp resample: its options and the one-file run (one file's work is
// cmd_resample_file.cpp, the folder run cmd_resample_folder.cpp).
// rotinterp resample IN -o OUT [--fps HZ | --keep-every N] [--method NAME] [--method-for JOINT=NAME ...]
//                    [--translation linear|cubic] [--range START:END] [--anim NAME|INDEX] [--bvh-order ZXY]
//                    [--unit U] [--out-unit U] [--quiet]
// rotinterp resample PATH... -o OUTDIR [the same] [-j N] [--shard I/N] [--skip-existing] [--format EXT]
//                    [--manifest FILE.csv]: a whole dataset, its layout mirrored under OUTDIR.
#include "cmd_resample.h"
#include "common.h"
#include "options.h"
#include "progress_line.h"
#include "rotinterp/interp/interpolator.h"
#include "rotinterp/io/files/formats.h"
#include "rotinterp/io/files/run_guard.h"
#include "rotinterp/io/read.h"
#include "rotinterp/io/takes.h"
#include "rotinterp/io/write.h"

#include <CLI/CLI.hpp>
#include <fmt/core.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rotinterp::cli {

namespace {

bool valid_bvh_order(std::string order) {
  std::sort(order.begin(), order.end());
  return order == "XYZ";
}

// The options every file of a run shares; an error is a usage error.
Result<ResampleOptions> resample_options(const ResampleArgs& a) {
  ResampleOptions opt;
  if (!a.fps.empty() && !a.keep_every.empty()) return make_error("give either --fps or --keep-every, not both");
  if (!a.fps.empty()) {
    auto r = parse_rate_value("--fps", a.fps);
    if (!r) return r.failure();
    opt.fps = *r;
  }
  if (!a.keep_every.empty()) {
    auto n = parse_whole_option("--keep-every", a.keep_every, 1, kMaxKeepEvery);
    if (!n) return n.failure();
    opt.keep_every = static_cast<std::size_t>(*n);
  }
  // source is no interpolator of the registry: resample_file reads the curves.
  auto method = is_source_method(a.method) ? Result<std::vector<std::string>>(std::vector<std::string>{kSourceMethodName})
                                           : parse_methods(a.method, false);
  if (!method) return method.failure();
  opt.method = method->front();
  for (const std::string& item : a.method_for) {
    const std::size_t eq = item.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == item.size())
      return make_error("--method-for '" + item + "' must be JOINT=METHOD");
    const std::string joint = item.substr(0, eq), name = item.substr(eq + 1);
    const MethodInfo* m = find_method(name);
    if (!m) return make_error("--method-for " + item + ": " + unknown_method_message(name));
    opt.method_for.emplace_back(joint, m->name);
  }
  auto translation = parse_translation_interp(a.translation);
  if (!translation) return translation.failure("--translation: ");
  opt.translation = *translation;
  if (!a.range.empty()) {
    auto r = parse_time_range(a.range);
    if (!r) return r.failure();
    opt.range = *r;
  }
  if (!valid_bvh_order(a.bvh_order)) return make_error("--bvh-order '" + a.bvh_order + "' must be a permutation of XYZ, e.g. ZXY");
  return opt;
}

// The summary line of one file's (or take's) run.
void print_run(const FileRun& run, const std::string& input, const std::string& output, const ResampleArgs& a,
               const ResampleOptions& opt) {
  const std::string from = run.rate ? run.rate->to_string() + " Hz" : "unknown rate";
  std::string how;
  if (opt.keep_every)
    how = fmt::format("keys every {} frame{}", *opt.keep_every, *opt.keep_every == 1 ? "" : "s");
  else
    how = fmt::format("{} → {} Hz", from,
                      opt.fps        ? opt.fps->to_string()
                      : run.rate        ? run.rate->to_string()
                      : run.output_rate ? run.output_rate->to_string()
                                        : "?");
  std::string methods = opt.method;
  if (run.replayed)
    methods += fmt::format(" ({} of {} joints from {}{})", run.replayed, run.joints, run.replays,
                           run.replayed < run.joints ? fmt::format(", the rest {} over the baked keys", kDefaultResampleMethod)
                                                     : std::string());
  if (run.copied_curves)
    methods += fmt::format("; FBX: the curves of {} joints written back as stored (keys and tangents)", run.copied_curves);
  if (!opt.method_for.empty()) methods += fmt::format(" (+{} per-joint override{})", opt.method_for.size(),
                                                      opt.method_for.size() == 1 ? "" : "s");
  fmt::print("{} → {}: {} → {} frames ({}), method {}, translation {}, {:.3f} s; unit {}{}\n", input, output,
             run.frames, run.output_frames, how, methods, translation_interp_name(opt.translation), run.seconds,
             describe_unit(run.unit), a.out_unit_m ? ", written in " + unit_name(*a.out_unit_m) : std::string());
  if (!run.cycle.empty()) fmt::print("  {}\n", run.cycle);
  if (!run.kept.empty()) fmt::print("  {}\n", run.kept);
}

// Stage names on the progress line (reading and writing long clips take seconds).
std::function<void(const std::string&)> progress_stage(bool quiet) {
  const bool show = !quiet && ::isatty(STDERR_FILENO);
  return [show, quiet](const std::string& what) {
    end_progress(quiet);
    if (show) std::fprintf(stderr, "\r\033[K%s …", what.c_str());
  };
}

int run_single(const ResampleArgs& a, ResampleOptions opt) {
  const std::string& input = a.inputs.front();
  protect_input(input);
  if (Status s = check_not_an_input(a.output); !s) return fail(s.error());
  opt.progress = make_progress("resample", a.quiet, "joints");
  FileRun run;
  run.input = input;
  run.output = a.output;
  const Status done = resample_file(run, a, opt, progress_stage(a.quiet));
  end_progress(a.quiet);
  if (!done) return fail(done.error());
  if (!a.quiet) print_run(run, input, a.output, a, opt);
  return kExitOk;
}

// --anim all, a list of takes, or {anim} in the output name: each take resampled on
// its own clock, then written, one file per take ({anim} filled with its name) or all
// into one file (FBX, glTF: a take each).
int run_takes(const ResampleArgs& a, ResampleOptions opt) {
  const std::string& input = a.inputs.front();
  protect_input(input);
  const bool per_take = a.output.find(kTakePlaceholder) != std::string::npos;
  if (!per_take && !can_write_takes(a.output))
    return fail_usage("--anim " + a.anim + ": " + a.output + " holds one take; put " + kTakePlaceholder +
                      " in the output name to write one file per take (or write " + format_names(holds_takes, " or ", true) + ")");
  ReadOptions read_options;
  read_options.unit = a.unit_m;
  read_options.allow_external_files = a.allow_external_files;
  read_options.on_warning = warn;
  auto takes = select_takes(input, a.anim, read_options);
  if (!takes) return fail(takes.error());
  std::vector<FileRun> runs(takes->size());
  for (std::size_t k = 0; k < runs.size(); ++k) {
    runs[k].input = input;
    runs[k].output = per_take ? with_take_name(a.output, (*takes)[k]) : a.output;
    for (std::size_t i = 0; i < k; ++i)
      if (per_take && runs[i].output == runs[k].output)
        return fail(input + ": takes '" + (*takes)[i].name + "' and '" + (*takes)[k].name + "' both make " +
                    runs[k].output.string() + "; name the takes apart, or put {anim} where they differ");
    if (Status s = check_not_an_input(runs[k].output.string()); !s) return fail(s.error());
  }
  // Every take is read and resampled before anything is written: a take that fails
  // leaves no file of the others.
  opt.progress = make_progress("resample", a.quiet, "joints");
  const auto stage = progress_stage(a.quiet);
  std::vector<ResampledFile> done;
  for (std::size_t k = 0; k < runs.size(); ++k) {
    ResampleArgs one = a;
    one.anim = std::to_string((*takes)[k].index);
    auto resampled = resample_input(runs[k], one, opt, stage);
    if (!resampled) return end_progress(a.quiet), fail(resampled.error());
    resampled->clip.name = (*takes)[k].name;
    done.push_back(std::move(*resampled));
  }
  Status written = Ok{};
  if (per_take) {
    for (std::size_t k = 0; k < runs.size() && written; ++k) written = write_resampled(runs[k], done[k], a, opt, stage);
  } else {
    stage("writing " + a.output);
    std::vector<Clip> clips;
    for (ResampledFile& d : done) clips.push_back(std::move(d.clip));
    written = write_clips(clips, a.output, resample_write_options(a, opt, runs.front()));
  }
  end_progress(a.quiet);
  if (!written) return fail(written.error());
  if (!a.quiet)
    for (std::size_t k = 0; k < runs.size(); ++k)
      print_run(runs[k], input + "#" + (*takes)[k].name, runs[k].output.string(), a, opt);
  return kExitOk;
}

int run_resample(ResampleArgs a) {
  // Everything that can be checked without the input is checked first (exit 2).
  auto opt = resample_options(a);
  if (!opt) return fail_usage(opt.error());
  auto loop = parse_loop_option(a.loop);
  if (!loop) return fail_usage(loop.error());
  a.loop_request = *loop;
  if (opt->method == kSourceMethodName && (opt->keep_every || opt->range || a.loop_request))
    return fail_usage("--method source evaluates the file's own motion on the output grid (--fps); --keep-every, --range "
                      "and --loop do not apply to it");
  auto unit = parse_unit_option(a.unit);
  if (!unit) return fail_usage(unit.error());
  a.unit_m = *unit;
  if (!a.out_unit.empty()) {
    auto out_unit = parse_unit(a.out_unit);
    if (!out_unit) return fail_usage("--out-unit: " + out_unit.error());
    a.out_unit_m = *out_unit;
    const std::string out_ext = a.format.empty() ? std::filesystem::path(a.output).extension().string() : "." + a.format;
    if (const FormatInfo* f = format_named(out_ext); f && f->unit == "metres")
      return fail_usage("--out-unit: glTF is always in metres (its spec); --out-unit is for " +
                        format_names([](const FormatInfo& g) { return g.writes && g.unit != "metres"; }, " and "));
  }
  if (a.output.empty()) return fail_usage("-o/--output: an empty path (a file such as out.bvh, or a folder such as out/)");
  std::error_code ec;
  // One file in, one out, as always; a folder run when given a folder, several
  // inputs, --format, an output ending with '/' (a folder, created if missing) or an
  // existing directory (not named like a clip) as output.
  const bool into_directory = a.output.back() == '/' ||
                              (std::filesystem::is_directory(a.output, ec) && !can_write_format(a.output));
  const bool one_file = a.inputs.size() == 1 && !std::filesystem::is_directory(a.inputs.front(), ec) &&
                        !into_directory && a.format.empty();
  if (!one_file && names_several_takes(a.anim))
    return fail_usage("--anim " + a.anim + " takes several takes of one input file; a folder run reads one take of each");
  if (!one_file) return run_resample_folder(a, *opt);
  if (!a.shard.empty() || !a.manifest.empty() || a.skip_existing)
    return fail_usage("--shard, --manifest and --skip-existing are for folder runs (-o DIR)");
  if (!can_write_format(a.output))
    return fail_usage("output '" + a.output + "': unknown format (use " + format_names(writable, " or ", true) + ")");
  if (names_several_takes(a.anim) || a.output.find(kTakePlaceholder) != std::string::npos) return run_takes(a, *opt);
  return run_single(a, *opt);
}

}  // namespace

void add_resample_command(CLI::App& app, int& exit_code) {
  auto* sub = app.add_subcommand("resample", "Resample a clip: change its frame rate or rebuild it from sparse keys");
  auto a = std::make_shared<ResampleArgs>();
  sub->add_option("IN", a->inputs,
                  "Input clip (BVH, FBX, glTF/GLB, Collada, … — anything assimp reads); several, or folders "
                  "(searched recursively), with -o DIR")
      ->required();
  add_output_option(*sub, a->output,
                    "Output file; the format follows the extension: " + format_names(writable, ", ") + ". For several inputs or "
                    "a folder: the output directory, the inputs' layout mirrored under it")
      ->required();
  add_fps_option(*sub, a->fps,
                 "the output rate: frames at start + k/HZ, k = 0 … floor(duration·HZ + 1e-9); default the source's "
                 "rate (or --keep-every)");
  add_keep_every_option(*sub, a->keep_every, false, "every source frame is rebuilt (default: unset, see --fps)");
  add_method_option(*sub, a->method, false,
                    std::string(kDefaultResampleMethod) +
                        ", for every joint; 'source' replays the file's own motion on the joints that have it: "
                        "an FBX file's curves (tangents, Euler order, pre/post-rotation), a glTF file's animation "
                        "samplers (STEP, LINEAR, CUBICSPLINE), a BVH's frames (slerp between them); " +
                        kDefaultResampleMethod + " on the rest; FBX to .fbx without --fps writes its curves back as "
                        "stored (keys and tangents)");
  sub->add_option("--method-for", a->method_for, "Per-joint override JOINT=METHOD (repeatable; default none)");
  sub->add_option("--translation", a->translation,
                  "Translation tracks: linear, or cubic (default: C¹, Steffen tangents — never overshoots between keys)");
  add_range_option(*sub, a->range, "cut before resampling (default: the whole clip)");
  add_loop_option(*sub, a->loop,
                  "The output is one period again, closing the same way; with --fps the period keeps whole frames "
                  "(the rate is kept, the period stretched by under half a frame where needed, and the summary says "
                  "so); --keep-every takes the wrap-around neighbours.");
  const std::string several = "each resampled on its own clock; written into one " + format_names(holds_takes, " or ", true) +
                              ", a take each, or one file per take with {anim} in the output name";
  add_anim_option(*sub, a->anim, several.c_str());
  add_unit_option(*sub, a->unit);
  add_external_files_option(*sub, a->allow_external_files);
  sub->add_option("--out-unit", a->out_unit,
                  "Unit of the written file: m, cm, mm, in, ft or metres per unit (default: the input's; glTF is "
                  "always metres)");
  sub->add_option("--bvh-order", a->bvh_order,
                  "Euler order for BVH output of joints without a BVH layout (non-BVH input); default ZXY");
  sub->add_flag("--fbx-ascii", a->fbx_ascii, "FBX output as ASCII FBX 7.4 (default: binary FBX 7.4, which Blender needs)");
  add_quiet_option(*sub, a->quiet);
  add_jobs_option(*sub, a->jobs, "Folder runs: files resampled at once");
  add_folder_run_options(*sub, a->shard, a->skip_existing, a->format,
                         format_names(writable) + " (default: the input's own, else " + std::string(formats().front().name) + ")", a->manifest,
                         "rate as written and as read, frames, duration, joints, output frames, method, time, status");
  sub->callback([a, &exit_code] { exit_code = run_resample(*a); });
}

}  // namespace rotinterp::cli
