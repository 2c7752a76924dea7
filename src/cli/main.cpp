// rotinterp command line: a thin layer over the library. Each subcommand lives in
// its own cmd_*.cpp; this file only wires them and maps errors to exit codes.
#include "common.h"
#include "rotinterp/io/files/interrupt_cleanup.h"
#include "rotinterp/io/files/output_dirs.h"

#include <CLI/CLI.hpp>

#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <exception>
#include <new>
#include <string>

namespace {

// The command's input, for the out-of-memory line: the first argument after the
// subcommand that is no option, not -o's value and names an existing path.
void note_input(int argc, char** argv) {
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    if (a.empty() || a[0] == '-') continue;
    const std::string before = argv[i - 1];
    if (before == "-o" || before == "--output") continue;
    std::error_code ec;
    if (!std::filesystem::exists(a, ec)) continue;
    rotinterp::cli::name_out_of_memory_file(a);
    return;
  }
}

// Out of memory on any thread (a worker of eval or render) ends the run with one
// line and exit 1, its temporary files removed, instead of an abort; anything else
// uncaught is a bug: named on one line, then an abort.
[[noreturn]] void on_terminate() {
  if (const std::exception_ptr current = std::current_exception()) {
    try {
      std::rethrow_exception(current);
    } catch (const std::bad_alloc&) {
      rotinterp::remove_live_temporaries();
      const char* line = rotinterp::cli::out_of_memory_line();
      (void)!::write(STDERR_FILENO, line, std::strlen(line));
      _exit(rotinterp::cli::kExitFailure);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "rotinterp: internal error: %s\n", e.what());
    } catch (...) {
    }
  }
  std::abort();
}

}  // namespace

namespace {
// Parses and runs the subcommand; its exit code.
int run(CLI::App& app, int argc, char** argv, const int& exit_code);
}  // namespace

int main(int argc, char** argv) {
  using namespace rotinterp::cli;
  rotinterp::install_interrupt_cleanup("rotinterp: interrupted\n");
  std::set_terminate(on_terminate);
  note_input(argc, argv);

  CLI::App app{"rotinterp: resample, compare and evaluate keyframed 3-D orientations in motion clips"};
  app.set_version_flag("--version", std::string("rotinterp ") + ROTINTERP_VERSION);
  app.require_subcommand(1);
  app.fallthrough(false);

  int exit_code = kExitOk;
  add_commands(app, exit_code);

  const int code = run(app, argc, argv, exit_code);
  // A run that did not succeed takes back the output folders it created, if still empty.
  if (code != kExitOk) rotinterp::remove_created_directories();
  return code;
}

namespace {

int run(CLI::App& app, int argc, char** argv, const int& exit_code) {
  using namespace rotinterp::cli;
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // One line, like every other error (CLI11 messages may span several).
    std::string message = e.what();
    for (char& c : message)
      if (c == '\n' || c == '\r') c = ' ';
    std::fprintf(stderr, "rotinterp: %s\n", usage_error_line(app, message, argc, argv).c_str());
    return kExitUsage;
  } catch (const std::bad_alloc&) {
    // Unwound: every AtomicOutput on the way removed its temporary.
    std::fputs(out_of_memory_line(), stderr);
    return kExitFailure;
  } catch (const std::exception& e) {
    return fail(e.what());
  }
  return exit_code;
}

}  // namespace
