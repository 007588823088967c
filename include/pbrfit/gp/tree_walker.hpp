#pragma once
// The straightforward interpreter: one row at a time, recursing from the output through the operands
// with apply() (semantics.hpp) at every node. A shared subexpression is evaluated once per use, as a tree
// would be. It is the baseline of the interpreter benchmark and the reference of the tests; it allocates
// nothing, and recursion depth is bounded by max_program_length.
#include <cstddef>
#include <span>

#include "pbrfit/gp/dataset.hpp"
#include "pbrfit/gp/program.hpp"

namespace pbrfit::gp {

// The program's output for one row of inputs (row.size() >= the inputs the program reads).
template <class T>
T walk_tree(const Program& program, std::span<const T> row);

// The output at every row of the dataset (its inputs converted to T): out.size() == dataset.rows().
template <class T>
void walk_tree(const Program& program, const Dataset& dataset, std::span<T> out);

}  // namespace pbrfit::gp
