// Blender (Debian's 3.4, headless) opens the sparse GLBs `rotinterp reduce` writes —
// each channel at its own key times — as ONE armature with the clip's bones, and,
// like every client test, is compared with nothing fitted: every bone head at every
// key it shows, at true size, against Blender's own import of the source BVH at
// scale 0.01 (the Bandai walk is in centimetres).
// LINEAR samplers (slerp, linear translations): within the reduction's 2 mm budget,
// give or take Blender blending quaternion components linearly where the spec says
// slerp (5 %).
// CUBICSPLINE (gltf-cubic, cubic translations): Blender 3.4's importer does NOT replay
// it as the spec does — measured 2.5 cm off at Toes_L with a 2 mm budget, 1.1 cm
// with CUBICSPLINE rotations alone, 3.8 mm with CUBICSPLINE translations alone —
// while the spec's own formula on the same file's bytes stays within the budget
// (tests/reduce, GltfReplayedWithTheSpecsInterpolationStaysWithinBudget) and assimp
// reads the same keys (its importer was noted to ignore the file's tangents,
// KhronosGroup/glTF-Blender-IO#419). Only the armature is checked for it here; the
// distance is printed.
#include "client_fixture.h"
#include "support/run_cli.h"

#include <gtest/gtest.h>

#include <cstdio>

namespace rotinterp::test {
namespace {

TEST(BlenderReduce, SparseGlbIsOneArmatureWithinTheBudgetOfBlendersImportOfTheSourceAtEveryKey) {
  const TempDir dir;
  const std::string source = (kData / "bvh/NC_bandai1_walk_normal_001.bvh").string();
  const double budget = 0.002;  // m: --tolerance-mm 2 at the default shell distance
  const std::vector<std::pair<std::string, std::string>> files = {
      {"linear.glb", "--method slerp --translation linear"}, {"cubic.glb", "--method gltf-cubic"}};
  std::vector<std::string> paths;
  for (const auto& [name, args] : files) {
    const auto r = run_cli("reduce " + source + " -o " + (dir / name).string() + " " + args + " --tolerance 1deg,2mm -q");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    paths.push_back((dir / name).string());
  }
  paths.push_back(source);  // at global_scale 0.01
  const std::vector<BlenderImport> imports = blender_imports(paths, dir.path());
  const BlenderImport& truth = imports.back();
  ASSERT_EQ(truth.armatures, 1);
  for (std::size_t i = 0; i < files.size(); ++i) {
    const std::string& name = files[i].first;
    const BlenderImport& ours = imports[i];
    ASSERT_EQ(ours.armatures, 1) << name;
    EXPECT_EQ(ours.bones.size(), truth.bones.size()) << name;
    // The union of the channels' key times is every frame here (the root's translation keeps them all).
    EXPECT_EQ(ours.times.size(), truth.times.size()) << name;
    const Deviation d = worst_deviation(ours, truth);
    EXPECT_EQ(d.problem, "") << name;
    std::printf("[ blender ] reduced %s: worst %.4g mm (budget %.3g mm) at %s, %.4g s\n", name.c_str(), d.distance * 1000,
                budget * 1000, d.joint.c_str(), d.time);
    if (name == "linear.glb") {
      EXPECT_LE(d.distance, 1.05 * budget) << name << " at " << d.joint << ", " << d.time << " s";
    }
  }
}

// The sparse FBX `reduce -o .fbx` writes: Blender 3.4's importer reads every FBX
// key as LINEAR (import_fbx.py: each curve sampled linearly at the union of all
// curves' key times — per bone, its own — the Euler angles turned into quaternion
// keys there, every key LINEAR, so between a bone's keys Blender lerps quaternion
// components). slerp's and nlerp's files (linear Euler keys, linear translations)
// stay within the budget at every key Blender shows, give or take that lerp (5 %);
// the cubic methods' tangents (and cubic translations') are dropped there, and how
// far that moves the figure is printed (docs/reduce.md has the numbers).
TEST(BlenderReduce, SparseFbxOfSlerpIsWithinTheBudgetInBlenderAndTheCubicMethodsDifferByWhatIsPrinted) {
  const TempDir dir;
  const std::string source = (kData / "bvh/NC_bandai1_walk_normal_001.bvh").string();
  const double budget = 0.002;  // m
  // squad-linear: squad's rotations with linear translations, to tell the two apart.
  const std::vector<std::string> methods = {"slerp", "nlerp", "squad", "c2", "gltf-cubic", "squad-linear"};
  std::vector<std::string> paths;
  for (const std::string& name : methods) {
    const std::string m = name == "squad-linear" ? "squad" : name;
    const std::string out = (dir / (name + ".fbx")).string();
    const std::string translation = m == "slerp" || m == "nlerp" || name == "squad-linear" ? " --translation linear" : "";
    const auto r = run_cli("reduce " + source + " -o " + out + " --method " + m + translation + " --tolerance 1deg,2mm -q");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    paths.push_back(out);
  }
  // The same clip with a key at every frame, for scale.
  ASSERT_EQ(run_cli("resample " + source + " -o " + (dir / "frames.fbx").string() + " -q").exit_code, 0);
  paths.push_back((dir / "frames.fbx").string());
  paths.push_back(source);
  const std::vector<BlenderImport> imports = blender_imports(paths, dir.path());
  const BlenderImport& truth = imports.back();
  const Deviation frames = worst_deviation(imports[methods.size()], truth);
  std::printf("[ blender ] every frame keyed (resample -o .fbx): worst %.4g mm at %s, %.4g s\n", frames.distance * 1000,
              frames.joint.c_str(), frames.time);
  for (std::size_t i = 0; i < methods.size(); ++i) {
    const BlenderImport& ours = imports[i];
    ASSERT_EQ(ours.armatures, 1) << methods[i];
    const Deviation d = worst_deviation(ours, truth);
    EXPECT_EQ(d.problem, "") << methods[i];
    std::printf("[ blender ] reduced %s.fbx: %zu keys shown, worst %.4g mm (budget %.3g mm) at %s, %.4g s\n",
                methods[i].c_str(), ours.times.size(), d.distance * 1000, budget * 1000, d.joint.c_str(), d.time);
    if (methods[i] == "slerp" || methods[i] == "nlerp") {
      EXPECT_LE(d.distance, 1.05 * budget) << methods[i] << " at " << d.joint << ", " << d.time << " s";
    }
  }
}

}  // namespace
}  // namespace rotinterp::test
