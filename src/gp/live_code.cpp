#include "pbrfit/gp/live_code.hpp"

namespace pbrfit::gp {

LiveMask live_instructions(const Program& program) {
  static_assert(max_program_length == 64, "the mask is one 64-bit word");
  if (program.length == 0) return {};
  std::uint64_t live = std::uint64_t{1} << (program.length - 1u);
  for (std::size_t i = program.length; i-- > 0;) {
    if (!((live >> i) & 1u)) continue;
    // Operands beyond the arity are {none, 0} (canonical form), so all three can be checked.
    for (const Operand& operand : program.code[i].operands) {
      if (operand.source == Source::instruction) live |= std::uint64_t{1} << operand.index;
    }
  }
  return LiveMask(live);
}

std::size_t live_length(const Program& program) { return live_instructions(program).count(); }

Program without_introns(const Program& program) {
  const LiveMask live = live_instructions(program);
  std::array<std::uint16_t, max_program_length> renumbered{};
  Program compact;
  for (std::size_t i = 0; i < program.length; ++i) {
    if (!live.test(i)) continue;
    Instruction instruction = program.code[i];
    for (Operand& operand : instruction.operands) {
      if (operand.source == Source::instruction) operand.index = renumbered[operand.index];
    }
    renumbered[i] = compact.length;
    compact.code[compact.length++] = instruction;
  }
  return compact;
}

}  // namespace pbrfit::gp
