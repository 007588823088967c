#include "pbrfit/gp/variation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "pbrfit/gp/live_code.hpp"
#include "program_edit.hpp"
#include "random_draws.hpp"

namespace pbrfit::gp {
namespace {

using detail::random_live_instruction;
using detail::set_operand;

void redraw_operand(Program& program, std::size_t k, std::size_t j, const ProgramShape& shape, RandomStream& random) {
  double constant = 0.0;
  const Operand operand = random_operand(shape, k, constant, random);
  set_operand(program.code[k], j, operand, constant);
}

Program change_operand(Program program, const ProgramShape& shape, RandomStream& random) {
  const std::size_t k = random_live_instruction(program, random);
  const std::size_t j = random.below(static_cast<std::uint64_t>(arity(program.code[k].op)));
  redraw_operand(program, k, j, shape, random);
  return program;
}

Program change_operator(Program program, const ProgramShape& shape, RandomStream& random) {
  const std::size_t k = random_live_instruction(program, random);
  Instruction& instruction = program.code[k];
  const Opcode old_op = instruction.op;
  const bool only_choice = shape.operators.size() == 1 && shape.operators.contains(old_op);
  if (only_choice) return change_operand(program, shape, random);
  do {
    instruction.op = shape.operators.nth(random.below(shape.operators.size()));
  } while (instruction.op == old_op);
  for (int j = arity(old_op); j < arity(instruction.op); ++j) redraw_operand(program, k, j, shape, random);
  detail::clear_unused_operands(instruction);
  return program;
}

Program step_constant(Program program, const ProgramShape& shape, double sigma, RandomStream& random) {
  const LiveMask live = live_instructions(program);
  std::vector<std::array<std::size_t, 2>> slots;
  for (std::size_t i = 0; i < program.length; ++i) {
    for (int j = 0; live.test(i) && j < arity(program.code[i].op); ++j) {
      if (program.code[i].operands[j].source == Source::constant) slots.push_back({i, static_cast<std::size_t>(j)});
    }
  }
  if (slots.empty()) return change_operand(program, shape, random);
  const auto [i, j] = slots[random.below(slots.size())];
  double& value = program.code[i].constants[j];
  const double stepped = value + sigma * std::max(1.0, std::abs(value)) * detail::normal(random);
  if (std::isfinite(stepped)) value = stepped;
  return program;
}

// A new instruction before live instruction k takes over k's operand j, and k reads the new one.
Program insert_wrapper(Program program, const ProgramShape& shape, RandomStream& random) {
  if (program.length >= shape.max_length) return change_operand(program, shape, random);
  const std::size_t k = random_live_instruction(program, random);
  const std::size_t j = random.below(static_cast<std::uint64_t>(arity(program.code[k].op)));
  Instruction wrapper = random_instruction(shape, k, random);
  set_operand(wrapper, 0, program.code[k].operands[j], program.code[k].constants[j]);
  detail::insert_instruction(program, k, wrapper);
  set_operand(program.code[k + 1], j, result_operand(k), 0.0);
  return program;
}

// Live instruction k is bypassed: its users read its first operand. The output becomes an identity.
Program delete_instruction(Program program, const ProgramShape& shape, RandomStream& random) {
  const std::size_t k = random_live_instruction(program, random);
  const Instruction removed = program.code[k];
  const bool is_output = k + 1u == program.length;
  if (program.length <= 1 || (is_output && removed.op == Opcode::identity)) {
    return change_operand(program, shape, random);
  }
  if (is_output) {
    program.code[k].op = Opcode::identity;
    detail::clear_unused_operands(program.code[k]);
    return program;
  }
  detail::erase_instruction(program, k, removed.operands[0], removed.constants[0]);
  return program;
}

}  // namespace

Program mutate(const Program& parent, MutationKind kind, const ProgramShape& shape, const MutationOptions& options,
               RandomStream& random) {
  switch (kind) {
    case MutationKind::operator_change:
      return change_operator(parent, shape, random);
    case MutationKind::operand_change:
      return change_operand(parent, shape, random);
    case MutationKind::constant_step:
      return step_constant(parent, shape, options.constant_sigma, random);
    case MutationKind::insertion:
      return insert_wrapper(parent, shape, random);
    case MutationKind::deletion:
      return delete_instruction(parent, shape, random);
  }
  return parent;
}

Program mutate(const Program& parent, const ProgramShape& shape, const MutationOptions& options, RandomStream& random) {
  const std::array<double, 5> weights{options.operator_weight, options.operand_weight, options.constant_weight,
                                      options.insertion_weight, options.deletion_weight};
  const auto kind = static_cast<MutationKind>(detail::choose_weighted(weights, random));
  return mutate(parent, kind, shape, options, random);
}

}  // namespace pbrfit::gp
