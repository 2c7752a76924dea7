// A clip larger than the address-space limit (ulimit -v in a child shell): resample,
// reduce and eval end with one line naming the clip, exit 1, and write nothing.
#include "support/run_cli.h"

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace rotinterp {
namespace {

namespace fs = std::filesystem;
using test::run_cli;
using test::slurp;

TEST(MemoryLimit, ClipTooLargeForTheLimitIsOneLineExit1AndNothingWritten) {
#ifdef ROTINTERP_SANITIZED
  GTEST_SKIP() << "a sanitizer build cannot run under an address-space limit (shadow memory)";
#endif
  const fs::path dir = fs::temp_directory_path() / ("rotinterp_memory_limit_" + std::to_string(::getpid()));
  const fs::path out = dir / "out";
  fs::create_directories(out);
  // 120 000 frames, 31 joints (108 MB of BVH, ≈ 150 MB decoded): more than fits in
  // 150 MB of address space next to the program and its libraries, for every command.
  // (Half of it fitted once resample stopped copying the clip it had read.)
  const std::string clip = (dir / "long.bvh").string();
  ASSERT_EQ(run_cli("synth " + clip + " --kind walk --seconds 1000 --fps 120 -q").exit_code, 0);
  const std::vector<std::string> commands = {"resample " + clip + " -o " + (out / "x.bvh").string() + " -q",
                                             "reduce " + clip + " -o " + (out / "x.glb").string() + " -q",
                                             "eval -q -m slerp,c2 " + clip + " -o " + (out / "report").string()};
  for (const std::string& args : commands) {
    const std::string cmd = "ulimit -v 150000; exec " + std::string(ROTINTERP_CLI) + " " + args + " 2>" +
                            (dir / "err").string();
    const int status = std::system(cmd.c_str());
    ASSERT_TRUE(WIFEXITED(status)) << args << ": killed by signal " << WTERMSIG(status);
    const std::string err = slurp(dir / "err");
    EXPECT_EQ(WEXITSTATUS(status), 1) << args << "\n" << err;
    // One line naming the clip ("out of memory", or "… while reading" where the reading ran out).
    EXPECT_EQ(err.rfind("rotinterp: " + clip + ": out of memory", 0), 0u) << args << "\n" << err;
    EXPECT_EQ(err.find('\n'), err.size() - 1) << args << "\n" << err;
    for (const auto& f : fs::recursive_directory_iterator(out))
      EXPECT_FALSE(f.is_regular_file()) << args << " wrote " << f.path();
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rotinterp
