// The subcommands' shared plumbing: error lines, the shared options and their parsers, progress.
#include "common.h"

#include "rotinterp/clip/units.h"
#include "rotinterp/core/nearest_name.h"
#include "rotinterp/interp/interpolator.h"
#include "rotinterp/io/files/atomic_file.h"
#include "rotinterp/batch/folder_run.h"
#include "rotinterp/io/source_motion.h"

#include <CLI/CLI.hpp>

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <mutex>
#include <new>

namespace rotinterp::cli {

namespace {
char oom_line[600] = "rotinterp: out of memory\n";
}  // namespace

void name_out_of_memory_file(const std::string& file) {
  if (file.size() < 400) std::snprintf(oom_line, sizeof oom_line, "rotinterp: %s: out of memory\n", file.c_str());
}

const char* out_of_memory_line() { return oom_line; }

int fail(std::string_view message) {
  std::fprintf(stderr, "rotinterp: %.*s\n", static_cast<int>(message.size()), message.data());
  return kExitFailure;
}

namespace {
// The subcommand being parsed (set by its preparse callback): usage errors name its help.
std::string current_command;  // NOLINT: one per process, written only by the parser's thread
}  // namespace

std::string help_hint() {
  return current_command.empty() ? "run 'rotinterp --help'" : "see 'rotinterp " + current_command + " --help'";
}

int fail_usage(std::string_view message) {
  fail(std::string(message) + " (" + help_hint() + ")");
  return kExitUsage;
}

void warn(const std::string& message) { std::fprintf(stderr, "rotinterp: warning: %s\n", message.c_str()); }

namespace {

// `text` as a finite double when all of it is one (strtod's forms: 1e9, -30, 0x1p4).
bool whole_text_number(const std::string& text, double& value) {
  if (text.empty() || std::isspace(static_cast<unsigned char>(text[0]))) return false;
  errno = 0;
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size() && std::isfinite(value);
}

}  // namespace

Result<Rate> parse_rate_option(const std::string& option, const std::string& text) {
  auto rate = parse_rate(text);
  if (rate) return rate;
  double v = 0;
  if (!whole_text_number(text, v)) return rate.failure(option + ": ");
  const std::string quoted = "'" + text + "'";
  if (v <= 0) return make_error(option + " " + quoted + " must be greater than 0");
  // In range but in a form parse_rate does not read (1e3): the same value as the
  // shortest decimal that reads back as it. Any number ≥ 1 so written reads unless
  // it is above parse_rate's limit.
  char buf[400];
  const auto printed = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed);
  if (auto again = parse_rate(std::string_view(buf, static_cast<std::size_t>(printed.ptr - buf)))) return again;
  if (v >= 1) return make_error(option + " " + quoted + " is out of range (at most 1e9 Hz)");
  return make_error(option + " " + quoted + " is too small or too precise for an exact rate; use a ratio such as 1/3600");
}

Result<long long> parse_whole_option(const std::string& option, const std::string& text, long long min, long long max) {
  const std::string quoted = "'" + text + "'";
  const std::string range = "from " + std::to_string(min) + " to " + std::to_string(max);
  double v = 0;
  if (!whole_text_number(text, v)) return make_error(option + " " + quoted + " is not a number (a whole number " + range + ")");
  if (v < static_cast<double>(min)) return make_error(option + " " + quoted + " is too small (a whole number " + range + ")");
  if (v > static_cast<double>(max)) return make_error(option + " " + quoted + " is too large (a whole number " + range + ")");
  if (v != std::floor(v)) return make_error(option + " " + quoted + " is not a whole number (" + range + ")");
  return static_cast<long long>(v);
}

void add_unit_option(CLI::App& sub, std::string& unit) {
  sub.add_option("--unit", unit,
                 "Unit of a file that states none (BVH): m, cm, mm, in, ft or metres per unit. Default: inferred "
                 "from the figure's size (info shows it); a file that declares its unit (FBX, glTF) keeps it");
}

