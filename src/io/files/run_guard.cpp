// The output directory's lock and the registry of inputs no output may overwrite.
#include "rotinterp/io/files/run_guard.h"

#include "rotinterp/io/files/output_dirs.h"
#include "rotinterp/io/files/file_errors.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <mutex>
#include <string>
#include <vector>

namespace rotinterp {

namespace {

namespace fs = std::filesystem;

// Errors about an output (its folder, its lock): the caller names the output.
Error write_error(std::string message) { return make_error(std::move(message), file_error::cannot_write); }

std::string reason(int err) { return std::strerror(err); }

// Inputs registered with protect_input: (device, inode, path as given).
struct InputId {
  dev_t dev;
  ino_t ino;
  std::string path;
};
std::mutex g_inputs_mutex;
std::vector<InputId> g_inputs;

}  // namespace

Result<DirectoryLock> DirectoryLock::acquire(const fs::path& dir) {
  if (Status made = create_output_directories(dir); !made) return made.failure();
  // The directory itself is locked: no lock file is left in it.
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return write_error(dir.string() + ": cannot lock the output directory: " + reason(errno));
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    const int err = errno;
    ::close(fd);
    if (err == EWOULDBLOCK)
      return write_error(dir.string() + ": another rotinterp run is writing to this directory; wait for it or choose "
                        "another output directory");
    return write_error(dir.string() + ": cannot lock the output directory: " + reason(err));
  }
  return DirectoryLock(fd);
}

DirectoryLock::~DirectoryLock() {
  if (fd_ >= 0) ::close(fd_);
}

void protect_input(const fs::path& input) {
  struct stat st {};
  if (::stat(input.c_str(), &st) != 0) return;
  std::lock_guard<std::mutex> lock(g_inputs_mutex);
  g_inputs.push_back({st.st_dev, st.st_ino, input.string()});
}

Status check_not_an_input(const fs::path& output) {
  struct stat st {};
  if (::stat(output.c_str(), &st) != 0) return Ok{};
  std::lock_guard<std::mutex> lock(g_inputs_mutex);
  for (const InputId& in : g_inputs)
    if (in.dev == st.st_dev && in.ino == st.st_ino)
      return write_error(output.string() + ": is the same file as the input " + in.path +
                        "; refusing to overwrite an input (choose another output)");
  return Ok{};
}

}  // namespace rotinterp
