#pragma once
// The operators of a program (Pesce & Iwanicki 2015, section 5.2) and their fixed properties: arity, the
// function name used in expression texts, and whether the operator is piecewise (section 5.1, figure 20).
//
// Invariants: Opcode values are dense, 0 <= value < opcode_count; `identity` is internal (it forwards its
// operand: a program whose output is a bare input or constant) and is never drawn by variation. The
// protected meaning of every operator is in semantics.hpp.
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

namespace pbrfit::gp {

enum class Opcode : std::uint8_t {
  identity,
  add,
  sub,
  mul,
  div,
  fma,
  min,
  max,
  abs,
  neg,
  sqrt,
  rsqrt,
  exp,
  exp2,
  log,
  log2,
  pow,
  sin,
  cos,
  saturate,
  tan,
  asin,
  acos,
  atan,
};

inline constexpr std::size_t opcode_count = 24;

struct OpcodeInfo {
  std::string_view name;  // lowercase, as in expression texts: "add", "sqrt", "saturate"
  int arity;              // 1, 2 or 3
  bool piecewise;         // min, max, abs, saturate
};

inline constexpr std::array<OpcodeInfo, opcode_count> opcode_table{{
    {"identity", 1, false}, {"add", 2, false},   {"sub", 2, false}, {"mul", 2, false},  {"div", 2, false},
    {"fma", 3, false},      {"min", 2, true},    {"max", 2, true},  {"abs", 1, true},   {"neg", 1, false},
    {"sqrt", 1, false},     {"rsqrt", 1, false}, {"exp", 1, false}, {"exp2", 1, false}, {"log", 1, false},
    {"log2", 1, false},     {"pow", 2, false},   {"sin", 1, false}, {"cos", 1, false},  {"saturate", 1, true},
    {"tan", 1, false},      {"asin", 1, false},  {"acos", 1, false}, {"atan", 1, false},
}};

constexpr const OpcodeInfo& info(Opcode op) { return opcode_table[static_cast<std::size_t>(op)]; }
constexpr int arity(Opcode op) { return info(op).arity; }
constexpr std::string_view name(Opcode op) { return info(op).name; }
constexpr bool is_piecewise(Opcode op) { return info(op).piecewise; }
constexpr bool is_valid_opcode(std::uint8_t raw) { return raw < opcode_count; }

// The opcode named `text` (as name() spells it), if any.
std::optional<Opcode> opcode_named(std::string_view text);

}  // namespace pbrfit::gp
