// reduce's options and its one-file run (one file's work is cmd_reduce_file.cpp, the folder run cmd_reduce_folder.cpp).
// rotinterp reduce IN -o OUT [-m NAME|LIST|all] [--tolerance 0.5deg,1mm] [--shell-distance 10cm]
//                  [--tolerance-for JOINT=LIST ...] [--report FILE.json] [--loop [auto|closed|open]] [--unit U] [--quiet]
// -m with several methods runs the selection for each and prints a table; -o OUT is
// written with the first.
// rotinterp reduce PATH... -o OUTDIR [the same] [-j N] [--shard I/N] [--skip-existing] [--format EXT]
//                  [--manifest FILE.csv]: a whole dataset, its layout mirrored under OUTDIR.
#include "cmd_reduce.h"
#include "common.h"
#include "options.h"
#include "rotinterp/io/files/atomic_file.h"
#include "rotinterp/io/files/formats.h"
#include "rotinterp/io/takes.h"
#include "rotinterp/reduce/reduce.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <memory>
#include <string>
#include <system_error>
#include <vector>

namespace rotinterp::cli {

namespace {

constexpr double kDefaultToleranceMm = kDefaultReduceToleranceMm;
constexpr double kDefaultShellMetres = kDefaultReduceShellDistanceCm / 100.0;

// One --tolerance-for item: JOINT=LIST, LIST as --tolerance takes it.
Result<JointBudget> parse_joint_budget(const std::string& item) {
  const std::size_t eq = item.rfind('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == item.size())
    return make_error("--tolerance-for '" + item + "' must be JOINT=0.5deg, JOINT=2mm or JOINT=0.5deg,2mm");
  BudgetText b;
  if (Status s = add_budget_items("--tolerance-for " + item.substr(0, eq), item.substr(eq + 1), b); !s)
    return s.failure();
  return JointBudget{item.substr(0, eq), b.deg, b.mm};
}

}  // namespace

Result<ReduceSetup> parse_reduce_setup(const ReduceArgs& a) {
  ReduceSetup s;
  auto listed = parse_methods(a.methods, true);
  if (!listed) return listed.failure();
  s.methods = *listed;
  auto translation = parse_translation_interp(a.translation);
  if (!translation) return make_error("--translation: " + translation.error());
  s.translation = *translation;
  BudgetText budget;
  for (const std::string& list : a.tolerance)
    if (Status st = add_budget_items("--tolerance", list, budget); !st) return st.failure();
  s.deg = budget.deg;
  s.mm = budget.mm;
  s.shell_m = kDefaultShellMetres;
  if (!a.shell_distance.empty()) {
    if (s.mm == 0.0) return make_error("--shell-distance needs a length budget (--tolerance 1mm)");
    auto v = parse_length(a.shell_distance);
    if (!v) return make_error("--shell-distance: " + v.error());
    s.shell_m = *v;
  }
  auto unit = parse_unit_option(a.unit);
  if (!unit) return unit.failure();
  s.unit_m = *unit;
  auto loop = parse_loop_option(a.loop);
  if (!loop) return loop.failure();
  s.loop = *loop;
  if (s.deg == 0.0 && s.mm == 0.0) s.mm = kDefaultToleranceMm;  // neither: ozz's 1 mm at 10 cm
  for (const std::string& item : a.tolerance_for) {
    auto b = parse_joint_budget(item);
    if (!b) return b.failure();
    if (b->mm > 0.0 && s.mm == 0.0) return make_error("--tolerance-for " + item + ": a length budget needs one in --tolerance");
    s.per_joint.push_back(*b);
  }
  return s;
}

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

std::string reduce_output_problem(const std::string& output, const std::string& method, bool loop) {
  const std::string ext = lower_extension(output);
  const FormatInfo* format = format_named(ext);
  const bool fbx = format && format->id == FormatId::fbx, gltf = format && format->curves && !fbx;
  if (!gltf && !fbx && ext != ".json")
    return "output '" + output + "': unknown format (use .json, " + format_names(keeps_curves, " or ", true) + ")";
  if (gltf && method != "slerp" && method != "gltf-cubic")
    return "a glTF viewer replays only --method slerp (LINEAR) or gltf-cubic (CUBICSPLINE); write .json for " + method;
  if (fbx && loop) return "--loop: FBX curves have no periodic form; write .json, .glb or .gltf for a cycle";
  return "";
}

namespace {

int run_reduce(const ReduceArgs& a) {
  // Everything that can be checked without the input first (exit 2).
  auto setup = parse_reduce_setup(a);
  if (!setup) return fail_usage(setup.error());
  std::error_code ec;
  // One file in, one out, as always; a folder run when given a folder, several
  // inputs, --format, an output ending with '/' or an existing directory (resample's rule).
  const bool into_directory =
      !a.output.empty() && (a.output.back() == '/' || std::filesystem::is_directory(a.output, ec));
  const bool one_file = a.inputs.size() == 1 && !std::filesystem::is_directory(a.inputs.front(), ec) &&
                        !into_directory && a.format.empty();
  const bool several = names_several_takes(a.anim) || a.output.find(kTakePlaceholder) != std::string::npos ||
                       a.report.find(kTakePlaceholder) != std::string::npos;
  if (!one_file && several)
    return fail_usage("--anim " + a.anim + " takes several takes of one input file; a folder run reads one take of each");
  if (!one_file) return run_reduce_folder(a, *setup);
  if (several && a.output.find(kTakePlaceholder) == std::string::npos && !a.output.empty())
    return fail_usage("--anim " + a.anim + ": reduce writes one take per file; put " + kTakePlaceholder +
                      " in the output name (and in --report's)");
  if (several && !a.report.empty() && a.report.find(kTakePlaceholder) == std::string::npos)
    return fail_usage("--anim " + a.anim + ": put " + kTakePlaceholder + " in --report's name too (a report per take)");
  if (!a.shard.empty() || !a.manifest.empty() || a.skip_existing)
    return fail_usage("--shard, --manifest and --skip-existing are for folder runs (-o DIR)");
  if (!a.output.empty())
    if (std::string problem = reduce_output_problem(a.output, setup->methods.front(), setup->loop.has_value());
        !problem.empty())
      return fail_usage(problem);
  if (!a.report.empty() && lower_extension(a.report) != ".json")
    return fail_usage("--report '" + a.report + "' must name a .json file");
  const std::string& input = a.inputs.front();
  protect_input(input);
  for (const std::string& out : {a.output, a.report})
    if (!out.empty())
      if (Status s = check_not_an_input(out); !s) return fail(s.error());

  std::vector<TakeRef> takes = {TakeRef{0, a.anim}};
  if (several) {
    ReadOptions read_options;
    read_options.unit = setup->unit_m;
    read_options.allow_external_files = a.allow_external_files;
    read_options.on_warning = warn;
    auto chosen = select_takes(input, a.anim, read_options);
    if (!chosen) return fail(chosen.error());
    takes = std::move(*chosen);
  }
  // A take each: {anim} in the output (and report) names is its name (io/takes.h).
  for (const TakeRef& take : takes) {
    ReduceArgs one = a;
    if (several) one.anim = std::to_string(take.index);
    ReduceFileOptions o;
    o.output = several ? with_take_name(a.output, take) : a.output;
    o.report = several ? with_take_name(a.report, take) : a.report;
    o.show_progress = !a.quiet;
    ReduceFileRun run;
    if (Status s = reduce_one_file(input, one, *setup, o, run); !s)
      return run.usage_error ? fail_usage(s.error()) : fail(s.error());
  }
  return kExitOk;
}

}  // namespace

void add_reduce_command(CLI::App& app, int& exit_code) {
  auto* sub = app.add_subcommand("reduce", "Keep the fewest keys per joint that rebuild the clip within an error budget");
  auto a = std::make_shared<ReduceArgs>();
  sub->add_option("IN", a->inputs,
                  "Input clip (BVH, FBX, glTF/GLB, Collada, … — anything assimp reads); several, or folders "
                  "(searched recursively), with -o DIR")
      ->required();
  add_output_option(*sub, a->output,
                    "Output: .json (per joint the kept key frames, times and values), .glb/.gltf (sparse keys, "
                    "LINEAR for slerp, CUBICSPLINE for gltf-cubic; from a glTF character, the source with only its "
                    "animation replaced) or .fbx (sparse Euler curves replaying the method: "
                    "linear keys for slerp/nlerp, cubic keys with user tangents for the others, keys added where our "
                    "reader's replay would miss the budget; no --loop); default none: print the table. For several inputs "
                    "or a folder: the output directory, the inputs' layout mirrored under it");
  add_method_option(*sub, a->methods, true,
                    "slerp. The keys are chosen for it; with several, each is run and tabled, and -o gets the first");
  sub->add_option("--tolerance", a->tolerance,
                  "Error budget, each item with its unit: an angle (0.5deg, 0.01rad) on each joint's local rotation, "
                  "and/or a length (1mm, 0.1cm) on the virtual-vertex (shell) error in object space with the "
                  "ancestors' rebuilt motion, also the translation tracks' budget (1mm when only an angle is given). "
                  "Default 1mm");
  sub->add_option("--shell-distance", a->shell_distance,
                  "Virtual-vertex distance from each joint: a length (10cm); a bare number is metres. Default 10cm");
  sub->add_option("--tolerance-for", a->tolerance_for,
                  "Per-joint budget JOINT=LIST, LIST as --tolerance takes it (repeatable; default none)");
  sub->add_option("--report", a->report, "Write the table as JSON to FILE.json (default none)");
  sub->add_option("--translation", a->translation,
                  "Translation curve: linear, or cubic (default: Steffen's, never overshoots)");
  add_loop_option(*sub, a->loop,
                  "Keys are chosen on each joint's periodic curve (wrap-around neighbours, the root with its "
                  "per-cycle offset) and the seam is one key; the output closes: each looped track's last key is its "
                  "first again, one period on.");
  add_unit_option(*sub, a->unit);
  add_external_files_option(*sub, a->allow_external_files);
  add_anim_option(*sub, a->anim, "a file per take: {anim} in the output name is the take's name");
  add_quiet_option(*sub, a->quiet);
  add_jobs_option(*sub, a->jobs, "Folder runs: files reduced at once");
  add_folder_run_options(*sub, a->shard, a->skip_existing, a->format,
                         "json, glb, gltf or fbx (default: the input's own where reduce writes it — fbx, glb, gltf "
                         "— else json)",
                         a->manifest, "frames, joints, keys kept of the source's, largest errors, method, time, status");
  sub->callback([a, &exit_code] { exit_code = run_reduce(*a); });
}

}  // namespace rotinterp::cli
