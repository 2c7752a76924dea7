// The eval CLI tests' scratch: fresh directories, a folder of links to real clips,
// and text split into lines.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace rotinterp::test {

// A fresh directory under the test temp dir.
inline std::filesystem::path fresh_dir(const std::string& name) {
  const std::filesystem::path d = std::filesystem::path(testing::TempDir()) / ("rotinterp_eval_" + name);
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

// A directory of symlinks to a few short real clips (never copies of them).
inline std::filesystem::path clip_dir(const std::string& name, bool with_bad_file) {
  const std::filesystem::path d = fresh_dir(name);
  const std::filesystem::path data = ROTINTERP_SHARED_DATA;
  std::filesystem::create_directories(d / "sub");
  std::filesystem::create_symlink(data / "bvh/NC_bandai1_walk_normal_001.bvh", d / "walk.bvh");
  std::filesystem::create_symlink(data / "bvh/NC_bandai2_raise-up-both-hands_active_031.bvh", d / "sub/raise.bvh");
  std::filesystem::create_symlink(data / "bvh/bvhio_example.bvh", d / "sub/two_frames.bvh");
  std::filesystem::create_symlink(data / "fbx/ufbx_maya_game_sausage_7500_binary_wiggle.fbx", d / "sausage.fbx");
  std::ofstream(d / "notes.txt") << "not a clip, not an assimp extension\n";
  // A mesh without animation next to the clips: skipped quietly, not a failure.
  std::ofstream(d / "sub/triangle.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  if (with_bad_file) std::ofstream(d / "sub/broken.bvh") << "HIERARCHY\nROOT Hips\n{\n  OFFSET 0 0\n";
  return d;
}

inline std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream ss(text);
  std::string line;
  while (std::getline(ss, line)) out.push_back(line);
  return out;
}

}  // namespace rotinterp::test
