#include "pbrfit/jobs/symreg/csv_table.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>
#include <set>

#include "pbrfit/core/quoted_text.hpp"

namespace pbrfit::jobs::symreg {
namespace {

struct Field {
  std::string_view text;
  std::size_t column;  // 1-based, of the field's first character (its opening quote when quoted)
};

// Where a quoted field's closing quote is missing or text follows it.
struct QuoteError {
  std::size_t column;
  std::string reason;
};

// Splits `line` into fields as RFC 4180 quotes them (a field in double quotes may hold commas, and "" for a
// quote), counting every field but keeping at most `keep` in `fields` (reused from line to line; a quoted
// field's text with its doubled quotes undone goes to `unquoted`, reserved to the line's size so that
// views into it stay valid). Returns the number of fields, or a QuoteError through `error`.
std::size_t split_fields(std::string_view line, std::size_t keep, std::vector<Field>& fields, std::string& unquoted,
                         std::optional<QuoteError>& error) {
  fields.clear();
  unquoted.clear();
  unquoted.reserve(line.size());
  std::size_t count = 0;
  std::size_t at = 0;
  for (;;) {
    while (at < line.size() && line[at] == ' ') ++at;
    const std::size_t column = at + 1;
    std::string_view text;
    if (at < line.size() && line[at] == '"') {
      const std::size_t first = unquoted.size();
      std::size_t i = at + 1;
      for (;; ++i) {
        if (i >= line.size()) {
          error = QuoteError{column, "a quoted field without its closing quote"};
          return count;
        }
        if (line[i] != '"') {
          unquoted.push_back(line[i]);
        } else if (i + 1 < line.size() && line[i + 1] == '"') {
          unquoted.push_back('"');
          ++i;
        } else {
          break;
        }
      }
      text = std::string_view(unquoted).substr(first);
      at = i + 1;
      while (at < line.size() && line[at] == ' ') ++at;
      if (at < line.size() && line[at] != ',') {
        error = QuoteError{at + 1, "text after a quoted field's closing quote"};
        return count;
      }
    } else {
      const std::size_t comma = std::min(line.find(',', at), line.size());
      text = line.substr(at, comma - at);
      while (!text.empty() && text.back() == ' ') text.remove_suffix(1);
      at = comma;
    }
    if (++count <= keep) fields.push_back({text, column});
    if (at >= line.size()) return count;
    ++at;  // past the comma
  }
}

double number_of(const Field& f, const std::string& file, int line) {
  std::string_view digits = f.text;
  // A leading '+', as spreadsheets write it; from_chars takes none.
  if (digits.size() > 1 && digits[0] == '+' && digits[1] != '-' && digits[1] != '+') digits.remove_prefix(1);
  double value = 0.0;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (digits.empty() || error != std::errc() || end != digits.data() + digits.size() || !std::isfinite(value))
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
  constexpr std::string_view byte_order_mark = "\xEF\xBB\xBF";  // as spreadsheets write UTF-8
  if (text.starts_with(byte_order_mark)) text.remove_prefix(byte_order_mark.size());
  std::vector<std::string> names;
  std::vector<std::vector<double>> columns;
  int line_number = 0;
  std::vector<Field> fields;
  std::string unquoted;
  while (!text.empty()) {
    const std::size_t end = text.find('\n');
    std::string_view line = text.substr(0, end);
    text = end == std::string_view::npos ? std::string_view() : text.substr(end + 1);
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (line.find_first_not_of(' ') == std::string_view::npos || line.front() == '#') continue;
    // No line keeps more fields than the header may have, or than the header has.
    const std::size_t keep = names.empty() ? max_csv_columns : names.size();
    std::optional<QuoteError> quote_error;
    const std::size_t count = split_fields(line, keep, fields, unquoted, quote_error);
    if (quote_error) throw InputError({file, line_number, int(quote_error->column)}, quote_error->reason);
    if (names.empty() && count > max_csv_columns)
      throw InputError({file, line_number, 1}, "a header of " + std::to_string(count) + " columns; at most " +
                                                   std::to_string(max_csv_columns));
    if (!names.empty() && count != names.size())
      throw InputError({file, line_number, 1}, "a row of " + std::to_string(count) + " fields; the header has " +
                                                   std::to_string(names.size()));
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