Result<std::optional<double>> parse_unit_option(const std::string& text) {
  if (text.empty()) return std::optional<double>();
  auto v = parse_unit(text);
  if (!v) return v.failure("--unit: ");
  return std::optional<double>(*v);
}

std::vector<std::string> split_comma_list(std::string_view text) {
  std::vector<std::string> items;
  for (std::size_t begin = 0; begin <= text.size();) {
    const std::size_t comma = std::min(text.find(',', begin), text.size());
    if (comma > begin) items.emplace_back(text.substr(begin, comma - begin));
    begin = comma + 1;
  }
  return items;
}

CLI::Option* add_output_option(CLI::App& sub, std::string& output, const std::string& what, const char* positional) {
  return sub.add_option(positional ? std::string(positional) + ",-o,--output" : "-o,--output", output, what);
}

CLI::Option* add_method_option(CLI::App& sub, std::string& methods, bool several, const std::string& default_text) {
  const std::string help = several ? "Interpolators: a name, a comma list or 'all' (see 'rotinterp methods'; any case); "
                                   : "Interpolator (see 'rotinterp methods'; any case); ";
  return sub.add_option("-m,--method,--methods", methods, help + "default " + default_text);
}

const char* const kSourceRunsIn = "resample -m source, render -m source, eval --truth source";

Result<std::vector<std::string>> parse_methods(const std::string& text, bool several) {
  std::vector<std::string> names;
  const std::vector<std::string> items = split_comma_list(text);
  for (const std::string& item : items) {
    if (several && (item == "all" || item == "ALL")) {  // every method not listed yet, in the registry's order
      for (const MethodInfo& m : methods())
        if (std::find(names.begin(), names.end(), m.name) == names.end()) names.push_back(m.name);
      continue;
    }
    const MethodInfo* m = find_method(item);
    if (!m && is_source_method(item))
      return make_error("--method '" + item + "' replays the file's own motion, it rebuilds nothing from keys: " +
                        "this command cannot run it (it runs in " + kSourceRunsIn + ")");
    if (!m) return make_error("--method: " + unknown_method_message(item));
    if (std::find(names.begin(), names.end(), m->name) == names.end()) names.push_back(m->name);
  }
  if (names.empty()) return make_error("--method '" + text + "' names no method (valid: " + method_names() + ")");
  if (!several && names.size() > 1) return make_error("--method '" + text + "': this command takes one method");
  return names;
}

CLI::Option* add_fps_option(CLI::App& sub, std::string& fps, const std::string& what) {
  return sub.add_option("--fps", fps, "Frame rate in Hz, a decimal (30, 59.94) or a rational (30000/1001); " + what);
}

CLI::Option* add_keep_every_option(CLI::App& sub, std::string& keep_every, bool several, const std::string& what) {
  return sub.add_option("--keep-every", keep_every,
                        std::string(several ? "Key spacings N, comma-separated" : "Key spacing N") +
                            ": keep every Nth frame (and the last) as keys, rebuild the rest; " + what);
}

CLI::Option* add_range_option(CLI::App& sub, std::string& range, const std::string& what) {
  return sub.add_option("--range", range,
                        "START:END from the first frame, in seconds (1.5:4) or frames (120f:480f), either side may "
                        "be empty; " + what);
}

CLI::Option* add_loop_option(CLI::App& sub, std::string& loop, const std::string& what) {
  return sub
      .add_option("--loop", loop,
                  "[auto|closed|open] The clip is a cycle, played end to start: closed (the last frame repeats the "
                  "first) or open (the last frame is one step before the first); alone or 'auto' detects the form "
                  "(within 0.5° per joint and 1 cm of root height). Default off. " + what)
      ->expected(0, 1);
}

Result<std::optional<LoopRequest>> parse_loop_option(const std::string& text) {
  if (text == "off") return std::optional<LoopRequest>();
  auto form = parse_loop_form(text);
  if (!form) return form.failure();
  return std::optional<LoopRequest>(LoopRequest{*form});
}

