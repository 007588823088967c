#pragma once
// Accumulates a block's residuals in double, in a fixed order (four interleaved partial sums, combined at
// the end): lane k of the partial sums takes rows k, k + 4, k + 8, ... of every block, so the four lanes
// run as vector operations while the result stays bitwise reproducible.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstddef>

#include "pbrfit/gp/error_measure.hpp"

namespace pbrfit::gp::detail {

class ErrorSums {
 public:
  template <class T>
  void add_block(const T* values, const double* target, const double* weights, const double* scale, std::size_t n) {
    // The partial sums as local vectors: kept in members, each row's sums would be stored through `this`
    // (which might alias the rows read) and the loop would stay scalar.
    Lanes squares = squares_;
    Lanes max_abs = max_abs_;
    std::size_t i = 0;
    for (; i + lanes <= n; i += lanes) {
      const Lanes residual = Eigen::Map<const Eigen::Array<T, lanes, 1>>(values + i).template cast<double>() -
                             Eigen::Map<const Lanes>(target + i);
      const Lanes scaled = residual * Eigen::Map<const Lanes>(scale + i);
      squares += Eigen::Map<const Lanes>(weights + i) * scaled * scaled;
      // Magnitudes are never -0 and a NaN or infinite residual makes the squares non-finite, when error()
      // ignores max_abs: any max of the two gives the same error.
      max_abs = max_abs.max(residual.abs());
    }
    for (; i < n; ++i) {  // a block's last rows beyond a multiple of 4, into lane 0
      const double residual = static_cast<double>(values[i]) - target[i];
      const double scaled = residual * scale[i];
      squares[0] += weights[i] * scaled * scaled;
      max_abs[0] = std::max(max_abs[0], std::abs(residual));
    }
    squares_ = squares;
    max_abs_ = max_abs;
  }

  // The error under `measure` given the sum of the weights.
  double error(ErrorMeasure measure, double weight_sum) const {
    const double squares = (squares_[0] + squares_[1]) + (squares_[2] + squares_[3]);
    if (!std::isfinite(squares)) return worst_error;
    if (measure == ErrorMeasure::max_abs) {
      return std::max(std::max(max_abs_[0], max_abs_[1]), std::max(max_abs_[2], max_abs_[3]));
    }
    return std::sqrt(squares / weight_sum);
  }

 private:
  static constexpr int lanes = 4;
  using Lanes = Eigen::Array<double, lanes, 1>;

  Lanes squares_ = Lanes::Zero();
  Lanes max_abs_ = Lanes::Zero();
};

}  // namespace pbrfit::gp::detail
