// The reader's side of the importer (import.h): finding the executable, the
// importer each thread keeps across files (started, reused, restarted), and one
// read through it under a deadline and a size cap.
#include "rotinterp/io/process/importer.h"
#include "clip_wire.h"
#include "import_protocol.h"
#include "rotinterp/clip/time_range.h"
#include "rotinterp/io/process/process_errors.h"

#include <dlfcn.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

extern char** environ;

namespace rotinterp {

namespace fs = std::filesystem;

namespace {

namespace protocol = detail::import_protocol;
using Clock = std::chrono::steady_clock;

constexpr const char* kImporterName = "rotinterp-import";

bool executable(const fs::path& p) {
  std::error_code ec;
  return fs::is_regular_file(p, ec) && ::access(p.c_str(), X_OK) == 0;
}


// An importer whose resident memory passes this after a reply is replaced before
// the next file: assimp leaks on malformed files (.ci/lsan.supp) and the heap keeps
// what a large import grew to. A fresh importer holds about 14 MB, and reading
// the test corpus's FBX folder (3.5 MB at most) peaks at 45 MB: 256 MiB leaves
// such files room several times over, while N workers' idle importers stay
// below N × 256 MiB.
constexpr std::size_t kRestartAboveResidentBytes = std::size_t{256} << 20;

std::atomic<long> started_count{0};

bool send_all(int fd, std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t put = ::send(fd, bytes.data(), bytes.size(), MSG_NOSIGNAL);
    if (put < 0 && errno == EINTR) continue;
    if (put <= 0) return false;
    bytes.remove_prefix(static_cast<std::size_t>(put));
  }
  return true;
}

// One running importer, talking through one socket that is both its standard
// input and output. It belongs to the thread that started it: PR_SET_PDEATHSIG
// fires when that thread ends, and the thread's exit (or the process's, for the
// main thread) kills and reaps it in the destructor.
class Importer {
 public:
  Importer() = default;
  Importer(const Importer&) = delete;
  Importer& operator=(const Importer&) = delete;
  ~Importer() { stop(); }

  pid_t pid() const { return running() ? pid_ : -1; }
  int socket() const { return fd_; }

  // Whether it can take a request for `exe`: started by this process from that
  // executable, still alive, and silent since its last reply.
  bool ready_for(const std::string& exe) {
    if (!running() || exe != exe_) return false;
    pollfd p{fd_, POLLIN, 0};
    if (::poll(&p, 1, 0) != 0) return false;  // it spoke unasked or hung up
    int status = 0;
    const pid_t r = ::waitpid(pid_, &status, WNOHANG);
    if (r == pid_) pid_ = -1;  // reaped: its pid is no longer ours to kill
    return r == 0;
  }

