#pragma once
// Partial evaluation for parameter fitting (parameter_fit.hpp). The live instructions of a program that
// read no parameter - no constant of parameter_slots, directly or through earlier instructions - give the
// same values at every evaluation of a fit: genBRDF's Cook-Torrance spends most of its time on
// tan(acos(n.h)), the geometry term and (1 - n.h)^5, none of which a parameter touches. fold_fixed_part
// computes each fixed value a parameter-dependent instruction reads once, in double precision, as an extra
// data column, and keeps only the instructions that depend on the parameters.
//
// Contract: for any parameter values x, the folded program with x in its slots (set_parameters) computes
// the original's output at every row, except that the fixed values are rounded once from double rather
// than computed in the interpreter's precision; the folded dataset is the original's with the extra
// columns appended (same rows, target and weights); parameter k of the result is parameter k of the
// input. A program whose output reads no parameter folds to a single identity of its output's column. A
// fixed value that is not finite at some row (a dataset holds only finite numbers) is not folded: that
// instruction stays in the program, computed as before.
#include <span>
#include <vector>

#include "pbrfit/gp/dataset.hpp"
#include "pbrfit/gp/program.hpp"
#include "pbrfit/gp/program_builder.hpp"

namespace pbrfit::gp {

struct FoldedFit {
  Program program;
  std::vector<std::vector<ConstantSlot>> parameter_slots;
  Dataset dataset;
};

FoldedFit fold_fixed_part(const Program& program, std::span<const std::vector<ConstantSlot>> parameter_slots,
                          const Dataset& dataset);

}  // namespace pbrfit::gp
