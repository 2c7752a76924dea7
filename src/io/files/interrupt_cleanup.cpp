// On SIGINT/SIGTERM/SIGHUP: the live temporaries and the run's empty new folders removed, then exit.
#include "rotinterp/io/files/interrupt_cleanup.h"

#include "cleanup_list.h"
#include "rotinterp/io/files/output_dirs.h"

#include <unistd.h>

#include <csignal>
#include <cstring>

namespace rotinterp {

namespace {

const char* g_interrupt_line = nullptr;  // set once, before the handlers

extern "C" void remove_live_and_exit(int sig) {
  remove_live_temporaries();
  remove_created_directories();
  if (g_interrupt_line) (void)!::write(STDERR_FILENO, g_interrupt_line, std::strlen(g_interrupt_line));
  _exit(128 + sig);
}

}  // namespace

void remove_live_temporaries() noexcept { cleanup::remove_all(cleanup::Kind::file); }

void install_interrupt_cleanup(const char* line) {
  g_interrupt_line = line;
  struct sigaction sa {};
  sa.sa_handler = remove_live_and_exit;
  sigemptyset(&sa.sa_mask);
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
    // A signal the caller ignores stays ignored (nohup, background jobs of a script).
    struct sigaction old {};
    if (sigaction(sig, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) continue;
    sigaction(sig, &sa, nullptr);
  }
}

}  // namespace rotinterp
