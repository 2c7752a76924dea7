// Shared plumbing of the subcommands: exit codes, error lines, progress.
#pragma once

#include "rotinterp/clip/sampling.h"
#include "rotinterp/core/progress.h"
#include "rotinterp/core/result.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace CLI {
class App;
}

namespace rotinterp::cli {

// Exit codes (README "Exit codes").
constexpr int kExitOk = 0;
constexpr int kExitFailure = 1;  // bad input or a failed run
constexpr int kExitUsage = 2;    // the command line itself is wrong
constexpr int kExitPartial = 3;  // eval: some inputs failed, the rest were written

// Largest --keep-every (frames between keys): far above any clip's frame count.
constexpr long long kMaxKeepEvery = 1000000000;

// Prints "rotinterp: <message>" on stderr and returns kExitFailure.
int fail(std::string_view message);
// The same for a bad option value: returns kExitUsage.
int fail_usage(std::string_view message);
// Prints "rotinterp: warning: <message>" on stderr (the reader's and writer's
// on_warning, and the commands' own warnings).
void warn(const std::string& message);

// A frame-rate option (--fps): parse_rate's forms, plus plain numbers it does not
// take (exponent notation: 1e3); a number out of range is called that, with the
// range, not "not a number". Errors start with the option name.
Result<Rate> parse_rate_option(const std::string& option, const std::string& text);
// A whole-number option value in [min, max] ("12", also "1e3"); errors say which of
// not a number / not whole / too small / too large it is.
Result<long long> parse_whole_option(const std::string& option, const std::string& text, long long min, long long max);

// --unit, on every command that reads clips: the unit of a file that states none
// (m, cm, mm, in, ft or metres per unit; clip/units.h). One declaration, one help text.
void add_unit_option(CLI::App& sub, std::string& unit);
// --unit's text as metres per unit; empty text (not given) is none.
Result<std::optional<double>> parse_unit_option(const std::string& text);

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
void add_reduce_command(CLI::App& app, int& exit_code);
#if ROTINTERP_HAVE_RENDER
void add_render_command(CLI::App& app, int& exit_code);
#endif

}  // namespace rotinterp::cli
