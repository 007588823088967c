#pragma once
// One table of a pbrfit result as a regression dataset: a row per cell with a finite value, the cell's
// axis values as inputs (named after the axes) and the table's value as the target.
#include <string>
#include <vector>

#include "pbrfit/jobs/symreg/symreg_data.hpp"

namespace pbrfit::jobs::symreg {

// The rows of the columns where every value is finite (columns and target of equal length).
SymregOutput output_from_columns(const std::string& name, const std::vector<std::string>& inputs,
                                 const std::vector<std::vector<double>>& input_columns, const std::vector<double>& target);

// `table` is GROUP/NAME; the output is named NAME. Throws RunError when the table cannot be read or is not a
// numeric table over its group's axes.
SymregOutput output_from_result_table(const std::string& path, const std::string& table);

}  // namespace pbrfit::jobs::symreg
