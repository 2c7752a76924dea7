// What every subcommand shares: exit codes, error and warning lines, usage errors, and
// the table of subcommands. Their options are options.h, the progress line
// progress_line.h, folder runs folder_plan.h.
#pragma once

#include <string>
#include <string_view>

namespace CLI {
class App;
}

namespace rotinterp::cli {

// Exit codes (README "Exit codes").
constexpr int kExitOk = 0;
constexpr int kExitFailure = 1;  // bad input or a failed run
constexpr int kExitUsage = 2;    // the command line itself is wrong
constexpr int kExitPartial = 3;  // eval: some inputs failed, the rest were written

// Out of memory ends a run with one line naming the file it happened on: "rotinterp:
// FILE: out of memory" (main prints it; the line is kept ready, as the handler may
// not allocate). main names the command's first input; a batch names the clip.
void name_out_of_memory_file(const std::string& file);
const char* out_of_memory_line();

// Prints "rotinterp: <message>" on stderr and returns kExitFailure.
int fail(std::string_view message);
// The same for a bad option value, pointing to the running subcommand's help
// ("… (see 'rotinterp render --help')"): returns kExitUsage.
int fail_usage(std::string_view message);
// "see 'rotinterp render --help'" for the subcommand being parsed, else the top help.
std::string help_hint();
// A command-line parse error's one line (without "rotinterp: "): a misspelled
// subcommand names the nearest ("unknown subcommand 'resampel' (did you mean
// 'resample'? …)"), an unknown option the subcommand's nearest option; both end with
// the help hint. `message` is the parser's own text, on one line.
std::string usage_error_line(CLI::App& app, const std::string& message, int argc, char** argv);
// Prints "rotinterp: warning: <message>" on stderr (the reader's and writer's
// on_warning, and the commands' own warnings).
void warn(const std::string& message);

// Every subcommand, added to `app` (main and the vocabulary test build the same app).
void add_commands(CLI::App& app, int& exit_code);

// Each subcommand adds itself to `app`; when it runs, it stores its exit code.
void add_methods_command(CLI::App& app, int& exit_code);
void add_resample_command(CLI::App& app, int& exit_code);
void add_synth_command(CLI::App& app, int& exit_code);
void add_eval_command(CLI::App& app, int& exit_code);
void add_info_command(CLI::App& app, int& exit_code);
void add_reduce_command(CLI::App& app, int& exit_code);
#if ROTINTERP_HAVE_RENDER
void add_render_command(CLI::App& app, int& exit_code);
#endif

}  // namespace rotinterp::cli
