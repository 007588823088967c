#include "pbrfit/gp/program_builder.hpp"

#include <cmath>
#include <stdexcept>

namespace pbrfit::gp {
namespace {

Instruction make_instruction(Opcode op, const Argument* arguments, std::size_t count, std::uint16_t position) {
  if (static_cast<int>(count) != arity(op)) throw std::invalid_argument("wrong number of operands for an operator");
  Instruction instruction;
  instruction.op = op;
  for (std::size_t j = 0; j < count; ++j) {
    const Argument& argument = arguments[j];
    if (argument.operand.source == Source::none) throw std::invalid_argument("an operand without a source");
    if (argument.operand.source == Source::instruction && argument.operand.index >= position) {
      throw std::invalid_argument("an operand refers to an instruction that is not earlier");
    }
    if (argument.operand.source == Source::constant && !std::isfinite(argument.constant)) {
      throw std::invalid_argument("a constant that is not finite");
    }
    instruction.operands[j] = argument.operand;
    if (argument.operand.source == Source::constant) instruction.constants[j] = argument.constant;
  }
  return instruction;
}

}  // namespace

Argument ProgramBuilder::append(Opcode op, std::initializer_list<Argument> arguments) {
  return append(op, arguments.begin(), arguments.size());
}

Argument ProgramBuilder::append(Opcode op, const Argument* arguments, std::size_t count) {
  const Instruction instruction = make_instruction(op, arguments, count, program_.length);
  std::array<std::int64_t, max_operands> tags;
  tags.fill(-1);
  for (std::size_t j = 0; j < count; ++j) tags[j] = arguments[j].tag;
  if (merge_duplicates_) {
    for (std::size_t i = 0; i < program_.length; ++i) {
      if (program_.code[i] == instruction && tags_[i] == tags) return {result_operand(i)};
    }
  }
  if (program_.length >= max_program_length) throw std::length_error("a program longer than max_program_length");
  program_.code[program_.length] = instruction;
  tags_.push_back(tags);
  return {result_operand(program_.length++)};
}

Program ProgramBuilder::finish(const Argument& result) {
  const bool is_last = result.operand.source == Source::instruction && result.operand.index + 1u == program_.length;
  if (!is_last) append(Opcode::identity, {result});
  return program_;
}

std::vector<ConstantSlot> ProgramBuilder::slots_tagged(std::int64_t tag) const {
  std::vector<ConstantSlot> slots;
  for (std::size_t i = 0; i < tags_.size(); ++i) {
    for (std::size_t j = 0; j < max_operands; ++j) {
      if (tags_[i][j] == tag) slots.push_back({static_cast<std::uint16_t>(i), static_cast<std::uint8_t>(j)});
    }
  }
  return slots;
}

}  // namespace pbrfit::gp
