#include "rotinterp/eval/batch.h"

#include "rotinterp/eval/inputs.h"
#include "rotinterp/eval/plots.h"
#include "rotinterp/io/atomic_file.h"
#include "rotinterp/io/read.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <ctime>
#include <fstream>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

namespace rotinterp {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

std::string utc_now() {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

json options_json(const ClipEvalOptions& o, bool truth) {
  return {{"methods", o.methods},
          {"keep_every", o.keep_every},
          {"subframe", o.subframe},
          {"shell_distance_m", o.shell_distance_m},
          {"truth", truth}};
}

json entry_json(const SummaryEntry& e) {
  return {{"method", e.method},
          {"keep_every", e.keep_every},
          {"clips", e.clips},
          {"joints", e.joints},
          {"samples", e.samples},
          {"mean_deg", e.mean_deg},
          {"rms_deg", e.rms_deg},
          {"p95_deg", e.p95_deg},
          {"max_deg", e.max_deg},
          {"swing_rms_deg", e.swing_rms_deg},
          {"twist_rms_deg", e.twist_rms_deg},
          {"pos_rms_pct", e.pos_rms_pct},
          {"pos_max_pct", e.pos_max_pct},
          {"shell_rms_pct", e.shell_rms_pct},
          {"shell_max_pct", e.shell_max_pct},
          {"acc_rms_dps2", e.acc_rms},
          {"acc_rms_ref_dps2", e.acc_rms_ref},
          {"vel_jump_max_dps", e.vel_jump_max},
          {"acc_jump_max_dps2", e.acc_jump_max},
          {"worst", {{"clip", e.worst_clip}, {"joint", e.worst_joint}}}};
}

json failures_json(const std::vector<EvalFailure>& failures) {
  json a = json::array();
  for (const EvalFailure& f : failures) a.push_back({{"file", f.file}, {"error", f.message}});
  return a;
}

// errors.csv into an unnamed temporary, one clip's rows at a time; committed with
// the other outputs by write_outputs.
class CsvWriter {
 public:
  explicit CsvWriter(const fs::path& target) : out_(target, TempKind::unnamed) {
    const std::string header = error_csv_header() + '\n';
    (void)out_.write(header.data(), header.size());
  }
  bool good() const { return out_.status().ok(); }
  // Writes the rows of one clip and adds them to the summary.
  void add_clip(const std::vector<ErrorRow>& rows, SummaryBuilder& summary) {
    std::string text;
    for (const ErrorRow& r : rows) text += format_error_row(r) + '\n';
    (void)out_.write(text.data(), text.size());
    summary.add_clip(rows);
  }
  std::string failure() const { return out_.status() ? out_.target().string() + ": write failed" : out_.status().error(); }
  AtomicOutput& output() { return out_; }

 private:
  AtomicOutput out_;
};

// Writes summary.json (meta + results) and the plots, then commits them with
// errors.csv as a unit: an interrupt before the end leaves the previous run's files
// (all of them), after it this run's. Plots of an earlier run that this one does
// not draw are removed, so no file in DIR is older than the others.
Status write_outputs(const fs::path& dir, json meta, const Summary& summary, bool plots, CsvWriter& csv) {
  json results = json::array();
  for (const SummaryEntry& e : summary.entries) results.push_back(entry_json(e));
  meta["clips_evaluated"] = summary.clips;
  meta["results"] = std::move(results);
  meta["worst_clip"] = {{"clip", summary.worst_clip}, {"keep_every", summary.worst_keep_every}};
  meta["units"] = {{"angles", "degrees"},
                   {"pct", "percent of each clip's skeleton height"},
                   {"acc", "deg/s^2"},
                   {"vel", "deg/s"}};
  const std::string text = meta.dump(2) + "\n";
  if (!csv.good()) return make_error(csv.failure());
  AtomicOutput json_out(dir / kSummaryJsonName, TempKind::unnamed);
  if (Status s = write_to(json_out,
                          [&](std::ostream& os) -> Status {
                            os << text;
                            return Ok{};
                          });
      !s)
    return s;
  std::vector<std::unique_ptr<AtomicOutput>> plot_outputs;
  const bool draw = plots && summary.clips > 0;
  if (draw)
    if (Status s = draw_plots(summary, dir, plot_outputs); !s) return s;
  std::vector<AtomicOutput*> all = {&csv.output(), &json_out};
  for (auto& p : plot_outputs) all.push_back(p.get());
  if (Status s = commit_together(all); !s) return s;
  if (!draw)
    for (const char* name : {kSpacingPlotName, kWorstClipPlotName}) {
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

// One clip's outcome: its rows (methods in order) and its failures.
struct Outcome {
  std::vector<ErrorRow> rows;
  std::vector<EvalFailure> failures;
  bool skipped = false;  // no animation in a file found in a directory
};

// A clip in flight: read and prepared once (by the first of its tasks to run),
// then shared by its method tasks.
struct ClipSlot {
  std::once_flag prepared;
  std::shared_ptr<const ClipReference> reference;
  std::optional<EvalFailure> load_failure;
  bool skipped = false;
  std::vector<std::vector<ErrorRow>> rows;         // per method
  std::vector<std::optional<EvalFailure>> failed;  // per method
  std::size_t remaining = 0;                       // method tasks not yet finished
};

}  // namespace

Result<EvalReport> run_eval(const EvalOptions& opt) {
  const auto t0 = std::chrono::steady_clock::now();
  const std::string started = utc_now();
  if (opt.clip.methods.empty()) return make_error("no methods to evaluate");
  if (opt.clip.keep_every.empty()) return make_error("no keep-every values");
  for (int n : opt.clip.keep_every)
    if (n < 1) return make_error("keep-every values must be at least 1");
  if (opt.shard_count < 1 || opt.shard_index < 1 || opt.shard_index > opt.shard_count)
    return make_error("shard must be I/N with 1 ≤ I ≤ N");
  auto all = discover_inputs(opt.inputs);
  if (!all) return make_error(all.error());
  if (all->empty()) {
    std::string where;
    for (const fs::path& p : opt.inputs) where += (where.empty() ? "" : ", ") + p.string();
    return make_error(where + ": no clip files found (looked for every format assimp imports)");
  }
  const std::vector<std::string> files = shard_of(*all, opt.shard_index, opt.shard_count);
  if (Status s = make_dir(opt.output_dir); !s) return make_error(s.error());
  auto lock = DirectoryLock::acquire(opt.output_dir);
  if (!lock) return make_error(lock.error());

  unsigned hw = std::max(1u, std::thread::hardware_concurrency());
  const std::size_t jobs = opt.jobs > 0 ? static_cast<std::size_t>(opt.jobs) : hw;
  const std::size_t window = 2 * jobs;

  EvalReport report;
  report.files = files.size();
  CsvWriter csv(opt.output_dir / kErrorsCsvName);
  if (!csv.good()) return make_error(csv.failure());

  // Work items are (clip, method) pairs in input order, so one long clip is shared
  // by the workers too; a clip's slot lives until its last method is done.
  const std::size_t nm = opt.clip.methods.size();
  const std::size_t tasks = files.size() * nm;
  std::mutex mutex;
  std::condition_variable cv;
  std::map<std::size_t, std::shared_ptr<ClipSlot>> slots;  // clips in flight
  std::map<std::size_t, Outcome> pending;                  // finished, not yet written
  std::size_t next_task = 0, next_to_write = 0;
  bool abort = false;

  auto prepare = [&](std::size_t i, ClipSlot& slot) {
    auto clip = read_clip(files[i]);
    if (!clip) {
      // A mesh found next to the clips is not an error. The reader's error kind
      // says so: no second look at a file that may crash its importer.
      if (found_in_directory(files[i], opt.inputs) && clip.error_kind() == ErrorKind::no_animation)
        slot.skipped = true;
      else
        slot.load_failure = EvalFailure{files[i], clip.error()};
      return;
    }
    ClipEvalOptions copt = opt.clip;
    if (opt.truth_for) {
      auto truth = opt.truth_for(files[i], *clip);
      if (!truth) {
        slot.load_failure = EvalFailure{files[i], truth.error()};
        return;
      }
      copt.truth = std::move(*truth);
    }
    auto ref = prepare_reference(*clip, files[i], copt);
    if (!ref)
      slot.load_failure = EvalFailure{files[i], ref.error()};
    else
      slot.reference = std::make_shared<const ClipReference>(std::move(*ref));
  };

  auto worker = [&] {
    for (;;) {
      std::size_t i, m;
      std::shared_ptr<ClipSlot> slot;
      {
        std::unique_lock<std::mutex> lock(mutex);
        cv.wait(lock, [&] { return abort || next_task >= tasks || next_task / nm < next_to_write + window; });
        if (abort || next_task >= tasks) return;
        i = next_task / nm;
        m = next_task % nm;
        ++next_task;
        auto& s = slots[i];
        if (!s) {
          s = std::make_shared<ClipSlot>();
          s->rows.resize(nm);
          s->failed.resize(nm);
          s->remaining = nm;
        }
        slot = s;
      }
      std::call_once(slot->prepared, prepare, i, std::ref(*slot));
      std::vector<ErrorRow> rows;
      std::optional<EvalFailure> failure;
      if (slot->reference) {
        auto r = evaluate_method(*slot->reference, opt.clip.methods[m], opt.clip);
        if (r)
          rows = std::move(*r);
        else
          failure = EvalFailure{files[i], r.error()};
      }
      {
        std::lock_guard<std::mutex> lock(mutex);
        slot->rows[m] = std::move(rows);
        slot->failed[m] = std::move(failure);
        if (--slot->remaining == 0) {
          Outcome o;
          o.skipped = slot->skipped;
          if (slot->load_failure) {
            o.failures.push_back(*slot->load_failure);
          } else {
            for (std::size_t k = 0; k < nm; ++k)
              if (slot->failed[k]) o.failures.push_back(*slot->failed[k]);
            // Every method is compared on the same clips: a clip where one fails is
            // skipped whole.
            if (o.failures.empty())
              for (std::size_t k = 0; k < nm; ++k)
                o.rows.insert(o.rows.end(), std::make_move_iterator(slot->rows[k].begin()),
                              std::make_move_iterator(slot->rows[k].end()));
          }
          pending[i] = std::move(o);
          slots.erase(i);
        }
      }
      cv.notify_all();
    }
  };
  std::vector<std::thread> threads;
  for (std::size_t t = 0; t < std::min(jobs, std::max<std::size_t>(1, tasks)); ++t) threads.emplace_back(worker);

  SummaryBuilder builder;
  std::string write_error;
  while (next_to_write < files.size()) {
    Outcome o;
    {
      std::unique_lock<std::mutex> lock(mutex);
      cv.wait(lock, [&] { return pending.count(next_to_write) > 0; });
      o = std::move(pending[next_to_write]);
      pending.erase(next_to_write);
    }
    if (o.skipped) report.skipped.push_back(files[next_to_write]);
    for (EvalFailure& f : o.failures) {
      if (opt.on_failure) opt.on_failure(f);
      report.failures.push_back(std::move(f));
    }
    if (!o.rows.empty()) {
      csv.add_clip(o.rows, builder);
      ++report.clips_evaluated;
    }
    {
      std::lock_guard<std::mutex> lock(mutex);
      ++next_to_write;
    }
    cv.notify_all();
    if (opt.progress) opt.progress(next_to_write, files.size());
    if (!csv.good() && write_error.empty()) {
      write_error = csv.failure();
      std::lock_guard<std::mutex> lock(mutex);
      abort = true;
      cv.notify_all();
      break;
    }
  }
  for (std::thread& t : threads) t.join();
  if (!write_error.empty()) return make_error(write_error);

  report.summary = builder.finish();
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  json inputs = json::array();
  for (const fs::path& p : opt.inputs) inputs.push_back(p.string());
  json meta = {{"tool", "rotinterp eval"},
               {"version", ROTINTERP_VERSION},
               {"inputs", inputs},
               {"files", files.size()},
               {"shard", {{"index", opt.shard_index}, {"count", opt.shard_count}}},
               {"options", options_json(opt.clip, static_cast<bool>(opt.truth_for))},
               {"jobs", jobs},
               {"started", started},
               {"seconds", report.seconds},
               {"failed", failures_json(report.failures)},
               {"skipped", report.skipped}};
  if (Status s = write_outputs(opt.output_dir, std::move(meta), report.summary, opt.plots, csv); !s)
    return make_error(s.error());
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
    if (!parser) return make_error(file.string() + ": " + parser.error());
    r->parser_.emplace(std::move(*parser));
    if (Status s = r->read_row(); !s) return make_error(s.error());
    return r;
  }
  bool at_end() const { return !lookahead_; }
  const std::string& clip() const { return lookahead_->clip; }
  // The rows of the next clip.
  Result<std::vector<ErrorRow>> next_clip() {
    std::vector<ErrorRow> rows;
    const std::string c = lookahead_->clip;
    while (lookahead_ && lookahead_->clip == c) {
      rows.push_back(std::move(*lookahead_));
      if (Status s = read_row(); !s) return make_error(s.error());
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
      if (!row) return make_error(file_.string() + ":" + std::to_string(line_ + 1) + ": " + row.error());
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
  json options;
  json inputs = json::array();
  std::string version;
  double seconds = 0;
  for (const fs::path& d : dirs) {
    const fs::path f = d / kSummaryJsonName;
    std::ifstream in(f);
    if (!in) return make_error(f.string() + ": cannot read");
    json j;
    try {
      j = json::parse(in);
    } catch (const std::exception& e) {
      return make_error(f.string() + ": not JSON (" + std::string(e.what()) + ")");
    }
    if (!j.is_object() || !j.contains("options") || !j.contains("failed") || !j.contains("files"))
      return make_error(f.string() + ": not a rotinterp eval summary");
    if (options.is_null())
      options = j["options"];
    else if (options != j["options"])
      return make_error(f.string() + ": evaluated with other options than " + (dirs.front() / kSummaryJsonName).string());
    try {
      for (const auto& p : j.value("inputs", json::array()))
        if (std::find(inputs.begin(), inputs.end(), p) == inputs.end()) inputs.push_back(p);
      for (const auto& sk : j.value("skipped", json::array())) report.skipped.push_back(sk.get<std::string>());
      for (const auto& fl : j["failed"])
        report.failures.push_back({fl.at("file").get<std::string>(), fl.at("error").get<std::string>()});
      report.files += j["files"].get<std::size_t>();
      seconds += j.value("seconds", 0.0);
      version = j.value("version", "");
    } catch (const std::exception& e) {
      return make_error(f.string() + ": malformed summary (" + std::string(e.what()) + ")");
    }
  }
  std::stable_sort(report.failures.begin(), report.failures.end(),
                   [](const EvalFailure& a, const EvalFailure& b) { return a.file < b.file; });
  std::sort(report.skipped.begin(), report.skipped.end());

  std::vector<std::unique_ptr<ShardReader>> readers;
  for (const fs::path& d : dirs) {
    auto r = ShardReader::open(d / kErrorsCsvName);
    if (!r) return make_error(r.error());
    readers.push_back(std::move(*r));
  }
  if (Status s = make_dir(out_dir); !s) return make_error(s.error());
  auto lock = DirectoryLock::acquire(out_dir);
  if (!lock) return make_error(lock.error());
  CsvWriter csv(out_dir / kErrorsCsvName);
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
    if (!rows) return make_error(rows.error());
    csv.add_clip(*rows, builder);
    ++report.clips_evaluated;
  }
  report.summary = builder.finish();
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  json merged_from = json::array();
  for (const fs::path& d : dirs) merged_from.push_back(d.string());
  json meta = {{"tool", "rotinterp eval"},
               {"version", version.empty() ? std::string(ROTINTERP_VERSION) : version},
               {"inputs", inputs},
               {"files", report.files},
               {"merged_from", merged_from},
               {"options", options},
               {"started", utc_now()},
               {"seconds", seconds},
               {"merge_seconds", report.seconds},
               {"failed", failures_json(report.failures)},
               {"skipped", report.skipped}};
  if (Status s = write_outputs(out_dir, std::move(meta), report.summary, plots, csv); !s) return make_error(s.error());
  return report;
}

}  // namespace rotinterp
