// bench_eval: the cost of `rotinterp eval` against assimp importing the same files.
//
//   bench_eval [--repeat R] [--metrics [--method M] | --angle-only] [PATH...]   (default PATH: the shared real clips)
//
// In one run, for the same files: (1) assimp alone — Assimp::Importer::ReadFile
// with the flags read_clip uses, one file after another; (2) the whole evaluation
// (read_clip + all methods × keep-every 2,4,8,16, CSV + summary, no plots) with
// --jobs 1 and (3) with --jobs 2. Each is the best of R runs (default 3). Prints
// the ratio eval/import (goal ≤ 2; also for the five seed methods alone), clip-frames per second, and the --jobs 2
// speedup (goal ≥ 1.7 on a machine with two free cores); then where the time goes:
// read_clip alone and each method alone beyond it (CPU seconds), and each method's
// own ratio: read_clip plus that method, all four spacings and every metric,
// against the import (goal ≤ 1.5, ≤ 3 for bf);
// then the floor: read_clip plus the seed methods' curves alone (built from the
// keys, evaluated at every frame and key-jump stencil, no metric), against the import;
// last, eval's own cost per joint-frame: each method's evaluate_method over the
// clips' references prepared beforehand (curves and every metric; no reading, no files).
// --metrics: that last part alone (--method: for that method only).
// --angle-only: each method alone with eval --metrics angle (read_clip, the curves, the
// angle error, the files), each run paired with an import run just before it: the
// median of the pairs' CPU ratios against the import (goal ≤ 1.5, ≤ 3 for bf).
#include "rotinterp/eval/batch.h"
#include "rotinterp/eval/evaluate_clip.h"
#include "rotinterp/batch/dataset.h"
#include "rotinterp/interp/interpolator.h"
#include "rotinterp/io/read.h"

#include "allocator.h"  // src/cli: the allocator setting the CLI runs eval with
#include "cpu_seconds.h"

#include <unistd.h>

#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/scene.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

double import_all(const std::vector<std::string>& files, double& cpu) {
  const auto t0 = Clock::now();
  const double c0 = cpu_seconds();
  for (const std::string& f : files) {
    Assimp::Importer importer;
    importer.SetPropertyBool(AI_CONFIG_IMPORT_NO_SKELETON_MESHES, true);
    const aiScene* scene = importer.ReadFile(f, 0);
    if (scene && scene->mNumAnimations == 0) std::fprintf(stderr, "note: %s has no animation\n", f.c_str());
  }
  cpu = cpu_seconds() - c0;
  return seconds_since(t0);
}

// The seed methods, which the speed goal names; c2 and expmap-c2 came later.
const std::vector<std::string> kSeedMethods = {"slerp", "squad", "expmap", "nlerp", "bf"};

// `only`: these methods; empty: all of them.
double eval_all(const std::vector<fs::path>& inputs, int jobs, const fs::path& out, std::size_t& frames, double& cpu,
                const std::vector<std::string>& only = {},
                rotinterp::MetricSet metrics = rotinterp::MetricSet::all()) {
  rotinterp::EvalOptions o;
  o.clip.metrics = metrics;
  o.inputs = inputs;
  o.output_dir = out;
  for (const rotinterp::MethodInfo& m : rotinterp::methods())
    if (only.empty() || std::find(only.begin(), only.end(), m.name) != only.end()) o.clip.methods.push_back(m.name);
  o.clip.keep_every = {2, 4, 8, 16};
  o.jobs = jobs;
  o.plots = false;
  const auto t0 = Clock::now();
  const double c0 = cpu_seconds();
  auto r = rotinterp::run_eval(o);
  const double s = seconds_since(t0);
  cpu = cpu_seconds() - c0;
  if (!r) {
    std::fprintf(stderr, "bench_eval: %s\n", r.error().c_str());
    std::exit(1);
  }
  frames = 0;
  for (const rotinterp::SummaryEntry& e : r->summary.entries)
    if (e.method == o.clip.methods.front() && e.keep_every == 2) frames = e.samples;  // joint-frames
  return s;
}

