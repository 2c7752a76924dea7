// The importer process (import.h): finding the executable, starting it, reading
// its reply under a deadline and a size cap, and its main().
#include "import.h"

#include <dlfcn.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

extern char** environ;

namespace rotinterp {

namespace fs = std::filesystem;

namespace {

constexpr const char* kImporterName = "rotinterp-import";
// The command line's first argument: both ends come from the same build.
constexpr std::string_view kProtocol = "rotinterp-import-3";

bool executable(const fs::path& p) {
  std::error_code ec;
  return fs::is_regular_file(p, ec) && ::access(p.c_str(), X_OK) == 0;
}

bool write_all(int fd, std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t put = ::write(fd, bytes.data(), bytes.size());
    if (put < 0 && errno == EINTR) continue;
    if (put <= 0) return false;
    bytes.remove_prefix(static_cast<std::size_t>(put));
  }
  return true;
}

// A started importer: killed and reaped by the destructor unless wait() reaped it,
// so no path out of read_in_importer (an exception included) leaves it running.
class Child {
 public:
  explicit Child(pid_t pid) : pid_(pid) {}
  Child(const Child&) = delete;
  Child& operator=(const Child&) = delete;
  ~Child() {
    if (pid_ <= 0) return;
    ::kill(pid_, SIGKILL);
    int status = 0;
    while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
  }
  void kill() { ::kill(pid_, SIGKILL); }
  // Its wait status; past `deadline` it is killed first (timed_out set).
  int wait(std::chrono::steady_clock::time_point deadline, bool& timed_out) {
    int status = 0;
    for (;;) {
      const pid_t r = ::waitpid(pid_, &status, WNOHANG);
      if (r == pid_ || (r < 0 && errno != EINTR)) break;
      if (r == 0 && std::chrono::steady_clock::now() >= deadline) {
        timed_out = true;
        kill();
        while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
        }
        break;
      }
      if (r == 0) ::usleep(200);  // it closed its output: it is exiting
    }
    pid_ = -1;
    return status;
  }

 private:
  pid_t pid_;
};

