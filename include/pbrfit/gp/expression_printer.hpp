#pragma once
// Prints a program as an expression text (expression_parser.hpp) that parses back to a program with the
// same values at every row. Only live instructions are printed; an instruction used more than once
// becomes a binding line (`t1 = ...`, names chosen not to clash with inputs or parameters), the rest is
// inlined, with the parentheses the tree needs and no more. Constants are printed with the fewest digits
// that read back to the same double; a constant in a named parameter slot is printed as its name.
#include <span>
#include <string>
#include <vector>

#include "pbrfit/gp/expression_parser.hpp"
#include "pbrfit/gp/program.hpp"

namespace pbrfit::gp {

// names.inputs must name every input the program reads; names.parameters[k], when given, names the
// constants in parameter_slots[k].
std::string print_expression(const Program& program, const ExpressionNames& names,
                             std::span<const std::vector<ConstantSlot>> parameter_slots = {});

// The shortest decimal text that reads back to `value` (std::to_chars).
std::string shortest_decimal(double value);

}  // namespace pbrfit::gp
