#pragma once
// The operators a run may draw when it creates or mutates programs (configurable per run).
//
// Invariant: `identity` is never a member (it is internal, see opcode.hpp); insert() ignores it.
#include <bitset>
#include <initializer_list>
#include <vector>

#include "pbrfit/gp/opcode.hpp"

namespace pbrfit::gp {

class OperatorSet {
 public:
  OperatorSet() = default;
  OperatorSet(std::initializer_list<Opcode> ops);

  void insert(Opcode op);
  void erase(Opcode op) { members_.reset(static_cast<std::size_t>(op)); }
  bool contains(Opcode op) const { return members_.test(static_cast<std::size_t>(op)); }
  bool empty() const { return members_.none(); }
  std::size_t size() const { return members_.count(); }
  // The k-th member in Opcode order, k < size().
  Opcode nth(std::size_t k) const;
  // The members in Opcode order.
  std::vector<Opcode> members() const;

 private:
  std::bitset<opcode_count> members_;
};

// + - * /
OperatorSet arithmetic_operators();
// Koza's set: + - * / sin cos exp log.
OperatorSet koza_operators();
// Every operator but identity.
OperatorSet all_operators();

}  // namespace pbrfit::gp
