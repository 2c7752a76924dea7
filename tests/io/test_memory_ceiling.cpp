// Issue 47's ceiling: every hostile input, through the CLI under an address-space
// limit of 1 GiB (`prlimit --as`, inherited by the importer process), ends in one
// line naming the file and exit 1 — not a signal, an abort or a core — within 10 s.
#include "hostile_inputs.h"
#include "io_test_util.h"
#include "support/run_cli.h"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdlib>
#include <string>
#include <vector>

namespace rotinterp {
namespace {

namespace fs = std::filesystem;
using test::kData;

struct Outcome {
  bool exited = false;
  int code = -1;
  std::string err;
  double seconds = 0.0;
};

// `rotinterp ARGS` under a 1 GiB address-space limit, stdout dropped.
Outcome run_capped(const fs::path& dir, const std::string& args) {
  const fs::path err = dir / "stderr.txt";
  const std::string cmd = "prlimit --as=1073741824 --core=0 " + std::string(ROTINTERP_CLI) + " " + args +
                          " >/dev/null 2>" + err.string() + " </dev/null";
  const auto start = std::chrono::steady_clock::now();
  const int status = std::system(cmd.c_str());
  Outcome o;
  o.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  o.exited = WIFEXITED(status);
  o.code = o.exited ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  o.err = test::slurp(err);
  return o;
}

TEST(MemoryCeiling, EveryHostileInputIsOneLineAndExit1UnderOneGiB) {
#ifdef ROTINTERP_SANITIZED
  GTEST_SKIP() << "a sanitizer build cannot run under an address-space limit (shadow memory)";
#endif
  test::TempDir dir;
  const fs::path d = dir.path();
  const std::string bomb = test::zlib_zeros(std::size_t{1} << 30);  // 1 GiB of zeros in ~1 MB
  std::vector<fs::path> files;
  for (const char* source : {"fbx/ufbx_maya_game_sausage_7500_binary_wiggle.fbx",
                             "fbx/ufbx_maya_game_sausage_6100_binary_wiggle.fbx"}) {
    files.push_back(d / (fs::path(source).stem().string() + "_bomb.fbx"));
    test::write_text(files.back(), test::fbx_with_zlib_array(kData / source, std::uint32_t{1} << 28, bomb));
  }
  files.push_back(d / "count.fbx");
  test::write_text(files.back(), test::fbx_with_key_count(0xfffffff0u));
  files.push_back(d / "nan.fbx");
  test::write_text(files.back(), test::fbx_ascii_with("KeyValueFloat", [](auto& v) { v[1] = "nan"; }));
  files.push_back(d / "reversed.fbx");
  test::write_text(files.back(), test::fbx_ascii_with("KeyTime", [](auto& t) { std::swap(t[1], t[2]); }));
  files.push_back(test::glb_with_json_length(d, 0x7ffffff0u));
  files.push_back(test::sparse_file(d / "sparse.bvh", "HIERARCHY\ngarbage\n", std::uintmax_t{3} << 30));
  const test::GltfFile gltf = test::shared_gltf(d);
  ASSERT_EQ(::mkfifo((d / "fifo.bin").c_str(), 0600), 0);
  files.push_back(gltf.write(d, "fifo.gltf", "fifo.bin"));
  fs::create_directories(d / "sub");
  gltf.write(d, "beside.gltf");
  files.push_back(gltf.write(d / "sub", "up.gltf", "../beside.gltf.bin"));

  for (const fs::path& file : files)
    for (const std::string& command : {std::string("info"), std::string("info --curves"), "resample -o " + (d / "out.bvh").string()}) {
      const std::string args = command + " " + file.string();
      const Outcome o = run_capped(d, args);
      EXPECT_TRUE(o.exited) << args << ": killed by signal " << o.code - 128;
      if (command == "info --curves" && file.extension() != ".fbx") continue;  // "FBX files only", exit 1 or 2
      EXPECT_EQ(o.code, 1) << args << "\n" << o.err;
      EXPECT_EQ(o.err.rfind("rotinterp: " + file.string() + ": ", 0), 0u) << args << "\n" << o.err;
      EXPECT_EQ(o.err.find('\n'), o.err.size() - 1) << args << "\n" << o.err;
      EXPECT_LT(o.seconds, 10.0) << args;
      EXPECT_FALSE(fs::exists(d / "out.bvh")) << args;
    }
  const std::string fbx = (kData / "fbx/ufbx_maya_game_sausage_7500_binary_wiggle.fbx").string();
  const Outcome sample = run_capped(d, "info --curves --sample 1e9 " + fbx);
  EXPECT_EQ(sample.code, 1) << sample.err;
  EXPECT_NE(sample.err.find("--sample"), std::string::npos) << sample.err;
  EXPECT_LT(sample.seconds, 10.0);
}

}  // namespace
}  // namespace rotinterp