  // A fresh importer from `exe` in place of this one.
  Status start(const std::string& exe, const std::string& label) {
    stop();
    int ends[2];
    if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, ends) != 0)
      return make_error(label + ": cannot start the importer: " + std::strerror(errno));
    // What a crash prints (glibc's "double free detected", a sanitizer's report)
    // is not the user's message: the parent's one line is. Signals unblocked
    // whatever this thread blocks.
    posix_spawn_file_actions_t actions;
    posix_spawnattr_t attr;
    ::posix_spawn_file_actions_init(&actions);
    ::posix_spawn_file_actions_adddup2(&actions, ends[1], STDIN_FILENO);
    ::posix_spawn_file_actions_adddup2(&actions, ends[1], STDOUT_FILENO);
    ::posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
    ::posix_spawnattr_init(&attr);
    sigset_t none;
    sigemptyset(&none);
    ::posix_spawnattr_setsigmask(&attr, &none);
    ::posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGMASK);
    std::vector<std::string> args = {exe, std::string(protocol::kVersion), std::to_string(::getpid())};
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    pid_t pid = -1;
    const int spawned = ::posix_spawn(&pid, exe.c_str(), &actions, &attr, argv.data(), environ);
    ::posix_spawn_file_actions_destroy(&actions);
    ::posix_spawnattr_destroy(&attr);
    ::close(ends[1]);
    if (spawned != 0) {
      ::close(ends[0]);
      return make_error(label + ": cannot start the importer " + exe + ": " + std::strerror(spawned));
    }
    pid_ = pid;
    owner_ = ::getpid();
    fd_ = ends[0];
    exe_ = exe;
    ++started_count;
    return Ok{};
  }

  // Killed and reaped; a copy inherited through fork (not this process's child)
  // is only forgotten.
  void stop() {
    if (running()) {
      ::kill(pid_, SIGKILL);
      int status = 0;
      while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
      }
    }
    forget();
  }

  // Its wait status once it has closed its end of the socket (it is exiting);
  // past `deadline` it is killed first (timed_out set).
  int reap(Clock::time_point deadline, bool& timed_out) {
    int status = 0;
    while (running()) {
      const pid_t r = ::waitpid(pid_, &status, WNOHANG);
      if (r == pid_ || (r < 0 && errno != EINTR)) break;
      if (r == 0 && Clock::now() >= deadline) {
        timed_out = true;
        ::kill(pid_, SIGKILL);
        while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
        }
        break;
      }
      if (r == 0) ::usleep(200);
    }
    forget();
    return status;
  }

  std::size_t resident_bytes() const {
    std::ifstream statm("/proc/" + std::to_string(pid_) + "/statm");
    std::size_t pages = 0, resident = 0;
    statm >> pages >> resident;
    return resident * static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
  }

 private:
  bool running() const { return pid_ > 0 && owner_ == ::getpid(); }
  void forget() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = pid_ = -1;
  }

  pid_t pid_ = -1;
  pid_t owner_ = -1;
  int fd_ = -1;
  std::string exe_;
};

Importer& this_threads_importer() {
  thread_local Importer importer;
  return importer;
}

// One reply read from the socket: whole, or why not.
struct Reply {
  std::string payload;
  bool whole = false, timed_out = false, too_large = false;
};

// Reads exactly one reply and nothing past it. Bytes that are not a reply are
// read on to the end (under the same limits) and come back not whole.
Reply read_reply(int fd, Clock::time_point deadline, std::size_t max_bytes) {
  Reply r;
  std::string header;
  std::optional<std::uint64_t> size;
  bool unframed = false;
  std::size_t stray = 0;  // bytes of what is not a reply
  std::vector<char> chunk(1 << 16);
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    if (left <= 0) {
      r.timed_out = true;
      return r;
    }
    pollfd p{fd, POLLIN, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(std::min<long long>(left, INT_MAX)));
    if (ready < 0 && errno != EINTR) return r;
    if (ready <= 0) continue;
    std::size_t want = chunk.size();
    if (!unframed && !size) want = protocol::kReplyHeader - header.size();
    if (size) want = std::min<std::size_t>(want, static_cast<std::size_t>(*size - r.payload.size()));
    const ssize_t n = ::read(fd, chunk.data(), want);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return r;  // it closed its end: it is exiting
    const std::string_view got(chunk.data(), static_cast<std::size_t>(n));
    if (size) {
      r.payload.append(got);
    } else if (unframed) {
      stray += got.size();
    } else {
      header.append(got);
      if (header.size() < protocol::kReplyHeader) continue;
      size = protocol::payload_size(header);
      unframed = !size;
      stray = header.size();
    }
    if (unframed && stray > max_bytes) r.too_large = true;
    if (size && *size > max_bytes) r.too_large = true;
    r.whole = size && r.payload.size() == *size;
    if (r.too_large || r.whole) return r;
  }
}

