#pragma once
// Random programs and random parts of programs, drawn from a shape (program_shape.hpp). Every result is
// valid for shape.input_count inputs and draws only operators of shape.operators.
#include <cstddef>

#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/gp/program.hpp"
#include "pbrfit/gp/program_shape.hpp"

namespace pbrfit::gp {

// A program of uniform length in [initial_min_length, initial_max_length].
Program random_program(const ProgramShape& shape, RandomStream& random);

// An operand for an instruction at `position`: an earlier result, an input or a constant (its value is
// written to `constant`, 0 otherwise).
Operand random_operand(const ProgramShape& shape, std::size_t position, double& constant, RandomStream& random);

// An instruction at `position` with a random operator and random operands.
Instruction random_instruction(const ProgramShape& shape, std::size_t position, RandomStream& random);

}  // namespace pbrfit::gp
