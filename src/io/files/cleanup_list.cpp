// The list of paths an interrupted or failed run takes back (cleanup_list.h).
#include "cleanup_list.h"

#include <unistd.h>

#include <atomic>
#include <cstring>
#include <mutex>

namespace rotinterp::cleanup {

namespace {

constexpr int kPerKind = 256;
constexpr int kSlots = 2 * kPerKind;  // files in [0, 256), folders in [256, 512)
constexpr int kMaxPath = 4096;
char g_path[kSlots][kMaxPath];
std::atomic<bool> g_used[kSlots];
std::mutex g_mutex;

int first_slot(Kind kind) { return kind == Kind::file ? 0 : kPerKind; }

}  // namespace

int add(const std::string& path, Kind kind) {
  if (path.size() >= kMaxPath) return -1;
  std::lock_guard<std::mutex> lock(g_mutex);
  for (int i = first_slot(kind); i < first_slot(kind) + kPerKind; ++i) {
    if (!g_used[i].load()) {
      std::memcpy(g_path[i], path.c_str(), path.size() + 1);
      g_used[i].store(true);  // published after the copy: a handler sees whole entries only
      return i;
    }
  }
  return -1;
}

void drop(int slot) {
  if (slot >= 0 && slot < kSlots) g_used[slot].store(false);
}

void remove_all(Kind kind) noexcept {
  const int first = first_slot(kind);
  if (kind == Kind::file) {
    for (int i = first; i < first + kPerKind; ++i)
      if (g_used[i].load()) ::unlink(g_path[i]);
    return;
  }
  // Folders are added outermost first and never dropped, so the newest is innermost.
  for (int i = first + kPerKind - 1; i >= first; --i)
    if (g_used[i].load()) ::rmdir(g_path[i]);
}

}  // namespace rotinterp::cleanup
