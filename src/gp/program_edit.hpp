#pragma once
// Editing steps shared by mutation and crossover. Each keeps every reference pointing to an earlier
// instruction and the program canonical (program.hpp).
#include <cstddef>

#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/gp/program.hpp"

namespace pbrfit::gp::detail {

// Sets operand j of `instruction` (and its constant slot, 0 unless the operand is a constant).
inline void set_operand(Instruction& instruction, std::size_t j, Operand operand, double constant) {
  instruction.operands[j] = operand;
  instruction.constants[j] = operand.source == Source::constant ? constant : 0.0;
}

// Clears the operand slots beyond the operator's arity.
void clear_unused_operands(Instruction& instruction);

// Inserts `instruction` at `position` (its references must be < position); later references to
// instructions at or after `position` move up by one. Needs length < max_program_length.
void insert_instruction(Program& program, std::size_t position, const Instruction& instruction);

// Removes instruction `position`; operands that read it read `replacement` (with `constant` if that is a
// constant; a reference must be < position) instead, and later references above it move down by one.
void erase_instruction(Program& program, std::size_t position, Operand replacement, double constant);

// A uniformly chosen live instruction.
std::size_t random_live_instruction(const Program& program, RandomStream& random);

}  // namespace pbrfit::gp::detail
