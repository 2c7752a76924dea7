// What the importer tests share: a stand-in importer, and the processes this one runs.
#pragma once

#include "io_test_util.h"

#include <sys/stat.h>
#include <sys/types.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace rotinterp::test {

// An executable shell script standing in for the importer (ROTINTERP_IMPORTER).
class FakeImporter {
 public:
  FakeImporter(const TempDir& dir, const std::string& body) : path_(dir / "fake-importer") {
    write_text(path_, "#!/bin/sh\n" + body + "\n");
    ::chmod(path_.c_str(), 0755);
    ::setenv("ROTINTERP_IMPORTER", path_.c_str(), 1);
  }
  ~FakeImporter() { ::unsetenv("ROTINTERP_IMPORTER"); }

 private:
  std::filesystem::path path_;
};

// The process ids whose parent is `parent` and whose name starts with `name`.
inline std::vector<pid_t> children_named(pid_t parent, const std::string& name) {
  std::vector<pid_t> out;
  for (const auto& e : std::filesystem::directory_iterator("/proc")) {
    const std::string pid = e.path().filename().string();
    if (pid.find_first_not_of("0123456789") != std::string::npos) continue;
    std::ifstream stat(e.path() / "stat");
    std::string line;
    std::getline(stat, line);
    const auto close = line.rfind(')');
    if (close == std::string::npos || line.find('(') == std::string::npos) continue;
    const std::string comm = line.substr(line.find('(') + 1, close - line.find('(') - 1);
    char state = 0;
    int ppid = 0;
    if (std::sscanf(line.c_str() + close + 1, " %c %d", &state, &ppid) == 2 && ppid == parent && state != 'Z' &&
        comm.rfind(name, 0) == 0)
      out.push_back(static_cast<pid_t>(std::stol(pid)));
  }
  return out;
}

inline bool alive(pid_t pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(stat, line)) return false;
  const auto close = line.rfind(')');
  return close != std::string::npos && close + 2 < line.size() && line[close + 2] != 'Z';
}

// A BVH of one joint and a million frames: assimp takes seconds over it (read it
// with cross_check_with_assimp to have the importer do so).
inline void write_long_bvh(const std::filesystem::path& path) {
  std::ofstream f(path);
  f << "HIERARCHY\nROOT Hips\n{\nOFFSET 0 0 0\nCHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"
    << "End Site\n{\nOFFSET 0 1 0\n}\n}\nMOTION\nFrames: 1000000\nFrame Time: 0.01\n";
  for (int k = 0; k < 1000000; ++k) f << "0.5 1.5 2.5 " << k % 360 << " 10.25 20.5\n";
}

}  // namespace rotinterp::test
