// rotinterp reduce IN -o OUT [--method NAME] [--tolerance-deg DEG] [--tolerance-mm MM [--shell-distance CM]]
//                  [--tolerance-for JOINT=VALUE ...] [--methods LIST|all] [--report FILE.json] [--quiet]
#include "common.h"
#include "rotinterp/clip/metrics.h"
#include "rotinterp/interp/interpolator.h"
#include "rotinterp/io/atomic_file.h"
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
constexpr double kDefaultShellCm = kDefaultReduceShellDistanceCm;
// What a BVH's numbers are taken to be when --unit-scale is not given.
constexpr double kBvhAssumedMetresPerUnit = 0.01;

struct ReduceArgs {
  std::string input, output, method = "slerp", methods, report, anim, translation = "cubic";
  std::string tolerance_deg, tolerance_mm, shell_cm, unit_scale;
  std::vector<std::string> tolerance_for;
  bool quiet = false;
};

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

// A budget value: a finite number > 0.
Result<double> parse_positive(const std::string& option, const std::string& text) {
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || errno == ERANGE || !std::isfinite(v))
    return make_error(option + " '" + text + "' is not a finite number");
  if (!(v > 0.0)) return make_error(option + " '" + text + "' must be > 0");
  return v;
}

// One --tolerance-for item: JOINT=0.5deg, JOINT=2mm or JOINT=0.5deg,2mm (mm: shell
// and translation budget in millimetres).
struct JointBudget {
  std::string joint;
  double deg = 0.0, mm = 0.0;
};
Result<JointBudget> parse_joint_budget(const std::string& item) {
  const std::size_t eq = item.rfind('=');
  const std::string form = "--tolerance-for '" + item + "' must be JOINT=DEGdeg, JOINT=MMmm or JOINT=DEGdeg,MMmm";
  if (eq == std::string::npos || eq == 0 || eq + 1 == item.size()) return make_error(form);
  JointBudget b;
  b.joint = item.substr(0, eq);
  for (const std::string& part : split_comma_list(item.substr(eq + 1))) {
    const bool deg = part.size() > 3 && part.compare(part.size() - 3, 3, "deg") == 0;
    const bool mm = part.size() > 2 && part.compare(part.size() - 2, 2, "mm") == 0;
    if (!deg && !mm) return make_error(form);
    auto v = parse_positive("--tolerance-for " + b.joint, part.substr(0, part.size() - (deg ? 3 : 2)));
    if (!v) return make_error(v.error());
    (deg ? b.deg : b.mm) = *v;
  }
  if (b.deg == 0.0 && b.mm == 0.0) return make_error(form);
  return b;
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
    if (opt.budget.shell > 0.0) joint["max_shell_error_mm"] = rj.max_shell_error * metres_per_unit * 1000.0;
    if (const auto& tr = r.reduced.translations[j]) {
      nlohmann::json tk = nlohmann::json::array();
      for (const Vec3& v : tr->keys) tk.push_back({v.x(), v.y(), v.z()});
      joint["translation"] = {{"frames", rj.translation_frames}, {"times", tr->times}, {"keys", tk}};
      joint["max_translation_error_mm"] = rj.max_translation_error * metres_per_unit * 1000.0;
    }
    joints.push_back(joint);
  }
  const nlohmann::json doc = {
      {"generator", std::string("rotinterp ") + ROTINTERP_VERSION + " reduce"},
      {"source", source.name},
      {"method", run.method},
      {"translation", translation_interp_name(opt.translation)},
      {"frames", r.grid.size()},
      {"frame_time", r.grid.frame_time},
      {"start_time", r.grid.start},
      {"metres_per_unit", metres_per_unit},
      {"quaternion_order", "xyzw"},
      {"budget", budgets},
      {"kept_keys", r.kept_keys},
      {"source_keys", r.source_keys},
      {"joints", joints}};
  return write_file_atomically(path, [&](std::ostream& out) -> Status {
    out << doc.dump(1) << '\n';
    return Ok{};
  });
}

