#pragma once
// The fronts of a symbolic-regression result as its file holds them (docs/results-symreg.md), read back:
// the output groups, and per output its inputs (group attribute `inputs`, in column order) and the rows of
// its `front` table (empty while the job has not finished its last stage). A table or attribute the
// layout promises that cannot be read is a RunError.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace pbrfit::jobs::symreg {

struct FrontMember {
  std::string expression;  // statements separated by "; ", constants with round-trip digits
  double cost = 0.0;
  double rmse = 0.0;
  double max_abs_error = 0.0;
  double test_rmse = 0.0;  // on the test rows; NaN without them
  bool knee = false;
};

struct OutputFront {
  std::string output;
  std::vector<std::string> inputs;
  std::vector<FrontMember> members;  // by increasing cost
};

// The member of the lowest test RMSE, the cheapest (first) of equals; none when no member has one.
std::optional<std::size_t> lowest_test_error_member(const OutputFront& front);

// The output groups: every group at the root but `subexpressions`, in name order.
std::vector<std::string> result_outputs(const std::string& path);

OutputFront read_output_front(const std::string& path, const std::string& output);

}  // namespace pbrfit::jobs::symreg
