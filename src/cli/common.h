// Shared plumbing of the subcommands: exit codes, error lines, progress.
#pragma once

#include "rotinterp/clip/loop.h"
#include "rotinterp/clip/sampling.h"
#include "rotinterp/core/progress.h"
#include "rotinterp/core/result.h"
#include "rotinterp/io/files/formats.h"
#include "rotinterp/batch/dataset.h"
#include "rotinterp/batch/folder_run.h"

#include <filesystem>
#include <functional>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace CLI {
class App;
class Option;
}

namespace rotinterp {
struct FileFailure;
}

namespace rotinterp::cli {

// Exit codes (README "Exit codes").
constexpr int kExitOk = 0;
constexpr int kExitFailure = 1;  // bad input or a failed run
constexpr int kExitUsage = 2;    // the command line itself is wrong
constexpr int kExitPartial = 3;  // eval: some inputs failed, the rest were written

// Largest --keep-every (frames between keys): far above any clip's frame count.
constexpr long long kMaxKeepEvery = 1000000000;

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

// Every long job's progress line, one format: "eval  3/12 files (25%)  1.5 files/s  ETA 6s"
// (`unit` may be empty: "3/12 (25%)  1.5/s"); the rate is done over `seconds` since the
// start, the ETA the rest at that rate ("?" before the first unit is done).
std::string progress_line(const std::string& label, const std::string& unit, std::size_t done, std::size_t total,
                          double seconds);
// "42s", "1m05s", "2h03m".
std::string duration_text(double seconds);
// A progress reporter that draws progress_line on stderr (at most 10 times a second)
// when stderr is a terminal and quiet is false; otherwise an empty function. Thread-safe.
ProgressFn make_progress(std::string label, bool quiet, std::string unit = "");
// Ends the progress line (if one was drawn).
void end_progress(bool quiet);
// A file of a folder run that failed (io/folder_run.h), said the same way by every
// command: the progress line cleared, then "rotinterp: <message>" on stderr. Out of
// memory ends the run instead: main's one line naming the file, exit 1.
void print_file_failure(const FileFailure& failure, bool quiet);

// ---- One vocabulary: every option that means the same in several subcommands is
// declared here, once, with its names, its default and its help (STYLE rule 15).
// `what` is the subcommand's own sentence; the shared part is appended.

// -o,--output: a file or a directory, as `what` says; with `positional`, also the
// positional argument of that name (synth OUT).
CLI::Option* add_output_option(CLI::App& sub, std::string& output, const std::string& what,
                               const char* positional = nullptr);
// -m,--method (also --methods): one method name, or with `several` a comma list or
// "all". Names are checked by parse_methods.
CLI::Option* add_method_option(CLI::App& sub, std::string& methods, bool several, const std::string& default_text);
// Where `source` (io/source_motion.h: the file's own motion, no interpolator of keys)
// runs: "resample -m source, render -m source, eval --truth source". `methods` says it,
// and a command whose -m does not take it refuses it with this line.
extern const char* const kSourceRunsIn;
// Names → the registry's spellings, in order, without repeats ("all": every method
// not listed before it, so "gltf-cubic,all" puts gltf-cubic first).
// Errors: unknown name (with "did you mean"), `source` (where it runs instead: kSourceRunsIn),
// an empty list, or several where one is taken.
Result<std::vector<std::string>> parse_methods(const std::string& text, bool several);
// --fps HZ: an exact rate (decimal or rational), parsed by parse_rate_option.
CLI::Option* add_fps_option(CLI::App& sub, std::string& fps, const std::string& what);
// --keep-every N: keep every Nth frame (and the last) as keys; with `several` a comma list.
CLI::Option* add_keep_every_option(CLI::App& sub, std::string& keep_every, bool several, const std::string& what);
// --range START:END, seconds or frames ("1.5:4", "120f:480f"), parsed by parse_time_range (clip/resample.h).
CLI::Option* add_range_option(CLI::App& sub, std::string& range, const std::string& what);
// --loop [auto|closed|open]: the clip is one period of a cycle (clip/loop.h); default
// off, `--loop` alone detects the form (auto). The text is "off" when not given.
CLI::Option* add_loop_option(CLI::App& sub, std::string& loop, const std::string& what);
// What --loop asked: nothing (off), or a cycle whose form is detected (inner
// nullopt) or forced. Errors: a word other than auto, closed, open.
struct LoopRequest {
  std::optional<LoopForm> form;
};
Result<std::optional<LoopRequest>> parse_loop_option(const std::string& text);
// --anim NAME|INDEX; where `several` says what several takes give, also "all" or a
// comma list (io/takes.h).
CLI::Option* add_anim_option(CLI::App& sub, std::string& anim, const char* several);
// -j,--jobs N: worker threads, 0 = one per core.
CLI::Option* add_jobs_option(CLI::App& sub, int& jobs, const std::string& what);
// -q,--quiet: no progress and no summary; errors and warnings still print.
CLI::Option* add_quiet_option(CLI::App& sub, bool& quiet);
// A folder run's --shard I/N, --skip-existing, --format (`formats`: the formats and
// the default) and --manifest (`manifest_row`: what a row holds), as resample and
// reduce take them.
void add_folder_run_options(CLI::App& sub, std::string& shard, bool& skip_existing, std::string& format,
                            const std::string& formats, std::string& manifest, const std::string& manifest_row);
// What a folder run works on: the named inputs, the clip files found under them
// (shard I/N of them, `shard` as --shard gave it), each one's output as `plan_outputs`
// places it under -o DIR, and each as a run file. The inputs are protected from
// being written over. On error it prints the line and sets `exit_code` (usage for a
// bad --shard, failure otherwise).
struct FolderPlan {
  std::vector<std::filesystem::path> named;
  std::vector<MirroredOutput> outputs;
  std::vector<RunFile> files;
  // How run_files runs it: its named inputs, -j workers, --skip-existing, and each
  // failure printed as its one line (print_file_failure).
  FileRunOptions run_options(int jobs, bool skip_existing, bool quiet) const;
};
using PlanOutputs = std::function<Result<std::vector<MirroredOutput>>(const std::vector<std::string>& files,
                                                                      const std::vector<std::filesystem::path>& named)>;
std::optional<FolderPlan> plan_folder_run(const std::vector<std::string>& inputs, const std::string& shard,
                                          const PlanOutputs& plan_outputs, int& exit_code);
// --json: JSON on stdout instead of text.
CLI::Option* add_json_option(CLI::App& sub, bool& json);

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