CLI::Option* add_anim_option(CLI::App& sub, std::string& anim, const char* several) {
  return sub.add_option("--anim", anim,
                        std::string("Animation (take) to read: its name or 0-based index") +
                            (several ? std::string(", 'all', or a comma list of names and indices (") + several + ")"
                                     : std::string()) +
                            "; default the first");
}

CLI::Option* add_jobs_option(CLI::App& sub, int& jobs, const std::string& what) {
  return sub.add_option("-j,--jobs", jobs, what + " (0 = one per core)")->capture_default_str()->check(CLI::Range(0, 4096));
}

CLI::Option* add_quiet_option(CLI::App& sub, bool& quiet) {
  return sub.add_flag("-q,--quiet", quiet, "No progress and no summary (errors and warnings still print)");
}

void add_folder_run_options(CLI::App& sub, std::string& shard, bool& skip_existing, std::string& format,
                            const std::string& formats, std::string& manifest, const std::string& manifest_row) {
  sub.add_option("--shard", shard, "Folder runs: only shard I of N (I/N) of the sorted inputs, for a cluster (default: all)");
  sub.add_flag("--skip-existing", skip_existing,
               "Folder runs: leave outputs that exist (an output is only ever complete), to resume a run "
               "(default: replace them)");
  sub.add_option("--format", format, "Folder runs: output format " + formats);
  sub.add_option("--manifest", manifest, "Folder runs: write a CSV row per file (" + manifest_row + "); default none");
}

std::optional<FolderPlan> plan_folder_run(const std::vector<std::string>& inputs, const std::string& shard,
                                          const PlanOutputs& plan_outputs, int& exit_code) {
  FolderPlan run;
  run.named.assign(inputs.begin(), inputs.end());
  int shard_index = 1, shard_count = 1;
  if (!shard.empty()) {
    auto parsed = parse_shard(shard);
    if (!parsed) {
      exit_code = fail_usage(parsed.error());
      return std::nullopt;
    }
    std::tie(shard_index, shard_count) = *parsed;
  }
  auto files = find_run_inputs(run.named, shard_index, shard_count);
  if (!files) {
    exit_code = fail(files.error());
    return std::nullopt;
  }
  auto outputs = plan_outputs(*files, run.named);
  if (!outputs) {
    exit_code = fail(outputs.error());
    return std::nullopt;
  }
  run.outputs = std::move(*outputs);
  for (const MirroredOutput& m : run.outputs) {
    protect_input(m.input);
    run.files.push_back({m.input, m.output});
  }
  return run;
}

FileRunOptions FolderPlan::run_options(int jobs, bool skip_existing, bool quiet) const {
  FileRunOptions o;
  o.named = named;
  o.threads = thread_count(static_cast<unsigned>(jobs));
  o.skip_existing = skip_existing;
  o.on_failure = [quiet](const FileFailure& f) { print_file_failure(f, quiet); };
  return o;
}

CLI::Option* add_json_option(CLI::App& sub, bool& json) {
  return sub.add_flag("--json", json, "Print JSON on stdout instead of text");
}

void add_commands(CLI::App& app, int& exit_code) {
  add_methods_command(app, exit_code);
  add_resample_command(app, exit_code);
  add_synth_command(app, exit_code);
  add_eval_command(app, exit_code);
  add_info_command(app, exit_code);
  add_reduce_command(app, exit_code);
#if ROTINTERP_HAVE_RENDER
  add_render_command(app, exit_code);
#endif
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) {
    const std::string name = sub->get_name();
    sub->preparse_callback([name](std::size_t) { current_command = name; });
  }
}

