// Running the rotinterp binary as a child process the test controls (signals,
// SIGKILL, what it has open), and looking at what it left in a directory.
#pragma once

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <functional>
#include <string>
#include <thread>
#include <vector>

namespace rotinterp::test {

// Starts the CLI with `args` (no shell), stdout and stderr to /dev/null (stderr to
// `err_file` when given); with `ignored` (a signal) ignored as under nohup.
inline pid_t spawn(const std::vector<std::string>& args, int ignored = 0, const std::string& err_file = "") {
  const pid_t pid = ::fork();
  if (pid == 0) {
    if (ignored != 0) std::signal(ignored, SIG_IGN);
    std::vector<char*> argv;
    static std::string cli = ROTINTERP_CLI;
    argv.push_back(cli.data());
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    const int null = ::open("/dev/null", O_WRONLY);
    ::dup2(null, STDOUT_FILENO);
    ::dup2(err_file.empty() ? null : ::open(err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644), STDERR_FILENO);
    ::execv(cli.c_str(), argv.data());
    ::_exit(127);
  }
  return pid;
}

// Polls `done` every 0.5 ms until it holds, the child exits (false, with `ended`
// set) or `seconds` pass (false).
inline bool wait_until(pid_t child, const std::function<bool()>& done, double seconds, bool* ended = nullptr) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < end) {
    if (done()) return true;
    int status = 0;
    if (::waitpid(child, &status, WNOHANG) == child) {
      if (ended) *ended = true;
      return false;
    }
    std::this_thread::sleep_for(std::chrono::microseconds(500));
  }
  return false;
}

// The child's exit code, or 1000 + signal when a signal ended it.
inline int exit_status(pid_t pid) {
  int status = 0;
  if (::waitpid(pid, &status, 0) != pid) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 1000 + WTERMSIG(status);
}

inline std::vector<std::string> names_in(const std::filesystem::path& dir) {
  std::vector<std::string> out;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(dir, ec)) out.push_back(e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

// How many files inside `dir` process `pid` has open (an unnamed O_TMPFILE
// temporary shows as "DIR/#inode (deleted)"); `except` is not counted.
inline int open_files_in(pid_t pid, const std::filesystem::path& dir, const std::filesystem::path& except = {}) {
  const std::string prefix = std::filesystem::absolute(dir).string() + "/";
  const std::string skip = except.empty() ? std::string() : std::filesystem::absolute(except).string();
  int count = 0;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator("/proc/" + std::to_string(pid) + "/fd", ec)) {
    std::error_code ec2;
    const std::string target = std::filesystem::read_symlink(e.path(), ec2).string();
    if (!ec2 && target.compare(0, prefix.size(), prefix) == 0 && target != skip) ++count;
  }
  return count;
}

inline bool has_open_file_in(pid_t pid, const std::filesystem::path& dir, const std::filesystem::path& except = {}) {
  return open_files_in(pid, dir, except) > 0;
}

}  // namespace rotinterp::test
