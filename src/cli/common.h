// Shared plumbing of the subcommands: exit codes, error lines, progress.
#pragma once

#include "rotinterp/core/progress.h"

#include <CLI/CLI.hpp>

#include <string>
#include <string_view>
#include <vector>

namespace rotinterp::cli {

// Exit codes (README "Exit codes").
constexpr int kExitOk = 0;
constexpr int kExitFailure = 1;  // bad input or a failed run
constexpr int kExitUsage = 2;    // the command line itself is wrong
constexpr int kExitPartial = 3;  // eval: some inputs failed, the rest were written

// Prints "rotinterp: <message>" on stderr and returns kExitFailure.
int fail(std::string_view message);
// The same for a bad option value: returns kExitUsage.
int fail_usage(std::string_view message);

// "a,b,,c" → {"a", "b", "c"}: the items of a comma-separated option, empty ones dropped.
std::vector<std::string> split_comma_list(std::string_view text);

// A progress reporter that draws "label  done/total" on stderr when stderr is a
// terminal and quiet is false; otherwise an empty function.
ProgressFn make_progress(std::string label, bool quiet);
// Ends the progress line (if one was drawn).
void end_progress(bool quiet);

// Each subcommand adds itself to `app`; when it runs, it stores its exit code.
void add_methods_command(CLI::App& app, int& exit_code);
void add_resample_command(CLI::App& app, int& exit_code);
void add_synth_command(CLI::App& app, int& exit_code);
void add_eval_command(CLI::App& app, int& exit_code);
void add_info_command(CLI::App& app, int& exit_code);
#if ROTINTERP_HAVE_RENDER
void add_render_command(CLI::App& app, int& exit_code);
#endif

}  // namespace rotinterp::cli
