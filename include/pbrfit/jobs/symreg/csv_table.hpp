#pragma once
// A numeric CSV table: a header line of column names, then rows of numbers separated by commas (spaces
// around fields ignored, '#' lines and empty lines skipped, CRLF accepted), as spreadsheets and pandas
// write them too: a UTF-8 byte-order mark, fields in double quotes (RFC 4180: commas inside, "" for a
// quote; a field does not span lines) and numbers with a leading '+'.
//
// Contract: parse_csv throws InputError at FILE:LINE:COL for a field that is not a finite number, a quoted
// field without its closing quote or with text after it, a row
// with another number of fields than the header, a duplicate or empty column name, no data rows, or more
// than max_csv_columns columns or max_csv_rows rows (refused at the line that exceeds them, before it is
// stored: a hostile file cannot make the table outgrow these bounds).
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "pbrfit/core/error.hpp"

namespace pbrfit::jobs::symreg {

inline constexpr std::size_t max_csv_columns = 1024;
inline constexpr std::size_t max_csv_rows = std::size_t(1) << 24;  // 16 Mi rows

class CsvTable {
 public:
  CsvTable(std::string file, std::vector<std::string> names, std::vector<std::vector<double>> columns)
      : file_(std::move(file)), names_(std::move(names)), columns_(std::move(columns)) {}

  const std::vector<std::string>& names() const { return names_; }
  std::size_t rows() const { return columns_.empty() ? 0 : columns_[0].size(); }
  // Throws InputError at `where` (the job key naming it) for a column the table does not have.
  const std::vector<double>& column(const std::string& name, const SourcePosition& where) const;

 private:
  std::string file_;
  std::vector<std::string> names_;
  std::vector<std::vector<double>> columns_;
};

CsvTable parse_csv(std::string_view text, const std::string& file);

}  // namespace pbrfit::jobs::symreg
