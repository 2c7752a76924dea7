// The seam figures of eval --loop in clips.csv and summary.json (SeamSummary, eval/summary.h).
#pragma once

#include "rotinterp/eval/summary.h"

#include <nlohmann/json.hpp>

#include <string>

namespace rotinterp {

// clips.csv's seam columns (no leading comma): their names, and one clip's values.
std::string seam_csv_header();
std::string seam_csv_fields(const SeamSummary& seam);
// summary.json's "seam" object of a result.
nlohmann::json seam_json(const SeamSummary& seam);

}  // namespace rotinterp
