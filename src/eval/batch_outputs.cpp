// eval's outputs: errors.csv streamed, then summary.json, clips.csv, per_frame.csv and
// the plots, committed together.
#include "batch_outputs.h"

#include "rotinterp/eval/plots.h"
#include "rotinterp/eval/seam.h"
#include "rotinterp/io/files/csv.h"

#include <fmt/format.h>

#include <ctime>
#include <memory>

namespace rotinterp {

namespace fs = std::filesystem;

std::string utc_now() {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

ErrorsCsv::ErrorsCsv(const fs::path& target, MetricSet columns) : out_(target, TempKind::unnamed), columns_(columns) {
  const std::string header = error_csv_schema(columns).header();
  (void)out_.write(header.data(), header.size());
}

void ErrorsCsv::add_clip(const std::vector<ErrorRow>& rows, SummaryBuilder& summary) {
  std::string text;
  for (const ErrorRow& r : rows) text += format_error_row(r, columns_);
  (void)out_.write(text.data(), text.size());
  summary.add_clip(rows);
}

std::string ErrorsCsv::failure() const {
  return out_.status() ? out_.target().string() + ": write failed" : out_.status().error();
}

Status write_outputs(const fs::path& dir, const RunRecord& record, const Summary& summary, bool plots, ErrorsCsv& csv,
                     const std::string& per_frame) {
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
  const bool draw = plots && summary.clips > 0 && summary.metrics.has(Metric::angle);  // the plots show angles
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

}  // namespace rotinterp
