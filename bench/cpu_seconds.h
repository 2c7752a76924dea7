// CPU seconds of the whole process (all threads) and of its children, finished or
// still running — the reader's assimp imports run in importer processes that
// outlive each file (include/rotinterp/io/process/importer.h): less sensitive than wall time to other work
// on a shared machine, for the single-threaded ratios.
#pragma once

#include <sys/resource.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

// The CPU seconds of this process's children that are still running (or not yet
// reaped), from /proc: getrusage counts a child only once it has been waited for.
// Each thread's children are listed under /proc/self/task/TID/children.
inline double running_children_cpu_seconds() {
  const double tick = static_cast<double>(::sysconf(_SC_CLK_TCK));
  double total = 0.0;
  std::error_code ec;
  for (const auto& task : std::filesystem::directory_iterator("/proc/self/task", ec)) {
    std::ifstream children(task.path() / "children");
    for (long pid = 0; children >> pid;) {
      std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
      std::string line;
      if (!std::getline(stat, line)) continue;
      const auto close = line.rfind(')');
      if (close == std::string::npos) continue;
      // After the name: state ppid pgrp session tty tpgid flags minflt cminflt majflt cmajflt utime stime.
      std::istringstream fields(line.substr(close + 2));
      std::string skip;
      for (int i = 0; i < 11; ++i) fields >> skip;
      unsigned long long utime = 0, stime = 0;
      if (fields >> utime >> stime) total += static_cast<double>(utime + stime) / tick;
    }
  }
  return total;
}

inline double cpu_seconds() {
  double total = running_children_cpu_seconds();
  for (int who : {RUSAGE_SELF, RUSAGE_CHILDREN}) {
    rusage u{};
    ::getrusage(who, &u);
    total += static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
             1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
  }
  return total;
}

// This process's own CPU seconds (all threads, no children): for timing that reads
// no file, often — cpu_seconds() lists the children from /proc each time.
inline double own_cpu_seconds() {
  rusage u{};
  ::getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}
