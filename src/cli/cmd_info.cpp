// rotinterp info CLIP [--json] [--anim NAME|INDEX]: what a clip file holds.
// rotinterp info CLIP --curves [--sample HZ] [--json]: an FBX file's curves as stored.
// rotinterp info PATH... --summary [--json] [-j N]: a dataset's files, its rate
// histogram and what looks wrong (rate labels, uneven keys, empty clips, copies).
#include "common.h"
#include "folder_plan.h"
#include "options.h"
#include "progress_line.h"
#include "info_curves.h"
#include "rotinterp/io/files/json_text.h"
#include "rotinterp/clip/loop.h"
#include "rotinterp/core/work_queue.h"
#include "rotinterp/batch/dataset.h"
#include "rotinterp/batch/folder_run.h"
#include "rotinterp/io/files/formats.h"
#include "rotinterp/io/info.h"
#include "rotinterp/io/files/file_errors.h"

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <nlohmann/json.hpp>

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace rotinterp::cli {

namespace {

struct InfoArgs {
  std::vector<std::string> paths;
  std::string anim, unit;
  bool allow_external_files = false;
  bool json = false;
  bool summary = false;
  bool curves = false;
  double sample_hz = 0.0;
  int jobs = 0;
};

// One file of a summary.
struct FileSummary {
  std::string file, format, error;
  ErrorKind error_kind = ErrorKind::other;
  std::size_t animations = 0, frames = 0, joints = 0;
  std::string frame_time;    // as written (BVH), else empty
  std::optional<Rate> rate;  // as recognized
  double duration = 0.0;
  std::vector<std::string> notes;  // oddities, the rate label, empty clip, copies
  ClipUnit unit;
};

// The reading options of both forms of info: --anim, --unit, --allow-external-files.
Result<ReadOptions> info_read_options(const InfoArgs& args) {
  ReadOptions options;
  options.animation = args.anim;
  options.allow_external_files = args.allow_external_files;
  auto unit = parse_unit_option(args.unit);
  if (!unit) return unit.failure();
  options.unit = *unit;
  return options;
}

FileSummary summarize(const std::string& file, const ReadOptions& options) {
  FileSummary s;
  s.file = file;
  Result<ClipFileInfo> info = inspect_clip(file, options);
  if (!info) {
    s.error = info.error();
    s.error_kind = info.error_kind();
    return s;
  }
  const ClipFacts facts = clip_facts(*info);
  s.format = info->format;
  s.animations = info->animations.size();
  s.frames = facts.frames;
  s.joints = facts.joints.size();
  s.frame_time = facts.frame_time_written;
  s.rate = facts.rate;
  s.duration = facts.duration;
  s.unit = info->clip.unit;
  if (!(s.duration > 0.0)) s.notes.push_back(fmt::format("zero-length clip ({} frame{})", s.frames, s.frames == 1 ? "" : "s"));
  if (std::string note = rate_label_note(info->clip); !note.empty()) s.notes.push_back(note);
  for (const std::string& o : facts.oddities) s.notes.push_back(o);
  return s;
}

std::string rate_key(const FileSummary& s) { return s.rate ? s.rate->to_string() + " Hz" : "no uniform rate"; }

int run_summary(const InfoArgs& args) {
  std::vector<std::filesystem::path> named(args.paths.begin(), args.paths.end());
  auto files = discover_inputs(named);
  if (!files) return fail(files.error());
  auto read_options = info_read_options(args);
  if (!read_options) return fail_usage(read_options.error());
  ReadOptions options = *read_options;
  // Warnings belong to the files' rows, not to stderr.
  options.on_warning = [](const std::string&) {};
  std::vector<FileSummary> all(files->size());
  std::vector<RunFile> run;
  for (const std::string& f : *files) run.push_back({f, {}});
  FileRunOptions run_options;
  run_options.named = named;
  run_options.threads = thread_count(static_cast<unsigned>(args.jobs));
  run_options.progress = make_progress("info", false, "files");
  run_options.on_failure = [](const FileFailure& f) { print_file_failure(f, false); };
  const FileRunReport report = run_files(run, run_options, [&](std::size_t i, unsigned threads) -> Status {
    ReadOptions mine = options;
    mine.threads = threads;
    all[i] = summarize((*files)[i], mine);
    if (!all[i].error.empty()) return make_error(all[i].error, all[i].error_kind);
    return Ok{};
  });
  end_progress(false);
  // Meshes found next to the clips are not part of the dataset (as eval skips them).
  std::vector<FileSummary> rows;
  for (std::size_t i = 0; i < all.size(); ++i)
    if (report.outcomes[i].status != FileStatus::no_animation) rows.push_back(std::move(all[i]));
  std::map<std::string, std::size_t> row_of;
  for (std::size_t i = 0; i < rows.size(); ++i) row_of[rows[i].file] = i;
  const auto copies = duplicate_files(*files);
  for (const auto& group : copies)
    for (const std::string& f : group) {
      std::string others;
      for (const std::string& g : group)
        if (g != f) others += (others.empty() ? "" : ", ") + g;
      if (row_of.count(f)) rows[row_of[f]].notes.push_back("same bytes as " + others);
    }
  std::map<std::string, std::size_t> histogram;
  std::size_t unreadable = 0, flagged = 0;
  for (const FileSummary& s : rows) {
    if (!s.error.empty()) {
      ++unreadable;
      continue;
    }
    ++histogram[rate_key(s)];
    flagged += !s.notes.empty();
  }
  std::vector<std::pair<std::string, std::size_t>> rates(histogram.begin(), histogram.end());
  std::stable_sort(rates.begin(), rates.end(), [](const auto& x, const auto& y) { return x.second > y.second; });

  if (args.json) {
    nlohmann::json out;
    out["files"] = nlohmann::json::array();
    for (const FileSummary& s : rows) {
      nlohmann::json row = {{"file", s.file}};
      if (!s.error.empty()) {
        row["error"] = s.error;
      } else {
        row.update({{"format", s.format},
                    {"animations", s.animations},
                    {"frames", s.frames},
                    {"frame_time_written", s.frame_time.empty() ? nlohmann::json(nullptr) : nlohmann::json(s.frame_time)},
                    {"frame_rate", s.rate ? nlohmann::json(s.rate->to_string()) : nlohmann::json(nullptr)},
                    {"frame_rate_hz", s.rate ? nlohmann::json(s.rate->hz()) : nlohmann::json(nullptr)},
                    {"duration_s", s.duration},
                    {"unit", nlohmann::json::parse(unit_info_json(s.unit))},
                    {"joints", s.joints},
                    {"notes", s.notes}});
      }
      out["files"].push_back(row);
    }
    out["rates"] = nlohmann::json::array();
    for (const auto& [rate, count] : rates) out["rates"].push_back({{"rate", rate}, {"files", count}});
    out["duplicates"] = copies;
    out["unreadable"] = unreadable;
    out["flagged"] = flagged;
    fmt::print("{}\n", json_text(out, 2));
  } else {
    std::size_t width = 4;
    for (const FileSummary& s : rows) width = std::max(width, s.file.size());
    fmt::print("{:<{}}  {:<6} {:>12} {:>10} {:>8} {:>10} {:>6}  {:<17} {}\n", "file", width, "format", "rate",
               "frame time", "frames", "duration", "joints", "unit", "notes");
    for (const FileSummary& s : rows) {
      if (!s.error.empty()) {
        fmt::print("{:<{}}  unreadable: {}\n", s.file, width, s.error);
        continue;
      }
      std::string notes;
      for (const std::string& n : s.notes) notes += (notes.empty() ? "" : "; ") + n;
      fmt::print("{:<{}}  {:<6} {:>12} {:>10} {:>8} {:>9.3f}s {:>6}  {:<17} {}\n", s.file, width, s.format,
                 s.rate ? s.rate->to_string() + " Hz" : "none", s.frame_time.empty() ? "-" : s.frame_time, s.frames,
                 s.duration, s.joints,
                 unit_name(s.unit.metres_per_unit) + " (" + unit_origin_name(s.unit.origin) + ")", notes);
    }
    fmt::print("\n{} file{}: {} read, {} unreadable, {} with notes, {} group{} of identical files\n", rows.size(),
               rows.size() == 1 ? "" : "s", rows.size() - unreadable, unreadable, flagged, copies.size(),
               copies.size() == 1 ? "" : "s");
    fmt::print("rates:\n");
    for (const auto& [rate, count] : rates) fmt::print("  {:>16}  {} file{}\n", rate, count, count == 1 ? "" : "s");
  }
  return unreadable > 0 ? kExitPartial : kExitOk;
}

// A file without animation (a static mesh) is still described: what it holds, exit 0.
int describe_static(const std::string& path, const std::string& holds, bool json) {
  std::string format = std::filesystem::path(path).extension().string();
  if (!format.empty()) format.erase(0, 1);
  for (char& c : format) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (json) {
    const nlohmann::json out = {{"file", path},           {"format", format},
                                {"animations", nlohmann::json::array()}, {"holds", holds},
                                {"no_animation", true}};
    fmt::print("{}\n", json_text(out, 2));
  } else {
    fmt::print("file:        {}\n", path);
    fmt::print("format:      {}\n", format);
    fmt::print("animations:  0 (no animation: a static file, nothing to resample, render or evaluate)\n");
    if (!holds.empty()) fmt::print("holds:       {}\n", holds);
  }
  return kExitOk;
}

// The frame time as the file wrote it (BVH), else as read.
std::string frame_time_shown(const ClipFacts& f) {
  return f.frame_time_written.empty() ? fmt::format("{:.9g}", f.frame_time) : f.frame_time_written;
}

// BVH speaks its own words: frames, Frame Time and the CHANNELS lines' count (not
// assimp's ticks and node channels).
std::string bvh_take_text(const ClipFacts& f) {
  return fmt::format("{} frames, Frame Time {}, {} channels (CHANNELS)", f.frames, frame_time_shown(f), f.channels);
}

// A take's span in file time and its length: "0.833333 s to 1.33333 s (0.5 s)"; the
// length alone where the reader cannot see the file's time.
std::string take_span_text(const AnimationSummary& take) {
  if (!std::isfinite(take.start)) return fmt::format("{:.6g} s", take.duration);
  return fmt::format("{:.6g} s to {:.6g} s ({:.6g} s)", take.start, take.start + take.duration, take.duration);
}

// "16 frames at 30 Hz (stated by the file)", or "12 frames (its keys; no rate)".
std::string take_frames_text(const AnimationSummary& take) {
  if (!(take.frame_rate_hz > 0.0)) return fmt::format("{} frames (its keys; no rate)", take_frames(take));
  return fmt::format("{} frames at {:.9g} Hz ({})", take_frames(take), take.frame_rate_hz, rate_origin_text(take.rate_stated));
}

std::string layout_text(const std::vector<Channel>& channels) {
  std::string s;
  for (Channel c : channels) s += (s.empty() ? "" : " ") + std::string(channel_name(c));
  return s;
}

std::string joint_text(const JointFacts& j) {
  std::string extra;
  if (!j.channels.empty()) extra += "  [" + layout_text(j.channels) + "]";
  extra += "  " + std::to_string(j.rotation_keys) + " rotation keys";
  if (j.translation_keys) extra += ", " + std::to_string(*j.translation_keys) + " translation keys";
  return std::string(2 * j.depth, ' ') + j.name + extra;
}

// `info`'s facts as text (clip_info_json prints the same facts as JSON).
void print_info_text(const std::string& path, const ClipFileInfo& info, const ClipFacts& f) {
  fmt::print("file:        {}\n", path);
  fmt::print("format:      {}\n", info.format);
  fmt::print("animations:  {}\n", info.animations.size());
  for (std::size_t a = 0; a < info.animations.size(); ++a) {
    const AnimationSummary& s = info.animations[a];
    if (is_format(info.format, FormatId::bvh))
      fmt::print("  {}{} '{}'  {:.6g} s  {}\n", a == info.selected ? "*" : " ", a, s.name, s.duration, bvh_take_text(f));
    else
      fmt::print("  {}{} '{}'  {}  {}  {} keys  {} channels{}\n", a == info.selected ? "*" : " ", a, s.name,
                 take_span_text(s), take_frames_text(s), s.keys, s.channels,
                 s.default_rate ? fmt::format("  (0 ticks/s in the file: {:.9g} assumed)", s.ticks_per_second) : "");
  }
  fmt::print("frames:      {}\n", f.frames);
  if (f.rate)
    fmt::print("frame rate:  {} Hz{} (frame time {} s), {}\n", f.rate->to_string(),
               f.rate->den == 1 ? std::string() : fmt::format(" = {:.9g} Hz", f.rate->hz()), frame_time_shown(f),
               rate_origin_text(f.rate_stated));
  else
    fmt::print("frame rate:  none (keys not on a uniform grid){}\n",
               f.file_rate_hz > 0 ? fmt::format("; the file's own: {:.9g} Hz (resample's default)", f.file_rate_hz) : "");
  fmt::print("duration:    {:.6g} s (keys from {:.6g} s to {:.6g} s)\n", f.duration, f.start, f.end);
  fmt::print("unit:        {}\n", describe_unit(info.clip.unit));
  fmt::print("size:        {:.3g} m (the first pose's largest side)\n", f.size_m);
  if (info.folded_helpers > 0) fmt::print("helpers:     {} $AssimpFbx$ helper nodes folded into their bones\n", info.folded_helpers);
  fmt::print("joints:      {} (+{} End Sites)\n", f.joints.size(), f.end_sites);
  for (const JointFacts& j : f.joints) fmt::print("  {}\n", joint_text(j));
  std::string translated;
  for (const std::string& name : f.translated) translated += (translated.empty() ? "" : ", ") + name;
  fmt::print("translation tracks: {}\n", translated.empty() ? "none" : translated);
  if (f.cycle) fmt::print("cycle:       {}\n", loop_check_text(*f.cycle));
  if (!f.oddities.empty()) {
    fmt::print("oddities:\n");
    for (const std::string& o : f.oddities) fmt::print("  - {}\n", o);
  }
}

int run_info(const InfoArgs& args) {
  if (args.summary) return run_summary(args);
  std::error_code ec;
  if (args.paths.size() != 1 || std::filesystem::is_directory(args.paths.front(), ec))
    return fail_usage("info describes one clip; for several files or a folder add --summary");
  auto read_options = info_read_options(args);
  if (!read_options) return fail_usage(read_options.error());
  ReadOptions options = *read_options;
  options.on_warning = warn;
  if (!std::isfinite(args.sample_hz)) return fail_usage("--sample must be a finite number of Hz");
  if (args.sample_hz > 0.0 && !args.curves) return fail_usage("--sample needs --curves");
  const std::string& path = args.paths.front();
  options.read_curves = args.curves;
  ReadOutcome read = inspect_clip_for_info(path, options);
  if (read.error && read.kind == file_error::no_animation) return describe_static(path, read.info.holds, args.json);
  Result<ClipFileInfo> info = reading_or_failure(std::move(read));
  if (!info) return fail(info.error());
  if (args.curves) return print_info_curves(path, *info, args.sample_hz, args.json);
  if (args.json) {
    fmt::print("{}\n", clip_info_json(path, *info));
    return kExitOk;
  }
  print_info_text(path, *info, clip_facts(*info));
  return kExitOk;
}

}  // namespace

void add_info_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<InfoArgs>();
  auto* sub = app.add_subcommand("info", "Describe a clip file: format, animations, joint tree and channel layout, "
                                         "frames, rate, duration, translation tracks, oddities");
  sub->add_option("clip", args->paths,
                  "Clip file (BVH, FBX, glTF/GLB, Collada, … anything assimp imports); with --summary, several "
                  "files and folders (searched recursively)")
      ->required();
  add_anim_option(*sub, args->anim, nullptr);
  add_unit_option(*sub, args->unit);
  add_external_files_option(*sub, args->allow_external_files);
  add_json_option(*sub, args->json);
  sub->add_flag("--summary", args->summary,
                "One row per file (format, rate as read and as written, frames, duration, joints, notes), then the "
                "rate histogram; flags rate labels that are not their rate, uneven keys, empty clips, identical files");
  add_jobs_option(*sub, args->jobs, "With --summary: files read at once");
  sub->add_flag("--curves", args->curves,
                "FBX: the selected take's curves as the file stores them, read by rotinterp's own FBX reader: per "
                "node, property (Lcl Translation/Rotation/Scaling), channel and layer, the keys with interpolation, "
                "tangent mode, slopes and weights, and the extrapolation");
  sub->add_option("--sample", args->sample_hz,
                  "With --curves: also the value of each curve as the DCC evaluates it at k/HZ s, k = 0, 1, … up to "
                  "the take's end (FBX time 0 is t = 0); default: no samples")
      ->check(CLI::PositiveNumber);
  sub->callback([args, &exit_code] { exit_code = run_info(*args); });
}

}  // namespace rotinterp::cli
