// What every subcommand shares: error lines, usage errors and the table of subcommands.
#include "common.h"

#include "rotinterp/core/nearest_name.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <vector>

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

}  // namespace rotinterp::cli
