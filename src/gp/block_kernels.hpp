#pragma once
// One operator over n <= block_rows values: out[i] = apply(op, a[i], b[i], c[i]) (semantics.hpp).
// Arithmetic and comparisons are plain loops the compiler vectorizes; transcendentals use Eigen's
// vectorized functions. `out` never aliases an operand; operands may alias each other.
#include <Eigen/Core>
#include <cmath>
#include <cstddef>
#include <numbers>

#include "pbrfit/gp/opcode.hpp"

namespace pbrfit::gp::detail {

template <class T>
using BlockMap = Eigen::Map<Eigen::Array<T, Eigen::Dynamic, 1>>;
template <class T>
using ConstBlockMap = Eigen::Map<const Eigen::Array<T, Eigen::Dynamic, 1>>;

template <class T, class F>
inline void unary_loop(const T* a, T* out, std::size_t n, F f) {
  for (std::size_t i = 0; i < n; ++i) out[i] = f(a[i]);
}

template <class T, class F>
inline void binary_loop(const T* a, const T* b, T* out, std::size_t n, F f) {
  for (std::size_t i = 0; i < n; ++i) out[i] = f(a[i], b[i]);
}

template <class T>
void transcendental_block(Opcode op, const T* a, const T* b, T* out, std::size_t n) {
  const ConstBlockMap<T> x(a, static_cast<Eigen::Index>(n));
  BlockMap<T> y(out, static_cast<Eigen::Index>(n));
  constexpr T ln2 = std::numbers::ln2_v<T>;
  switch (op) {
    case Opcode::sqrt:
      y = x.abs().sqrt();
      break;
    case Opcode::rsqrt:
      y = T(1) / x.abs().sqrt();
      break;
    case Opcode::exp:
      y = x.exp();
      break;
    case Opcode::exp2:
      y = (x * ln2).exp();
      break;
    case Opcode::log:
      y = x.abs().log();
      break;
    case Opcode::log2:
      y = x.abs().log2();
      break;
    case Opcode::pow:
      y = (ConstBlockMap<T>(b, static_cast<Eigen::Index>(n)) * x.abs().log2() * ln2).exp();
      break;
    case Opcode::sin:
      y = x.sin();
      break;
    case Opcode::cos:
      y = x.cos();
      break;
    case Opcode::tan:
      y = x.tan();
      break;
    case Opcode::asin:
      y = x.asin();
      break;
    case Opcode::acos:
      y = x.acos();
      break;
    case Opcode::atan:
      y = x.atan();
      break;
    default:
      break;
  }
}

template <class T>
void run_block(Opcode op, const T* a, const T* b, const T* c, T* out, std::size_t n) {
  switch (op) {
    case Opcode::identity:
      unary_loop(a, out, n, [](T x) { return x; });
      break;
    case Opcode::add:
      binary_loop(a, b, out, n, [](T x, T y) { return x + y; });
      break;
    case Opcode::sub:
      binary_loop(a, b, out, n, [](T x, T y) { return x - y; });
      break;
    case Opcode::mul:
      binary_loop(a, b, out, n, [](T x, T y) { return x * y; });
      break;
    case Opcode::div:
      binary_loop(a, b, out, n, [](T x, T y) { return x / y; });
      break;
    case Opcode::fma:
      for (std::size_t i = 0; i < n; ++i) out[i] = a[i] * b[i] + c[i];
      break;
    case Opcode::min:
      binary_loop(a, b, out, n, [](T x, T y) { return (x < y || x != x) ? x : y; });
      break;
    case Opcode::max:
      binary_loop(a, b, out, n, [](T x, T y) { return (x > y || x != x) ? x : y; });
      break;
    case Opcode::abs:
      unary_loop(a, out, n, [](T x) { return std::abs(x); });
      break;
    case Opcode::neg:
      unary_loop(a, out, n, [](T x) { return -x; });
      break;
    case Opcode::saturate:
      unary_loop(a, out, n, [](T x) { return x < T(0) ? T(0) : (x > T(1) ? T(1) : x); });
      break;
    default:
      transcendental_block(op, a, b, out, n);
      break;
  }
}

}  // namespace pbrfit::gp::detail