std::string usage_error_line(CLI::App& app, const std::string& message, int argc, char** argv) {
  const auto parsed = app.get_subcommands();
  if (parsed.empty()) {  // no subcommand: argv[1], if a word, is a misspelled one
    if (argc > 1 && argv[1][0] != '-') {
      std::vector<std::string> names;
      for (const CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) names.push_back(sub->get_name());
      const auto best = nearest_name(argv[1], names);
      return std::string("unknown subcommand '") + argv[1] + "' (" + (best ? "did you mean '" + *best + "'? " : "") +
             help_hint() + ")";
    }
    return message + " (" + help_hint() + ")";
  }
  // An option the subcommand does not have ("--fsp", "-x"; not a value such as "-30"):
  // the nearest of its options.
  const CLI::App& sub = *parsed.front();
  std::vector<std::string> names;
  for (const CLI::Option* o : sub.get_options()) {
    for (const std::string& l : o->get_lnames()) names.push_back("--" + l);
    for (const std::string& s : o->get_snames()) names.push_back("-" + s);
  }
  for (int i = 2; i < argc; ++i) {
    std::string a = argv[i];
    if (a.size() < 2 || a[0] != '-' || !(std::isalpha(static_cast<unsigned char>(a[1])) || a[1] == '-')) continue;
    a = a.substr(0, a.find('='));
    if (std::find(names.begin(), names.end(), a) != names.end()) continue;
    if (const auto best = nearest_name(a, names)) return message + " (did you mean '" + *best + "'? " + help_hint() + ")";
  }
  return message + " (" + help_hint() + ")";
}

static bool progress_visible(bool quiet) { return !quiet && ::isatty(STDERR_FILENO); }

std::string duration_text(double seconds) {
  const auto s = static_cast<long long>(std::llround(seconds));
  char text[48];
  if (s >= 3600) std::snprintf(text, sizeof text, "%lldh%02lldm", s / 3600, s / 60 % 60);
  else if (s >= 60) std::snprintf(text, sizeof text, "%lldm%02llds", s / 60, s % 60);
  else std::snprintf(text, sizeof text, "%llds", s);
  return text;
}

std::string progress_line(const std::string& label, const std::string& unit, std::size_t done, std::size_t total,
                          double seconds) {
  const int pct = total ? static_cast<int>(100.0 * static_cast<double>(done) / static_cast<double>(total)) : 100;
  const double rate = seconds > 0.0 ? static_cast<double>(done) / seconds : 0.0;
  const std::string per = unit.empty() ? "/s" : " " + unit + "/s";
  char text[256];
  std::snprintf(text, sizeof text, "%s  %zu/%zu%s%s (%d%%)  %.3g%s  ETA %s", label.c_str(), done, total,
                unit.empty() ? "" : " ", unit.c_str(), pct, rate, per.c_str(),
                rate > 0.0 ? duration_text(static_cast<double>(total - std::min(done, total)) / rate).c_str() : "?");
  return text;
}

ProgressFn make_progress(std::string label, bool quiet, std::string unit) {
  if (!progress_visible(quiet)) return {};
  struct State {
    std::mutex mutex;
    std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now();
    std::chrono::steady_clock::time_point last{};
  };
  auto state = std::make_shared<State>();
  return [label = std::move(label), unit = std::move(unit), state](std::size_t done, std::size_t total) {
    std::lock_guard<std::mutex> lock(state->mutex);
    const auto now = std::chrono::steady_clock::now();
    if (done < total && now - state->last < std::chrono::milliseconds(100)) return;  // at most 10 redraws/s
    state->last = now;
    const double seconds = std::chrono::duration<double>(now - state->started).count();
    std::fprintf(stderr, "\r\033[K%s", progress_line(label, unit, done, total, seconds).c_str());
    std::fflush(stderr);
  };
}

void end_progress(bool quiet) {
  if (progress_visible(quiet)) std::fprintf(stderr, "\r\033[K");
}

void print_file_failure(const FileFailure& failure, bool quiet) {
  if (failure.kind == ErrorKind::out_of_memory) {
    name_out_of_memory_file(failure.file);
    throw std::bad_alloc();
  }
  end_progress(quiet);
  fail(failure.message);
}

}  // namespace rotinterp::cli
