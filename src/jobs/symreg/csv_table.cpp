#include "pbrfit/jobs/symreg/csv_table.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <set>

#include "pbrfit/core/quoted_text.hpp"

namespace pbrfit::jobs::symreg {
namespace {

struct Field {
  std::string_view text;
  std::size_t column;  // 1-based, of the field's first character
};

// The fields of `line` into `fields` (reused from line to line: no allocation per row).
void split_fields(std::string_view line, std::vector<Field>& fields) {
  fields.clear();
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = line.find(',', start);
    std::string_view field = line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start);
    std::size_t column = start + 1;
    while (!field.empty() && field.front() == ' ') field.remove_prefix(1), ++column;
    while (!field.empty() && field.back() == ' ') field.remove_suffix(1);
    fields.push_back({field, column});
    if (comma == std::string_view::npos) return;
    start = comma + 1;
  }
}

double number_of(const Field& f, const std::string& file, int line) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(f.text.data(), f.text.data() + f.text.size(), value);
  if (f.text.empty() || error != std::errc() || end != f.text.data() + f.text.size() || !std::isfinite(value))
    throw InputError({file, line, int(f.column)}, "expected a finite number, got " + quote(std::string(f.text)));
  return value;
}

}  // namespace

const std::vector<double>& CsvTable::column(const std::string& name, const SourcePosition& where) const {
  for (std::size_t k = 0; k < names_.size(); ++k)
    if (names_[k] == name) return columns_[k];
  std::string all;
  for (const auto& n : names_) all += (all.empty() ? "" : ", ") + n;
  throw InputError(where, quote(name) + " is not a column of " + file_ + " (columns: " + all + ")");
}

CsvTable parse_csv(std::string_view text, const std::string& file) {
  std::vector<std::string> names;
  std::vector<std::vector<double>> columns;
  int line_number = 0;
  std::vector<Field> fields;
  while (!text.empty()) {
    const std::size_t end = text.find('\n');
    std::string_view line = text.substr(0, end);
    text = end == std::string_view::npos ? std::string_view() : text.substr(end + 1);
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (line.find_first_not_of(' ') == std::string_view::npos || line.front() == '#') continue;
    // Fields are counted before they are split: no line makes more of them than the header may have.
    const auto count = std::size_t(std::count(line.begin(), line.end(), ',')) + 1;
    if (names.empty() && count > max_csv_columns)
      throw InputError({file, line_number, 1}, "a header of " + std::to_string(count) + " columns; at most " +
                                                   std::to_string(max_csv_columns));
    if (!names.empty() && count != names.size())
      throw InputError({file, line_number, 1}, "a row of " + std::to_string(count) + " fields; the header has " +
                                                   std::to_string(names.size()));
    split_fields(line, fields);
    if (names.empty()) {
      std::set<std::string> seen;
      for (const auto& f : fields) {
        if (f.text.empty() || !seen.insert(std::string(f.text)).second)
          throw InputError({file, line_number, int(f.column)}, "column names must be non-empty and unique");
        names.emplace_back(f.text);
      }
      columns.resize(names.size());
      continue;
    }
    if (columns[0].size() == max_csv_rows)
      throw InputError({file, line_number, 1}, "more than " + std::to_string(max_csv_rows) + " data rows");
    for (std::size_t k = 0; k < fields.size(); ++k) columns[k].push_back(number_of(fields[k], file, line_number));
  }
  if (names.empty() || columns[0].empty()) throw InputError({file}, "has no header line and data rows");
  return CsvTable(file, std::move(names), std::move(columns));
}

}  // namespace pbrfit::jobs::symreg
