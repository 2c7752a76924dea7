#include "rotinterp/eval/batch.h"

#include "rotinterp/core/work_queue.h"
#include "rotinterp/io/dataset.h"
#include "rotinterp/eval/plots.h"
#include "rotinterp/io/atomic_file.h"
#include "rotinterp/io/info.h"
#include "rotinterp/io/read.h"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <malloc.h>
#include <chrono>
#include <ctime>
#include <deque>
#include <functional>
#include <future>
#include <fstream>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

namespace rotinterp {

namespace fs = std::filesystem;

namespace {

std::string utc_now() {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

RunOptions run_options(const EvalOptions& e) {
  const ClipEvalOptions& o = e.clip;
  return {o.methods,          o.keep_every,           o.subframe,
          o.shell_distance_m, e.truth.name, e.animation,
          o.min_frames,       o.feet.feet,            o.feet.contact_height_m,
          o.feet.contact_speed_mps, o.feet.floor_m, e.unit,
          o.loop ? (o.loop_form ? loop_form_name(*o.loop_form) : "auto") : "off"};
}

// errors.csv into an unnamed temporary, one clip's rows at a time; committed with
// the other outputs by write_outputs.
class CsvWriter {
 public:
  // `seam`: the seam columns of eval --loop.
  CsvWriter(const fs::path& target, bool seam) : out_(target, TempKind::unnamed), seam_(seam) {
    const std::string header = error_csv_schema(seam).header();
    (void)out_.write(header.data(), header.size());
  }
  bool good() const { return out_.status().ok(); }
  // Writes the rows of one clip and adds them to the summary.
  void add_clip(const std::vector<ErrorRow>& rows, SummaryBuilder& summary) {
    std::string text;
    for (const ErrorRow& r : rows) text += format_error_row(r, seam_);
    (void)out_.write(text.data(), text.size());
    summary.add_clip(rows);
  }
  std::string failure() const { return out_.status() ? out_.target().string() + ": write failed" : out_.status().error(); }
  AtomicOutput& output() { return out_; }

 private:
  AtomicOutput out_;
  bool seam_;
};

// Writes summary.json (the run record and the results) and the plots, then commits them with
// errors.csv as a unit: an interrupt before the end leaves the previous run's files
// (all of them), after it this run's. Plots of an earlier run that this one does
// not draw are removed, so no file in DIR is older than the others.
Status write_outputs(const fs::path& dir, const RunRecord& record, const Summary& summary, bool plots, CsvWriter& csv,
                     const std::string& per_frame = {}) {
  if (!csv.good()) return make_error(csv.failure());
  std::vector<std::unique_ptr<AtomicOutput>> texts;
  auto text_file = [&](const char* name, const std::string& text) -> Status {
    texts.push_back(std::make_unique<AtomicOutput>(dir / name, TempKind::unnamed));
    return write_to(*texts.back(), [&](std::ostream& os) -> Status {
      os << text;
      return Ok{};
    });
  };
  if (Status s = text_file(kSummaryJsonName, summary_json(record, summary)); !s) return s;
  if (Status s = text_file(kClipsCsvName, clips_csv(summary)); !s) return s;
  if (!per_frame.empty())
    if (Status s = text_file(kPerFrameCsvName, per_frame); !s) return s;
  std::vector<std::unique_ptr<AtomicOutput>> plot_outputs;
  const bool draw = plots && summary.clips > 0;
  if (draw)
    if (Status s = draw_plots(summary, dir, plot_outputs); !s) return s;
  std::vector<AtomicOutput*> all = {&csv.output()};
  for (auto& t : texts) all.push_back(t.get());
  for (auto& p : plot_outputs) all.push_back(p.get());
  if (Status s = commit_together(all); !s) return s;
  std::vector<std::string> stale;
  if (!draw) stale = plot_file_names();
  if (per_frame.empty()) stale.push_back(kPerFrameCsvName);
  for (const std::string& name : stale) {
    std::error_code ec;
    fs::remove(dir / name, ec);
  }
  return Ok{};
}

Status make_dir(const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir)) return make_error(dir.string() + ": cannot create the output directory");
  return Ok{};
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
  if (opt.shard_count < 1 || opt.shard_index < 1 || opt.shard_index > opt.shard_count)
    return make_error("shard must be I/N with 1 ≤ I ≤ N");
  return Ok{};
}

// The clip files of this run: the inputs found, then this shard's part of them.
Result<std::vector<std::string>> files_of_shard(const EvalOptions& opt) {
  auto all = discover_inputs(opt.inputs);
  if (!all) return all.failure();
  if (all->empty()) {
    std::string where;
    for (const fs::path& p : opt.inputs) where += (where.empty() ? "" : ", ") + p.string();
    return make_error(where + ": no clip files found (looked for every format assimp imports)");
  }
  return shard_of(*all, opt.shard_index, opt.shard_count);
}

// The takes of `file` that `animation` selects (EvalOptions::animation), each with
// its clip id, in the order of their ids.
Result<std::vector<std::pair<std::string, Clip>>> read_takes(const std::string& file, const std::string& animation,
                                                             std::optional<double> unit) {
  ReadOptions ro;
  ro.animation = animation == "all" ? "" : animation;
  ro.unit = unit;
  auto info = inspect_clip(file, ro);
  if (!info) return info.failure();
  const std::vector<AnimationSummary>& anims = info->animations;
  auto id_of = [&](std::size_t a) {
    if (anims.size() <= 1) return file;
    const std::string& name = anims[a].name;
    const bool unique = std::count_if(anims.begin(), anims.end(), [&](const auto& x) { return x.name == name; }) == 1;
    return file + "#" + (name.empty() || !unique ? std::to_string(a) : name);
  };
  std::vector<std::pair<std::string, Clip>> takes;
  takes.emplace_back(id_of(info->selected), std::move(info->clip));
  if (animation == "all")
    for (std::size_t a = 0; a < anims.size(); ++a) {
      if (a == info->selected) continue;
      ro.animation = std::to_string(a);
      auto clip = read_clip(file, ro);
      if (!clip) return clip.failure(id_of(a) + ": ");
      takes.emplace_back(id_of(a), std::move(*clip));
    }
  std::sort(takes.begin(), takes.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  return takes;
}

// The per-frame error series of `R` as CSV: sample, time, whether the sample is a
// key, then one column of degrees per joint.
std::string per_frame_csv(const ClipReference& R, const PerFrameRequest& q, const PerFrameErrors& e) {
  std::vector<std::string> columns = {"sample", "time_s", "key"};
  for (const Joint& j : R.skeleton.joints) columns.push_back(j.name);
  const CsvSchema schema(std::move(columns));
  std::string out = schema.header();
  const std::vector<std::size_t> kf = key_frames(R, q.keep_every);  // eval/seam.h: with --loop, the period's
  std::vector<char> key(R.samples, 0);
  for (std::size_t k : kf) key[k * R.per_frame] = 1;
  for (std::size_t m = 0; m < R.samples; ++m) {
    CsvRow row(schema);
    row << std::to_string(m) << fmt::format("{}", e.times[m]) << (key[m] ? "1" : "0");
    for (const auto& joint : e.angle) row << fmt::format("{}", joint[m]);
    out += row.line();
  }
  return out;
}

// Reads a file's takes and prepares their references, into its slot.
void prepare_clip(const std::string& file, const EvalOptions& opt, ClipSlot& slot) {
  auto takes = read_takes(file, opt.animation, opt.unit);
  if (!takes) {
    // A mesh found next to the clips is not an error. The reader's error kind
    // says so: no second look at a file that may crash its importer.
    if (found_in_directory(file, opt.inputs) && takes.error_kind() == ErrorKind::no_animation)
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

// Evaluates every file × method on the work queue — (clip, method) tasks in input
// order, so a long clip is shared by the workers too — with at most `window` clips
// in flight, and hands each clip's outcome to `take` in input order. Stops early
// when `take` returns false.
void evaluate_in_order(const std::vector<std::string>& files, const EvalOptions& opt, std::size_t jobs,
                       const std::function<bool(std::size_t, Outcome)>& take) {
  const std::size_t nm = opt.clip.methods.size(), window = 2 * jobs;
  std::atomic<bool> stop{false};
  struct InFlight {
    std::shared_ptr<ClipSlot> slot;
    std::vector<std::future<MethodOutcome>> methods;
  };
  WorkQueue queue(static_cast<unsigned>(std::min(jobs, std::max<std::size_t>(1, files.size() * nm))));
  std::deque<InFlight> in_flight;  // after the queue: its futures go first, then the queue finishes its jobs
  std::size_t submitted = 0;
  for (std::size_t i = 0; i < files.size(); ++i) {
    for (; submitted < files.size() && submitted < i + window; ++submitted) {
      InFlight c{std::make_shared<ClipSlot>(), {}};
      for (std::size_t m = 0; m < nm; ++m)
        c.methods.push_back(queue.submit([&, i = submitted, m, slot = c.slot] {
          MethodOutcome out;
          if (stop) return out;
          std::call_once(slot->prepared, prepare_clip, std::cref(files[i]), std::cref(opt), std::ref(*slot));
          for (const auto& take : slot->takes) {
            auto rows = evaluate_method(*take, opt.clip.methods[m], opt.clip);
            if (!rows) {
              out.failure = EvalFailure{files[i], rows.error()};
              break;
            }
            out.takes.push_back(std::move(*rows));
          }
          return out;
        }));
      in_flight.push_back(std::move(c));
    }
    InFlight c = std::move(in_flight.front());
    in_flight.pop_front();
    std::vector<MethodOutcome> methods;
    for (auto& f : c.methods) methods.push_back(f.get());
    if (!take(i, clip_outcome(*c.slot, std::move(methods)))) {
      stop = true;
      return;
    }
  }
}

std::size_t worker_count(int jobs) {
  return jobs > 0 ? static_cast<std::size_t>(jobs) : std::max(1u, std::thread::hardware_concurrency());
}

}  // namespace

void keep_freed_memory_for_reuse() {
  mallopt(M_MMAP_THRESHOLD, 32 << 20);  // glibc's largest allowed value on 64-bit
  mallopt(M_TRIM_THRESHOLD, 512 << 20);
  mallopt(M_TOP_PAD, 16 << 20);
}

Result<EvalReport> run_eval(const EvalOptions& opt) {
  const auto t0 = std::chrono::steady_clock::now();
  const std::string started = utc_now();
  if (Status s = check_options(opt); !s) return s.failure();
  auto shard = files_of_shard(opt);
  if (!shard) return shard.failure();
  const std::vector<std::string>& files = *shard;
  if (Status s = make_dir(opt.output_dir); !s) return s.failure();
  auto lock = DirectoryLock::acquire(opt.output_dir);
  if (!lock) return lock.failure();

  EvalReport report;
  report.files = files.size();
  CsvWriter csv(opt.output_dir / kErrorsCsvName, opt.clip.loop);
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
  report.summary.seam = opt.clip.loop;
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

namespace {

// Reads one shard's errors.csv a clip at a time.
class ShardReader {
 public:
  static Result<std::unique_ptr<ShardReader>> open(const fs::path& file) {
    auto r = std::unique_ptr<ShardReader>(new ShardReader);
    r->file_ = file;
    r->in_.open(file, std::ios::binary);
    if (!r->in_) return make_error(file.string() + ": cannot read");
    std::string header;
    if (!std::getline(r->in_, header)) return make_error(file.string() + ": empty file");
    auto parser = ErrorRowParser::from_header(header);
    if (!parser) return parser.failure(file.string() + ": ");
    r->parser_.emplace(std::move(*parser));
    if (Status s = r->read_row(); !s) return s.failure();
    return r;
  }
  bool at_end() const { return !lookahead_; }
  bool has_seam_columns() const { return parser_->has_seam_columns(); }
  const std::string& clip() const { return lookahead_->clip; }
  // The rows of the next clip.
  Result<std::vector<ErrorRow>> next_clip() {
    std::vector<ErrorRow> rows;
    const std::string c = lookahead_->clip;
    while (lookahead_ && lookahead_->clip == c) {
      rows.push_back(std::move(*lookahead_));
      if (Status s = read_row(); !s) return s.failure();
    }
    if (lookahead_ && lookahead_->clip < c)
      return make_error(file_.string() + ":" + std::to_string(line_) + ": clips are not in sorted order");
    return rows;
  }

 private:
  Status read_row() {
    lookahead_.reset();
    std::string line;
    while (std::getline(in_, line)) {
      ++line_;
      if (line.empty() || line == "\r") continue;
      auto row = parser_->parse(line);
      if (!row) return row.failure(file_.string() + ":" + std::to_string(line_ + 1) + ": ");
      lookahead_ = std::move(*row);
      return Ok{};
    }
    if (in_.bad()) return make_error(file_.string() + ": read failed");
    return Ok{};
  }
  fs::path file_;
  std::ifstream in_;
  std::optional<ErrorRowParser> parser_;
  std::optional<ErrorRow> lookahead_;
  std::size_t line_ = 0;
};

}  // namespace

Result<EvalReport> merge_eval(const std::vector<fs::path>& dirs, const fs::path& out_dir, bool plots) {
  const auto t0 = std::chrono::steady_clock::now();
  if (dirs.empty()) return make_error("--merge needs at least one directory");
  EvalReport report;
  RunRecord merged;
  for (const fs::path& d : dirs) {
    const fs::path f = d / kSummaryJsonName;
    auto shard = read_summary_json(f);
    if (!shard) return shard.failure();
    if (&d == &dirs.front())
      merged.options = shard->options;
    else if (!(merged.options == shard->options))
      return make_error(f.string() + ": evaluated with other options than " + (dirs.front() / kSummaryJsonName).string());
    for (const std::string& p : shard->inputs)
      if (std::find(merged.inputs.begin(), merged.inputs.end(), p) == merged.inputs.end()) merged.inputs.push_back(p);
    report.skipped.insert(report.skipped.end(), shard->skipped.begin(), shard->skipped.end());
    report.failures.insert(report.failures.end(), shard->failed.begin(), shard->failed.end());
    report.too_short.insert(report.too_short.end(), shard->too_short.begin(), shard->too_short.end());
    report.files += shard->files;
    merged.seconds += shard->seconds;
    merged.version = shard->version;
  }
  std::stable_sort(report.failures.begin(), report.failures.end(),
                   [](const EvalFailure& a, const EvalFailure& b) { return a.file < b.file; });
  std::sort(report.skipped.begin(), report.skipped.end());
  std::stable_sort(report.too_short.begin(), report.too_short.end(),
                   [](const ShortClip& a, const ShortClip& b) { return a.clip < b.clip; });

  std::vector<std::unique_ptr<ShardReader>> readers;
  for (const fs::path& d : dirs) {
    auto r = ShardReader::open(d / kErrorsCsvName);
    if (!r) return r.failure();
    readers.push_back(std::move(*r));
  }
  if (Status s = make_dir(out_dir); !s) return s.failure();
  auto lock = DirectoryLock::acquire(out_dir);
  if (!lock) return lock.failure();
  const bool seam = merged.options.loop != "off";
  for (const auto& r : readers)
    if (r->has_seam_columns() != seam)
      return make_error(std::string("a shard's errors.csv ") + (seam ? "lacks" : "has") +
                        " the seam columns (seam_angle_deg … looped) its summary.json's loop option says");
  CsvWriter csv(out_dir / kErrorsCsvName, seam);
  if (!csv.good()) return make_error(csv.failure());
  SummaryBuilder builder;
  std::string last_clip;
  for (;;) {
    ShardReader* next = nullptr;
    for (auto& r : readers)
      if (!r->at_end() && (!next || r->clip() < next->clip())) next = r.get();
    if (!next) break;
    if (!last_clip.empty() && next->clip() == last_clip)
      return make_error("clip '" + last_clip + "' appears in more than one shard");
    last_clip = next->clip();
    auto rows = next->next_clip();
    if (!rows) return rows.failure();
    csv.add_clip(*rows, builder);
    ++report.clips_evaluated;
  }
  report.summary = builder.finish();
  report.summary.seam = seam;
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (merged.version.empty()) merged.version = ROTINTERP_VERSION;
  merged.files = report.files;
  for (const fs::path& d : dirs) merged.merged_from.push_back(d.string());
  merged.started = utc_now();
  merged.merge_seconds = report.seconds;
  merged.failed = report.failures;
  merged.skipped = report.skipped;
  merged.too_short = report.too_short;
  if (Status s = write_outputs(out_dir, merged, report.summary, plots, csv); !s) return s.failure();
  return report;
}

}  // namespace rotinterp
