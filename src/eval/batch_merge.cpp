// eval --merge: the shards' errors.csv merged clip by clip in sorted order, and
// their records into one summary.json.
#include "batch_outputs.h"

#include "rotinterp/eval/batch.h"

#include <algorithm>
#include <chrono>
#include <fstream>
#include <memory>
#include <optional>

namespace rotinterp {

namespace fs = std::filesystem;

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
  MetricSet columns() const { return parser_->metrics(); }
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
  auto lock = DirectoryLock::acquire(out_dir);
  if (!lock) return lock.failure();
  const bool seam = merged.options.loop != "off";
  auto chosen = parse_metrics(merged.options.metrics);
  if (!chosen) return chosen.failure((dirs.front() / kSummaryJsonName).string() + ": ");
  const MetricSet columns = csv_metrics(*chosen, seam);
  for (const auto& r : readers) {
    if (r->columns().has(Metric::seam) != columns.has(Metric::seam))
      return make_error(std::string("a shard's errors.csv ") + (columns.has(Metric::seam) ? "lacks" : "has") +
                        " the seam columns (seam_angle_deg … looped) its summary.json's loop and metrics options say");
    if (r->columns() != columns)
      return make_error("a shard's errors.csv has the columns of metrics " + metrics_text(r->columns()) +
                        ", not those its summary.json's metrics option says (" + merged.options.metrics + ")");
  }
  ErrorsCsv csv(out_dir / kErrorsCsvName, columns);
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
  report.summary.seam = columns.has(Metric::seam);
  report.summary.metrics = columns;
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
