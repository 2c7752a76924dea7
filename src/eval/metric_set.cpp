// The metric names, in one place.
#include "rotinterp/eval/metric_set.h"

namespace rotinterp {

namespace {

constexpr const char* kNames[kMetricCount] = {"angle", "swing-twist", "fk", "shell", "smoothness", "foot-skating",
                                              "seam"};

}  // namespace

std::string metric_names() {
  std::string out;
  for (const char* n : kNames) out += (out.empty() ? "" : ", ") + std::string(n);
  return out;
}

const char* metric_name(Metric m) { return kNames[static_cast<int>(m)]; }

Result<MetricSet> parse_metrics(std::string_view list) {
  if (list == "all") return MetricSet::all();
  MetricSet set = MetricSet::none();
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = list.find(',', start);
    const std::string_view item = list.substr(start, comma == std::string_view::npos ? list.npos : comma - start);
    int found = -1;
    for (int m = 0; m < kMetricCount; ++m)
      if (item == kNames[m]) found = m;
    if (found < 0)
      return make_error("unknown metric '" + std::string(item) + "'; valid: all, " + metric_names());
    set.add(static_cast<Metric>(found));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return set;
}

std::string metrics_text(MetricSet set) {
  if (set.is_all()) return "all";
  std::string out;
  for (int m = 0; m < kMetricCount; ++m)
    if (set.has(static_cast<Metric>(m))) out += (out.empty() ? "" : ",") + std::string(kNames[m]);
  return out;
}

}  // namespace rotinterp
