// What an eval run writes into its directory: errors.csv streamed a clip at a time,
// then summary.json, clips.csv, per_frame.csv and the plots, committed with it as a
// unit. Shared by a run (batch.cpp) and a merge of shards (batch_merge.cpp).
#pragma once

#include "rotinterp/eval/batch.h"
#include "rotinterp/eval/error_row.h"
#include "rotinterp/eval/evaluate_clip.h"
#include "rotinterp/eval/summary.h"
#include "rotinterp/io/files/atomic_file.h"

#include <filesystem>
#include <string>
#include <vector>

namespace rotinterp {

// The time now, as summary.json records it (ISO 8601, UTC).
std::string utc_now();

// errors.csv into an unnamed temporary, one clip's rows at a time; committed with
// the other outputs by write_outputs.
class ErrorsCsv {
 public:
  // `columns`: the metrics whose columns the file has (csv_metrics).
  ErrorsCsv(const std::filesystem::path& target, MetricSet columns);
  bool good() const { return out_.status().ok(); }
  // Writes the rows of one clip and adds them to the summary.
  void add_clip(const std::vector<ErrorRow>& rows, SummaryBuilder& summary);
  std::string failure() const;
  AtomicOutput& output() { return out_; }

 private:
  AtomicOutput out_;
  MetricSet columns_;
};

// Writes summary.json (the run record and the results) and the plots, then commits them with
// errors.csv as a unit: an interrupt before the end leaves the previous run's files
// (all of them), after it this run's. Plots of an earlier run that this one does
// not draw are removed, so no file in DIR is older than the others.
Status write_outputs(const std::filesystem::path& dir, const RunRecord& record, const Summary& summary, bool plots,
                     ErrorsCsv& csv, const std::string& per_frame = {});

// The per-frame error series of `R` as CSV: sample, time, whether the sample is a
// key, then one column of degrees per joint.
std::string per_frame_csv(const ClipReference& R, const PerFrameRequest& q, const PerFrameErrors& e);

}  // namespace rotinterp
