// Named temporaries: their names, the claim of a free one, the sweep of those a killed process left.
#include "temp_names.h"

#include "cleanup_list.h"

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <mutex>
#include <set>
#include <string>

namespace rotinterp {

namespace fs = std::filesystem;

namespace {

// Our named temporaries: ".rotinterp.PID.N.tmp" + the target's extension (the
// exporter that opens a path, assimp's, picks the format by it). Short, so a target name of
// 255 bytes still works, and the PID tells whose it is.
constexpr const char* kTempPrefix = ".rotinterp.";
constexpr std::size_t kMaxKeptExtension = 8;

fs::path temp_name(const fs::path& target, unsigned n) {
  std::string ext = target.extension().string();
  if (ext.size() > kMaxKeptExtension) ext.clear();
  fs::path p = target;
  p.replace_filename(std::string(kTempPrefix) + std::to_string(::getpid()) + "." + std::to_string(n) + ".tmp" + ext);
  return p;
}

// A leftover of a process that no longer runs here (killed with SIGKILL, or on a
// filesystem without O_TMPFILE), untouched for 10 minutes: removed. The age keeps
// a live writer on another machine sharing the directory safe from PID reuse.
constexpr std::time_t kStaleSeconds = 600;

std::atomic<unsigned> g_counter{0};

}  // namespace

void remove_stale_temporaries(const fs::path& dir) {
  static std::mutex mutex;
  static std::set<std::string> swept;  // once per directory and process
  {
    std::lock_guard<std::mutex> lock(mutex);
    if (!swept.insert(dir.string()).second) return;
  }
  const std::string d = dir.empty() ? std::string(".") : dir.string();
  DIR* h = ::opendir(d.c_str());
  if (!h) return;
  const std::time_t now = std::time(nullptr);
  const std::size_t plen = std::strlen(kTempPrefix);
  while (const dirent* e = ::readdir(h)) {
    const char* name = e->d_name;
    if (std::strncmp(name, kTempPrefix, plen) != 0 || !std::strstr(name, ".tmp")) continue;
    char* end = nullptr;
    const long pid = std::strtol(name + plen, &end, 10);
    if (end == name + plen || *end != '.' || pid <= 0) continue;
    if (pid == ::getpid() || ::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;
    struct stat st {};
    if (::fstatat(::dirfd(h), name, &st, AT_SYMLINK_NOFOLLOW) != 0 || !S_ISREG(st.st_mode)) continue;
    if (now - st.st_mtime < kStaleSeconds) continue;
    ::unlinkat(::dirfd(h), name, 0);
  }
  ::closedir(h);
}

fs::path claim_temp_name(const fs::path& target, int& slot, int& err,
                         const std::function<bool(const fs::path& name)>& create) {
  for (int attempt = 0; attempt < 100; ++attempt) {
    fs::path name = temp_name(target, g_counter++);
    slot = cleanup::add(name.string(), cleanup::Kind::file);
    if (create(name)) return name;
    err = errno;
    cleanup::drop(slot);
    slot = -1;
    if (err != EEXIST) break;
  }
  return {};
}

}  // namespace rotinterp
