#include "pbrfit/gp/program.hpp"

#include <cmath>

namespace pbrfit::gp {
namespace {

bool operand_valid(const Instruction& instruction, std::size_t j, std::size_t position, std::size_t input_count) {
  const Operand& operand = instruction.operands[j];
  const double constant = instruction.constants[j];
  if (static_cast<int>(j) >= arity(instruction.op)) return operand == Operand{} && constant == 0.0;
  switch (operand.source) {
    case Source::input:
      return operand.index < input_count && constant == 0.0;
    case Source::instruction:
      return operand.index < position && constant == 0.0;
    case Source::constant:
      return operand.index == 0 && std::isfinite(constant);
    case Source::none:
      return false;
  }
  return false;
}

bool instruction_valid(const Instruction& instruction, std::size_t position, std::size_t input_count) {
  if (!is_valid_opcode(static_cast<std::uint8_t>(instruction.op))) return false;
  for (std::size_t j = 0; j < max_operands; ++j) {
    if (!operand_valid(instruction, j, position, input_count)) return false;
  }
  return true;
}

}  // namespace

bool is_valid(const Program& program, std::size_t input_count) {
  if (program.length < 1 || program.length > max_program_length) return false;
  for (std::size_t i = 0; i < program.length; ++i) {
    if (!instruction_valid(program.code[i], i, input_count)) return false;
  }
  for (std::size_t i = program.length; i < max_program_length; ++i) {
    if (!(program.code[i] == Instruction{})) return false;
  }
  return true;
}

}  // namespace pbrfit::gp
