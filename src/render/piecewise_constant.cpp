#include "pbrfit/render/piecewise_constant.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pbrfit::render {

PiecewiseConstant::PiecewiseConstant(std::span<const double> weights) : cumulative_(weights.size() + 1, 0.0) {
  if (weights.empty()) throw std::invalid_argument("a piecewise-constant distribution needs at least one bin");
  for (std::size_t i = 0; i < weights.size(); ++i) {
    if (!std::isfinite(weights[i]) || weights[i] < 0.0)
      throw std::invalid_argument("piecewise-constant weights must be finite and >= 0");
    cumulative_[i + 1] = cumulative_[i] + weights[i];
  }
  total_ = cumulative_.back();
  const std::size_t n = weights.size();
  for (std::size_t i = 1; i <= n; ++i) cumulative_[i] = total_ > 0.0 ? cumulative_[i] / total_ : double(i) / double(n);
  cumulative_[n] = 1.0;
}

BinSample PiecewiseConstant::sample(double u) const {
  u = std::clamp(u, 0.0, std::nextafter(1.0, 0.0));
  const auto above = std::upper_bound(cumulative_.begin(), cumulative_.end(), u);
  const std::size_t bin = std::min(std::size_t(above - cumulative_.begin()), size()) - 1;
  const double position = (u - cumulative_[bin]) / probability(bin);
  return {bin, std::clamp(position, 0.0, std::nextafter(1.0, 0.0))};
}

}  // namespace pbrfit::render