std::string seconds_text(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", s);
  return buf;
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

// A double as text that reads back as the same double.
std::string fmt_double(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

Result<wire::ReadOutcome> read_in_importer(const fs::path& path, const ReadOptions& options) {
  const std::string label = path.string();
  Result<fs::path> exe = find_importer();
  if (!exe) return exe.failure(label + ": cannot read: ");
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) return make_error(label + ": cannot start the importer: " + std::strerror(errno));

  // Its standard output is the pipe; no input, and what a crash prints (glibc's
  // "double free detected", a sanitizer's report) is not the user's message: the
  // parent's one line is. Signals unblocked whatever this thread blocks.
  posix_spawn_file_actions_t actions;
  posix_spawnattr_t attr;
  ::posix_spawn_file_actions_init(&actions);
  ::posix_spawn_file_actions_adddup2(&actions, fds[1], STDOUT_FILENO);
  ::posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  ::posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  ::posix_spawnattr_init(&attr);
  sigset_t none;
  sigemptyset(&none);
  ::posix_spawnattr_setsigmask(&attr, &none);
  ::posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGMASK);
  const std::string parent = std::to_string(::getpid());
  const std::string exe_text = exe->string();
  std::vector<std::string> args = {exe_text,
                                   std::string(kProtocol),
                                   parent,
                                   label,
                                   options.animation,
                                   options.fold_fbx_helpers ? "1" : "0",
                                   options.cross_check_with_assimp ? "1" : "0",
                                   options.read_curves ? "1" : "0",
                                   options.unit ? fmt_double(*options.unit) : std::string()};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = -1;
  const int spawned = ::posix_spawn(&pid, exe_text.c_str(), &actions, &attr, argv.data(), environ);
  ::posix_spawn_file_actions_destroy(&actions);
  ::posix_spawnattr_destroy(&attr);
  ::close(fds[1]);
  if (spawned != 0) {
    ::close(fds[0]);
    return make_error(label + ": cannot start the importer " + exe_text + ": " + std::strerror(spawned));
  }
  Child child(pid);

  // Its reply, up to the end of the pipe (the importer exits right after writing).
  using Clock = std::chrono::steady_clock;
  const auto deadline =
      Clock::now() + std::chrono::duration_cast<Clock::duration>(
                         std::chrono::duration<double>(std::min(options.import_timeout_seconds, 1e9)));
  std::string reply;
  bool timed_out = false, too_large = false;
  std::vector<char> chunk(1 << 16);
  try {
    for (;;) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
      if (left <= 0) {
        timed_out = true;
        break;
      }
      pollfd p{fds[0], POLLIN, 0};
      const int ready = ::poll(&p, 1, static_cast<int>(std::min<long long>(left, INT_MAX)));
      if (ready < 0 && errno != EINTR) break;
      if (ready <= 0) continue;
      const ssize_t n = ::read(fds[0], chunk.data(), chunk.size());
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) break;
      if (reply.size() + static_cast<std::size_t>(n) > options.max_import_bytes) {
        too_large = true;
        break;
      }
      reply.append(chunk.data(), static_cast<std::size_t>(n));
    }
  } catch (...) {  // out of memory for the reply: the Child destructor kills it
    ::close(fds[0]);
    throw;
  }
  ::close(fds[0]);
  if (timed_out || too_large) child.kill();
  const int status = child.wait(deadline, timed_out);

  if (too_large)
    return make_error(label + ": the importer's result passed " + std::to_string(options.max_import_bytes) +
                          " bytes (ReadOptions::max_import_bytes); it was stopped and the file refused",
                      ErrorKind::too_large);
  if (timed_out)
    return make_error(label + ": the import took longer than " + seconds_text(options.import_timeout_seconds) +
                          " s (ReadOptions::import_timeout_seconds); it was stopped and the file refused",
                      ErrorKind::timed_out);
  std::string how;
  if (WIFSIGNALED(status))
    how = "signal " + std::to_string(WTERMSIG(status)) + ", " + ::strsignal(WTERMSIG(status));
  else if (WIFEXITED(status) && WEXITSTATUS(status) != 0)
    how = "exit status " + std::to_string(WEXITSTATUS(status));
  if (how.empty())
    if (Result<wire::ReadOutcome> got = wire::decode(reply)) return got;
  if (how.empty()) how = "its report was cut short or garbled";
  return make_error(label + ": assimp crashed importing this file (" + how + "); refused", ErrorKind::crashed);
}

int importer_main(int argc, char** argv) {
  if (argc != 9 || argv[1] != kProtocol) {
    std::fprintf(stderr, "%s: the importer of rotinterp's reader, started by it; not a command\n", kImporterName);
    return 2;
  }
  // Dies with the process that started it, even one killed by SIGKILL; does
  // nothing if that one is gone already.
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (std::to_string(::getppid()) != argv[2]) return 3;
  // The reply gets a descriptor of its own; anything a library prints to stdout
  // goes nowhere instead of into the reply.
  const int reply = ::fcntl(STDOUT_FILENO, F_DUPFD_CLOEXEC, 3);
  if (const int null = ::open("/dev/null", O_WRONLY); null >= 0) ::dup2(null, STDOUT_FILENO);
  if (reply < 0) return 4;
  ReadOptions options;
  options.animation = argv[4];
  options.fold_fbx_helpers = std::string_view(argv[5]) == "1";
  options.cross_check_with_assimp = std::string_view(argv[6]) == "1";
  options.read_curves = std::string_view(argv[7]) == "1";
  if (argv[8][0] != '\0') options.unit = std::strtod(argv[8], nullptr);
  const std::string payload = wire::encode(read_in_this_process(argv[3], options));
  // _exit: no exit handlers, so LeakSanitizer does not turn assimp's leaks on a
  // bad file into a failed import.
  ::_exit(write_all(reply, payload) ? 0 : 1);
}

}  // namespace detail

}  // namespace rotinterp
