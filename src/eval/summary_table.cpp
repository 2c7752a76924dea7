// The summary as tables: the text, Markdown or LaTeX table on stdout, and clips.csv.
#include "rotinterp/eval/summary.h"
#include "rotinterp/io/files/csv.h"
#include "seam_summary.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

namespace rotinterp {

namespace {

// `v` to 4 significant figures in fixed notation; "< 0.001" below, "0" for zero.
std::string sig4(double v) {
  if (v == 0.0 || !std::isfinite(v)) return "0";
  if (std::fabs(v) < 1e-3) return v < 0 ? "> -0.001" : "< 0.001";
  const int digits = static_cast<int>(std::floor(std::log10(std::fabs(v))));
  return fmt::format("{:.{}f}", v, std::max(0, 3 - digits));
}

}  // namespace

std::string format_summary_table(const Summary& s, TableFormat format) {
  // Each column with the summary value it shows (summary_metric), empty for method, N, clips.
  const std::vector<std::pair<std::string, const char*>> columns = {
      {"method", ""}, {"N", ""}, {"clips", ""}, {"mean°", "mean_deg"}, {"RMS°", "rms_deg"}, {"p95°", "p95_deg"},
      {"max°", "max_deg"}, {"median clip RMS°", "clip_rms_median_deg"}, {"pos max %", "pos_max_pct"},
      {"extra skate %", "extra_skate_ratio"}};
  std::vector<bool> shown;
  std::vector<std::string> head;
  for (const auto& [title, value] : columns) {
    const std::optional<Metric> m = summary_metric(value);
    shown.push_back(!m || s.metrics.has(*m));
    if (shown.back()) head.push_back(title);
  }
  std::vector<std::vector<std::string>> body;
  for (const SummaryEntry& e : s.entries) {
    const std::vector<std::string> all = {
        e.method, std::to_string(e.keep_every), std::to_string(e.clips), sig4(e.mean_deg), sig4(e.rms_deg),
        sig4(e.p95_deg), sig4(e.max_deg), sig4(e.clip_rms_median_deg), sig4(e.pos_max_pct),
        e.skating.feet ? sig4(100.0 * (e.skating.ratio() - e.skating.ratio_ref())) : "–"};
    body.emplace_back();
    for (std::size_t i = 0; i < all.size(); ++i)
      if (shown[i]) body.back().push_back(all[i]);
  }
  std::string out;
  if (format == TableFormat::markdown) {
    auto line = [](const std::vector<std::string>& cells) {
      std::string l = "|";
      for (const std::string& c : cells) l += " " + c + " |";
      return l + "\n";
    };
    out += line(head);
    out += "|---|" + std::string() ;
    for (std::size_t i = 1; i < head.size(); ++i) out += "---:|";
    out += "\n";
    for (const auto& b : body) out += line(b);
    return out;
  }
  if (format == TableFormat::latex) {
    auto tex = [](std::string c) {
      std::string o;
      for (char ch : c) {
        if (ch == '_' || ch == '%' || ch == '&' || ch == '#') o += '\\';
        o += ch;
      }
      std::string deg = "°";
      for (std::size_t p; (p = o.find(deg)) != std::string::npos;) o.replace(p, deg.size(), "$^\\circ$");
      std::string lt = "< ";
      for (std::size_t p; (p = o.find(lt)) != std::string::npos;) o.replace(p, lt.size(), "$<$\\,");
      std::string dash = "–";
      for (std::size_t p; (p = o.find(dash)) != std::string::npos;) o.replace(p, dash.size(), "--");
      return o;
    };
    out += "\\begin{tabular}{lrr" + std::string(head.size() - 3, 'r') + "}\n\\hline\n";
    auto line = [&](const std::vector<std::string>& cells) {
      std::string l;
      for (std::size_t i = 0; i < cells.size(); ++i) l += (i ? " & " : "") + tex(cells[i]);
      return l + " \\\\\n";
    };
    out += line(head) + "\\hline\n";
    for (const auto& b : body) out += line(b);
    out += "\\hline\n\\end{tabular}\n";
    return out;
  }
  out = fmt::format("{} clip{}; mean and RMS weight every joint sample alike (clips by their samples), median clip "
                    "RMS counts each clip once\n",
                    s.clips, s.clips == 1 ? "" : "s");
  std::vector<std::size_t> width(head.size(), 0);
  auto display = [](const std::string& t) {  // UTF-8 code points
    std::size_t n = 0;
    for (char c : t) n += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
    return n;
  };
  for (std::size_t i = 0; i < head.size(); ++i) width[i] = display(head[i]);
  for (const auto& b : body)
    for (std::size_t i = 0; i < b.size(); ++i) width[i] = std::max(width[i], display(b[i]));
  auto line = [&](const std::vector<std::string>& cells) {
    std::string l;
    for (std::size_t i = 0; i < cells.size(); ++i) {
      const std::string pad(width[i] - display(cells[i]), ' ');
      l += (i ? "  " : "") + (i == 0 ? cells[i] + pad : pad + cells[i]);
    }
    return l + "\n";
  };
  out += line(head);
  std::string last;
  for (std::size_t k = 0; k < body.size(); ++k) {
    if (!last.empty() && s.entries[k].method != last) out += '\n';
    last = s.entries[k].method;
    out += line(body[k]);
  }
  if (!s.worst_clip.empty() && s.metrics.has(Metric::angle))
    out += fmt::format("worst clip (RMS at keep {}): {}\n", s.worst_keep_every, s.worst_clip);
  return out;
}

std::string clips_csv(const Summary& s) {
  static const std::vector<std::string> plain = {
      "clip", "method", "keep_every", "frames", "joints", "keys", "motion_deg", "samples", "mean_deg", "rms_deg",
      "p95_deg", "max_deg", "max_joint", "pos_rms_pct", "pos_max_pct", "shell_rms_pct", "shell_max_pct", "feet",
      "contact_frames", "skate_ratio", "skate_speed_mps", "contact_frames_ref", "skate_ratio_ref",
      "skate_speed_ref_mps", "extra_skate_ratio", "extra_skate_speed_mps"};
  // The columns of the summary's metrics (summary_metric), then the seam's.
  std::vector<bool> shown;
  std::vector<std::string> names;
  for (const std::string& name : plain) {
    const std::optional<Metric> m = summary_metric(name);
    shown.push_back(!m || s.metrics.has(*m));
    if (shown.back()) names.push_back(name);
  }
  const CsvSchema schema = s.seam ? CsvSchema(names) + seam_csv_schema() : CsvSchema(names);
  const auto n = [](auto v) { return fmt::format("{}", v); };
  std::string out = schema.header();
  for (const ClipResult& c : s.clip_results) {
    std::vector<std::string> fields = {c.clip, c.method, n(c.keep_every), n(c.frames), n(c.joints), n(c.keys),
                                       n(c.motion_deg), n(c.samples), n(c.mean_deg), n(c.rms_deg), n(c.p95_deg),
                                       n(c.max_deg), c.max_joint, n(c.pos_rms_pct), n(c.pos_max_pct),
                                       n(c.shell_rms_pct), n(c.shell_max_pct), n(c.skating.feet)};
    const FootSkating& f = c.skating;
    if (f.feet)
      fields.insert(fields.end(), {n(f.contact), n(f.ratio()), n(f.speed()), n(f.contact_ref), n(f.ratio_ref()),
                                   n(f.speed_ref()), n(f.ratio() - f.ratio_ref()), n(f.speed() - f.speed_ref())});
    else
      fields.resize(plain.size());  // no feet: the eight contact fields empty
    CsvRow row(schema);
    for (std::size_t i = 0; i < fields.size(); ++i)
      if (shown[i]) row << fields[i];
    if (s.seam) add_seam_fields(row, c.seam);
    out += row.line();
  }
  return out;
}

}  // namespace rotinterp
