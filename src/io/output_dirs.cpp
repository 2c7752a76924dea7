// The output folders a run created, kept as fixed C strings so a signal handler can
// remove them without allocating.
#include "rotinterp/io/output_dirs.h"

#include <unistd.h>

#include <atomic>
#include <cstring>
#include <mutex>
#include <system_error>
#include <vector>

namespace rotinterp {

namespace {

namespace fs = std::filesystem;

constexpr int kMaxCreated = 256;
constexpr int kMaxPath = 4096;
char g_created[kMaxCreated][kMaxPath];
std::atomic<int> g_count{0};
std::mutex g_mutex;

void note_created(const std::string& path) {
  const int n = g_count.load();
  if (n >= kMaxCreated || path.size() >= kMaxPath) return;
  std::memcpy(g_created[n], path.c_str(), path.size() + 1);
  g_count.store(n + 1);  // published after the copy: a handler sees whole entries only
}

Error in_the_way(const fs::path& p) {
  return make_error(p.string() + ": cannot create the output folder: a file of that name is in the way");
}

}  // namespace

Status create_output_directories(const fs::path& dir) {
  fs::path d = dir.lexically_normal();
  if (!d.has_filename()) d = d.parent_path();  // "out/" is the folder "out"
  if (d.empty()) return Ok{};
  std::lock_guard<std::mutex> lock(g_mutex);
  std::error_code ec;
  // The missing ancestors, outermost first: each one created is noted.
  std::vector<fs::path> missing;
  for (fs::path p = d; !p.empty(); p = p.parent_path()) {
    if (fs::exists(p, ec)) {
      if (!fs::is_directory(p, ec)) return in_the_way(p);
      break;
    }
    missing.push_back(p);
    if (p == p.parent_path()) break;
  }
  for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
    if (fs::create_directory(*it, ec)) note_created(it->string());
    if (ec) return make_error(it->string() + ": cannot create the output folder: " + ec.message());
  }
  if (!fs::is_directory(d, ec)) return in_the_way(d);
  return Ok{};
}

void remove_created_directories() noexcept {
  for (int i = g_count.load() - 1; i >= 0; --i) ::rmdir(g_created[i]);
}

}  // namespace rotinterp
