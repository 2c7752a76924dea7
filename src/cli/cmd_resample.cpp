// rotinterp resample IN -o OUT [--fps HZ | --keep-every N] [--method NAME] [--method-for JOINT=NAME ...]
//                    [--translation linear|cubic] [--range START:END] [--anim NAME|INDEX] [--bvh-order ZXY]
//                    [--unit U] [--out-unit U] [--quiet]
// rotinterp resample PATH... -o OUTDIR [the same] [-j N] [--shard I/N] [--skip-existing] [--format EXT]
//                    [--manifest FILE.csv]: a whole dataset, its layout mirrored under OUTDIR.
#include "common.h"
#include "rotinterp/clip/frames.h"
#include "rotinterp/clip/bvh_layout.h"
#include "rotinterp/clip/resample.h"
#include "rotinterp/clip/resample_loop.h"
#include "rotinterp/clip/units.h"
#include "rotinterp/core/work_queue.h"
#include "rotinterp/eval/error_row.h"  // csv_field: the one CSV quoting
#include "rotinterp/interp/interpolator.h"
#include "rotinterp/io/atomic_file.h"
#include "rotinterp/io/dataset.h"
#include "rotinterp/io/fbx_source.h"
#include "rotinterp/io/read.h"
#include "rotinterp/io/write.h"

#include <CLI/CLI.hpp>
#include <fmt/core.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace rotinterp::cli {

