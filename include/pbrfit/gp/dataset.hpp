#pragma once
// The data a program is fitted to: one row per sample, one column per input, a target per row and
// optional weights (Pesce & Iwanicki 2015, section 5.2: subsampled regions carry larger weights).
//
// Invariants (validate() checks them): at least one row and one input; target.size() == rows; weights are
// empty (every row weighs 1) or one per row, finite, >= 0 and not all 0; every value is finite.
#include <Eigen/Core>
#include <cstddef>

namespace pbrfit::gp {

struct Dataset {
  Eigen::ArrayXXd inputs;  // rows x inputs
  Eigen::ArrayXd target;
  Eigen::ArrayXd weights;  // empty: uniform

  std::size_t rows() const { return static_cast<std::size_t>(inputs.rows()); }
  std::size_t input_count() const { return static_cast<std::size_t>(inputs.cols()); }
  double weight(std::size_t row) const { return weights.size() == 0 ? 1.0 : weights[static_cast<Eigen::Index>(row)]; }
};

// Throws std::invalid_argument when an invariant does not hold.
void validate(const Dataset& dataset);

}  // namespace pbrfit::gp
