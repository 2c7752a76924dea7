// What the fault tests share (test_faults.cpp, test_faults_runs.cpp): snapshots of
// an output directory, the fault seam of io/files/atomic_file.h, and the Faults fixture
// with its synth walk and per-test output directory.
#pragma once

#include "support/processes.h"
#include "support/run_cli.h"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <sys/time.h>
#include <utime.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <thread>
#include <vector>

namespace rotinterp::test {

namespace fs = std::filesystem;

// The output directory's files and their bytes.
inline std::map<std::string, std::string> snapshot(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const std::string& n : names_in(dir)) files[n] = slurp(dir / n);
  return files;
}

// "name (N bytes), …": what a snapshot holds, short enough for a failure message.
inline std::string describe(const std::map<std::string, std::string>& files) {
  std::string out;
  for (const auto& [name, bytes] : files)
    out += (out.empty() ? "" : ", ") + name + " (" + std::to_string(bytes.size()) + " bytes)";
  return out;
}

inline void write_text(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

// Every file in `dir` replaced by a marker naming it: a failed run must leave these.
inline void mark_previous(const fs::path& dir) {
  for (const std::string& n : names_in(dir)) write_text(dir / n, "previous " + n + "\n");
}

inline bool render_built() { return run_cli("render --help").exit_code == 0; }

inline int lines(const std::string& text) { return static_cast<int>(std::count(text.begin(), text.end(), '\n')); }

// Runs the CLI with the checked-operation fault seam of io/files/atomic_file.h set.
inline CliResult run_with_fault(const std::string& args, long at) {
  ::setenv("ROTINTERP_TEST_FAULT_AT", std::to_string(at).c_str(), 1);
  auto r = run_cli(args);
  ::unsetenv("ROTINTERP_TEST_FAULT_AT");
  return r;
}

class Faults : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    in_ = fs::temp_directory_path() / ("rotinterp_faults_in_" + std::to_string(::getpid()));
    fs::remove_all(in_);
    fs::create_directories(in_);
    // 2 s of a 31-joint walk at 120 Hz: a 110 kB BVH, several writes per output.
    const auto r = run_cli("synth " + clip().string() + " --kind walk --seconds 2 --fps 120 -q");
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  static void TearDownTestSuite() { fs::remove_all(in_); }
  static fs::path clip() { return in_ / "walk.bvh"; }

  void SetUp() override {
    out_ = fs::temp_directory_path() / ("rotinterp_faults_out_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(out_);
    fs::create_directories(out_);
  }
  void TearDown() override { fs::remove_all(out_); }

  // Runs `args` (writing into `dir`) once to get its outputs, marks them, then
  // makes the 1st, 2nd, … checked operation fail until a run gets through: each
  // failing run must exit 1 with one line and leave the marked files as they were
  // (`unit`; else, as render does, each file either marked or replaced whole) and
  // nothing else. Returns how many fault points the writer has.
  static int fail_everywhere(const std::string& args, const fs::path& dir, bool unit = true) {
    const auto good = run_cli(args);
    EXPECT_EQ(good.exit_code, 0) << args << "\n" << good.err;
    mark_previous(dir);
    const auto previous = snapshot(dir);
    EXPECT_FALSE(previous.empty()) << args;
    for (long at = 1; at < 400; ++at) {
      const auto r = run_with_fault(args, at);
      if (r.exit_code == 0) return static_cast<int>(at - 1);
      EXPECT_EQ(r.exit_code, 1) << args << " fault at " << at << "\n" << r.err;
      EXPECT_EQ(lines(r.err), 1) << args << " fault at " << at << "\n" << r.err;
      EXPECT_NE(r.err.find("No space left on device"), std::string::npos) << args << " fault at " << at << "\n" << r.err;
      const auto now = snapshot(dir);
      if (unit) {
        EXPECT_TRUE(now == previous) << args << " fault at " << at << ": the previous output changed: " << describe(now);
      } else {
        EXPECT_EQ(names_in(dir).size(), previous.size()) << args << " fault at " << at << ": files left";
        for (const auto& [name, bytes] : now)
          EXPECT_TRUE(bytes == previous.at(name) || bytes.compare(0, 4, "\x89PNG") == 0) << name;
      }
      for (const auto& [name, bytes] : now) EXPECT_EQ(previous.count(name), 1u) << args << " left " << name;
    }
    ADD_FAILURE() << args << ": never got through";
    return 0;
  }

  inline static fs::path in_;
  fs::path out_;
};

}  // namespace rotinterp::test