// CPU seconds of `method`'s curves alone over `refs`: for every clip, keep-every
// 2, 4, 8, 16 and joint, built from the keys, evaluated at every frame and at the
// key-jump stencils — what eval cannot skip whatever it measures; no reading, no
// metrics. `stencils`: the part spent on the key-jump stencils. Nothing is read:
// this process's own CPU.
double curves_alone(const std::vector<rotinterp::ClipReference>& refs, const std::string& method, double& stencils) {
  const double c0 = own_cpu_seconds();
  stencils = 0.0;
  std::vector<rotinterp::Quat> out, at_keys;
  for (const rotinterp::ClipReference& ref : refs)
    for (int keep : {2, 4, 8, 16})
      for (std::size_t j = 0; j < ref.skeleton.joints.size(); ++j) {
        const std::vector<std::size_t> kf = rotinterp::keep_every_indices(ref.frames.size(), static_cast<std::size_t>(keep));
        const rotinterp::RotationTrack track = rotinterp::decimated_track(ref.frames, ref.original[j], kf);
        auto curve = rotinterp::make_interpolator(method, track);
        if (!curve) continue;
        out.resize(ref.frames.size());  // no subframes here: the samples are the frames
        (*curve)->evaluate(ref.frames.data(), out.size(), out.data());
        // The stencils' centres are among the frames, as in evaluate_method.
        const double s0 = own_cpu_seconds();
        at_keys.resize(kf.size());
        for (std::size_t i = 0; i < kf.size(); ++i) at_keys[i] = out[kf[i]];
        (void)rotinterp::key_jumps(**curve, track.times, at_keys.data());
        stencils += own_cpu_seconds() - s0;
      }
  return own_cpu_seconds() - c0;
}

// Best CPU seconds of evaluate_method(`method`) over `refs` at keep-every 2, 4, 8, 16,
// and the joint-frames it measured (joints × samples × spacings evaluated).
double metrics_alone(const std::vector<rotinterp::ClipReference>& refs, const std::string& method, int repeat,
                     double& joint_frames) {
  rotinterp::ClipEvalOptions o;
  o.methods = {method};
  o.keep_every = {2, 4, 8, 16};
  joint_frames = 0.0;
  for (const rotinterp::ClipReference& ref : refs)
    joint_frames += static_cast<double>(ref.skeleton.joints.size() * ref.samples *
                                        (o.keep_every.size() - rotinterp::skipped_spacings(ref.frames.size(), o).size()));
  double best = 1e300;
  for (int r = 0; r < repeat; ++r) {
    const double c0 = own_cpu_seconds();
    for (const rotinterp::ClipReference& ref : refs)
      if (!rotinterp::evaluate_method(ref, method, o)) std::exit(1);
    best = std::min(best, own_cpu_seconds() - c0);
  }
  return best;
}

// The clips' references, prepared as eval prepares them (no options).
std::vector<rotinterp::ClipReference> references(const std::vector<std::string>& files) {
  std::vector<rotinterp::ClipReference> refs;
  for (const std::string& f : files)
    if (auto clip = rotinterp::read_clip(f))
      if (auto ref = rotinterp::prepare_reference(*clip, f, {})) refs.push_back(std::move(*ref));
  return refs;
}

void print_metrics_alone(const std::vector<rotinterp::ClipReference>& refs, int repeat, const std::string& only = "") {
  std::printf("eval's own cost (evaluate_method on prepared references: curves and every metric), ns CPU per joint-frame and spacing:\n");
  for (const rotinterp::MethodInfo& m : rotinterp::methods()) {
    if (!only.empty() && m.name != only) continue;
    double measured = 0.0;
    const double cpu = metrics_alone(refs, m.name, repeat, measured);
    std::printf("  %-10s %7.1f ns\n", m.name.c_str(), cpu / measured * 1e9);
  }
}

