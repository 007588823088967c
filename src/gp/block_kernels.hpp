// One operator over n <= block_rows values: out[i] = apply(op, a[i], b[i], c[i]) (semantics.hpp).
// Arithmetic, comparisons, sqrt and rsqrt are plain loops the compiler vectorizes (bitwise the same in
// every kernel set); other transcendentals use Eigen's vectorized functions (and, in the avx2 and avx512
// sets, glibc's for tan, asin, acos and atan: block_vector_math.hpp), lane by lane the same wherever a row
// sits. `out` never aliases an operand; operands may alias each other.
//
// Included once by each kernel set's file (block_kernels_isa_<set>.cpp, compiled for that instruction
// set), inside a namespace named by PBRFIT_KERNEL_ISA, so that the sets' copies never meet at link time;
// it defines that set's entry points.
#ifndef PBRFIT_KERNEL_ISA
#error "block_kernels.hpp is included by the block_kernels_isa_<set>.cpp files only"
#endif
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <numbers>

#include "block_kernel_sets.hpp"
#include "pbrfit/gp/opcode.hpp"
#if defined(PBRFIT_KERNEL_LIBMVEC)
#include "block_vector_math.hpp"
#endif

namespace pbrfit::gp::detail::PBRFIT_KERNEL_ISA {

template <class T>
using BlockMap = Eigen::Map<Eigen::Array<T, Eigen::Dynamic, 1>>;
template <class T>
using ConstBlockMap = Eigen::Map<const Eigen::Array<T, Eigen::Dynamic, 1>>;

template <class T, class F>
inline void unary_loop(const T* __restrict a, T* __restrict out, std::size_t n, F f) {
  for (std::size_t i = 0; i < n; ++i) out[i] = f(a[i]);
}

template <class T, class F>
inline void binary_loop(const T* a, const T* b, T* __restrict out, std::size_t n, F f) {
  for (std::size_t i = 0; i < n; ++i) out[i] = f(a[i], b[i]);
}

// An operand of a block: its values, and whether they are one constant repeated.
template <class T>
struct BlockOperand {
  const T* values;
  bool constant;
};

// A binary operator with a constant operand reads the constant once into a register instead of its block
// (the same values, so the same results): a constant costs no load per row and its block stays cold.
template <class T, class F>
inline void binary_block(BlockOperand<T> a, BlockOperand<T> b, T* out, std::size_t n, F f) {
  if (b.constant && !a.constant) {
    const T y = b.values[0];
    unary_loop(a.values, out, n, [&](T x) { return f(x, y); });
  } else if (a.constant && !b.constant) {
    const T x = a.values[0];
    unary_loop(b.values, out, n, [&](T y) { return f(x, y); });
  } else {
    binary_loop(a.values, b.values, out, n, f);
  }
}

// Transcendentals run over chunks of a fixed size, copied into aligned local arrays padded past the
// block's end: every value takes Eigen's packet code, never its scalar head or tail, whose results differ
// by ulps. A row's value then depends on its inputs only, not on its place in the block or its buffer's
// alignment, which threads, ranks and resumed runs change (test "A row's value depends on its inputs only").
inline constexpr std::size_t chunk_bytes = 128;  // two AVX-512 vectors, eight SSE ones

template <class T>
void transcendental_chunk(Opcode op, const T* a, const T* b, T* out) {
  constexpr int size = chunk_bytes / sizeof(T);
  using Chunk = Eigen::Array<T, size, 1>;
  const Eigen::Map<const Chunk, Eigen::Aligned64> x(a);
  Eigen::Map<Chunk, Eigen::Aligned64> y(out);
  constexpr T ln2 = std::numbers::ln2_v<T>;
#if defined(PBRFIT_KERNEL_LIBMVEC)
  if (libmvec_chunk<size>(op, a, out)) return;
#endif
  switch (op) {
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
      y = (Eigen::Map<const Chunk, Eigen::Aligned64>(b) * x.abs().log2() * ln2).exp();
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
void transcendental_block(Opcode op, const T* a, const T* b, T* out, std::size_t n) {
  switch (op) {
    // sqrt and rsqrt as plain loops, correctly rounded in every set (Eigen's AVX-512 sqrt is a Newton
    // approximation under its default EIGEN_FAST_MATH); -fno-math-errno lets them vectorize.
    case Opcode::sqrt:
      unary_loop(a, out, n, [](T v) { return std::sqrt(std::abs(v)); });
      return;
    case Opcode::rsqrt:
      unary_loop(a, out, n, [](T v) { return T(1) / std::sqrt(std::abs(v)); });
      return;
    default:
      break;
  }
  constexpr std::size_t size = chunk_bytes / sizeof(T);
  alignas(64) T x[size];
  alignas(64) T y[size];
  alignas(64) T z[size];
  const bool binary = arity(op) == 2;
  for (std::size_t first = 0; first < n; first += size) {
    const std::size_t m = std::min(size, n - first);
    if (m == size) {  // a whole chunk: copies of a constant size, a few vector moves (copy_n of m is a rep movs)
      std::memcpy(x, a + first, sizeof x);
      if (binary) std::memcpy(y, b + first, sizeof y);
      transcendental_chunk<T>(op, x, y, z);
      std::memcpy(out + first, z, sizeof z);
      continue;
    }
    std::copy_n(a + first, m, x);
    std::fill(x + m, x + size, T(1));
    if (binary) {
      std::copy_n(b + first, m, y);
      std::fill(y + m, y + size, T(1));
    }
    transcendental_chunk<T>(op, x, y, z);
    std::copy_n(z, m, out + first);
  }
}

// Calls visit with the function of a fusable operator (block_schedule.hpp).
template <class T, class Visit>
inline void with_arithmetic(Opcode op, Visit visit) {
  switch (op) {
    case Opcode::add:
      visit([](T x, T y) { return x + y; });
      break;
    case Opcode::sub:
      visit([](T x, T y) { return x - y; });
      break;
    case Opcode::mul:
      visit([](T x, T y) { return x * y; });
      break;
    case Opcode::div:
      visit([](T x, T y) { return x / y; });
      break;
    default:
      break;
  }
}

// A fused pair's operand: a block read row by row, or a constant read once into a register.
template <class T>
struct RowValues {
  const T* values;
  T operator[](std::size_t i) const { return values[i]; }
};
template <class T>
struct RepeatedValue {
  T value;
  T operator[](std::size_t) const { return value; }
};

template <class T, class A, class B, class C, class F, class G>
inline void fused_rows(A a, B b, C c, bool intermediate_left, T* __restrict out, std::size_t n, F f, G g) {
  if (intermediate_left) {
    for (std::size_t i = 0; i < n; ++i) out[i] = g(f(a[i], b[i]), c[i]);
  } else {
    for (std::size_t i = 0; i < n; ++i) out[i] = g(c[i], f(a[i], b[i]));
  }
}

// Calls visit with the operand as RowValues, or as RepeatedValue when it is a constant's block.
template <class T, class Visit>
inline void with_operand(BlockOperand<T> operand, Visit visit) {
  if (operand.constant) {
    visit(RepeatedValue<T>{operand.values[0]});
  } else {
    visit(RowValues<T>{operand.values});
  }
}

// A fused pair (block_schedule.hpp): the first operator's value stays in a register, and so does any
// constant operand.
template <class T>
void run_fused_block(Opcode op, Opcode second, bool intermediate_left, BlockOperand<T> a, BlockOperand<T> b,
                     BlockOperand<T> c, T* __restrict out, std::size_t n) {
  with_arithmetic<T>(op, [&](auto f) {
    with_arithmetic<T>(second, [&](auto g) {
      with_operand<T>(a, [&](auto first) {
        with_operand<T>(b, [&](auto middle) {
          with_operand<T>(c, [&](auto third) {
            fused_rows<T>(first, middle, third, intermediate_left, out, n, f, g);
          });
        });
      });
    });
  });
}

template <class T>
void run_block(Opcode op, BlockOperand<T> first, BlockOperand<T> second, const T* c, T* out, std::size_t n) {
  const T* a = first.values;
  const T* b = second.values;
  if (fusable(op)) {
    with_arithmetic<T>(op, [&](auto f) { binary_block(first, second, out, n, f); });
    return;
  }
  switch (op) {
    case Opcode::identity:
      unary_loop(a, out, n, [](T x) { return x; });
      break;
    case Opcode::fma:
      for (std::size_t i = 0; i < n; ++i) out[i] = a[i] * b[i] + c[i];
      break;
    case Opcode::min:
      binary_block(first, second, out, n, [](T x, T y) { return (x < y || x != x) ? x : y; });
      break;
    case Opcode::max:
      binary_block(first, second, out, n, [](T x, T y) { return (x > y || x != x) ? x : y; });
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

template <class T>
void run_schedule(const BlockSchedule<T>& schedule, std::size_t rows, std::size_t block_rows, BlockSink<T> sink) {
  for (std::size_t first = 0; first < rows; first += block_rows) {
    const std::size_t n = std::min(block_rows, rows - first);
    for (std::size_t s = 0; s < schedule.step_count; ++s) {
      const auto& step = schedule.steps[s];
      const auto& [a, b, c] = step.operands;
      if (step.second != Opcode::identity) {
        run_fused_block<T>(step.op, step.second, step.intermediate_left, {a.at(first), a.constant},
                           {b.at(first), b.constant}, {c.at(first), c.constant}, step.out, n);
      } else {
        run_block<T>(step.op, {a.at(first), a.constant}, {b.at(first), b.constant}, c.at(first), step.out, n);
      }
    }
    sink.take(sink.context, first, n, schedule.output.at(first));
  }
}

// The set's entry points (block_kernel_sets.hpp), defined once per set: flatten inlines every call into
// them, Eigen's included, so that the including file emits no inline function the linker could pick for
// another file compiled for another set (the test "layers: kernel set objects share no inline code"; for
// clang, whose flatten goes one level deep, cmake/layers.cmake raises the inliner's threshold too).
[[gnu::flatten]] void run_schedule_f32(const BlockSchedule<float>& schedule, std::size_t rows, std::size_t block_rows,
                                       BlockSink<float> sink) {
  run_schedule<float>(schedule, rows, block_rows, sink);
}

[[gnu::flatten]] void run_schedule_f64(const BlockSchedule<double>& schedule, std::size_t rows, std::size_t block_rows,
                                       BlockSink<double> sink) {
  run_schedule<double>(schedule, rows, block_rows, sink);
}

}  // namespace pbrfit::gp::detail::PBRFIT_KERNEL_ISA
