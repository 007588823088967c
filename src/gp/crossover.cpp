#include "pbrfit/gp/variation.hpp"

#include <algorithm>
#include <array>

#include "pbrfit/gp/live_code.hpp"
#include "program_edit.hpp"

namespace pbrfit::gp {
namespace {

using Renumbering = std::array<std::uint16_t, max_program_length>;

void renumber(Instruction& instruction, const Renumbering& to) {
  for (Operand& operand : instruction.operands) {
    if (operand.source == Source::instruction) operand.index = to[operand.index];
  }
}

// The instructions of `program` that `root` depends on, root included, in program order.
LiveMask subgraph(const Program& program, std::size_t root) {
  LiveMask reached;
  reached.set(root);
  for (std::size_t i = root + 1; i-- > 0;) {
    if (!reached.test(i)) continue;
    for (int j = 0; j < arity(program.code[i].op); ++j) {
      const Operand& operand = program.code[i].operands[j];
      if (operand.source == Source::instruction) reached.set(operand.index);
    }
  }
  return reached;
}

// mother[0, x) + the father's subgraph of y + mother(x, end), references renumbered.
Program splice(const Program& mother, std::size_t x, const Program& father, std::size_t y) {
  const LiveMask part = subgraph(father, y);
  Program child;
  std::copy_n(mother.code.begin(), x, child.code.begin());
  child.length = static_cast<std::uint16_t>(x);
  Renumbering from_father{};
  for (std::size_t i = 0; i <= y; ++i) {
    if (!part.test(i)) continue;
    Instruction instruction = father.code[i];
    renumber(instruction, from_father);
    from_father[i] = child.length;
    child.code[child.length++] = instruction;
  }
  Renumbering from_mother{};
  for (std::size_t i = 0; i < x; ++i) from_mother[i] = static_cast<std::uint16_t>(i);
  from_mother[x] = static_cast<std::uint16_t>(child.length - 1u);
  for (std::size_t i = x + 1; i < mother.length; ++i) {
    Instruction instruction = mother.code[i];
    renumber(instruction, from_mother);
    from_mother[i] = child.length;
    child.code[child.length++] = instruction;
  }
  return child;
}

}  // namespace

Program string_crossover(const Program& mother, const Program& father, std::size_t max_length, RandomStream& random) {
  const std::size_t cut = 1 + random.below(std::min(mother.length, father.length));
  const std::size_t length = std::max<std::size_t>(cut, father.length);
  if (length > max_length) return mother;
  Program child = father;
  std::copy_n(mother.code.begin(), cut, child.code.begin());
  if (cut >= father.length) {
    child.length = static_cast<std::uint16_t>(cut);
    std::fill(child.code.begin() + cut, child.code.end(), Instruction{});
  }
  return child;
}

Program subgraph_crossover(const Program& mother, const Program& father, std::size_t max_length, RandomStream& random) {
  const std::size_t x = detail::random_live_instruction(mother, random);
  const std::size_t y = detail::random_live_instruction(father, random);
  const std::size_t inserted = subgraph(father, y).count();
  if (mother.length - 1u + inserted <= max_length) return splice(mother, x, father, y);
  // Without its introns the mother may leave room; x keeps its place among the live instructions.
  const Program compact = without_introns(mother);
  if (compact.length - 1u + inserted > max_length) return mother;
  const LiveMask live = live_instructions(mother);
  std::size_t compact_x = 0;
  for (std::size_t i = 0; i < x; ++i) compact_x += live.test(i);
  return splice(compact, compact_x, father, y);
}

}  // namespace pbrfit::gp
