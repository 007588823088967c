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