int run_reduce(const ReduceArgs& a) {
  // Everything that can be checked without the input first (exit 2).
  std::vector<std::string> names;
  if (!a.methods.empty()) {
    names = a.methods == "all" ? std::vector<std::string>{} : split_comma_list(a.methods);
    if (a.methods == "all")
      for (const MethodInfo& m : methods()) names.push_back(m.name);
    if (names.empty()) return fail_usage("--methods '" + a.methods + "' names no method");
    for (const std::string& m : names)
      if (!find_method(m)) return fail_usage("unknown method '" + m + "' in --methods (valid: " + method_names() + ")");
  }
  if (!find_method(a.method)) return fail_usage("unknown method '" + a.method + "' (valid: " + method_names() + ")");
  if (a.output.empty() && names.empty()) return fail_usage("give -o OUT (or --methods to compare methods)");
  const std::string ext = a.output.empty() ? "" : lower_extension(a.output);
  const bool gltf = ext == ".glb" || ext == ".gltf";
  if (!a.output.empty() && !gltf && ext != ".json")
    return fail_usage("output '" + a.output + "': unknown format (use .json, .glb or .gltf)");
  if (gltf && a.method != "slerp" && a.method != "gltf-cubic")
    return fail_usage("a glTF viewer replays only --method slerp (LINEAR) or gltf-cubic (CUBICSPLINE); write .json for " +
                      a.method);
  if (!a.report.empty() && lower_extension(a.report) != ".json")
    return fail_usage("--report '" + a.report + "' must name a .json file");
  auto translation = parse_translation_interp(a.translation);
  if (!translation) return fail_usage("--translation: " + translation.error());
  double deg = 0.0, mm = 0.0, shell_cm = kDefaultShellCm, unit = 0.0;
  if (!a.tolerance_deg.empty()) {
    auto v = parse_positive("--tolerance-deg", a.tolerance_deg);
    if (!v) return fail_usage(v.error());
    deg = *v;
  }
  if (!a.tolerance_mm.empty()) {
    auto v = parse_positive("--tolerance-mm", a.tolerance_mm);
    if (!v) return fail_usage(v.error());
    mm = *v;
  }
  if (!a.shell_cm.empty()) {
    if (a.tolerance_mm.empty()) return fail_usage("--shell-distance needs --tolerance-mm");
    auto v = parse_positive("--shell-distance", a.shell_cm);
    if (!v) return fail_usage(v.error());
    shell_cm = *v;
  }
  if (!a.unit_scale.empty()) {
    auto v = parse_positive("--unit-scale", a.unit_scale);
    if (!v) return fail_usage(v.error());
    unit = *v;
  }
  if (deg == 0.0 && mm == 0.0) mm = kDefaultToleranceMm;  // neither: ozz's 1 mm at 10 cm
  std::vector<JointBudget> per_joint;
  for (const std::string& item : a.tolerance_for) {
    auto b = parse_joint_budget(item);
    if (!b) return fail_usage(b.error());
    if (b->mm > 0.0 && mm == 0.0) return fail_usage("--tolerance-for " + item + ": a mm budget needs --tolerance-mm");
    per_joint.push_back(*b);
  }
  protect_input(a.input);
  for (const std::string& out : {a.output, a.report})
    if (!out.empty())
      if (Status s = check_not_an_input(out); !s) return fail(s.error());

  ReadOptions read_options;
  read_options.animation = a.anim;
  auto clip = read_clip(a.input, read_options);
  if (!clip) return fail(clip.error());
  for (const JointBudget& b : per_joint)
    if (clip->skeleton.find(b.joint) < 0)
      return fail_usage("--tolerance-for: " + a.input + " has no joint named '" + b.joint + "'");

  // Millimetres in clip units: the clip's own unit, or for BVH (which has none) the assumption, said once.
  if (unit == 0.0) {
    unit = clip->unit_scale > 0.0 && std::isfinite(clip->unit_scale) ? clip->unit_scale : 1.0;
    if (clip->source_format == "bvh") {
      unit = kBvhAssumedMetresPerUnit;
      if (!a.quiet && mm > 0.0)
        warn(a.input + ": BVH states no unit; its numbers are taken as centimetres (--unit-scale METRES to change)");
    }
  }
  auto units = [unit](double millimetres) { return millimetres / 1000.0 / unit; };
  ReduceOptions opt;
  opt.translation = *translation;
  opt.budget.rotation_deg = deg;
  opt.budget.shell = units(mm);
  opt.budget.translation = units(mm > 0.0 ? mm : kDefaultToleranceMm);
  opt.shell_distance = units(shell_cm * 10.0);
  for (const JointBudget& b : per_joint) {
    ReduceBudget rb;
    rb.rotation_deg = b.deg;
    rb.shell = units(b.mm);
    rb.translation = units(b.mm);
    opt.budget_for.emplace_back(b.joint, rb);
  }
  nlohmann::json budgets = {{"tolerance_deg", deg > 0.0 ? nlohmann::json(deg) : nlohmann::json(nullptr)},
                            {"tolerance_mm", mm > 0.0 ? nlohmann::json(mm) : nlohmann::json(nullptr)},
                            {"shell_distance_cm", mm > 0.0 ? nlohmann::json(shell_cm) : nlohmann::json(nullptr)},
                            {"translation_tolerance_mm", translation_tolerance({deg, mm, mm > 0.0 ? mm : kDefaultToleranceMm})},
                            {"metres_per_unit", unit}};
  nlohmann::json per = nlohmann::json::object();
  for (const JointBudget& b : per_joint) {
    nlohmann::json& e = per[b.joint];
    if (b.deg > 0.0) e["tolerance_deg"] = b.deg;
    if (b.mm > 0.0) e["tolerance_mm"] = b.mm;
  }
  if (!per.empty()) budgets["per_joint"] = per;

  // The runs: each of --methods in its order, then --method for the output if not among them.
  std::vector<std::string> order = names;
  if (!a.output.empty() && std::find(order.begin(), order.end(), a.method) == order.end()) order.push_back(a.method);
  std::vector<MethodRun> runs;
  for (const std::string& m : order) {
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
      run.max_shell_mm = std::max(run.max_shell_mm, j.max_shell_error * unit * 1000.0);
      run.max_translation_mm = std::max(run.max_translation_mm, j.max_translation_error * unit * 1000.0);
      run.rotation_keys += j.rotation_frames.size();
      run.translation_keys += j.translation_frames.size();
    }
    run.result = std::move(*r);
    runs.push_back(std::move(run));
  }

  if (!a.output.empty()) {
    const MethodRun& run = *std::find_if(runs.begin(), runs.end(), [&](const MethodRun& r) { return r.method == a.method; });
    Status written = Ok{};
    if (gltf) {
      WriteOptions w;
      w.gltf_own_key_times = true;
      w.gltf_cubic_rotations = a.method == "gltf-cubic";
      w.gltf_cubic_translations = opt.translation == TranslationInterp::cubic;
      w.on_warning = warn;
      written = write_clip(run.result.reduced, a.output, w);
    } else {
      opt.method = run.method;
      written = write_keys_json(a.output, *clip, run, opt, unit, budgets);
    }
    if (!written) return fail(written.error());
  }
  if (!a.report.empty()) {
    nlohmann::json list = nlohmann::json::array();
    for (const MethodRun& r : runs) list.push_back(run_json(r));
    const nlohmann::json report = {{"generator", std::string("rotinterp ") + ROTINTERP_VERSION + " reduce"},
                                   {"input", a.input},
                                   {"frames", runs.front().result.grid.size()},
                                   {"joints", clip->skeleton.joints.size()},
                                   {"translation", translation_interp_name(opt.translation)},
                                   {"budget", budgets},
                                   {"methods", list}};
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
    const MethodRun& r = *std::find_if(runs.begin(), runs.end(), [&](const MethodRun& x) { return x.method == a.method; });
    fmt::print("{} → {}: method {}, {} frames, {} of {} keys kept ({:.2f} %), max {:.4f}° local{}, {:.3f} s\n", a.input,
               a.output, r.method, r.result.grid.size(), r.result.kept_keys, r.result.source_keys,
               100.0 * static_cast<double>(r.result.kept_keys) / static_cast<double>(std::max<std::size_t>(1, r.result.source_keys)),
               r.max_rotation_deg, mm > 0.0 ? fmt::format(", {:.4f} mm shell", r.max_shell_mm) : std::string(), r.seconds);
  }
  return kExitOk;
}

}  // namespace

