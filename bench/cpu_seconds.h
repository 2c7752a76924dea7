// CPU seconds of the whole process (all threads) and of its children, finished or
// still running — the reader's assimp imports run in importer processes that
// outlive each file (src/io/import.h): less sensitive than wall time to other work
// on a shared machine, for the single-threaded ratios.
#pragma once

#include <sys/resource.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

// The CPU seconds of this process's children that are still running (or not yet
// reaped), from /proc: getrusage counts a child only once it has been waited for.
inline double running_children_cpu_seconds() {
  const long parent = static_cast<long>(::getpid());
  const double tick = static_cast<double>(::sysconf(_SC_CLK_TCK));
  double total = 0.0;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator("/proc", ec)) {
    const std::string name = entry.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    std::ifstream stat(entry.path() / "stat");
    std::string line;
    if (!std::getline(stat, line)) continue;
    const auto close = line.rfind(')');
    if (close == std::string::npos) continue;
    // After the name: state ppid pgrp session tty tpgid flags minflt cminflt majflt cmajflt utime stime.
    std::istringstream fields(line.substr(close + 2));
    std::string state;
    long ppid = 0, skip = 0;
    unsigned long long utime = 0, stime = 0;
    fields >> state >> ppid;
    for (int i = 0; i < 9; ++i) fields >> skip;
    fields >> utime >> stime;
    if (fields && ppid == parent) total += static_cast<double>(utime + stime) / tick;
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
