// One vocabulary: every option that means the same in several subcommands is declared
// here, once, with its names, its default and its help (STYLE rule 15), and the
// parsers of their values. `what` is the subcommand's own sentence; the shared part
// is appended.
#pragma once

#include "rotinterp/clip/loop.h"
#include "rotinterp/clip/rate_value.h"
#include "rotinterp/clip/sampling.h"
#include "rotinterp/core/result.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace CLI {
class App;
class Option;
}

namespace rotinterp::cli {

// A whole-number option value in [min, max] ("12", also "1e3"); errors say which of
// not a number / not whole / too small / too large it is.
Result<long long> parse_whole_option(const std::string& option, const std::string& text, long long min, long long max);

// --unit, on every command that reads clips: the unit of a file that states none
// (m, cm, mm, in, ft or metres per unit; clip/units.h). One declaration, one help text.
void add_unit_option(CLI::App& sub, std::string& unit);
// --allow-external-files, on every command that reads clips: a glTF may read buffer
// files outside its folder (ReadOptions::allow_external_files; docs/limits.md).
void add_external_files_option(CLI::App& sub, bool& allow);
// --unit's text as metres per unit; empty text (not given) is none.
Result<std::optional<double>> parse_unit_option(const std::string& text);

// "a,b,,c" → {"a", "b", "c"}: the items of a comma-separated option, empty ones dropped.
std::vector<std::string> split_comma_list(std::string_view text);

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
// --fps HZ: an exact rate (decimal or rational), parsed by parse_rate_value (clip/rate_value.h).
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
// --json: JSON on stdout instead of text.
CLI::Option* add_json_option(CLI::App& sub, bool& json);

}  // namespace rotinterp::cli