// `path` read by this thread's importer; a fresh one when `fresh` or when it has none.
Result<ReadOutcome> read_once(Importer& importer, bool fresh, const fs::path& path, const std::string& exe,
                                    const ReadOptions& options) {
  const std::string label = path.string();
  const auto deadline =
      Clock::now() + std::chrono::duration_cast<Clock::duration>(
                         std::chrono::duration<double>(std::min(options.import_timeout_seconds, 1e9)));
  if (fresh)
    if (Status started = importer.start(exe, label); !started) return started.failure();
  // An importer gone already shows below as the end of its socket.
  (void)send_all(importer.socket(), protocol::encode_request(path, options));
  Reply reply;
  try {
    reply = read_reply(importer.socket(), deadline, options.max_import_bytes);
  } catch (...) {  // out of memory for the reply
    importer.stop();
    throw;
  }
  if (reply.whole) {
    Result<ReadOutcome> got = wire::decode(reply.payload);
    if (!got || importer.resident_bytes() > kRestartAboveResidentBytes) importer.stop();
    if (got) return got;
  }
  bool timed_out = reply.timed_out;
  int status = 0;
  if (reply.whole || reply.too_large || reply.timed_out)
    importer.stop();
  else
    status = importer.reap(deadline, timed_out);

  if (reply.too_large)
    return make_error(label + ": the importer's result passed " + std::to_string(options.max_import_bytes) +
                          " bytes (ReadOptions::max_import_bytes); it was stopped and the file refused",
                      process_error::too_large);
  if (timed_out)
    return make_error(label + ": the import took longer than " + seconds_text(options.import_timeout_seconds) +
                          " s (ReadOptions::import_timeout_seconds); it was stopped and the file refused",
                      process_error::timed_out);
  std::string how;
  if (WIFSIGNALED(status))
    how = "signal " + std::to_string(WTERMSIG(status)) + ", " + ::strsignal(WTERMSIG(status));
  else if (WIFEXITED(status) && WEXITSTATUS(status) != 0)
    how = "exit status " + std::to_string(WEXITSTATUS(status));
  if (how.empty()) how = "its report was cut short or garbled";
  return make_error(label + ": assimp crashed importing this file (" + how + "); refused", process_error::crashed);
}
}  // namespace

Result<fs::path> find_importer() {
  if (const char* env = std::getenv("ROTINTERP_IMPORTER"); env && *env) {
    if (executable(env)) return fs::path(env);
    return make_error(std::string("ROTINTERP_IMPORTER=") + env + ": not an executable file");
  }
  // The object holding this function (the shared library, or the executable that
  // linked the static one), then the running executable.
  std::vector<fs::path> dirs;
  Dl_info dl{};
  if (::dladdr(reinterpret_cast<void*>(&find_importer), &dl) != 0 && dl.dli_fname && *dl.dli_fname)
    dirs.push_back(fs::path(dl.dli_fname).parent_path());
  std::error_code ec;
  if (const fs::path exe = fs::read_symlink("/proc/self/exe", ec); !ec) dirs.push_back(exe.parent_path());
  for (const fs::path& dir : dirs)
    for (const char* rel : {".", ROTINTERP_LIBEXEC_FROM_BIN, ROTINTERP_LIBEXEC_FROM_LIB})
      if (const fs::path p = (dir / rel / kImporterName).lexically_normal(); executable(p)) return p;
  if (executable(ROTINTERP_IMPORTER_BUILD_PATH)) return fs::path(ROTINTERP_IMPORTER_BUILD_PATH);
  return make_error(std::string("the importer '") + kImporterName +
                    "' is neither next to this program nor in its libexec directory; set ROTINTERP_IMPORTER to its path");
}


namespace detail {

Result<ReadOutcome> read_in_importer(const fs::path& path, const ReadOptions& options) {
  Result<fs::path> exe = find_importer();
  if (!exe) return exe.failure(path.string() + ": cannot read: ");
  Importer& importer = this_threads_importer();
  const bool reused = importer.ready_for(exe->string());
  Result<ReadOutcome> got = read_once(importer, !reused, path, exe->string(), options);
  // An importer that read other files first may have been broken by one of them
  // (a heap damaged without a crash there): before this file is called a crash,
  // a fresh importer reads it.
  if (reused && !got && got.error_kind() == process_error::crashed)
    got = read_once(importer, true, path, exe->string(), options);
  return got;
}

long importers_started() { return started_count.load(); }

pid_t importer_of_this_thread() { return this_threads_importer().pid(); }

}  // namespace detail

}  // namespace rotinterp
