#pragma once
// One member of a symbolic-regression front as a function in HLSL, GLSL or C++ (`pbrfit export`,
// docs/results-symreg.md). The member's expression text is parsed back with the output's inputs: its
// constants have round-trip digits, so the program is exactly the one that was measured. The function
// (gp/export.hpp) takes the output's inputs in column order, under their portable names
// (gp/export_names.hpp), and is preceded by one comment line with the job's name, the output, the member,
// and its cost, RMSE and max abs error (measured in double on the training rows).
//
// Refusals are InputErrors on one line: naming the result file for a result that is not a symreg result,
// an output it does not have (or none chosen when it has several), a member out of range, a front that
// does not exist yet (the job has not finished its last stage), a stored expression that does not parse,
// a choice by test error in a result without test rows;
// naming the option for a --name that is not a portable name and for --double outside C++.
#include <cstddef>
#include <optional>
#include <string>

#include "pbrfit/gp/export.hpp"
#include "pbrfit/store/result_file.hpp"

namespace pbrfit::jobs::symreg {

struct MemberExport {
  std::string output;                 // empty: the result's only output
  std::optional<std::size_t> member;  // row of <output>/front; empty: the knee (or, by_test_error, ...)
  bool by_test_error = false;         // the member of the lowest test RMSE (the cheapest of equals)
  gp::ExportLanguage language = gp::ExportLanguage::hlsl;
  std::string function_name;          // empty: the output's name as a portable name
  bool cpp_double = false;
};

// `summary` is what store::read_result_summary read from `path`.
std::string export_member(const std::string& path, const store::ResultSummary& summary, const MemberExport& request);

}  // namespace pbrfit::jobs::symreg