// --angle-only: per method, import then eval --metrics angle, `repeat` pairs in turn.
void print_angle_only(const std::vector<std::string>& files, const std::vector<fs::path>& inputs, int repeat,
                      const fs::path& out) {
  rotinterp::MetricSet angle = rotinterp::MetricSet::none();
  angle.add(rotinterp::Metric::angle);
  std::printf("each method alone, eval --metrics angle -j 1 (read_clip included) / assimp import, CPU, median of %d "
              "pairs run in turn:\n", repeat);
  for (const rotinterp::MethodInfo& m : rotinterp::methods()) {
    std::vector<double> ratios;
    double best_eval = 1e300, best_import = 1e300, c_import, c_eval;
    std::size_t frames = 0;
    for (int r = 0; r < repeat; ++r) {
      import_all(files, c_import);
      eval_all(inputs, 1, out, frames, c_eval, {m.name}, angle);
      ratios.push_back(c_eval / c_import);
      best_eval = std::min(best_eval, c_eval), best_import = std::min(best_import, c_import);
    }
    std::sort(ratios.begin(), ratios.end());
    const double median = ratios[ratios.size() / 2], goal = m.name == "bf" ? 3.0 : 1.5;
    std::printf("  %-10s %.3f s / %.3f s (best)   ratio %.2f (pairs %.2f-%.2f; goal <= %.1f: %s)\n", m.name.c_str(),
                best_eval, best_import, median, ratios.front(), ratios.back(), goal, median <= goal ? "met" : "not met");
  }
  fs::remove_all(out);
}

}  // namespace

