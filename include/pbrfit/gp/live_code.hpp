#pragma once
// Introns (Pesce & Iwanicki 2015, section 5.2): instructions the output does not reach. They stay in the
// genome (neutral material for variation) but are skipped by evaluation and by the cost.
#include <bitset>
#include <cstddef>

#include "pbrfit/gp/program.hpp"

namespace pbrfit::gp {

using LiveMask = std::bitset<max_program_length>;

// Bit i is set when instruction i is the output or feeds it, directly or through other instructions.
LiveMask live_instructions(const Program& program);
std::size_t live_length(const Program& program);

// The same function without introns: the live instructions in their order, references renumbered. The
// result is valid and evaluates bitwise equal to `program` at every row.
Program without_introns(const Program& program);

}  // namespace pbrfit::gp
