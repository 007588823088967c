#pragma once
// What the programs of a run may contain: operators, inputs, constants, lengths. Random programs and
// variation draw only from it.
//
// Invariants (validate() checks them): operators not empty; input_count >= 1; 1 <= initial_min_length <=
// initial_max_length <= max_length <= max_program_length; probabilities in [0, 1]; constant_min <=
// constant_max, both finite.
#include <cstddef>

#include "pbrfit/gp/operator_set.hpp"

namespace pbrfit::gp {

struct ProgramShape {
  OperatorSet operators = arithmetic_operators();
  std::size_t input_count = 1;
  std::size_t max_length = 32;  // instructions, introns included
  std::size_t initial_min_length = 1;
  std::size_t initial_max_length = 12;
  // When an operand is drawn: the chance that it is an earlier instruction's result (if there is one);
  // otherwise it is a leaf: a constant with constant_probability (0: no constants), else an input.
  double reference_probability = 0.6;
  double constant_probability = 0.0;
  double constant_min = -1.0;  // random constants are uniform in [constant_min, constant_max]
  double constant_max = 1.0;
};

// Throws std::invalid_argument when an invariant does not hold.
void validate(const ProgramShape& shape);

}  // namespace pbrfit::gp
