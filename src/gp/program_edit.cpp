#include "program_edit.hpp"

#include "pbrfit/gp/live_code.hpp"

namespace pbrfit::gp::detail {

void clear_unused_operands(Instruction& instruction) {
  for (std::size_t j = static_cast<std::size_t>(arity(instruction.op)); j < max_operands; ++j) {
    set_operand(instruction, j, Operand{}, 0.0);
  }
}

void insert_instruction(Program& program, std::size_t position, const Instruction& instruction) {
  for (std::size_t i = program.length; i > position; --i) {
    program.code[i] = program.code[i - 1];
    for (Operand& operand : program.code[i].operands) {
      if (operand.source == Source::instruction && operand.index >= position) ++operand.index;
    }
  }
  program.code[position] = instruction;
  ++program.length;
}

void erase_instruction(Program& program, std::size_t position, Operand replacement, double constant) {
  for (std::size_t i = position + 1; i < program.length; ++i) {
    Instruction& instruction = program.code[i];
    for (std::size_t j = 0; j < max_operands; ++j) {
      Operand& operand = instruction.operands[j];
      if (operand.source != Source::instruction || operand.index < position) continue;
      if (operand.index == position) {
        set_operand(instruction, j, replacement, constant);
      } else {
        --operand.index;
      }
    }
    program.code[i - 1] = instruction;
  }
  program.code[--program.length] = Instruction{};
}

std::size_t random_live_instruction(const Program& program, RandomStream& random) {
  const LiveMask live = live_instructions(program);
  std::size_t k = random.below(live.count());
  for (std::size_t i = 0; i < program.length; ++i) {
    if (live.test(i) && k-- == 0) return i;
  }
  return program.length - 1u;
}

}  // namespace pbrfit::gp::detail
