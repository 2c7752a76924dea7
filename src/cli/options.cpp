// The options every subcommand declares the same way, and the parsers of their values.
#include "options.h"

#include "rotinterp/clip/units.h"
#include "rotinterp/interp/interpolator.h"
#include "rotinterp/io/source_motion.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace rotinterp::cli {

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

void add_external_files_option(CLI::App& sub, bool& allow) {
  sub.add_flag("--allow-external-files", allow,
               "glTF: also read buffer files outside the file's folder (a uri with '..', an absolute path, a link "
               "leading out). Default: refused, so that a file from elsewhere cannot make rotinterp read /etc");
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

CLI::Option* add_json_option(CLI::App& sub, bool& json) {
  return sub.add_flag("--json", json, "Print JSON on stdout instead of text");
}

}  // namespace rotinterp::cli
