// eval's run: the clip files of this shard evaluated method by method on the folder
// run's queue (batch/folder_run.h), a bounded number of clips in flight, their rows
// handed on in input order.
#include "rotinterp/eval/batch.h"

#include "batch_outputs.h"
#include "rotinterp/core/work_queue.h"
#include "rotinterp/batch/dataset.h"
#include "rotinterp/batch/folder_run.h"
#include "rotinterp/io/files/atomic_file.h"
#include "rotinterp/io/info.h"
#include "rotinterp/io/read.h"
#include "rotinterp/io/takes.h"
#include "rotinterp/io/files/file_errors.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>

namespace rotinterp {

namespace fs = std::filesystem;

namespace {


RunOptions run_options(const EvalOptions& e) {
  const ClipEvalOptions& o = e.clip;
  return {o.methods,          o.keep_every,           o.subframe,
          o.shell_distance_m, e.truth.name, e.animation,
          o.min_frames,       o.feet.feet,            o.feet.contact_height_m,
          o.feet.contact_speed_mps, o.feet.floor_m, e.unit,
          o.loop ? (o.loop_form ? loop_form_name(*o.loop_form) : "auto") : "off",
          metrics_text(o.metrics)};
}


// One file's outcome: the rows of each of its takes (methods in order), its
// failures, and its takes evaluated at fewer spacings than asked.
struct Outcome {
  std::vector<std::vector<ErrorRow>> takes;
  std::vector<EvalFailure> failures;
  std::vector<ShortClip> too_short;
  std::string per_frame;  // per_frame.csv, when the requested clip is here
  bool skipped = false;   // no animation in a file found in a directory
};

// One (file, method) task's result: rows per take.
struct MethodOutcome {
  std::vector<std::vector<ErrorRow>> takes;
  std::optional<EvalFailure> failure;
};

// A file in flight: read and its takes prepared once, by the first of its method
// tasks to run, then shared by the others.
struct ClipSlot {
  std::once_flag prepared;
  std::vector<std::shared_ptr<const ClipReference>> takes;
  std::vector<ShortClip> too_short;
  std::string per_frame;
  std::optional<EvalFailure> load_failure;
  bool skipped = false;
};

Status check_options(const EvalOptions& opt) {
  if (opt.clip.methods.empty()) return make_error("no methods to evaluate");
  if (opt.clip.keep_every.empty()) return make_error("no keep-every values");
  for (int n : opt.clip.keep_every)
    if (n < 1) return make_error("keep-every values must be at least 1");
  return Ok{};
}

// The takes of `file` that `animation` selects (EvalOptions::animation), each with
// its clip id, in the order of their ids.
Result<std::vector<std::pair<std::string, Clip>>> read_takes(const std::string& file, const EvalOptions& opt,
                                                             unsigned threads) {
  const std::string& animation = opt.animation;
  ReadOptions ro;
  ro.threads = threads;
  const bool several = names_several_takes(animation);
  ro.animation = several ? "" : animation;
  ro.unit = opt.unit;
  ro.allow_external_files = opt.allow_external_files;
  auto info = inspect_clip(file, ro);
  if (!info) return info.failure();
  const std::vector<AnimationSummary>& anims = info->animations;
  auto chosen = choose_takes(anims, several ? animation : "", file);
  if (!chosen) return chosen.failure();
  auto id_of = [&](std::size_t a) {
    if (anims.size() <= 1) return file;
    const std::string& name = anims[a].name;
    const bool unique = std::count_if(anims.begin(), anims.end(), [&](const auto& x) { return x.name == name; }) == 1;
    return file + "#" + (name.empty() || !unique ? std::to_string(a) : name);
  };
  std::vector<std::pair<std::string, Clip>> takes;
  if (!several) takes.emplace_back(id_of(info->selected), std::move(info->clip));
  for (const TakeRef& take : several ? *chosen : std::vector<TakeRef>{}) {
    if (take.index == info->selected) {
      takes.emplace_back(id_of(take.index), info->clip);
      continue;
    }
    ro.animation = std::to_string(take.index);
    auto clip = read_clip(file, ro);
    if (!clip) return clip.failure(id_of(take.index) + ": ");
    takes.emplace_back(id_of(take.index), std::move(*clip));
  }
  std::sort(takes.begin(), takes.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  return takes;
}


// Reads a file's takes and prepares their references, into its slot.
void prepare_clip(const std::string& file, const EvalOptions& opt, unsigned threads, ClipSlot& slot) {
  auto takes = read_takes(file, opt, threads);
  if (!takes) {
    // A mesh found next to the clips is not an error. The reader's error kind
    // says so: no second look at a file that may crash its importer.
    if (found_in_directory(file, opt.inputs) && takes.error_kind() == file_error::no_animation)
      slot.skipped = true;
    else
      slot.load_failure = EvalFailure{file, takes.error(), takes.error_kind()};
    return;
  }
  for (auto& [id, clip] : *takes) {
    ClipEvalOptions copt = opt.clip;
    if (opt.truth.for_clip) {
      auto truth = opt.truth.for_clip(file, clip);
      if (!truth) {
        slot.load_failure = EvalFailure{file, truth.error()};
        return;
      }
      copt.truth = std::move(*truth);
    }
    auto ref = prepare_reference(clip, id, copt);
    if (!ref) {
      slot.load_failure = EvalFailure{file, ref.error()};
      return;
    }
    if (auto skip = skipped_spacings(ref->frames.size(), opt.clip); !skip.empty())
      slot.too_short.push_back({id, ref->frames.size(), std::move(skip)});
    if (opt.per_frame && opt.per_frame->clip == id) {
      auto e = per_frame_errors(*ref, opt.per_frame->method, opt.per_frame->keep_every);
      if (!e) {
        slot.load_failure = EvalFailure{file, e.error()};
        return;
      }
      slot.per_frame = per_frame_csv(*ref, *opt.per_frame, *e);
    }
    slot.takes.push_back(std::make_shared<const ClipReference>(std::move(*ref)));
  }
}

// A file's outcome from its slot and its methods' results.
Outcome clip_outcome(ClipSlot& slot, std::vector<MethodOutcome> methods) {
  Outcome o;
  o.skipped = slot.skipped;
  if (slot.load_failure) {
    o.failures.push_back(*slot.load_failure);
    return o;
  }
  o.too_short = std::move(slot.too_short);
  o.per_frame = std::move(slot.per_frame);
  for (MethodOutcome& m : methods)
    if (m.failure) o.failures.push_back(std::move(*m.failure));
  // Every method is compared on the same clips: a file where one fails is skipped whole.
  if (!o.failures.empty()) return o;
  o.takes.resize(slot.takes.size());
  for (std::size_t t = 0; t < slot.takes.size(); ++t)
    for (MethodOutcome& m : methods)
      o.takes[t].insert(o.takes[t].end(), std::make_move_iterator(m.takes[t].begin()),
                        std::make_move_iterator(m.takes[t].end()));
  return o;
}

// Evaluates every file × method on the folder run's queue (batch/folder_run.h) —
// (clip, method) tasks in input order, so a long clip is shared by the workers too —
// with at most `window` clips in flight, and hands each clip's outcome to `take` in
// input order. Stops early when `take` returns false.
void evaluate_in_order(const std::vector<std::string>& files, const EvalOptions& opt, std::size_t jobs,
                       const std::function<bool(std::size_t, Outcome)>& take) {
  const std::size_t nm = opt.clip.methods.size(), window = 2 * jobs;
  // A read inside a worker takes no threads of its own, unless it is the run's only file.
  const unsigned read_threads = files.size() == 1 ? static_cast<unsigned>(jobs) : 1u;
  std::vector<std::shared_ptr<ClipSlot>> slots(files.size());
  for (auto& slot : slots) slot = std::make_shared<ClipSlot>();
  std::vector<MethodOutcome> methods;
  run_in_order<MethodOutcome>(
      files.size() * nm, static_cast<unsigned>(jobs), window * nm,
      [&](std::size_t k) {
        const std::size_t i = k / nm, m = k % nm;
        ClipSlot& slot = *slots[i];
        MethodOutcome out;
        std::call_once(slot.prepared, prepare_clip, std::cref(files[i]), std::cref(opt), read_threads, std::ref(slot));
        for (const auto& t : slot.takes) {
          auto rows = evaluate_method(*t, opt.clip.methods[m], opt.clip);
          if (!rows) {
            out.failure = EvalFailure{files[i], rows.error()};
            break;
          }
          out.takes.push_back(std::move(*rows));
        }
        return out;
      },
      [&](std::size_t k, MethodOutcome out) {
        methods.push_back(std::move(out));
        if (methods.size() < nm) return true;
        const std::size_t i = k / nm;
        Outcome o = clip_outcome(*slots[i], std::move(methods));
        methods.clear();
        slots[i].reset();  // its clip is written: its memory goes
        return take(i, std::move(o));
      });
}

std::size_t worker_count(int jobs) {
  return thread_count(jobs > 0 ? static_cast<unsigned>(jobs) : 0);
}

}  // namespace

Result<EvalReport> run_eval(const EvalOptions& opt) {
  const auto t0 = std::chrono::steady_clock::now();
  const std::string started = utc_now();
  if (Status s = check_options(opt); !s) return s.failure();
  auto shard = find_run_inputs(opt.inputs, opt.shard_index, opt.shard_count);
  if (!shard) return shard.failure();
  const std::vector<std::string>& files = *shard;
  auto lock = DirectoryLock::acquire(opt.output_dir);
  if (!lock) return lock.failure();

  EvalReport report;
  report.files = files.size();
  const MetricSet columns = csv_metrics(opt.clip.metrics, opt.clip.loop);
  ErrorsCsv csv(opt.output_dir / kErrorsCsvName, columns);
  if (!csv.good()) return make_error(csv.failure());
  SummaryBuilder builder;
  const std::size_t jobs = worker_count(opt.jobs);
  std::string per_frame;
  evaluate_in_order(files, opt, jobs, [&](std::size_t i, Outcome o) {
    if (o.skipped) report.skipped.push_back(files[i]);
    for (EvalFailure& f : o.failures) {
      if (opt.on_failure) opt.on_failure(f);
      report.failures.push_back(std::move(f));
    }
    for (ShortClip& c : o.too_short) report.too_short.push_back(std::move(c));
    if (!o.per_frame.empty()) per_frame = std::move(o.per_frame);
    for (const std::vector<ErrorRow>& rows : o.takes)
      if (!rows.empty()) {
        csv.add_clip(rows, builder);
        ++report.clips_evaluated;
      }
    if (opt.progress) opt.progress(i + 1, files.size());
    return csv.good();
  });
  if (!csv.good()) return make_error(csv.failure());
  if (opt.per_frame && per_frame.empty())
    return make_error("--per-frame: no clip '" + opt.per_frame->clip + "' was read (the clip id as in errors.csv: "
                      "the file's path as found, file#take for a take of a file of several)");

  report.summary = builder.finish();
  report.summary.seam = columns.has(Metric::seam);
  report.summary.metrics = columns;
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  RunRecord record;
  record.version = ROTINTERP_VERSION;
  for (const fs::path& p : opt.inputs) record.inputs.push_back(p.string());
  record.files = files.size();
  record.options = run_options(opt);
  record.shard_index = opt.shard_index;
  record.shard_count = opt.shard_count;
  record.jobs = jobs;
  record.started = started;
  record.seconds = report.seconds;
  record.failed = report.failures;
  record.skipped = report.skipped;
  record.too_short = report.too_short;
  if (Status s = write_outputs(opt.output_dir, record, report.summary, opt.plots, csv, per_frame); !s)
    return s.failure();
  return report;
}


}  // namespace rotinterp
