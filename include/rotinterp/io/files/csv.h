// The one CSV dialect of every table rotinterp writes (errors.csv, clips.csv,
// per_frame.csv, resample's manifest) and reads back: each table declares its
// columns once, as a CsvSchema, and its rows are written against that schema, so a
// row with a field too many or too few is caught where it is written. Fields are
// quoted (quotes doubled) only when they hold a comma, quote or line break
// (RFC 4180); lines end in '\n'.
#pragma once

#include "rotinterp/core/result.h"

#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace rotinterp {

// A text field as CSV writes it.
std::string csv_field(std::string_view text);

// Splits one CSV line into fields. Error on an unterminated quote.
Result<std::vector<std::string>> split_csv_line(std::string_view line);

// A table's column names, in file order.
class CsvSchema {
 public:
  CsvSchema(std::initializer_list<std::string_view> columns);
  explicit CsvSchema(std::vector<std::string> columns) : columns_(std::move(columns)) {}

  // This table's columns followed by `more`'s (an optional group, e.g. eval --loop's seam).
  CsvSchema operator+(const CsvSchema& more) const;

  const std::vector<std::string>& columns() const { return columns_; }
  std::size_t size() const { return columns_.size(); }
  // The header line, with its '\n'.
  std::string header() const;

 private:
  std::vector<std::string> columns_;
};

// One row, built field by field in the schema's order; line() checks the count.
class CsvRow {
 public:
  explicit CsvRow(const CsvSchema& schema) : schema_(&schema) {}

  // A field: text is quoted as needed; numbers are formatted by the caller, the one
  // place that knows the column's precision.
  CsvRow& operator<<(std::string_view field);
  // `n` empty fields (a group of columns this row has no value for).
  CsvRow& skip(std::size_t n = 1);
  // The line with its '\n'. The row must hold exactly one field per column.
  std::string line() const;

 private:
  const CsvSchema* schema_;
  std::string text_;
  std::size_t fields_ = 0;
};

}  // namespace rotinterp
