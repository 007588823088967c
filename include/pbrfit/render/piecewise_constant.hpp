#pragma once
// A discrete distribution over bins 0..n-1 with probabilities proportional to non-negative weights, as a
// cumulative table; sampling by inversion also returns where in its bin the number fell, so that one
// uniform number places a point both in a bin and inside it (stratification carries over).
//
// Invariants: n >= 1; weights finite and >= 0 (std::invalid_argument otherwise); all-zero weights give the
// uniform distribution; a bin of probability 0 is never sampled; sample(u) for u in [0, 1) returns a bin
// of positive probability and a position in [0, 1) that is uniform within the bin when u is uniform.
#include <cstddef>
#include <span>
#include <vector>

namespace pbrfit::render {

struct BinSample {
  std::size_t bin = 0;
  double position = 0.0;  // where u fell inside the bin's share of [0, 1), rescaled to [0, 1)
};

class PiecewiseConstant {
 public:
  explicit PiecewiseConstant(std::span<const double> weights);

  BinSample sample(double u) const;
  double probability(std::size_t bin) const { return cumulative_[bin + 1] - cumulative_[bin]; }
  double total_weight() const { return total_; }
  std::size_t size() const { return cumulative_.size() - 1; }

 private:
  std::vector<double> cumulative_;  // n + 1 entries from 0 to 1
  double total_ = 0.0;
};

}  // namespace pbrfit::render
