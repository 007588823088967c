#include "pbrfit/gp/cost_model.hpp"

namespace pbrfit::gp {

CostTable gcn_cost_table() {
  CostTable table;
  for (Opcode op : {Opcode::add, Opcode::sub, Opcode::mul, Opcode::fma, Opcode::min, Opcode::max, Opcode::abs,
                    Opcode::neg, Opcode::saturate}) {
    table[op] = 1.0;
  }
  for (Opcode op : {Opcode::exp2, Opcode::log2, Opcode::sqrt, Opcode::rsqrt}) table[op] = 4.0;
  for (Opcode op : {Opcode::div, Opcode::exp, Opcode::log, Opcode::sin, Opcode::cos}) table[op] = 5.0;
  table[Opcode::pow] = 9.0;
  table[Opcode::tan] = 9.0;  // sin / cos
  for (Opcode op : {Opcode::asin, Opcode::acos, Opcode::atan}) table[op] = 10.0;  // no hardware unit: a short polynomial
  table[Opcode::identity] = 0.0;
  return table;
}

void cost_and_piecewise(const Program& program, const LiveMask& live, const CostTable& table, double& cost,
                        std::size_t& piecewise) {
  cost = 0.0;
  piecewise = 0;
  for (std::size_t i = 0; i < program.length; ++i) {
    if (!live.test(i)) continue;
    const Opcode op = program.code[i].op;
    cost += table[op];
    if (is_piecewise(op)) {
      cost += table.piecewise_penalty;
      ++piecewise;
    }
  }
}

double program_cost(const Program& program, const CostTable& table) {
  double cost = 0.0;
  std::size_t piecewise = 0;
  cost_and_piecewise(program, live_instructions(program), table, cost, piecewise);
  return cost;
}

std::size_t piecewise_count(const Program& program) {
  double cost = 0.0;
  std::size_t piecewise = 0;
  cost_and_piecewise(program, live_instructions(program), CostTable{}, cost, piecewise);
  return piecewise;
}

}  // namespace pbrfit::gp
