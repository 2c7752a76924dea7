// bench_fbx_curves: reading an FBX file's curves with our own reader (nodes,
// objects, every take, layer and key: read_fbx_curves_file) against assimp 5.2.5
// importing the same file, in the same run and process, best of R each.
//
//   bench_fbx_curves [--repeat R] [PATH...]
//   (default: every FBX file under the shared data that assimp imports; R = 5)
//
// Prints per file and in total: our time, assimp's, and their ratio (the issue's
// budget: at most 1.5). assimp is configured as the reader configures it
// (no skeleton meshes, pivots preserved).
#include "rotinterp/io/fbx/fbx_curves.h"

#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/scene.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

double best_of(int repeat, const std::function<bool()>& run) {
  double best = 1e300;
  for (int r = 0; r < repeat; ++r) {
    const auto t0 = Clock::now();
    if (!run()) return -1.0;
    best = std::min(best, std::chrono::duration<double>(Clock::now() - t0).count());
  }
  return best;
}

bool assimp_import(const std::string& path) {
  Assimp::Importer importer;
  importer.SetPropertyBool(AI_CONFIG_IMPORT_NO_SKELETON_MESHES, true);
  importer.SetPropertyBool(AI_CONFIG_IMPORT_FBX_PRESERVE_PIVOTS, true);
  return importer.ReadFile(path, 0) != nullptr;
}

}  // namespace

int main(int argc, char** argv) {
  int repeat = 5;
  std::vector<std::string> paths;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--repeat" && i + 1 < argc) repeat = std::max(1, std::atoi(argv[++i]));
    else paths.push_back(a);
  }
  if (paths.empty())
    for (const char* dir : {"fbx", "curves"})
      for (const auto& e : fs::directory_iterator(fs::path(ROTINTERP_SHARED_DATA) / dir))
        if (e.path().extension() == ".fbx") paths.push_back(e.path().string());
  std::sort(paths.begin(), paths.end());
  double ours_total = 0.0, assimp_total = 0.0;
  std::printf("%-60s %12s %12s %7s\n", "file", "curves ms", "assimp ms", "ratio");
  for (const std::string& p : paths) {
    const double assimp = best_of(repeat, [&] { return assimp_import(p); });
    if (assimp < 0.0) {
      std::printf("%-60s (assimp refuses it: not counted)\n", fs::path(p).filename().c_str());
      continue;
    }
    const double ours = best_of(repeat, [&] { return rotinterp::read_fbx_curves_file(p, p).ok(); });
    if (ours < 0.0) {
      std::printf("%-60s our reader refuses it\n", fs::path(p).filename().c_str());
      return 1;
    }
    ours_total += ours, assimp_total += assimp;
    std::printf("%-60s %12.3f %12.3f %7.3f\n", fs::path(p).filename().c_str(), 1e3 * ours, 1e3 * assimp, ours / assimp);
  }
  std::printf("%-60s %12.3f %12.3f %7.3f\n", "total", 1e3 * ours_total, 1e3 * assimp_total, ours_total / assimp_total);
  return 0;
}
