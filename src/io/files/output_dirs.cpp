// The output folders a run creates, noted in the run's cleanup list.
#include "rotinterp/io/files/output_dirs.h"

#include "cleanup_list.h"
#include "rotinterp/io/files/file_errors.h"

#include <mutex>
#include <system_error>
#include <vector>

namespace rotinterp {

namespace {

namespace fs = std::filesystem;

std::mutex g_mutex;

Error in_the_way(const fs::path& p) {
  return make_error(p.string() + ": cannot create the output folder: a file of that name is in the way",
                    file_error::cannot_write);
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
    if (fs::create_directory(*it, ec)) cleanup::add(it->string(), cleanup::Kind::folder);
    if (ec) return make_error(it->string() + ": cannot create the output folder: " + ec.message(), file_error::cannot_write);
  }
  if (!fs::is_directory(d, ec)) return in_the_way(d);
  return Ok{};
}

void remove_created_directories() noexcept { cleanup::remove_all(cleanup::Kind::folder); }

}  // namespace rotinterp
