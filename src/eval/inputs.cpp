#include "rotinterp/eval/inputs.h"

#include "rotinterp/io/read.h"

#include <algorithm>
#include <cstdlib>
#include <system_error>

namespace rotinterp {

namespace fs = std::filesystem;

Result<std::vector<std::string>> discover_inputs(const std::vector<fs::path>& paths) {
  std::vector<std::string> files;
  for (const fs::path& p : paths) {
    std::error_code ec;
    const fs::file_status st = fs::status(p, ec);
    if (ec || !fs::exists(st)) return make_error(p.string() + ": no such file or directory");
    if (!fs::is_directory(st)) {
      files.push_back(p.string());
      continue;
    }
    fs::recursive_directory_iterator it(p, fs::directory_options::skip_permission_denied, ec), end;
    if (ec) return make_error(p.string() + ": " + ec.message());
    for (; it != end; it.increment(ec)) {
      if (ec) return make_error(p.string() + ": " + ec.message());
      const fs::path& f = it->path();
      const std::string name = f.filename().string();
      if (!name.empty() && name[0] == '.') {
        if (it->is_directory(ec)) it.disable_recursion_pending();
        continue;
      }
      if (!it->is_regular_file(ec)) continue;
      const std::string ext = f.extension().string();
      if (ext.size() > 1 && importable_extension(ext)) files.push_back(f.string());
    }
  }
  std::sort(files.begin(), files.end());
  files.erase(std::unique(files.begin(), files.end()), files.end());
  return files;
}

bool found_in_directory(const std::string& path, const std::vector<fs::path>& named) {
  for (const fs::path& p : named)
    if (p.string() == path) return false;
  return true;
}

std::vector<std::string> shard_of(const std::vector<std::string>& files, int index, int count) {
  std::vector<std::string> out;
  if (count < 1 || index < 1 || index > count) return out;
  for (std::size_t i = static_cast<std::size_t>(index - 1); i < files.size(); i += static_cast<std::size_t>(count))
    out.push_back(files[i]);
  return out;
}

Result<std::pair<int, int>> parse_shard(const std::string& text) {
  const auto slash = text.find('/');
  auto number = [](const std::string& s, long& v) {
    if (s.empty() || s.size() > 7 || s.find_first_not_of("0123456789") != std::string::npos) return false;
    v = std::strtol(s.c_str(), nullptr, 10);
    return true;
  };
  long i = 0, n = 0;
  if (slash == std::string::npos || !number(text.substr(0, slash), i) || !number(text.substr(slash + 1), n) || n < 1 ||
      n > 1000000 || i < 1 || i > n)
    return make_error("--shard '" + text + "' is not I/N with 1 ≤ I ≤ N");
  return std::make_pair(static_cast<int>(i), static_cast<int>(n));
}

}  // namespace rotinterp
