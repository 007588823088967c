#include "pbrfit/gp/operator_set.hpp"

namespace pbrfit::gp {

OperatorSet::OperatorSet(std::initializer_list<Opcode> ops) {
  for (Opcode op : ops) insert(op);
}

void OperatorSet::insert(Opcode op) {
  if (op != Opcode::identity) members_.set(static_cast<std::size_t>(op));
}

Opcode OperatorSet::nth(std::size_t k) const {
  for (std::size_t i = 0; i < opcode_count; ++i) {
    if (members_.test(i) && k-- == 0) return static_cast<Opcode>(i);
  }
  return Opcode::identity;
}

std::vector<Opcode> OperatorSet::members() const {
  std::vector<Opcode> ops;
  for (std::size_t i = 0; i < opcode_count; ++i) {
    if (members_.test(i)) ops.push_back(static_cast<Opcode>(i));
  }
  return ops;
}

OperatorSet arithmetic_operators() { return {Opcode::add, Opcode::sub, Opcode::mul, Opcode::div}; }

OperatorSet koza_operators() {
  return {Opcode::add, Opcode::sub, Opcode::mul, Opcode::div, Opcode::sin, Opcode::cos, Opcode::exp, Opcode::log};
}

OperatorSet all_operators() {
  OperatorSet set;
  for (std::size_t i = 0; i < opcode_count; ++i) set.insert(static_cast<Opcode>(i));
  return set;
}

}  // namespace pbrfit::gp
