#pragma once
// Accumulates a block's residuals in double, in a fixed order (four interleaved partial sums, combined at
// the end), so the compiler may vectorize while the result stays bitwise reproducible.
#include <array>
#include <cmath>
#include <cstddef>

#include "pbrfit/gp/error_measure.hpp"

namespace pbrfit::gp::detail {

class ErrorSums {
 public:
  template <class T>
  void add_block(const T* values, const double* target, const double* weights, const double* scale, std::size_t n) {
    std::size_t i = 0;
    for (; i + lanes <= n; i += lanes) {
      for (std::size_t k = 0; k < lanes; ++k)
        add(k, static_cast<double>(values[i + k]), target[i + k], weights[i + k], scale[i + k]);
    }
    for (; i < n; ++i) add(0, static_cast<double>(values[i]), target[i], weights[i], scale[i]);
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
  static constexpr std::size_t lanes = 4;

  void add(std::size_t k, double value, double target, double weight, double scale) {
    const double residual = value - target;
    const double scaled = residual * scale;
    squares_[k] += weight * scaled * scaled;
    const double magnitude = std::abs(residual);
    max_abs_[k] = magnitude > max_abs_[k] ? magnitude : max_abs_[k];
  }

  std::array<double, lanes> squares_{};
  std::array<double, lanes> max_abs_{};
};

}  // namespace pbrfit::gp::detail
