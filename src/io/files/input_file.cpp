// The checks every file a read opens goes through (io/files/input_file.h).
#include "rotinterp/io/files/input_file.h"
#include "rotinterp/io/files/file_errors.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <system_error>

namespace rotinterp {

namespace fs = std::filesystem;

Status check_file(const fs::path& path, const std::string& label) {
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (ec == std::errc::too_many_symbolic_link_levels)
    return make_error(label + ": a loop of symbolic links (too many levels of symbolic links)", file_error::no_file);
  if (ec || !fs::exists(st)) {
    std::error_code lec;
    if (fs::is_symlink(fs::symlink_status(path, lec)))
      return make_error(label + ": a symbolic link to a missing file", file_error::no_file);
    if (ec && ec != std::errc::no_such_file_or_directory)
      return make_error(label + ": cannot read: " + ec.message(), file_error::cannot_open);
    return make_error(label + ": no such file", file_error::no_file);
  }
  if (fs::is_directory(st)) return make_error(label + ": is a directory, not a clip file", file_error::directory);
  if (!fs::is_regular_file(st)) return make_error(label + ": not a regular file", file_error::cannot_open);
  const auto size = fs::file_size(path, ec);
  if (ec) return make_error(label + ": cannot read: " + ec.message(), file_error::cannot_open);
  if (size == 0) return make_error(label + ": the file is empty", file_error::unreadable);
  std::ifstream f(path, std::ios::binary);
  if (!f) return make_error(label + ": cannot open for reading", file_error::cannot_open);
  return Ok{};
}

Result<std::string> read_input_file(const fs::path& path, const std::string& label) {
  if (Status s = check_file(path, label); !s) return s.failure();
  // O_NONBLOCK: were the path swapped for a FIFO since the check, open would not wait
  // for a writer; fstat below then refuses it.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) return make_error(label + ": cannot open for reading: " + std::strerror(errno), file_error::cannot_open);
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd);
    return make_error(label + ": not a regular file", file_error::cannot_open);
  }
  std::string bytes(static_cast<std::size_t>(st.st_size), '\0');
  std::size_t size = 0;
  while (size < bytes.size()) {
    const ssize_t got = ::read(fd, bytes.data() + size, bytes.size() - size);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) {
      const std::string why = std::strerror(errno);
      ::close(fd);
      return make_error(label + ": read failed: " + why, file_error::cannot_open);
    }
    if (got == 0) break;  // truncated while read: the parser reports what is missing
    size += static_cast<std::size_t>(got);
  }
  ::close(fd);
  bytes.resize(size);
  return bytes;
}

Result<fs::path> referenced_file(const fs::path& folder, const std::string& reference, bool allow_outside,
                                 const std::string& what) {
  const fs::path relative(reference);
  if (relative.empty()) return make_error(what + " names no file", file_error::unreadable);
  const fs::path path = relative.is_absolute() ? relative : folder / relative;
  if (!allow_outside) {
    std::error_code ec;
    const fs::path base = fs::weakly_canonical(folder.empty() ? fs::path(".") : folder, ec);
    const fs::path target = ec ? fs::path() : fs::weakly_canonical(path, ec);
    const fs::path inside = ec ? fs::path() : target.lexically_relative(base);
    bool leaves = relative.has_root_path() || inside.empty();
    for (const fs::path& part : inside) leaves = leaves || part == "..";
    for (const fs::path& part : relative) leaves = leaves || part == "..";
    if (leaves)
      return make_error(what + " leads out of the file's folder (refused unless --allow-external-files, in Python allow_external_files=True)",
                        file_error::unreadable);
  }
  if (Status s = check_file(path, what); !s) return s.failure();
  return path;
}

}  // namespace rotinterp
