#include "pbrfit/gp/variation.hpp"

namespace pbrfit::gp {

Operand random_operand(const ProgramShape& shape, std::size_t position, double& constant, RandomStream& random) {
  constant = 0.0;
  if (position > 0 && random.uniform() < shape.reference_probability) return result_operand(random.below(position));
  if (shape.constant_probability > 0.0 && random.uniform() < shape.constant_probability) {
    constant = shape.constant_min + (shape.constant_max - shape.constant_min) * random.uniform();
    return constant_operand();
  }
  return input_operand(random.below(shape.input_count));
}

Instruction random_instruction(const ProgramShape& shape, std::size_t position, RandomStream& random) {
  Instruction instruction;
  instruction.op = shape.operators.nth(random.below(shape.operators.size()));
  for (int j = 0; j < arity(instruction.op); ++j) {
    instruction.operands[j] = random_operand(shape, position, instruction.constants[j], random);
  }
  return instruction;
}

Program random_program(const ProgramShape& shape, RandomStream& random) {
  const std::size_t span = shape.initial_max_length - shape.initial_min_length + 1;
  Program program;
  program.length = static_cast<std::uint16_t>(shape.initial_min_length + random.below(span));
  for (std::size_t i = 0; i < program.length; ++i) program.code[i] = random_instruction(shape, i, random);
  return program;
}

}  // namespace pbrfit::gp
