// CSV data files for symbolic regression: columns by name, and every malformed input refused at its place.
#include <catch2/catch_test_macros.hpp>

#include <string>

#include "pbrfit/jobs/symreg/csv_table.hpp"

using pbrfit::InputError;
using pbrfit::jobs::symreg::parse_csv;

namespace {

std::string refusal(const std::string& text) {
  try {
    parse_csv(text, "d.csv");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

}  // namespace

TEST_CASE("a CSV table has named numeric columns; comments, blank lines, spaces and CRLF are allowed") {
  const auto table = parse_csv("# data\nx, y\r\n1, 2.5\r\n\n-3e-2,4\n", "d.csv");
  CHECK(table.names() == std::vector<std::string>{"x", "y"});
  CHECK(table.rows() == 2);
  CHECK(table.column("x", {}) == std::vector<double>{1.0, -0.03});
  CHECK(table.column("y", {}) == std::vector<double>{2.5, 4.0});
  CHECK_THROWS_AS(table.column("z", {"job.yaml", 3, 4}), InputError);
}

TEST_CASE("malformed CSV files are refused at the line and column of the problem") {
  CHECK(refusal("x,y\n1,2\n3,four\n") == "d.csv:3:3: error: expected a finite number, got 'four'");
  CHECK(refusal("x,y\n1,inf\n") == "d.csv:2:3: error: expected a finite number, got 'inf'");
  CHECK(refusal("x,y\n1,\n") == "d.csv:2:3: error: expected a finite number, got ''");
  CHECK(refusal("x,y\n1,2,3\n") == "d.csv:2:1: error: a row of 3 fields; the header has 2");
  CHECK(refusal("x,x\n1,2\n") == "d.csv:1:3: error: column names must be non-empty and unique");
  CHECK(refusal("x,y\n") == "d.csv: error: has no header line and data rows");
  CHECK(refusal("") == "d.csv: error: has no header line and data rows");
  CHECK(refusal(std::string("x\n1\0", 4)) == "d.csv:2:1: error: expected a finite number, got '1\\x00'");
}

// Hostile sizes are refused at the line that exceeds them, before the table grows past the limits.
TEST_CASE("a CSV file of too many columns or rows is refused at the line that exceeds the limit") {
  using pbrfit::jobs::symreg::max_csv_columns;
  using pbrfit::jobs::symreg::max_csv_rows;
  std::string header;
  for (std::size_t k = 0; k < max_csv_columns; ++k) header += (k ? ",c" : "c") + std::to_string(k);
  std::string row = "1";
  for (std::size_t k = 1; k < max_csv_columns; ++k) row += ",1";
  CHECK_NOTHROW(parse_csv(header + "\n" + row + "\n", "d.csv"));  // at the limit: accepted
  CHECK(refusal(header + ",extra\n" + row + ",1\n") ==
        "d.csv:1:1: error: a header of " + std::to_string(max_csv_columns + 1) + " columns; at most " +
            std::to_string(max_csv_columns));
  std::string rows = "x\n";
  rows.reserve(2 * max_csv_rows + 8);
  for (std::size_t r = 0; r < max_csv_rows; ++r) rows += "1\n";
  CHECK(parse_csv(rows, "d.csv").rows() == max_csv_rows);  // at the limit: accepted
  rows += "2\n";
  CHECK(refusal(rows) == "d.csv:" + std::to_string(max_csv_rows + 2) + ":1: error: more than " +
                             std::to_string(max_csv_rows) + " data rows");
}


// What spreadsheet programs and pandas write (issue 24): a byte-order mark, quoted header names and fields
// (commas and doubled quotes inside), a leading '+'.
TEST_CASE("CSV files as spreadsheets and pandas write them are read") {
  const auto table = parse_csv("\xEF\xBB\xBF\"x\",\"a, \"\"b\"\"\"\r\n+0.4,\"-1e1\"\r\n\"+2\" , 3\r\n", "d.csv");
  CHECK(table.names() == std::vector<std::string>{"x", "a, \"b\""});
  CHECK(table.column("x", {}) == std::vector<double>{0.4, 2.0});
  CHECK(table.column("a, \"b\"", {}) == std::vector<double>{-10.0, 3.0});
  CHECK(refusal("x,y\n\"1,2\n") == "d.csv:2:1: error: a quoted field without its closing quote");
  CHECK(refusal("x,y\n\"1\"2,3\n") == "d.csv:2:4: error: text after a quoted field's closing quote");
  CHECK(refusal("x,y\n1,\"1,5\"\n") == "d.csv:2:3: error: expected a finite number, got '1,5'");
  CHECK(refusal("x,y\n1,+-2\n") == "d.csv:2:3: error: expected a finite number, got '+-2'");
  CHECK(refusal("x,y\n1,++2\n") == "d.csv:2:3: error: expected a finite number, got '++2'");
  CHECK(refusal("x,y\n1,+\n") == "d.csv:2:3: error: expected a finite number, got '+'");
  CHECK(refusal("\"x\",\"x\"\n1,2\n") == "d.csv:1:5: error: column names must be non-empty and unique");
  CHECK(refusal("x,y\n1,\"2\",3\n") == "d.csv:2:1: error: a row of 3 fields; the header has 2");
}
