// rotinterp command line: a thin layer over the library. Each subcommand lives in
// its own cmd_*.cpp; this file only wires them and maps errors to exit codes.
#include "common.h"
#include "rotinterp/io/atomic_file.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <string>

int main(int argc, char** argv) {
  using namespace rotinterp::cli;
  rotinterp::install_interrupt_cleanup();

  CLI::App app{"rotinterp: resample, compare and evaluate keyframed 3-D orientations in motion clips"};
  app.set_version_flag("--version", std::string("rotinterp ") + ROTINTERP_VERSION);
  app.require_subcommand(1);
  app.fallthrough(false);

  int exit_code = kExitOk;
  add_methods_command(app, exit_code);
  add_resample_command(app, exit_code);
  add_synth_command(app, exit_code);
  add_eval_command(app, exit_code);
  add_info_command(app, exit_code);
#if ROTINTERP_HAVE_RENDER
  add_render_command(app, exit_code);
#endif

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
    std::fprintf(stderr, "rotinterp: %s (run 'rotinterp --help' for usage)\n", message.c_str());
    return kExitUsage;
  } catch (const std::bad_alloc&) {
    return fail("out of memory");
  } catch (const std::exception& e) {
    return fail(e.what());
  }
  return exit_code;
}
