#pragma once
// The complexity objective (Pesce & Iwanicki 2015, section 5.1): an estimate of the shader cost of the
// live instructions, from a per-operator table. Inputs and constants are free; introns cost nothing.
//
// The default table follows GCN issue rates: full-rate operations (add, sub, mul, fma, min, max, abs,
// neg, saturate) cost 1; the quarter-rate transcendentals (exp2, log2, sqrt, rsqrt: 4); division is a
// reciprocal and a multiply (5); exp, log, sin and cos add the multiply that rescales their argument or
// result (5); pow = log2, multiply, exp2 (9); tan = sin / cos (9); asin, acos and atan have no hardware unit
// and become short polynomials with a square root (10); identity is a copy the compiler removes (0). The table is
// configurable per run; every entry must be finite and >= 0.
#include <array>
#include <cstddef>

#include "pbrfit/gp/live_code.hpp"
#include "pbrfit/gp/opcode.hpp"
#include "pbrfit/gp/program.hpp"

namespace pbrfit::gp {

struct CostTable {
  std::array<double, opcode_count> per_opcode{};
  // Added once per live piecewise operator (min, max, abs, saturate): a soft ban (section 5.1).
  double piecewise_penalty = 0.0;

  double operator[](Opcode op) const { return per_opcode[static_cast<std::size_t>(op)]; }
  double& operator[](Opcode op) { return per_opcode[static_cast<std::size_t>(op)]; }
};

CostTable gcn_cost_table();

// Sum of the table's cost (plus the piecewise penalty) over the live instructions.
double program_cost(const Program& program, const CostTable& table);
// Live piecewise instructions: the optional third objective.
std::size_t piecewise_count(const Program& program);
// Both at once, given the live instructions (live_code.hpp).
void cost_and_piecewise(const Program& program, const LiveMask& live, const CostTable& table, double& cost,
                        std::size_t& piecewise);

}  // namespace pbrfit::gp