namespace {

struct ResampleArgs {
  std::vector<std::string> inputs;
  std::string output;
  std::string fps, keep_every, method = kDefaultResampleMethod, translation = "cubic", range, anim, bvh_order = "ZXY";
  std::vector<std::string> method_for;
  bool quiet = false;
  bool fbx_ascii = false;
  // Folder runs.
  int jobs = 0;
  std::string shard, format, manifest;
  bool skip_existing = false;
  std::string unit, out_unit;  // as written; parsed into:
  std::optional<double> unit_m, out_unit_m;  // metres per unit
  std::string loop = "off";                  // --loop as written; parsed into:
  std::optional<LoopRequest> loop_request;
};

// One file's run: a row of the manifest.
struct FileRun {
  std::string input;
  std::filesystem::path output;
  std::string status = "ok";  // ok, exists (--skip-existing), no-animation, failed
  std::string message;        // the error line of a failed file
  std::string frame_time;     // as written in the file (BVH), else empty
  std::optional<Rate> rate;   // as recognized
  std::optional<Rate> output_rate;
  std::size_t frames = 0, joints = 0, output_frames = 0;
  double duration = 0.0, seconds = 0.0;
  std::uintmax_t bytes = 0;  // of the input
  ClipUnit unit;             // the input's (clip/units.h)
  double output_metres_per_unit = 0.0;
  std::string cycle;  // --loop: the cycle's summary (clip/resample_loop.h)
  std::size_t replayed = 0;  // --method source: joints evaluated from the file's curves
};

bool valid_bvh_order(std::string order) {
  std::sort(order.begin(), order.end());
  return order == "XYZ";
}

// The options every file of a run shares; an error is a usage error.
Result<ResampleOptions> resample_options(const ResampleArgs& a) {
  ResampleOptions opt;
  if (!a.fps.empty() && !a.keep_every.empty()) return make_error("give either --fps or --keep-every, not both");
  if (!a.fps.empty()) {
    auto r = parse_rate_option("--fps", a.fps);
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

// Reads, resamples and writes one file, filling `run`; `stage` names each step.
Status resample_file(FileRun& run, const ResampleArgs& a, const ResampleOptions& opt,
                     const std::function<void(const std::string&)>& stage) {
  const auto started = std::chrono::steady_clock::now();
  ReadOptions read_options;
  read_options.animation = a.anim;
  read_options.unit = a.unit_m;
  read_options.on_warning = warn;
  stage("reading " + run.input);
  // --method source: the frames come from the grid and the default method, then the
  // joints with curves are evaluated from them (io/fbx_source.h).
  const bool source = opt.method == kSourceMethodName;
  std::optional<SourceClip> curves;
  Result<Clip> clip = make_error("");
  if (source) {
    auto read = read_source_clip(run.input, read_options);
    if (!read) return read.failure();
    curves = std::move(*read);
    clip = curves->clip;
  } else {
    clip = read_clip(run.input, read_options);
  }
  if (!clip) return clip.failure();
  run.frame_time = frame_time_text(*clip);
  run.rate = clip_rate(*clip);
  run.frames = clip->frame_count();
  run.joints = clip->skeleton.joints.size();
  run.duration = clip->end_time() - clip->start_time();
  run.unit = clip->unit;

  Result<Clip> out = make_error("");
  if (a.loop_request) {
    auto cycle = resample_cycle(*clip, opt, a.loop_request->form);
    if (!cycle) return cycle.failure(run.input + ": ");
    run.cycle = cycle->summary();
    out = std::move(cycle->clip);
  } else {
    ResampleOptions base = opt;
    if (source) base.method = kDefaultResampleMethod;
    out = resample_clip(*clip, base);
  }
  if (!out) return out.failure(run.input + ": ");
  if (curves) {
    std::vector<std::string> keep;
    for (const auto& [joint, method] : opt.method_for) keep.push_back(joint);
    auto replayed = replay_fbx_rotations(*out, *curves, keep, run.input);
    if (!replayed) return replayed.failure();
    run.replayed = *replayed;
  }
  if (a.out_unit_m) convert_unit(*out, *a.out_unit_m, "--out-unit " + a.out_unit);
  run.output_metres_per_unit = out->unit.metres_per_unit;
  run.output_frames = out->frame_count();
  run.output_rate = clip_rate(*out);

  WriteOptions write_options;
  write_options.bvh_order = a.bvh_order;
  write_options.fbx_ascii = a.fbx_ascii;
  write_options.on_warning = warn;
  stage("writing " + run.output.string());
  const Status written = write_clip(*out, run.output, write_options);
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return written;
}

int run_single(const ResampleArgs& a, ResampleOptions opt) {
  const std::string& input = a.inputs.front();
  protect_input(input);
  if (Status s = check_not_an_input(a.output); !s) return fail(s.error());
  // Stage names on the progress line (reading and writing long clips take seconds).
  const bool show = !a.quiet && ::isatty(STDERR_FILENO);
  auto stage = [show, &a](const std::string& what) {
    end_progress(a.quiet);
    if (show) std::fprintf(stderr, "\r\033[K%s …", what.c_str());
  };
  opt.progress = make_progress("resample", a.quiet);
  FileRun run;
  run.input = input;
  run.output = a.output;
  const Status done = resample_file(run, a, opt, stage);
  end_progress(a.quiet);
  if (!done) return fail(done.error());

  if (!a.quiet) {
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
      methods += fmt::format(" ({} of {} joints from the file's curves, the rest {} over the baked keys)", run.replayed,
                             run.joints, kDefaultResampleMethod);
    if (!opt.method_for.empty()) methods += fmt::format(" (+{} per-joint override{})", opt.method_for.size(),
                                                        opt.method_for.size() == 1 ? "" : "s");
    fmt::print("{} → {}: {} → {} frames ({}), method {}, translation {}, {:.3f} s; unit {}{}\n", input, a.output,
               run.frames, run.output_frames, how, methods, translation_interp_name(opt.translation), run.seconds,
               describe_unit(run.unit), a.out_unit_m ? ", written in " + unit_name(*a.out_unit_m) : std::string());
    if (!run.cycle.empty()) fmt::print("  {}\n", run.cycle);
  }
  return kExitOk;
}

Status write_manifest(const std::string& path, const std::vector<FileRun>& runs, const ResampleOptions& opt) {
  return write_file_atomically(path, [&](std::ostream& out) -> Status {
    out << "input,output,status,frame_time_written,rate_hz,rate,frames,duration_s,joints,output_frames,method,"
           "seconds,message,metres_per_unit,unit\n";
    for (const FileRun& r : runs) {
      const bool read = r.status == "ok" || (r.status == "failed" && r.frames > 0);
      out << csv_field(r.input) << ',' << csv_field(r.output.string()) << ',' << r.status << ','
          << csv_field(r.frame_time) << ',' << (r.rate ? fmt::format("{:.9g}", r.rate->hz()) : "") << ','
          << (r.rate ? r.rate->to_string() : "") << ',' << (read ? std::to_string(r.frames) : "") << ','
          << (read ? fmt::format("{:.9g}", r.duration) : "") << ',' << (read ? std::to_string(r.joints) : "") << ','
          << (r.status == "ok" ? std::to_string(r.output_frames) : "") << ',' << csv_field(opt.method) << ','
          << (r.status == "ok" ? fmt::format("{:.3f}", r.seconds) : "") << ',' << csv_field(r.message) << ','
          << (read ? fmt::format("{}", r.unit.metres_per_unit) : "") << ','
          << (read ? csv_field(describe_unit(r.unit)) : "") << '\n';
    }
    return Ok{};
  });
}

// "1m05s", "42s".
std::string duration_text(double seconds) {
  const auto s = static_cast<long long>(std::llround(seconds));
  return s >= 60 ? fmt::format("{}m{:02}s", s / 60, s % 60) : fmt::format("{}s", s);
}

int run_folder(const ResampleArgs& a, ResampleOptions opt) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::exists(a.output, ec) ? !fs::is_directory(a.output, ec) : can_write_format(a.output))
    return fail_usage("output '" + a.output + "' is a file name; several inputs or a folder need an output directory");
  if (!a.format.empty() && !can_write_format(fs::path("x." + a.format)))
    return fail_usage("--format '" + a.format + "': unknown format (use bvh, fbx, glb, gltf or dae)");
  std::vector<fs::path> named(a.inputs.begin(), a.inputs.end());
  auto found = discover_inputs(named);
  if (!found) return fail(found.error());
  if (found->empty()) {
    std::string where;
    for (const std::string& p : a.inputs) where += (where.empty() ? "" : ", ") + p;
    return fail(where + ": no clip files found (looked for every format assimp imports)");
  }
  std::vector<std::string> files = *found;
  if (!a.shard.empty()) {
    auto shard = parse_shard(a.shard);
    if (!shard) return fail_usage(shard.error());
    files = shard_of(files, shard->first, shard->second);
  }
  auto plan = mirror_outputs(files, named, a.output, a.format);
  if (!plan) return fail(plan.error());
  for (const MirroredOutput& m : *plan) protect_input(m.input);

  WorkQueue queue(static_cast<unsigned>(a.jobs));
  // Joints in parallel only where fewer files than workers are in flight (the last ones).
  std::atomic<unsigned> in_flight{0};
  std::atomic<std::size_t> done{0};
  std::atomic<std::uintmax_t> bytes_done{0};
  std::uintmax_t bytes_total = 0;
  for (const MirroredOutput& m : *plan) bytes_total += fs::file_size(m.input, ec) * !ec;
  const bool show = !a.quiet && ::isatty(STDERR_FILENO);
  std::mutex progress_mutex;
  const auto started = std::chrono::steady_clock::now();
  auto report = [&] {
    if (!show) return;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    const double mb = static_cast<double>(bytes_done.load()) / 1e6;
    const double rate = elapsed > 0 ? mb / elapsed : 0.0;
    const double left = static_cast<double>(bytes_total - std::min(bytes_total, bytes_done.load())) / 1e6;
    std::lock_guard<std::mutex> lock(progress_mutex);
    std::fprintf(stderr, "\r\033[Kresample  %zu/%zu files  %.1f MB/s  ETA %s", done.load(), plan->size(), rate,
                 rate > 0 ? duration_text(left / rate).c_str() : "?");
  };
  auto no_stage = [](const std::string&) {};

  std::vector<std::future<FileRun>> futures;
  for (const MirroredOutput& m : *plan) {
    futures.push_back(queue.submit([&, m] {
      FileRun run;
      run.input = m.input;
      run.output = m.output;
      std::error_code size_error;  // this worker's own
      run.bytes = fs::file_size(m.input, size_error) * !size_error;
      if (a.skip_existing && fs::is_regular_file(m.output, size_error)) {
        run.status = "exists";
      } else if (Status mine = check_not_an_input(m.output); !mine) {
        run.status = "failed";
        run.message = mine.error();
      } else {
        ResampleOptions file_opt = opt;
        const unsigned now = ++in_flight;
        file_opt.threads = std::max(1u, queue.threads() / std::max(1u, now));
        std::error_code mkdir_error;
        fs::create_directories(m.output.parent_path(), mkdir_error);
        Status s = mkdir_error ? Status(make_error(m.output.parent_path().string() + ": " + mkdir_error.message()))
                               : resample_file(run, a, file_opt, no_stage);
        --in_flight;
        if (!s && s.error_kind() == ErrorKind::no_animation && found_in_directory(m.input, named)) {
          run.status = "no-animation";  // a mesh next to the clips, as eval skips it
        } else if (!s) {
          run.status = "failed";
          run.message = s.error();
        }
      }
      ++done;
      bytes_done += run.bytes;
      report();
      return run;
    }));
  }
  std::vector<FileRun> runs;
  std::size_t failed = 0, written = 0, existing = 0;
  for (auto& f : futures) {
    runs.push_back(f.get());
    const FileRun& r = runs.back();
    if (r.status == "failed") {
      ++failed;
      if (show) std::fprintf(stderr, "\r\033[K");
      fail(r.message);
    }
    written += r.status == "ok";
    existing += r.status == "exists";
  }
  end_progress(a.quiet);
  if (!a.manifest.empty())
    if (Status s = write_manifest(a.manifest, runs, opt); !s) return fail(s.error());
  if (!a.quiet) {
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    fmt::print("{} file{} → {}: {} written, {} already there, {} failed, {} skipped (no animation); {:.1f} MB in "
               "{:.2f} s ({:.1f} MB/s), {} worker{}\n",
               runs.size(), runs.size() == 1 ? "" : "s", a.output, written, existing, failed,
               runs.size() - written - existing - failed, static_cast<double>(bytes_total) / 1e6, seconds,
               seconds > 0 ? static_cast<double>(bytes_total) / 1e6 / seconds : 0.0, queue.threads(),
               queue.threads() == 1 ? "" : "s");
  }
  return failed > 0 ? kExitPartial : kExitOk;
}

int run_resample(ResampleArgs a) {
  // Everything that can be checked without the input is checked first (exit 2).
  auto opt = resample_options(a);
  if (!opt) return fail_usage(opt.error());
  auto loop = parse_loop_option(a.loop);
  if (!loop) return fail_usage(loop.error());
  a.loop_request = *loop;
  if (opt->method == kSourceMethodName && (opt->keep_every || opt->range || a.loop_request))
    return fail_usage("--method source evaluates the file's curves on the output grid (--fps); --keep-every, --range "
                      "and --loop do not apply to it");
  auto unit = parse_unit_option(a.unit);
  if (!unit) return fail_usage(unit.error());
  a.unit_m = *unit;
  if (!a.out_unit.empty()) {
    auto out_unit = parse_unit(a.out_unit);
    if (!out_unit) return fail_usage("--out-unit: " + out_unit.error());
    a.out_unit_m = *out_unit;
    const std::string out_ext = a.format.empty() ? std::filesystem::path(a.output).extension().string() : "." + a.format;
    if (out_ext == ".glb" || out_ext == ".gltf")
      return fail_usage("--out-unit: glTF is always in metres (its spec); --out-unit is for bvh, fbx and dae");
  }
  std::error_code ec;
  // One file in, one out, as always; a folder run when given a folder, several
  // inputs, --format, or an existing directory (not named like a clip) as output.
  const bool into_directory = std::filesystem::is_directory(a.output, ec) && !can_write_format(a.output);
  const bool one_file = a.inputs.size() == 1 && !std::filesystem::is_directory(a.inputs.front(), ec) &&
                        !into_directory && a.format.empty();
  if (!one_file) return run_folder(a, *opt);
  if (!a.shard.empty() || !a.manifest.empty() || a.skip_existing)
    return fail_usage("--shard, --manifest and --skip-existing are for folder runs (-o DIR)");
  if (!can_write_format(a.output))
    return fail_usage("output '" + a.output + "': unknown format (use .bvh, .fbx, .glb, .gltf or .dae)");
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
                    "Output file; the format follows the extension: bvh, fbx, glb, gltf, dae. For several inputs or "
                    "a folder: the output directory, the inputs' layout mirrored under it")
      ->required();
  add_fps_option(*sub, a->fps,
                 "the output rate: frames at start + k/HZ, k = 0 … floor(duration·HZ + 1e-9); default the source's "
                 "rate (or --keep-every)");
  add_keep_every_option(*sub, a->keep_every, false, "every source frame is rebuilt (default: unset, see --fps)");
  add_method_option(*sub, a->method, false,
                    std::string(kDefaultResampleMethod) +
                        ", for every joint; 'source' replays an FBX file's own curves (tangents, Euler order, "
                        "pre/post-rotation) on the joints that have them, " + kDefaultResampleMethod + " on the rest");
  sub->add_option("--method-for", a->method_for, "Per-joint override JOINT=METHOD (repeatable; default none)");
  sub->add_option("--translation", a->translation,
                  "Translation tracks: linear, or cubic (default: C¹, Steffen tangents — never overshoots between keys)");
  add_range_option(*sub, a->range, "cut before resampling (default: the whole clip)");
  add_loop_option(*sub, a->loop,
                  "The output is one period again, closing the same way; with --fps the period keeps whole frames "
                  "(the rate is kept, the period stretched by under half a frame where needed, and the summary says "
                  "so); --keep-every takes the wrap-around neighbours.");
  add_anim_option(*sub, a->anim, false);
  add_unit_option(*sub, a->unit);
  sub->add_option("--out-unit", a->out_unit,
                  "Unit of the written file: m, cm, mm, in, ft or metres per unit (default: the input's; glTF is "
                  "always metres)");
  sub->add_option("--bvh-order", a->bvh_order,
                  "Euler order for BVH output of joints without a BVH layout (non-BVH input); default ZXY");
  sub->add_flag("--fbx-ascii", a->fbx_ascii, "FBX output as ASCII FBX 7.4 (default: binary FBX 7.4, which Blender needs)");
  add_quiet_option(*sub, a->quiet);
  add_jobs_option(*sub, a->jobs, "Folder runs: files resampled at once");
  sub->add_option("--shard", a->shard,
                  "Folder runs: only shard I of N (I/N) of the sorted inputs, for a cluster (default: all)");
  sub->add_flag("--skip-existing", a->skip_existing,
                "Folder runs: leave outputs that exist (an output is only ever complete), to resume a run "
                "(default: replace them)");
  sub->add_option("--format", a->format,
                  "Folder runs: output format bvh, fbx, glb, gltf or dae (default: the input's own, else bvh)");
  sub->add_option("--manifest", a->manifest,
                  "Folder runs: write a CSV row per file (rate as written and as read, frames, duration, joints, "
                  "output frames, method, time, status); default none");
  sub->callback([a, &exit_code] { exit_code = run_resample(*a); });
}

}  // namespace rotinterp::cli
