#pragma once
// The meaning of every operator, one value at a time: the reference that the tree walker uses, that the
// batch interpreter reproduces block by block (its transcendentals may differ by a few ulps), and that
// the exported functions reproduce (export.hpp).
//
// Protected semantics, chosen so that they cost nothing extra on a GPU (abs is a free input modifier):
//  - sqrt, rsqrt, log, log2 take |a|; pow(a, b) = exp2(b * log2(|a|)), as GPUs implement it;
//  - division, overflow, poles and asin/acos beyond [-1, 1] are not protected: they give +-inf or NaN, and
//    an output that is not finite at some row gives the program the worst error (fitness_evaluator.hpp);
//  - min, max and saturate propagate NaN (a NaN on the path to the output is never hidden);
//  - fma(a, b, c) = a * b + c, rounded twice (the interpreter never fuses).
#include <cmath>

#include "pbrfit/gp/opcode.hpp"

namespace pbrfit::gp {

template <class T>
T apply(Opcode op, T a, T b, T c) {
  switch (op) {
    case Opcode::identity:
      return a;
    case Opcode::add:
      return a + b;
    case Opcode::sub:
      return a - b;
    case Opcode::mul:
      return a * b;
    case Opcode::div:
      return a / b;
    case Opcode::fma:
      return a * b + c;
    case Opcode::min:
      return (a < b || a != a) ? a : b;
    case Opcode::max:
      return (a > b || a != a) ? a : b;
    case Opcode::abs:
      return std::abs(a);
    case Opcode::neg:
      return -a;
    case Opcode::sqrt:
      return std::sqrt(std::abs(a));
    case Opcode::rsqrt:
      return T(1) / std::sqrt(std::abs(a));
    case Opcode::exp:
      return std::exp(a);
    case Opcode::exp2:
      return std::exp2(a);
    case Opcode::log:
      return std::log(std::abs(a));
    case Opcode::log2:
      return std::log2(std::abs(a));
    case Opcode::pow:
      return std::exp2(b * std::log2(std::abs(a)));
    case Opcode::sin:
      return std::sin(a);
    case Opcode::cos:
      return std::cos(a);
    case Opcode::saturate:
      return a < T(0) ? T(0) : (a > T(1) ? T(1) : a);
    case Opcode::tan:
      return std::tan(a);
    case Opcode::asin:
      return std::asin(a);
    case Opcode::acos:
      return std::acos(a);
    case Opcode::atan:
      return std::atan(a);
  }
  return a;
}

}  // namespace pbrfit::gp