int main(int argc, char** argv) {
  int repeat = 3;
  bool metrics_only = false, angle_only = false;
  std::string method;
  std::vector<fs::path> inputs;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--repeat" && i + 1 < argc)
      repeat = std::max(1, std::atoi(argv[++i]));
    else if (a == "--metrics")
      metrics_only = true;
    else if (a == "--angle-only")
      angle_only = true;
    else if (a == "--method" && i + 1 < argc)
      method = argv[++i];
    else
      inputs.emplace_back(a);
  }
  if (inputs.empty()) inputs.emplace_back(ROTINTERP_SHARED_DATA);
  rotinterp::cli::keep_freed_memory_for_reuse();  // as the CLI runs eval
  auto files = rotinterp::discover_inputs(inputs);
  if (!files || files->empty()) {
    std::fprintf(stderr, "bench_eval: %s\n", files ? "no input files" : files.error().c_str());
    return 1;
  }
  if (metrics_only) {
    print_metrics_alone(references(*files), repeat, method);
    return 0;
  }
  const fs::path out = fs::temp_directory_path() / ("rotinterp_bench_eval_" + std::to_string(::getpid()));
  if (angle_only) {
    print_angle_only(*files, inputs, repeat, out);
    return 0;
  }
  // Clip-frames: frames of every clip that loads.
  std::size_t clip_frames = 0, clips = 0;
  for (const std::string& f : *files)
    if (auto c = rotinterp::read_clip(f)) clip_frames += c->frame_count(), ++clips;

  double t_import = 1e300, t_j1 = 1e300, t_j2 = 1e300, c_import = 1e300, c_j1 = 1e300, c_seed = 1e300, c;
  std::size_t joint_frames = 0;
  for (int r = 0; r < repeat; ++r) {
    t_import = std::min(t_import, import_all(*files, c));
    c_import = std::min(c_import, c);
    t_j1 = std::min(t_j1, eval_all(inputs, 1, out, joint_frames, c));
    c_j1 = std::min(c_j1, c);
    t_j2 = std::min(t_j2, eval_all(inputs, 2, out, joint_frames, c));
    eval_all(inputs, 1, out, joint_frames, c, kSeedMethods);
    c_seed = std::min(c_seed, c);
  }
  // Where the time goes: read_clip alone, then each method alone (read included).
  double c_read = 1e300;
  for (int r = 0; r < repeat; ++r) {
    const double c0 = cpu_seconds();
    for (const std::string& f : *files) (void)rotinterp::read_clip(f);
    c_read = std::min(c_read, cpu_seconds() - c0);
  }
  std::vector<std::pair<std::string, double>> per_method;
  for (const rotinterp::MethodInfo& m : rotinterp::methods()) {
    double best = 1e300;
    for (int r = 0; r < repeat; ++r) {
      eval_all(inputs, 1, out, joint_frames, c, {m.name});
      best = std::min(best, c);
    }
    per_method.emplace_back(m.name, best - c_read);
  }
  // The floor: the seed methods' curves alone, read_clip's cost added.
  const std::vector<rotinterp::ClipReference> refs = references(*files);
  std::vector<std::pair<std::string, double>> floor_per_method;
  double c_floor = 0.0, c_stencils = 0.0;
  for (const std::string& m : kSeedMethods) {
    double best = 1e300, best_stencils = 0.0, stencils;
    for (int r = 0; r < repeat; ++r) {
      const double c_curves = curves_alone(refs, m, stencils);
      if (c_curves < best) best = c_curves, best_stencils = stencils;
    }
    floor_per_method.emplace_back(m, best);
    c_floor += best;
    c_stencils += best_stencils;
  }
  eval_all(inputs, 1, out, joint_frames, c);  // joint_frames of the full run again
  fs::remove_all(out);
  const std::size_t combos = rotinterp::methods().size() * 4;
  std::printf("files %zu (clips loaded %zu), clip-frames %zu, methods %zu x keep-every {2,4,8,16}, best of %d\n",
              files->size(), clips, clip_frames, rotinterp::methods().size(), repeat);
  std::printf("assimp import alone       %8.3f s wall  %8.3f s CPU\n", t_import, c_import);
  std::printf("eval --jobs 1             %8.3f s wall  %8.3f s CPU   ratio eval/import %.2f wall, %.2f CPU (goal <= 2)\n",
              t_j1, c_j1, t_j1 / t_import, c_j1 / c_import);
  std::printf("eval --jobs 1, the 5 seed methods (slerp squad expmap nlerp bf) %8.3f s CPU   ratio %.2f (goal <= 2)\n",
              c_seed, c_seed / c_import);
  std::printf("eval --jobs 2             %8.3f s   speedup %.2fx (goal >= 1.7; %u hardware threads); wall ratio to the import %.2f\n",
              t_j2, t_j1 / t_j2, std::thread::hardware_concurrency(), t_j2 / t_import);
  std::printf("throughput (--jobs 1)     %8.0f clip-frames/s (each rebuilt %zu times), %.0f joint-frames/s per rebuild\n",
              static_cast<double>(clip_frames) / t_j1, combos,
              static_cast<double>(joint_frames) * static_cast<double>(combos) / t_j1);
  std::printf("read_clip alone (CPU)     %8.3f s   (assimp + our BVH pass + clip building)\n", c_read);
  for (const auto& [name, cpu] : per_method) {
    const double ratio = (c_read + cpu) / c_import, goal = name == "bf" ? 3.0 : 1.5;
    std::printf("  %-10s CPU beyond read_clip, 4 spacings: %7.3f s   alone (read_clip + method) / import: %.2f "
                "(goal <= %.1f: %s)\n",
                name.c_str(), cpu, ratio, goal, ratio <= goal ? "met" : "not met");
  }
  std::printf("the seed methods' curves alone (built, evaluated at every frame and key-jump stencil; no metrics):\n");
  for (const auto& [name, cpu] : floor_per_method) std::printf("  %-10s %7.3f s CPU\n", name.c_str(), cpu);
  std::printf("  read_clip + these curves: %.3f s CPU, ratio %.2f to the import: the floor under any metric set\n",
              c_read + c_floor, (c_read + c_floor) / c_import);
  std::printf("  without the key-jump stencils (%.3f s of it): ratio %.2f\n", c_stencils,
              (c_read + c_floor - c_stencils) / c_import);
  print_metrics_alone(refs, repeat);
  return 0;
}
