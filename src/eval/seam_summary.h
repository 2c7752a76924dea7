// The seam figures of eval --loop in clips.csv and summary.json (SeamSummary, eval/summary.h).
#pragma once

#include "rotinterp/eval/summary.h"
#include "rotinterp/io/files/csv.h"

#include <nlohmann/json.hpp>

#include <string>

namespace rotinterp {

// clips.csv's seam columns, and one clip's values appended to its row.
const CsvSchema& seam_csv_schema();
void add_seam_fields(CsvRow& row, const SeamSummary& seam);
// summary.json's "seam" object of a result.
nlohmann::json seam_json(const SeamSummary& seam);

}  // namespace rotinterp
