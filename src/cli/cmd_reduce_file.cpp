// One file's reduce: read, reduce with each method, write the keys (JSON, glTF or FBX) and the report.
#include "cmd_reduce.h"
#include "common.h"
#include "progress_line.h"
#include "rotinterp/clip/units.h"
#include "rotinterp/interp/interpolator.h"
#include "rotinterp/io/files/atomic_file.h"
#include "rotinterp/io/fbx/fbx_reduced.h"
#include "rotinterp/io/files/formats.h"
#include "rotinterp/io/files/json_text.h"
#include "rotinterp/io/files/written_names.h"
#include "rotinterp/io/read.h"
#include "rotinterp/io/write.h"
#include "rotinterp/reduce/reduce.h"

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace rotinterp::cli {

namespace {


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
nlohmann::json loop_json(const LoopCheck& c, const std::vector<std::string>& names) {
  nlohmann::json misses = nlohmann::json::array();
  for (const ClosureMiss& m : c.misses) misses.push_back({{"joint", names[m.joint]}, {"angle_deg", m.angle * 180.0 / kPi}});
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
  const std::vector<std::string> names = written_joint_names(source.skeleton, NameForm::text);
  for (std::size_t j = 0; j < r.joints.size(); ++j) {
    const ReducedJoint& rj = r.joints[j];
    const RotationTrack& rt = r.reduced.rotations[j];
    nlohmann::json rot_keys = nlohmann::json::array();
    for (const Quat& q : rt.keys) rot_keys.push_back({q.x(), q.y(), q.z(), q.w()});
    nlohmann::json joint = {{"name", names[j]},
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
      {"source", readable_text(source.name)},
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
  if (r.cycle) doc["loop"] = loop_json(*r.cycle, names);
  return write_file_atomically(path, [&](std::ostream& out) -> Status {
    out << json_text(doc, 1) << '\n';
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

// The kept keys as FBX curves replaying the method (io/fbx/fbx_reduced.h), refused
// unless our reader's replay of the file is within the budget at every frame.
Status write_reduced_fbx(const std::string& path, const Clip& source, const std::string& input, const MethodRun& run,
                         const ReduceOptions& opt, bool quiet, std::string& kept) {
  FbxReducedOptions o;
  // A character's file with its reduced curves (io/fbx/fbx_character.h), else the skeleton alone.
  std::optional<FbxCharacter> character;
  if (keeps_fbx_character(source, input)) {
    auto read = read_fbx_character(input);
    if (read) character = std::move(*read);
    else warn(path + ": the character is not kept: " + read.error());
  }
  o.character = character ? &*character : nullptr;
  o.method = run.method;
  o.translation = opt.translation;
  o.shell_distance = opt.shell_distance;
  for (const ReducedJoint& j : run.result.joints) o.budgets.push_back({j.budget.rotation_deg, j.budget.shell, j.budget.translation});
  auto fbx = encode_reduced_fbx(run.result.reduced, source, o);
  if (!fbx) return make_error(path + ": " + fbx.error());
  if (!character)
    if (const std::string lost = meshes_not_written(source, path); !lost.empty()) warn(lost);
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
  if (fbx->kept) kept = path + ": " + fbx->kept->text();
  return write_file_atomically(path, [&](std::ostream& out) -> Status {
    out.write(fbx->bytes.data(), static_cast<std::streamsize>(fbx->bytes.size()));
    return Ok{};
  });
}

}  // namespace

Status reduce_one_file(const std::string& input, const ReduceArgs& a, const ReduceSetup& s,
                       const ReduceFileOptions& o, ReduceFileRun& file_run) {
  const std::string& method = s.methods.front();
  const double deg = s.deg, mm = s.mm, shell_m = s.shell_m;
  // The table lists every method when there are several, or when there is no output to write.
  const std::vector<std::string> names =
      s.methods.size() > 1 || o.output.empty() ? s.methods : std::vector<std::string>{};
  const std::string ext = o.output.empty() ? "" : lower_extension(o.output);
  const FormatInfo* format = ext.empty() ? nullptr : format_named(ext);
  const bool fbx = format && format->id == FormatId::fbx, gltf = format && format->curves && !fbx;

  ReadOptions read_options;
  read_options.animation = a.anim;
  read_options.unit = s.unit_m;
  read_options.allow_external_files = a.allow_external_files;
  read_options.on_warning = warn;
  auto clip = read_clip(input, read_options);
  if (!clip) return clip.failure();
  for (const JointBudget& b : s.per_joint)
    if (clip->skeleton.find(b.joint) < 0) {
      file_run.usage_error = true;
      return make_error("--tolerance-for: " + input + " has no joint named '" + b.joint + "'");
    }
  file_run.joints = clip->skeleton.joints.size();

  // Budgets in clip units, through the clip's one unit (clip/units.h).
  const double metres_per_unit = clip->unit.metres_per_unit;
  auto units = [&](double millimetres) { return in_clip_units(*clip, millimetres / 1000.0); };
  ReduceOptions opt;
  opt.threads = o.threads;
  opt.translation = s.translation;
  opt.budget.rotation_deg = deg;
  opt.budget.shell = units(mm);
  opt.budget.translation = units(mm > 0.0 ? mm : kDefaultReduceToleranceMm);
  opt.shell_distance = in_clip_units(*clip, shell_m);
  opt.loop = s.loop.has_value();
  if (s.loop) opt.loop_form = s.loop->form;
  for (const JointBudget& b : s.per_joint) {
    ReduceBudget rb;
    rb.rotation_deg = b.deg;
    rb.shell = units(b.mm);
    rb.translation = units(b.mm);
    opt.budget_for.emplace_back(b.joint, rb);
  }
  nlohmann::json budgets = {{"tolerance_deg", deg > 0.0 ? nlohmann::json(deg) : nlohmann::json(nullptr)},
                            {"tolerance_mm", mm > 0.0 ? nlohmann::json(mm) : nlohmann::json(nullptr)},
                            {"shell_distance_cm", mm > 0.0 ? nlohmann::json(shell_m * 100.0) : nlohmann::json(nullptr)},
                            {"translation_tolerance_mm", translation_tolerance({deg, mm, mm > 0.0 ? mm : kDefaultReduceToleranceMm})},
                            {"metres_per_unit", metres_per_unit},
                            {"unit", describe_unit(clip->unit)}};
  nlohmann::json per = nlohmann::json::object();
  for (const JointBudget& b : s.per_joint) {
    nlohmann::json& e = per[b.joint];
    if (b.deg > 0.0) e["tolerance_deg"] = b.deg;
    if (b.mm > 0.0) e["tolerance_mm"] = b.mm;
  }
  if (!per.empty()) budgets["per_joint"] = per;

  // The runs: each method listed, in its order.
  const bool quiet = !o.show_progress;
  std::vector<MethodRun> runs;
  for (const std::string& m : s.methods) {
    const auto started = std::chrono::steady_clock::now();
    opt.method = m;
    opt.progress = make_progress("reduce " + m, quiet, "joints");
    auto r = reduce_clip(*clip, opt);
    end_progress(quiet);
    if (!r) return make_error(input + ": " + r.error());
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
  const MethodRun& first = runs.front();
  file_run.frames = first.result.grid.size();
  file_run.source_keys = first.result.source_keys;
  file_run.kept_keys = first.result.kept_keys;
  file_run.max_rotation_deg = first.max_rotation_deg;
  file_run.max_shell_mm = first.max_shell_mm;
  file_run.seconds = first.seconds;

  if (!o.output.empty()) {
    Status written = Ok{};
    if (gltf) {
      WriteOptions w;
      w.gltf_own_key_times = true;
      w.gltf_cubic_rotations = method == "gltf-cubic";
      w.gltf_cubic_translations = opt.translation == TranslationInterp::cubic;
      w.on_warning = warn;
      w.source = input;
      w.on_kept = [&file_run](const std::string& kept) { file_run.kept = kept; };
      written = write_clip(first.result.reduced, o.output, w);
    } else if (fbx) {
      written = write_reduced_fbx(o.output, *clip, input, first, opt, a.quiet || !o.print, file_run.kept);
    } else {
      opt.method = first.method;
      written = write_keys_json(o.output, *clip, first, opt, metres_per_unit, budgets);
    }
    if (!written) return written;
  }
  if (!o.report.empty()) {
    nlohmann::json list = nlohmann::json::array();
    for (const MethodRun& r : runs) list.push_back(run_json(r));
    nlohmann::json report = {{"generator", std::string("rotinterp ") + ROTINTERP_VERSION + " reduce"},
                             {"input", input},
                             {"frames", first.result.grid.size()},
                             {"joints", clip->skeleton.joints.size()},
                             {"translation", translation_interp_name(opt.translation)},
                             {"budget", budgets},
                             {"methods", list}};
    if (first.result.cycle)
      report["loop"] = loop_json(*first.result.cycle, written_joint_names(clip->skeleton, NameForm::text));
    const Status written = write_file_atomically(o.report, [&](std::ostream& out) -> Status {
      out << json_text(report, 1) << '\n';
      return Ok{};
    });
    if (!written) return written;
  }
  if (!o.print) return Ok{};

  if (!names.empty()) {
    fmt::print("{:<11} {:>9} {:>8} {:>12} {:>11} {:>9}\n", "method", "keys", "% kept", "max err deg", "max err mm", "seconds");
    for (const MethodRun& r : runs) {
      if (std::find(names.begin(), names.end(), r.method) == names.end()) continue;
      const double pct = 100.0 * static_cast<double>(r.result.kept_keys) / static_cast<double>(std::max<std::size_t>(1, r.result.source_keys));
      fmt::print("{:<11} {:>9} {:>8.2f} {:>12.4f} {:>11} {:>9.3f}\n", r.method, r.result.kept_keys, pct, r.max_rotation_deg,
                 mm > 0.0 ? fmt::format("{:.4f}", r.max_shell_mm) : std::string("-"), r.seconds);
    }
  }
  if (!a.quiet && !o.output.empty()) {
    const MethodRun& r = first;
    fmt::print("{} → {}: method {}, {} frames, {} of {} keys kept ({:.2f} %), max {:.4f}° local{}, {:.3f} s\n", input,
               o.output, r.method, r.result.grid.size(), r.result.kept_keys, r.result.source_keys,
               100.0 * static_cast<double>(r.result.kept_keys) / static_cast<double>(std::max<std::size_t>(1, r.result.source_keys)),
               r.max_rotation_deg, mm > 0.0 ? fmt::format(", {:.4f} mm shell", r.max_shell_mm) : std::string(), r.seconds);
  }
  if (!a.quiet && first.result.cycle) fmt::print("  {}\n", cycle_text(first.result));
  if (!a.quiet && !file_run.kept.empty()) fmt::print("  {}\n", file_run.kept);
  return Ok{};
}

}  // namespace rotinterp::cli
