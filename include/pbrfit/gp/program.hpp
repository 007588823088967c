#pragma once
// A linear genetic program (Pesce & Iwanicki 2015, section 5.2): a flat, trivially copyable array of at
// most max_program_length instructions. Each instruction applies one operator to operands that are a data
// column (input), a constant held in the instruction itself, or the result of an EARLIER instruction, so a
// program is a directed acyclic graph; the last instruction is the output. Instructions the output does
// not reach are introns (live_code.hpp).
//
// Invariants (is_valid() checks them all; every function of this engine returns programs that hold them):
//  - 1 <= length <= max_program_length;
//  - for i < length, operand j < arity(code[i].op) has a source: an input index < the dataset's input
//    count, an instruction index < i, or a constant whose value constants[j] is finite;
//  - canonical form: operand slots beyond the arity are {none, 0}, constants[j] is 0 unless operand j is a
//    constant, and every instruction at or beyond `length` is a default Instruction. Two programs with the
//    same meaning in their first `length` instructions therefore compare (and serialize) equal.
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <type_traits>

#include "pbrfit/gp/opcode.hpp"

namespace pbrfit::gp {

inline constexpr std::size_t max_program_length = 64;
inline constexpr std::size_t max_operands = 3;

enum class Source : std::uint8_t { none, input, constant, instruction };

struct Operand {
  Source source = Source::none;
  std::uint16_t index = 0;  // the input column or the earlier instruction; 0 for constants

  bool operator==(const Operand&) const = default;
};

struct Instruction {
  Opcode op = Opcode::identity;
  std::array<Operand, max_operands> operands{};
  std::array<double, max_operands> constants{};  // the value of each constant operand

  bool operator==(const Instruction&) const = default;
};

struct Program {
  std::uint16_t length = 0;
  std::array<Instruction, max_program_length> code{};

  std::span<const Instruction> instructions() const { return {code.data(), length}; }
  const Instruction& output() const { return code[length - 1u]; }
  bool operator==(const Program&) const = default;
};

static_assert(std::is_trivially_copyable_v<Program>);

bool is_valid(const Program& program, std::size_t input_count);

// Operand constructors.
inline Operand input_operand(std::size_t column) { return {Source::input, static_cast<std::uint16_t>(column)}; }
inline Operand result_operand(std::size_t instruction) {
  return {Source::instruction, static_cast<std::uint16_t>(instruction)};
}
inline Operand constant_operand() { return {Source::constant, 0}; }

}  // namespace pbrfit::gp
