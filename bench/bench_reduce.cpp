// bench_reduce: `rotinterp reduce` on real clips — keys kept by every method against
// a per-track Ramer–Douglas–Peucker baseline (ozz-animation's optimizer), every
// frame checked, and the time against assimp importing the same files.
//
//   bench_reduce [--repeat R] [--tolerance-mm MM] [--shell-cm CM] [PATH...]
//   (default: every clip under the shared data that loads; 1 mm at 10 cm, ozz's default)
//
// Quality: for each method, the keys kept over all clips (rotation + translation
// keys, % of frames × tracks), the largest shell error and the joint-frames over the
// budget — measured here, not by the selection: each clip is rebuilt from the kept
// keys (the method through the result's rotation keys, TranslationCurve), posed by
// forward_kinematics and compared by accumulate_pose_error (clip/metrics.h),
// ancestors rebuilt too. Translations are linear in every row, as the baseline's.
// The baseline is ozz's AnimationOptimizer as published: each track decimated on its
// own by RDP (keep the worst frame of a span while it is over the tolerance, recurse),
// rotations rebuilt by slerp and measured as the displacement of a point at the
// joint's hierarchical length (the shell distance, plus the longest chain of child
// offsets below it: 2·sin(θ/2)·length), translations by lerp, |Δ| — with the same
// budget; measured the same way. Units: BVH as centimetres (as the CLI), others by
// their unit scale.
// Speed: read_clip + reduce_clip (slerp) over all files against assimp's import of
// the same files, wall and CPU (all threads), best of R; read_clip alone (the floor);
// and every method's CPU time.
#include "rotinterp/clip/frames.h"
#include "rotinterp/clip/metrics.h"
#include "rotinterp/clip/translation_curve.h"
#include "rotinterp/interp/interpolator.h"
#include "rotinterp/interp/slerp.h"
#include "rotinterp/io/read.h"
#include "rotinterp/reduce/reduce.h"

#include "cpu_seconds.h"

#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/scene.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace rotinterp;
using Clock = std::chrono::steady_clock;

