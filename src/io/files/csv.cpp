// CSV quoting, splitting, and rows checked against their table's schema.
#include "rotinterp/io/files/csv.h"

namespace rotinterp {

std::string csv_field(std::string_view s) {
  if (s.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(s);
  std::string out = "\"";
  for (char c : s) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

Result<std::vector<std::string>> split_csv_line(std::string_view line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"') {
        if (i + 1 < line.size() && line[i + 1] == '"') {
          fields.back() += '"';
          ++i;
        } else {
          quoted = false;
        }
      } else {
        fields.back() += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else if (c != '\r' && c != '\n') {  // a line read with its end
      fields.back() += c;
    }
  }
  if (quoted) return make_error("unterminated quote");
  return fields;
}

CsvSchema::CsvSchema(std::initializer_list<std::string_view> columns) {
  for (std::string_view c : columns) columns_.emplace_back(c);
}

CsvSchema CsvSchema::operator+(const CsvSchema& more) const {
  std::vector<std::string> all = columns_;
  all.insert(all.end(), more.columns_.begin(), more.columns_.end());
  return CsvSchema(std::move(all));
}

std::string CsvSchema::header() const {
  std::string h;
  for (std::size_t i = 0; i < columns_.size(); ++i) h += (i ? "," : "") + csv_field(columns_[i]);
  return h + '\n';
}

CsvRow& CsvRow::operator<<(std::string_view field) {
  if (fields_++) text_ += ',';
  text_ += csv_field(field);
  return *this;
}

CsvRow& CsvRow::skip(std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) *this << std::string_view();
  return *this;
}

std::string CsvRow::line() const {
  ROTINTERP_ASSERT(fields_ == schema_->size());
  return text_ + '\n';
}

}  // namespace rotinterp
