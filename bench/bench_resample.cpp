// `resample` of a long clip against assimp's own import of the same file.
//
// Generates a 100 000-frame, 31-joint BVH (rotinterp synth --kind walk at 120 Hz,
// random rotation orders), then times in the same run:
//   import   — assimp alone: Assimp::Importer::ReadFile, as read_clip configures it;
//   resample — what `rotinterp resample` does: read_clip + resample_clip (default
//              method) + write_clip to BVH, at the same rate and at 120 → 30 Hz
//              (with the three stages of the best run).
// and prints the ratios resample/import (goal ≤ 1.5; README "rotinterp resample").
// Usage: bench_resample [--frames N] [--keep PATH] [Google Benchmark flags]
#include "rotinterp/clip/resample.h"
#include "rotinterp/clip/synth.h"
#include "rotinterp/io/read.h"
#include "rotinterp/io/write.h"

#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/scene.h>
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <optional>
#include <cstdio>
#include <ctime>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <limits>
#include <string>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace rotinterp;

namespace {

fs::path g_file;
double g_best_import = std::numeric_limits<double>::infinity();
double g_best_same = std::numeric_limits<double>::infinity();
double g_best_30 = std::numeric_limits<double>::infinity();
// Process CPU time (all threads, std::clock), best of the runs: less sensitive than
// wall time to other jobs on a shared machine, but it charges the worker threads.
double g_cpu_import = std::numeric_limits<double>::infinity();
double g_cpu_same = std::numeric_limits<double>::infinity();
double g_cpu_30 = std::numeric_limits<double>::infinity();

double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

void BM_AssimpImport(benchmark::State& state) {
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    const double c0 = cpu_seconds();
    Assimp::Importer importer;
    importer.SetPropertyBool(AI_CONFIG_IMPORT_NO_SKELETON_MESHES, true);
    const aiScene* scene = importer.ReadFile(g_file.string(), 0);
    if (!scene || scene->mNumAnimations != 1) state.SkipWithError("assimp could not read the file");
    benchmark::DoNotOptimize(scene);
    g_best_import = std::min(g_best_import, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    g_cpu_import = std::min(g_cpu_import, cpu_seconds() - c0);
  }
}

// The stages of the best run: read_clip, resample_clip, write_clip.
struct Stages {
  double read = 0, resample = 0, write = 0;
};
Stages g_stages_same, g_stages_30;

void resample_once(benchmark::State& state, std::optional<Rate> fps, double& best, Stages& stages, double& cpu) {
  const fs::path out = fs::temp_directory_path() / ("rotinterp_bench_out_" + std::to_string(::getpid()) + ".bvh");
  using clock = std::chrono::steady_clock;
  auto seconds = [](clock::time_point a, clock::time_point b) { return std::chrono::duration<double>(b - a).count(); };
  for (auto _ : state) {
    const auto t0 = clock::now();
    const double c0 = cpu_seconds();
    auto clip = read_clip(g_file);
    if (!clip) {
      state.SkipWithError(clip.error().c_str());
      break;
    }
    const auto t1 = clock::now();
    ResampleOptions o;
    o.fps = fps;
    auto res = resample_clip(std::move(*clip), o);  // as the command does: the read clip is given up
    if (!res) {
      state.SkipWithError("resample failed");
      break;
    }
    const auto t2 = clock::now();
    if (!write_clip(*res, out)) {
      state.SkipWithError("write failed");
      break;
    }
    const auto t3 = clock::now();
    cpu = std::min(cpu, cpu_seconds() - c0);
    if (seconds(t0, t3) < best) {
      best = seconds(t0, t3);
      stages = Stages{seconds(t0, t1), seconds(t1, t2), seconds(t2, t3)};
    }
  }
  fs::remove(out);
}

void BM_ResampleSameRate(benchmark::State& state) { resample_once(state, std::nullopt, g_best_same, g_stages_same, g_cpu_same); }
void BM_Resample120To30(benchmark::State& state) { resample_once(state, Rate{30, 1}, g_best_30, g_stages_30, g_cpu_30); }

}  // namespace

BENCHMARK(BM_AssimpImport)->Unit(benchmark::kMillisecond)->Iterations(1)->Repetitions(3)->ReportAggregatesOnly(true);
BENCHMARK(BM_ResampleSameRate)->Unit(benchmark::kMillisecond)->Iterations(1)->Repetitions(3)->ReportAggregatesOnly(true);
BENCHMARK(BM_Resample120To30)->Unit(benchmark::kMillisecond)->Iterations(1)->Repetitions(3)->ReportAggregatesOnly(true);

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  long frames = 100000;
  std::string keep;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--frames") && i + 1 < argc) frames = std::atol(argv[++i]);
    else if (!std::strcmp(argv[i], "--keep") && i + 1 < argc) keep = argv[++i];
    else {
      std::fprintf(stderr, "usage: bench_resample [--frames N] [--keep PATH] [benchmark flags]\n");
      return 2;
    }
  }
  if (frames < 2) frames = 2;
  g_file = keep.empty() ? fs::temp_directory_path() / ("rotinterp_bench_in_" + std::to_string(::getpid()) + ".bvh")
                        : fs::path(keep);
  SynthOptions o;
  o.kind = SynthKind::walk;
  o.fps = Rate{120, 1};
  o.seconds = static_cast<double>(frames - 1) / 120.0;
  auto clip = make_synth_clip(o);
  if (!clip || !write_clip(*clip, g_file)) {
    std::fprintf(stderr, "bench_resample: could not write %s\n", g_file.c_str());
    return 1;
  }
  std::printf("input: %s, %zu frames × %zu joints, %.1f MB\n", g_file.c_str(), clip->frame_count(),
              clip->skeleton.joints.size(), static_cast<double>(fs::file_size(g_file)) / 1e6);
  clip = Clip{};
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  std::printf("wall time, best of 3: assimp import %.3f s; resample same rate %.3f s (ratio %.2f); resample 120→30 Hz %.3f s (ratio %.2f)\n",
              g_best_import, g_best_same, g_best_same / g_best_import, g_best_30, g_best_30 / g_best_import);
  std::printf("CPU time (all threads), best of 3: assimp import %.3f s; resample same rate %.3f s (ratio %.2f); "
              "120→30 Hz %.3f s (ratio %.2f)\n",
              g_cpu_import, g_cpu_same, g_cpu_same / g_cpu_import, g_cpu_30, g_cpu_30 / g_cpu_import);
  for (const auto& [what, st] : {std::pair{"same rate", g_stages_same}, std::pair{"120→30 Hz", g_stages_30}})
    std::printf("  resample %s, best run: read_clip %.3f s, resample_clip %.3f s, write_clip %.3f s\n", what, st.read,
                st.resample, st.write);
  if (keep.empty()) fs::remove(g_file);
  return 0;
}