namespace {

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

struct Input {
  std::string path;
  Clip clip;
  double unit = 1.0;  // metres per clip unit
};

// The kept keys of every track of a clip: rotation keys (times and values); the
// kept frames of each translation track (values: the source's).
struct Kept {
  std::vector<RotationTrack> rotation;
  std::vector<std::vector<std::size_t>> translation;
};

// RDP on frames [a, b] of one track: `error(f, a, b)` is the error at f of the span's
// straight rebuild (slerp / lerp between the frames a and b).
template <class Error>
void rdp(std::size_t a, std::size_t b, double tol, const Error& error, std::vector<std::size_t>& keep) {
  if (b <= a + 1) return;
  std::size_t worst = 0;
  double w = tol;
  for (std::size_t f = a + 1; f < b; ++f)
    if (const double e = error(f, a, b); e > w) w = e, worst = f;
  if (!worst) return;
  keep.push_back(worst);
  rdp(a, worst, tol, error, keep);
  rdp(worst, b, tol, error, keep);
}

Kept ozz_baseline(const Clip& clip, const DenseClip& d, double tol, double shell) {
  const Skeleton& sk = clip.skeleton;
  const std::size_t n = sk.joints.size(), frames = d.grid.size();
  // Hierarchical length: the shell distance at the joint, or a child's length plus the
  // child's largest translation, whichever is longer (ozz's HierarchyBuilder).
  std::vector<double> length(n, shell);
  for (std::size_t j = n; j-- > 0;) {
    const int p = sk.joints[j].parent;
    if (p < 0) continue;
    double reach = 0.0;
    for (const Vec3& t : d.translation[j]) reach = std::max(reach, t.norm());
    length[static_cast<std::size_t>(p)] = std::max(length[static_cast<std::size_t>(p)], length[j] + reach);
  }
  Kept k;
  for (std::size_t j = 0; j < n; ++j) {
    const auto& q = d.rotation[j];
    std::vector<std::size_t> keep = {0, frames - 1};
    const std::vector<double>& t = d.grid.times;
    rdp(0, frames - 1, tol, [&](std::size_t f, std::size_t a, std::size_t b) {
      const Quat r = slerp(q[a], q[b], (t[f] - t[a]) / (t[b] - t[a]));
      return 2.0 * std::sin(0.5 * angular_distance(q[f], r)) * length[j];
    }, keep);
    std::sort(keep.begin(), keep.end());
    k.rotation.push_back(decimated_track(t, q, keep));
    keep = {0, frames - 1};
    if (clip.translations[j]) {
      const auto& p = d.translation[j];
      rdp(0, frames - 1, tol, [&](std::size_t f, std::size_t a, std::size_t b) {
        const double u = (t[f] - t[a]) / (t[b] - t[a]);
        return (p[f] - ((1 - u) * p[a] + u * p[b])).norm();
      }, keep);
      std::sort(keep.begin(), keep.end());
    } else {
      keep.clear();
    }
    k.translation.push_back(keep);
  }
  return k;
}

struct Quality {
  std::size_t kept = 0, source = 0, over = 0, joint_frames = 0;
  double max_shell = 0.0;  // metres
};

// Rebuilds from `kept` and measures every frame with the eval metrics.
void measure(const Input& in, const DenseClip& d, const Kept& kept, const std::string& method, TranslationInterp tr,
             double tol, double shell, Quality& q) {
  const Clip& clip = in.clip;
  const std::size_t n = clip.skeleton.joints.size(), frames = d.grid.size();
  const std::vector<double>& times = d.grid.times;
  std::vector<std::vector<Quat>> rot(n);
  std::vector<std::vector<Vec3>> pos(n);
  for (std::size_t j = 0; j < n; ++j) {
    rot[j].resize(frames);
    (*make_interpolator(method, kept.rotation[j]))->evaluate(times.data(), frames, rot[j].data());
    q.kept += kept.rotation[j].keys.size();
    q.source += frames;
    if (clip.translations[j]) {
      TranslationTrack t;
      for (std::size_t f : kept.translation[j]) t.times.push_back(times[f]), t.keys.push_back(d.translation[j][f]);
      const TranslationCurve c(t, tr);
      for (double time : times) pos[j].push_back(c.evaluate(time));
      q.kept += kept.translation[j].size();
      q.source += frames;
    } else {
      pos[j] = d.translation[j];
    }
  }
  std::vector<Quat> qr(n), qt(n);
  std::vector<Vec3> tr_ref(n), tr_test(n);
  WorldPose wr, wt;
  for (std::size_t f = 0; f < frames; ++f) {
    for (std::size_t j = 0; j < n; ++j) {
      qr[j] = d.rotation[j][f], tr_ref[j] = d.translation[j][f];
      qt[j] = rot[j][f], tr_test[j] = pos[j][f];
    }
    forward_kinematics(clip.skeleton, qr, tr_ref, wr);
    forward_kinematics(clip.skeleton, qt, tr_test, wt);
    PoseError acc = make_pose_error(clip.skeleton);
    accumulate_pose_error(wr, wt, shell, acc);
    for (const RunningError& e : acc.joint_shell) {
      q.max_shell = std::max(q.max_shell, e.max * in.unit);
      q.over += e.max > tol * (1 + 1e-9);
      ++q.joint_frames;
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  int repeat = 3;
  double mm = 1.0, cm = 10.0;
  std::vector<fs::path> roots;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--repeat" && i + 1 < argc) repeat = std::max(1, std::atoi(argv[++i]));
    else if (a == "--tolerance-mm" && i + 1 < argc) mm = std::atof(argv[++i]);
    else if (a == "--shell-cm" && i + 1 < argc) cm = std::atof(argv[++i]);
    else roots.emplace_back(a);
  }
  if (roots.empty()) roots = {fs::path(ROTINTERP_SHARED_DATA) / "bvh", fs::path(ROTINTERP_SHARED_DATA) / "fbx"};
  std::vector<std::string> files;
  for (const fs::path& r : roots) {
    if (fs::is_regular_file(r)) files.push_back(r.string());
    else if (fs::is_directory(r))
      for (const auto& e : fs::directory_iterator(r))
        if (e.is_regular_file()) files.push_back(e.path().string());
  }
  std::sort(files.begin(), files.end());
  std::vector<Input> inputs;
  std::vector<std::string> loaded;
  std::size_t frames = 0;
  for (const std::string& f : files) {
    auto c = read_clip(f);
    if (!c || c->frame_count() < 3) {
      std::fprintf(stderr, "skipped %s: %s\n", f.c_str(), c ? "fewer than 3 frames" : c.error().c_str());
      continue;
    }
    Input in{f, std::move(*c), 1.0};
    in.unit = in.clip.unit.metres_per_unit;
    frames += in.clip.frame_count();
    loaded.push_back(f);
    inputs.push_back(std::move(in));
  }
  auto options_for = [&](const Input& in, const std::string& method) {
    ReduceOptions o;
    o.method = method;
    o.translation = TranslationInterp::linear;  // the baseline's lerp: rows differ by rotation method and selection
    o.budget.shell = o.budget.translation = mm / 1000.0 / in.unit;
    o.shell_distance = cm / 100.0 / in.unit;
    return o;
  };

  // Speed: assimp's import vs read_clip + reduce (slerp), same files, best of R.
  double import_wall = 1e300, import_cpu = 1e300, reduce_wall = 1e300, reduce_cpu = 1e300, read_cpu = 1e300;
  for (int r = 0; r < repeat; ++r) {
    auto t0 = Clock::now();
    double c0 = cpu_seconds();
    for (const std::string& f : loaded) {
      Assimp::Importer importer;
      importer.SetPropertyBool(AI_CONFIG_IMPORT_NO_SKELETON_MESHES, true);
      (void)importer.ReadFile(f, 0);
    }
    import_wall = std::min(import_wall, seconds_since(t0));
    import_cpu = std::min(import_cpu, cpu_seconds() - c0);
    c0 = cpu_seconds();
    for (const Input& in : inputs) (void)read_clip(in.path);
    read_cpu = std::min(read_cpu, cpu_seconds() - c0);
    t0 = Clock::now();
    c0 = cpu_seconds();
    for (const Input& in : inputs) {
      auto clip = read_clip(in.path);
      auto red = reduce_clip(*clip, options_for(in, "slerp"));
      if (!red) std::fprintf(stderr, "%s: %s\n", in.path.c_str(), red.error().c_str());
    }
    reduce_wall = std::min(reduce_wall, seconds_since(t0));
    reduce_cpu = std::min(reduce_cpu, cpu_seconds() - c0);
  }
  std::printf("%zu clips, %zu frames; budget %g mm at %g cm; best of %d\n", inputs.size(), frames, mm, cm, repeat);
  std::printf("assimp import            %7.3f s wall %7.3f s CPU\n", import_wall, import_cpu);
  std::printf("read_clip + reduce slerp %7.3f s wall %7.3f s CPU   ratio %.2f wall, %.2f CPU (goal <= 3)\n", reduce_wall,
              reduce_cpu, reduce_wall / import_wall, reduce_cpu / import_cpu);
  std::printf("read_clip alone                    %7.3f s CPU   ratio %.2f CPU (the floor under the goal)\n", read_cpu,
              read_cpu / import_cpu);

  // Quality, and each method's time (CPU, reduce_clip alone, one run).
  std::vector<DenseClip> dense;
  for (const Input& in : inputs) dense.push_back(exact_dense_clip(in.clip));  // at the frames' times, as reduce keys them
  Quality base;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const Input& in = inputs[i];
    const double tol = mm / 1000.0 / in.unit, shell = cm / 100.0 / in.unit;
    measure(in, dense[i], ozz_baseline(in.clip, dense[i], tol, shell), "slerp", TranslationInterp::linear, tol, shell, base);
  }
  auto pct = [](const Quality& q) { return 100.0 * double(q.kept) / double(std::max<std::size_t>(1, q.source)); };
  // The baseline with its tolerance scaled down until every frame is inside the budget.
  Quality strict;
  double scale = 1.0;
  for (double s : {0.7, 0.5, 0.35, 0.25, 0.18, 0.125}) {
    strict = Quality{};
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      const Input& in = inputs[i];
      const double tol = mm / 1000.0 / in.unit, shell = cm / 100.0 / in.unit;
      measure(in, dense[i], ozz_baseline(in.clip, dense[i], s * tol, shell), "slerp", TranslationInterp::linear, tol, shell, strict);
    }
    scale = s;
    if (strict.over == 0) break;
  }
  std::printf("\n| method | keys kept | %% of source | vs RDP baseline | largest shell error (mm) | joint-frames over budget | CPU s | CPU / import |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  std::printf("| RDP per track (ozz), slerp/lerp | %zu | %.2f | 1.000 | %.4f | %zu of %zu | | |\n", base.kept, pct(base),
              base.max_shell * 1000.0, base.over, base.joint_frames);
  std::printf("| RDP per track, tolerance x %.3g | %zu | %.2f | %.3f | %.4f | %zu | | |\n", scale, strict.kept, pct(strict),
              double(strict.kept) / double(base.kept), strict.max_shell * 1000.0, strict.over);
  for (const MethodInfo& m : methods()) {
    Quality q;
    double cpu = 0.0;
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      const Input& in = inputs[i];
      const double c0 = cpu_seconds();
      auto red = reduce_clip(in.clip, options_for(in, m.name));
      cpu += cpu_seconds() - c0;
      if (!red) {
        std::fprintf(stderr, "%s %s: %s\n", in.path.c_str(), m.name.c_str(), red.error().c_str());
        continue;
      }
      Kept k;
      k.rotation = red->reduced.rotations;
      for (const ReducedJoint& j : red->joints) k.translation.push_back(j.translation_frames);
      const double tol = mm / 1000.0 / in.unit, shell = cm / 100.0 / in.unit;
      measure(in, dense[i], k, m.name, TranslationInterp::linear, tol, shell, q);
    }
    std::printf("| %s | %zu | %.2f | %.3f | %.4f | %zu | %.3f | %.2f |\n", m.name.c_str(), q.kept, pct(q),
                double(q.kept) / double(base.kept), q.max_shell * 1000.0, q.over, cpu, cpu / import_cpu);
  }
  return 0;
}
