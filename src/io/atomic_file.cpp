#include "rotinterp/io/atomic_file.h"

#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <mutex>
#include <random>
#include <string>

namespace rotinterp {

namespace {

// Live temporary paths, kept as fixed C strings so the signal handler can unlink
// them without allocating.
constexpr int kMaxLive = 256;
constexpr int kMaxPath = 4096;
char g_live[kMaxLive][kMaxPath];
std::atomic<bool> g_used[kMaxLive];
std::mutex g_mutex;

int register_live(const std::string& path) {
  if (path.size() >= kMaxPath) return -1;
  std::lock_guard<std::mutex> lock(g_mutex);
  for (int i = 0; i < kMaxLive; ++i) {
    if (!g_used[i].load()) {
      std::memcpy(g_live[i], path.c_str(), path.size() + 1);
      g_used[i].store(true);
      return i;
    }
  }
  return -1;
}

void unregister_live(int slot) {
  if (slot >= 0) g_used[slot].store(false);
}

extern "C" void remove_live_and_exit(int sig) {
  for (int i = 0; i < kMaxLive; ++i)
    if (g_used[i].load()) ::unlink(g_live[i]);
  _exit(128 + sig);
}

std::filesystem::path make_temp_name(const std::filesystem::path& target) {
  static std::atomic<unsigned> counter{0};
  std::random_device rd;
  const std::string suffix = ".tmp" + std::to_string(::getpid()) + "." + std::to_string(counter++) + "." +
                             std::to_string(rd() % 100000);
  // Keep the extension last: some writers (assimp, PLplot) pick formats by it.
  std::filesystem::path p = target;
  const std::string ext = target.extension().string();
  p.replace_filename("." + target.stem().string() + suffix + ext);
  return p;
}

}  // namespace

AtomicOutput::AtomicOutput(std::filesystem::path target) : target_(std::move(target)), temp_(make_temp_name(target_)) {
  slot_ = register_live(temp_.string());
}

AtomicOutput::~AtomicOutput() {
  if (!committed_) {
    std::error_code ec;
    std::filesystem::remove(temp_, ec);
  }
  unregister_live(slot_);
}

Status AtomicOutput::commit() {
  std::error_code ec;
  if (!std::filesystem::exists(temp_, ec)) return make_error(target_.string() + ": nothing was written");
  std::filesystem::rename(temp_, target_, ec);
  if (ec) return make_error(target_.string() + ": cannot write: " + ec.message());
  committed_ = true;
  return Ok{};
}

ScopedTempFile::ScopedTempFile(std::filesystem::path path) : path_(std::move(path)), slot_(register_live(path_.string())) {}

ScopedTempFile::~ScopedTempFile() {
  std::error_code ec;
  std::filesystem::remove(path_, ec);
  unregister_live(slot_);
}

Status write_file_atomically(const std::filesystem::path& target, const std::function<Status(std::ostream&)>& write) {
  AtomicOutput out(target);
  {
    std::ofstream f(out.temp_path(), std::ios::binary | std::ios::trunc);
    if (!f) return make_error(target.string() + ": cannot write: " + std::strerror(errno));
    if (Status s = write(f); !s) return s;
    f.flush();
    if (!f) return make_error(target.string() + ": write failed: " + std::strerror(errno));
  }
  return out.commit();
}

void install_interrupt_cleanup() {
  struct sigaction sa {};
  sa.sa_handler = remove_live_and_exit;
  sigemptyset(&sa.sa_mask);
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
    // A signal the caller ignores stays ignored (nohup, background jobs of a script).
    struct sigaction old {};
    if (sigaction(sig, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) continue;
    sigaction(sig, &sa, nullptr);
  }
}

}  // namespace rotinterp
