// CPU seconds of the whole process (all threads) and of its finished children (the
// reader's assimp imports in the importer process, src/io/import.h): less sensitive than
// wall time to other work on a shared machine, for the single-threaded ratios.
#pragma once

#include <sys/resource.h>

inline double cpu_seconds() {
  double total = 0.0;
  for (int who : {RUSAGE_SELF, RUSAGE_CHILDREN}) {
    rusage u{};
    ::getrusage(who, &u);
    total += static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
             1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
  }
  return total;
}
