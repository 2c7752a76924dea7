// A PNG that cannot be encoded for lack of memory says so (not "PNG encoding
// failed", which reads as a bug), and leaves no file.
#include "rotinterp/render/image.h"

#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace rotinterp::render {
namespace {

namespace fs = std::filesystem;

// The address space in use now, from /proc/self/statm (pages).
std::size_t address_space_bytes() {
  std::ifstream f("/proc/self/statm");
  std::size_t pages = 0;
  f >> pages;
  return pages * static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
}

TEST(PngMemory, AnImageTooLargeForTheMemoryLeftIsAnOutOfMemoryError) {
#ifdef ROTINTERP_SANITIZED
  GTEST_SKIP() << "a sanitizer build cannot run under an address-space limit (shadow memory)";
#endif
  const fs::path dir = fs::temp_directory_path() / ("rotinterp_png_memory_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path out = dir / "big.png";
  const fs::path msg = dir / "message";
  // In a child: the limit must not reach the test runner. The 8192×8192 image
  // (192 MiB) exists; the encoder's buffers (as large again) do not fit in 64 MiB more.
  const pid_t pid = ::fork();
  if (pid == 0) {
    Image image(8192, 8192);
    for (std::size_t i = 0; i < image.rgb.size(); i += 4099) image.rgb[i] = static_cast<std::uint8_t>(i);
    const rlim_t limit = address_space_bytes() + (rlim_t{64} << 20);
    const struct rlimit rl{limit, limit};
    ::setrlimit(RLIMIT_AS, &rl);
    const Status s = write_png(image, out);
    std::ofstream(msg) << (s ? std::string("ok") : s.error());
    ::_exit(0);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status)) << "signal " << WTERMSIG(status);
  std::ifstream f(msg);
  const std::string message((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  EXPECT_EQ(message, out.string() + ": out of memory encoding the 8192x8192 PNG");
  EXPECT_FALSE(fs::exists(out));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rotinterp::render
