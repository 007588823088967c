#pragma once
// Builds a valid program instruction by instruction: each append() returns an Argument that later
// instructions may use. Used by the expression parser, by tests and by examples.
//
// Contract: arguments that refer to an instruction must come from this builder; append() throws
// std::length_error beyond max_program_length and std::invalid_argument for a wrong argument count or a
// non-finite constant. With `merge_duplicates`, appending an instruction equal to an earlier one (same
// operator, operands and constant values, and the same tag on every constant) returns the earlier one
// (common subexpressions become one node of the DAG). finish() needs at least one instruction; a bare
// input or constant becomes an identity instruction.
#include <array>
#include <cstdint>
#include <initializer_list>
#include <vector>

#include "pbrfit/gp/program.hpp"

namespace pbrfit::gp {

struct Argument {
  Operand operand;
  double constant = 0.0;  // when operand.source == Source::constant
  std::int64_t tag = -1;  // a constant's identity for merging (a parameter's index); -1: a literal
};

// Where a constant lives: operand `operand` of instruction `instruction`.
struct ConstantSlot {
  std::uint16_t instruction = 0;
  std::uint8_t operand = 0;
  bool operator==(const ConstantSlot&) const = default;
};

inline Argument input_argument(std::size_t column) { return {input_operand(column)}; }
inline Argument constant_argument(double value, std::int64_t tag = -1) { return {constant_operand(), value, tag}; }

class ProgramBuilder {
 public:
  explicit ProgramBuilder(bool merge_duplicates = false) : merge_duplicates_(merge_duplicates) {}

  Argument append(Opcode op, std::initializer_list<Argument> arguments);
  Argument append(Opcode op, const Argument* arguments, std::size_t count);
  std::size_t size() const { return program_.length; }
  // The program whose output is `result` (an instruction of this builder, or a bare input or constant).
  Program finish(const Argument& result);
  // The slots of the constants appended with `tag`, in program order (valid for the finished program too).
  std::vector<ConstantSlot> slots_tagged(std::int64_t tag) const;

 private:
  Program program_;
  std::vector<std::array<std::int64_t, max_operands>> tags_;  // per instruction, per operand
  bool merge_duplicates_;
};

}  // namespace pbrfit::gp
