#pragma once
// The data-parallel interpreter (Pesce & Iwanicki 2015, section 5.2): runs one instruction over a block
// of block_rows rows at a time, so the cost of decoding an instruction is shared by the whole block and
// every block's intermediate values stay in the cache (a float block is 2 KiB: the live values of a
// typical program fit the L1 cache). T is float (the default of a run) or double.
//
// Contract:
//  - only live instructions run (introns are skipped); identity instructions cost nothing; a binary
//    operator reads a constant operand once, not per row; two arithmetic instructions where the second
//    alone reads the first may run as one loop (block_schedule.hpp), with the same results;
//  - outputs follow semantics.hpp; arithmetic, min, max, abs, neg, saturate, sqrt and rsqrt are bitwise
//    equal to apply<T>(); exp, exp2, log, log2, pow, sin, cos, tan and the inverse trigonometric operators
//    use vectorized implementations that may differ from the standard library's by a few ulps, and between
//    kernel sets;
//  - the block loop runs in the process's kernel set (core/kernel_set.hpp), read at each evaluation;
//  - errors are accumulated in double (error_measure.hpp) in a fixed order: the result depends only on the
//    program and the dataset, bitwise;
//  - no allocation per evaluation: all scratch space is allocated by the constructor. One interpreter
//    serves one thread at a time (evaluate() and error() use its scratch space).
#include <Eigen/Core>
#include <cstddef>
#include <span>
#include <vector>

#include "pbrfit/gp/dataset.hpp"
#include "pbrfit/gp/error_measure.hpp"
#include "pbrfit/gp/program.hpp"

namespace pbrfit::gp {

// 512 rows: 32 AVX-512 vectors of floats per instruction, enough to hide the per-instruction dispatch (128
// rows ran float arithmetic at about three quarters of the speed; docs/BENCHMARKS.md). Any multiple of 4
// gives the same errors, bitwise (error_sums.hpp interleaves by row index modulo 4).
inline constexpr std::size_t block_rows = 512;

template <class T>
class BatchInterpreter {
 public:
  // Copies the inputs as T (column by column) and the target and weights as double.
  BatchInterpreter(const Dataset& dataset, const ErrorOptions& error_options = {});

  std::size_t rows() const { return static_cast<std::size_t>(columns_.rows()); }
  // The program's output at every row: out.size() == rows().
  void evaluate(const Program& program, std::span<T> out);
  // The program's error against the target; worst_error when an output is not finite.
  double error(const Program& program);

 private:
  template <class Sink>
  void run(const Program& program, Sink& sink);

  Eigen::Array<T, Eigen::Dynamic, Eigen::Dynamic> columns_;
  Eigen::ArrayXd target_;
  Eigen::ArrayXd weights_;      // one per row (1 when the dataset has none)
  Eigen::ArrayXd error_scale_;  // 1, or 1 / max(|target|, floor) for the relative error
  double weight_sum_ = 0.0;
  ErrorOptions error_options_;
  std::vector<T> slots_;            // one block per live instruction
  std::vector<T> constant_blocks_;  // one block per constant operand of a live instruction
};

extern template class BatchInterpreter<float>;
extern template class BatchInterpreter<double>;

}  // namespace pbrfit::gp