void add_reduce_command(CLI::App& app, int& exit_code) {
  auto* sub = app.add_subcommand("reduce", "Keep the fewest keys per joint that rebuild the clip within an error budget");
  auto a = std::make_shared<ReduceArgs>();
  sub->add_option("IN", a->input, "Input clip (BVH, FBX, glTF/GLB, Collada, … — anything assimp reads)")->required();
  sub->add_option("-o,--output", a->output,
                  "Output: .json (per joint the kept key frames, times and values) or .glb/.gltf (sparse keys, "
                  "LINEAR for slerp, CUBICSPLINE for gltf-cubic)");
  sub->add_option("--method", a->method, "Interpolator the keys are chosen for (see 'rotinterp methods'); default slerp");
  sub->add_option("--tolerance-deg", a->tolerance_deg, "Budget on each joint's local rotation error, degrees (> 0)");
  sub->add_option("--tolerance-mm", a->tolerance_mm,
                  "Budget on the virtual-vertex (shell) error in object space, millimetres, with the ancestors' rebuilt "
                  "motion; also the translation tracks' budget (1 mm when only --tolerance-deg is given). Default 1 (at 10 cm) "
                  "when no --tolerance-deg is given");
  sub->add_option("--shell-distance", a->shell_cm, "Virtual-vertex distance from each joint, centimetres (default 10)");
  sub->add_option("--tolerance-for", a->tolerance_for,
                  "Per-joint budget JOINT=DEGdeg, JOINT=MMmm or JOINT=DEGdeg,MMmm (repeatable)");
  sub->add_option("--methods", a->methods, "Run the selection for each method of LIST (or all) and print a table");
  sub->add_option("--report", a->report, "Write the table as JSON to FILE.json");
  sub->add_option("--translation", a->translation,
                  "Translation curve: linear, or cubic (default: Steffen's, never overshoots)");
  sub->add_option("--unit-scale", a->unit_scale,
                  "Metres per clip unit, overriding the file's (BVH states none and is taken as centimetres: 0.01)");
  sub->add_option("--anim", a->anim, "Animation to read: its name or index (default the first)");
  sub->add_flag("-q,--quiet", a->quiet, "No progress and no summary line");
  sub->callback([a, &exit_code] { exit_code = run_reduce(*a); });
}

}  // namespace rotinterp::cli
