// rotinterp reduce IN -o OUT [-m NAME|LIST|all] [--tolerance 0.5deg,1mm] [--shell-distance 10cm]
//                  [--tolerance-for JOINT=LIST ...] [--report FILE.json] [--loop [auto|closed|open]] [--unit U] [--quiet]
// -m with several methods runs the selection for each and prints a table; -o OUT is
// written with the first.
#include "common.h"
#include "rotinterp/clip/units.h"
#include "rotinterp/interp/interpolator.h"
#include "rotinterp/io/atomic_file.h"
#include "rotinterp/io/fbx_reduced.h"
#include "rotinterp/io/read.h"
#include "rotinterp/io/write.h"
#include "rotinterp/reduce/reduce.h"

#include <CLI/CLI.hpp>
#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace rotinterp::cli {

namespace {

constexpr double kDefaultToleranceMm = kDefaultReduceToleranceMm;
constexpr double kDefaultShellMetres = kDefaultReduceShellDistanceCm / 100.0;

struct ReduceArgs {
  std::string input, output, methods = "slerp", report, anim, translation = "cubic";
  std::string shell_distance, unit, loop = "off";
  std::vector<std::string> tolerance, tolerance_for;
  bool quiet = false;
};

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

// One --tolerance-for item: JOINT=LIST, LIST as --tolerance takes it.
struct JointBudget {
  std::string joint;
  double deg = 0.0, mm = 0.0;
};
Result<JointBudget> parse_joint_budget(const std::string& item) {
  const std::size_t eq = item.rfind('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == item.size())
    return make_error("--tolerance-for '" + item + "' must be JOINT=0.5deg, JOINT=2mm or JOINT=0.5deg,2mm");
  BudgetText b;
  if (Status s = add_budget_items("--tolerance-for " + item.substr(0, eq), item.substr(eq + 1), b); !s)
    return s.failure();
  return JointBudget{item.substr(0, eq), b.deg, b.mm};
}

struct MethodRun {
  std::string method;
  ReduceResult result;
  double seconds = 0.0;
  double max_rotation_deg = 0.0, max_shell_mm = 0.0, max_translation_mm = 0.0;
  std::size_t rotation_keys = 0, translation_keys = 0;
};

nlohmann::json run_json(const MethodRun& r) {
  return {{"method", r.method},
          {"kept_keys", r.result.kept_keys},
          {"source_keys", r.result.source_keys},
          {"kept_percent", 100.0 * static_cast<double>(r.result.kept_keys) / static_cast<double>(std::max<std::size_t>(1, r.result.source_keys))},
          {"rotation_keys", r.rotation_keys},
          {"translation_keys", r.translation_keys},
          {"max_rotation_error_deg", r.max_rotation_deg},
          {"max_shell_error_mm", r.max_shell_mm},
          {"max_translation_error_mm", r.max_translation_mm},
          {"seconds", r.seconds}};
}

// A cycle as the keys file and the report state it: its form and period, the joints that
// miss closure (reduced with their ends, as without --loop).
nlohmann::json loop_json(const LoopCheck& c) {
  nlohmann::json misses = nlohmann::json::array();
  for (const ClosureMiss& m : c.misses) misses.push_back({{"joint", m.name}, {"angle_deg", m.angle * 180.0 / kPi}});
  return {{"form", loop_form_name(c.form)},
          {"period_frames", c.period_frames},
          {"period", c.period},
          {"misses", misses}};
}

// The keys file: per joint the kept frames, their times and values.
Status write_keys_json(const std::filesystem::path& path, const Clip& source, const MethodRun& run,
                       const ReduceOptions& opt, double metres_per_unit, const nlohmann::json& budgets) {
  const ReduceResult& r = run.result;
  nlohmann::json joints = nlohmann::json::array();
  for (std::size_t j = 0; j < r.joints.size(); ++j) {
    const ReducedJoint& rj = r.joints[j];
    const RotationTrack& rt = r.reduced.rotations[j];
    nlohmann::json rot_keys = nlohmann::json::array();
    for (const Quat& q : rt.keys) rot_keys.push_back({q.x(), q.y(), q.z(), q.w()});
    nlohmann::json joint = {{"name", source.skeleton.joints[j].name},
                            {"parent", source.skeleton.joints[j].parent},
                            {"rotation", {{"frames", rj.rotation_frames}, {"times", rt.times}, {"keys", rot_keys}}},
                            {"max_rotation_error_deg", rj.max_rotation_error * 180.0 / kPi}};
    if (r.cycle) joint["looped"] = rj.looped;
    if (opt.budget.shell > 0.0) joint["max_shell_error_mm"] = rj.max_shell_error * metres_per_unit * 1000.0;
    if (const auto& tr = r.reduced.translations[j]) {
      nlohmann::json tk = nlohmann::json::array();
      for (const Vec3& v : tr->keys) tk.push_back({v.x(), v.y(), v.z()});
      joint["translation"] = {{"frames", rj.translation_frames}, {"times", tr->times}, {"keys", tk}};
      joint["max_translation_error_mm"] = rj.max_translation_error * metres_per_unit * 1000.0;
    }
    joints.push_back(joint);
  }
  nlohmann::json doc = {
      {"generator", std::string("rotinterp ") + ROTINTERP_VERSION + " reduce"},
      {"source", source.name},
      {"method", run.method},
      {"translation", translation_interp_name(opt.translation)},
      {"frames", r.grid.size()},
      {"frame_time", r.grid.frame_time},  // exact: 1/rate, as resample writes
      {"frame_rate", r.grid.rate ? nlohmann::json(r.grid.rate->to_string()) : nlohmann::json(nullptr)},
      {"start_time", r.grid.start},
      {"metres_per_unit", metres_per_unit},
      {"quaternion_order", "xyzw"},
      {"budget", budgets},
      {"kept_keys", r.kept_keys},
      {"source_keys", r.source_keys},
      {"joints", joints}};
  if (r.cycle) doc["loop"] = loop_json(*r.cycle);
  return write_file_atomically(path, [&](std::ostream& out) -> Status {
    out << doc.dump(1) << '\n';
    return Ok{};
  });
}

// "cycle (closed form): 38 frames per period of 1.267 s, 37 of 38 joints looped (the seam one key); 1 joint misses closure (…): L_Arm 4.39°,
// reduced with its ends".
std::string cycle_text(const ReduceResult& r) {
  const LoopCheck& c = *r.cycle;
  const auto looped = std::count_if(r.joints.begin(), r.joints.end(), [](const ReducedJoint& j) { return j.looped; });
  std::string s = fmt::format("cycle ({} form): {} frames per period of {:.4g} s, {} of {} joints looped (the seam one key)",
                              loop_form_name(c.form), c.period_frames, c.period, looped, r.joints.size());
  if (!c.misses.empty()) s += "; " + closure_misses_text(c.misses) + ", reduced with its ends";
  return s;
}

// The kept keys as FBX curves replaying the method (io/fbx_reduced.h), refused
// unless our reader's replay of the file is within the budget at every frame.
Status write_reduced_fbx(const std::string& path, const Clip& source, const MethodRun& run, const ReduceOptions& opt,
                         bool quiet) {
  FbxReducedOptions o;
  o.method = run.method;
  o.translation = opt.translation;
  o.shell_distance = opt.shell_distance;
  for (const ReducedJoint& j : run.result.joints) o.budgets.push_back({j.budget.rotation_deg, j.budget.shell, j.budget.translation});
  auto fbx = encode_reduced_fbx(run.result.reduced, source, o);
  if (!fbx) return make_error(path + ": " + fbx.error());
  const double mm = source.unit.metres_per_unit * 1000.0;
  if (!fbx->within_budget)
    return make_error(fmt::format("{}: the FBX Euler curves miss the budget even keyed with the source's values "
                                  "(max {:.4f}° local, {:.4f} mm shell, {:.4f} mm translation); not written",
                                  path, fbx->max_rotation_error_deg, fbx->max_shell_error * mm, fbx->max_translation_error * mm));
  if (!quiet)
    fmt::print("FBX curves: {} rotation + {} translation keys ({} kept, {} added where the Euler curves miss the method's, "
               "{} set to the source's value); replayed by our reader: max {:.4f}° local, {:.4f} mm shell, {:.4f} mm "
               "translation\n",
               fbx->rotation_keys, fbx->translation_keys, run.result.kept_keys, fbx->added_keys, fbx->corrected_keys,
               fbx->max_rotation_error_deg, fbx->max_shell_error * mm, fbx->max_translation_error * mm);
  return write_file_atomically(path, [&](std::ostream& out) -> Status {
    out.write(fbx->bytes.data(), static_cast<std::streamsize>(fbx->bytes.size()));
    return Ok{};
  });
}

int run_reduce(const ReduceArgs& a) {
  // Everything that can be checked without the input first (exit 2).
  auto listed = parse_methods(a.methods, true);
  if (!listed) return fail_usage(listed.error());
  // The output's method is the first; the table lists them all when there are
  // several, or when there is no output to write.
  const std::string method = listed->front();
  const std::vector<std::string> names = listed->size() > 1 || a.output.empty() ? *listed : std::vector<std::string>{};
  const std::string ext = a.output.empty() ? "" : lower_extension(a.output);
  const bool gltf = ext == ".glb" || ext == ".gltf", fbx = ext == ".fbx";
  if (!a.output.empty() && !gltf && !fbx && ext != ".json")
    return fail_usage("output '" + a.output + "': unknown format (use .json, .glb, .gltf or .fbx)");
  if (gltf && method != "slerp" && method != "gltf-cubic")
    return fail_usage("a glTF viewer replays only --method slerp (LINEAR) or gltf-cubic (CUBICSPLINE); write .json for " +
                      method);
  if (!a.report.empty() && lower_extension(a.report) != ".json")
    return fail_usage("--report '" + a.report + "' must name a .json file");
  auto translation = parse_translation_interp(a.translation);
  if (!translation) return fail_usage("--translation: " + translation.error());
  BudgetText budget;
  for (const std::string& list : a.tolerance)
    if (Status s = add_budget_items("--tolerance", list, budget); !s) return fail_usage(s.error());
  double deg = budget.deg, mm = budget.mm, shell_m = kDefaultShellMetres;
  if (!a.shell_distance.empty()) {
    if (mm == 0.0) return fail_usage("--shell-distance needs a length budget (--tolerance 1mm)");
    auto v = parse_length(a.shell_distance);
    if (!v) return fail_usage("--shell-distance: " + v.error());
    shell_m = *v;
  }
  auto unit = parse_unit_option(a.unit);
  if (!unit) return fail_usage(unit.error());
  auto loop = parse_loop_option(a.loop);
  if (!loop) return fail_usage(loop.error());
  if (fbx && loop->has_value())
    return fail_usage("--loop: FBX curves have no periodic form; write .json, .glb or .gltf for a cycle");
  if (deg == 0.0 && mm == 0.0) mm = kDefaultToleranceMm;  // neither: ozz's 1 mm at 10 cm
  std::vector<JointBudget> per_joint;
  for (const std::string& item : a.tolerance_for) {
    auto b = parse_joint_budget(item);
    if (!b) return fail_usage(b.error());
    if (b->mm > 0.0 && mm == 0.0) return fail_usage("--tolerance-for " + item + ": a length budget needs one in --tolerance");
    per_joint.push_back(*b);
  }
  protect_input(a.input);
  for (const std::string& out : {a.output, a.report})
    if (!out.empty())
      if (Status s = check_not_an_input(out); !s) return fail(s.error());

  ReadOptions read_options;
  read_options.animation = a.anim;
  read_options.unit = *unit;
  read_options.on_warning = warn;
  auto clip = read_clip(a.input, read_options);
  if (!clip) return fail(clip.error());
  for (const JointBudget& b : per_joint)
    if (clip->skeleton.find(b.joint) < 0)
      return fail_usage("--tolerance-for: " + a.input + " has no joint named '" + b.joint + "'");

  // Budgets in clip units, through the clip's one unit (clip/units.h).
  const double metres_per_unit = clip->unit.metres_per_unit;
  auto units = [&](double millimetres) { return in_clip_units(*clip, millimetres / 1000.0); };
  ReduceOptions opt;
  opt.translation = *translation;
  opt.budget.rotation_deg = deg;
  opt.budget.shell = units(mm);
  opt.budget.translation = units(mm > 0.0 ? mm : kDefaultToleranceMm);
  opt.shell_distance = in_clip_units(*clip, shell_m);
  opt.loop = loop->has_value();
  if (*loop) opt.loop_form = (*loop)->form;
  for (const JointBudget& b : per_joint) {
    ReduceBudget rb;
    rb.rotation_deg = b.deg;
    rb.shell = units(b.mm);
    rb.translation = units(b.mm);
    opt.budget_for.emplace_back(b.joint, rb);
  }
  nlohmann::json budgets = {{"tolerance_deg", deg > 0.0 ? nlohmann::json(deg) : nlohmann::json(nullptr)},
                            {"tolerance_mm", mm > 0.0 ? nlohmann::json(mm) : nlohmann::json(nullptr)},
                            {"shell_distance_cm", mm > 0.0 ? nlohmann::json(shell_m * 100.0) : nlohmann::json(nullptr)},
                            {"translation_tolerance_mm", translation_tolerance({deg, mm, mm > 0.0 ? mm : kDefaultToleranceMm})},
                            {"metres_per_unit", metres_per_unit},
                            {"unit", describe_unit(clip->unit)}};
  nlohmann::json per = nlohmann::json::object();
  for (const JointBudget& b : per_joint) {
    nlohmann::json& e = per[b.joint];
    if (b.deg > 0.0) e["tolerance_deg"] = b.deg;
    if (b.mm > 0.0) e["tolerance_mm"] = b.mm;
  }
  if (!per.empty()) budgets["per_joint"] = per;

  // The runs: each method listed, in its order.
  std::vector<MethodRun> runs;
  for (const std::string& m : *listed) {
    const auto started = std::chrono::steady_clock::now();
    opt.method = m;
    opt.progress = make_progress("reduce " + m, a.quiet);
    auto r = reduce_clip(*clip, opt);
    end_progress(a.quiet);
    if (!r) return fail(a.input + ": " + r.error());
    MethodRun run;
    run.method = m;
    run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    for (const ReducedJoint& j : r->joints) {
      run.max_rotation_deg = std::max(run.max_rotation_deg, j.max_rotation_error * 180.0 / kPi);
      run.max_shell_mm = std::max(run.max_shell_mm, j.max_shell_error * metres_per_unit * 1000.0);
      run.max_translation_mm = std::max(run.max_translation_mm, j.max_translation_error * metres_per_unit * 1000.0);
      run.rotation_keys += j.rotation_frames.size();
      run.translation_keys += j.translation_frames.size();
    }
    run.result = std::move(*r);
    runs.push_back(std::move(run));
  }

  if (!a.output.empty()) {
    const MethodRun& run = runs.front();
    Status written = Ok{};
    if (gltf) {
      WriteOptions w;
      w.gltf_own_key_times = true;
      w.gltf_cubic_rotations = method == "gltf-cubic";
      w.gltf_cubic_translations = opt.translation == TranslationInterp::cubic;
      w.on_warning = warn;
      written = write_clip(run.result.reduced, a.output, w);
    } else if (fbx) {
      written = write_reduced_fbx(a.output, *clip, run, opt, a.quiet);
    } else {
      opt.method = run.method;
      written = write_keys_json(a.output, *clip, run, opt, metres_per_unit, budgets);
    }
    if (!written) return fail(written.error());
  }
  if (!a.report.empty()) {
    nlohmann::json list = nlohmann::json::array();
    for (const MethodRun& r : runs) list.push_back(run_json(r));
    nlohmann::json report = {{"generator", std::string("rotinterp ") + ROTINTERP_VERSION + " reduce"},
                                   {"input", a.input},
                                   {"frames", runs.front().result.grid.size()},
                                   {"joints", clip->skeleton.joints.size()},
                                   {"translation", translation_interp_name(opt.translation)},
                                   {"budget", budgets},
                                   {"methods", list}};
    if (runs.front().result.cycle) report["loop"] = loop_json(*runs.front().result.cycle);
    const Status s = write_file_atomically(a.report, [&](std::ostream& out) -> Status {
      out << report.dump(1) << '\n';
      return Ok{};
    });
    if (!s) return fail(s.error());
  }

  if (!names.empty()) {
    fmt::print("{:<11} {:>9} {:>8} {:>12} {:>11} {:>9}\n", "method", "keys", "% kept", "max err deg", "max err mm", "seconds");
    for (const MethodRun& r : runs) {
      if (std::find(names.begin(), names.end(), r.method) == names.end()) continue;
      const double pct = 100.0 * static_cast<double>(r.result.kept_keys) / static_cast<double>(std::max<std::size_t>(1, r.result.source_keys));
      fmt::print("{:<11} {:>9} {:>8.2f} {:>12.4f} {:>11} {:>9.3f}\n", r.method, r.result.kept_keys, pct, r.max_rotation_deg,
                 mm > 0.0 ? fmt::format("{:.4f}", r.max_shell_mm) : std::string("-"), r.seconds);
    }
  }
  if (!a.quiet && !a.output.empty()) {
    const MethodRun& r = runs.front();
    fmt::print("{} → {}: method {}, {} frames, {} of {} keys kept ({:.2f} %), max {:.4f}° local{}, {:.3f} s\n", a.input,
               a.output, r.method, r.result.grid.size(), r.result.kept_keys, r.result.source_keys,
               100.0 * static_cast<double>(r.result.kept_keys) / static_cast<double>(std::max<std::size_t>(1, r.result.source_keys)),
               r.max_rotation_deg, mm > 0.0 ? fmt::format(", {:.4f} mm shell", r.max_shell_mm) : std::string(), r.seconds);
  }
  if (!a.quiet && runs.front().result.cycle) fmt::print("  {}\n", cycle_text(runs.front().result));
  return kExitOk;
}

}  // namespace

void add_reduce_command(CLI::App& app, int& exit_code) {
  auto* sub = app.add_subcommand("reduce", "Keep the fewest keys per joint that rebuild the clip within an error budget");
  auto a = std::make_shared<ReduceArgs>();
  sub->add_option("IN", a->input, "Input clip (BVH, FBX, glTF/GLB, Collada, … — anything assimp reads)")->required();
  add_output_option(*sub, a->output,
                    "Output: .json (per joint the kept key frames, times and values), .glb/.gltf (sparse keys, "
                    "LINEAR for slerp, CUBICSPLINE for gltf-cubic) or .fbx (sparse Euler curves replaying the method: "
                    "linear keys for slerp/nlerp, cubic keys with user tangents for the others, keys added where our "
                    "reader's replay would miss the budget; no --loop); default none: print the table");
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
  add_anim_option(*sub, a->anim, false);
  add_quiet_option(*sub, a->quiet);
  sub->callback([a, &exit_code] { exit_code = run_reduce(*a); });
}

}  // namespace rotinterp::cli
