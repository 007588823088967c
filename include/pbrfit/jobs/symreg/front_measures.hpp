#pragma once
// What the result reports about a program beyond its search objectives: RMSE and largest absolute error on
// the training rows (and RMSE on fresh rows when there are any), in double precision whatever the search
// used; its live operations; its constants; its text.
#include <cstdint>
#include <string>
#include <vector>

#include "pbrfit/gp/dataset.hpp"
#include "pbrfit/gp/expression_parser.hpp"
#include "pbrfit/gp/program.hpp"

namespace pbrfit::jobs::symreg {

struct ProgramMeasures {
  double rmse = 0.0;
  double max_abs_error = 0.0;
  double test_rmse = 0.0;  // NaN without fresh rows
  std::uint32_t operations = 0;
};

ProgramMeasures measure_program(const gp::Program& program, const gp::Dataset& train, const gp::Dataset& test);
// Live operations (identity copies do not count).
std::uint32_t live_operations(const gp::Program& program);
// The program's outputs at every row of the dataset, in double.
std::vector<double> predictions(const gp::Program& program, const gp::Dataset& data);
// One line: statements joined by "; " (the expression parser reads it back).
std::string expression_text(const gp::Program& program, const gp::ExpressionNames& names);
// The live constants, comma-separated, each the shortest decimal that reads back to it.
std::string constants_text(const gp::Program& program);

}  // namespace pbrfit::jobs::symreg
