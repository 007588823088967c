#include "pbrfit/ltc/sliced_wasserstein.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <utility>

#include "pbrfit/core/kernel_set.hpp"
#include "pbrfit/ltc/clamped_cosine.hpp"
#include "pbrfit/ltc/point_sets.hpp"
#include "projection_sort.hpp"

namespace pbrfit::ltc {

SlicedWasserstein::SlicedWasserstein(std::span<const Vector3> targets, std::size_t axis_count)
    : SlicedWasserstein(targets, cosine_samples(targets.size()), axis_directions(axis_count)) {}

SlicedWasserstein::SlicedWasserstein(std::span<const Vector3> targets, std::vector<Vector3> base,
                                     std::vector<Vector3> axes)
    : base_(std::move(base)), axes_(std::move(axes)) {
  const std::size_t n = targets.size();
  if (n == 0 || base_.size() != n || axes_.empty()) {
    throw std::invalid_argument("ltc: sliced Wasserstein needs targets, one base sample per target, and axes");
  }
  if (n > std::numeric_limits<std::uint32_t>::max()) {
    throw std::invalid_argument("ltc: sliced Wasserstein takes fewer than 2^32 samples");
  }
  transformed_.resize(n);
  lengths_.resize(n);
  values_.resize(n);
  keys_.resize(n);
  projections_.resize(n);
  signed_axes_.resize(n);
  signed_projections_.resize(n);
  orders_.resize(axes_.size() * n);
  ordered_.assign(axes_.size(), false);
  sorted_targets_.resize(axes_.size() * n);
  for (std::size_t p = 0; p < axes_.size(); ++p) {  // order(p) is scratch here: the first call ranks afresh
    for (std::size_t k = 0; k < n; ++k) values_[k] = axes_[p].dot(targets[k]);
    rank_sort(values_.data(), sorted_targets_.data() + p * n, order(p));
  }
}

void SlicedWasserstein::transform_base(const Matrix3& m) {
  for (std::size_t k = 0; k < base_.size(); ++k) {
    const Vector3 image = m * base_[k];
    lengths_[k] = image.norm();
    transformed_[k] = image / lengths_[k];
  }
}

void SlicedWasserstein::rank_sort(const double* values, double* sorted, std::uint32_t* order) {
  const std::size_t n = base_.size();
  const double* keys = values;
  if (std::any_of(values, values + n, [](double v) { return std::isnan(v); })) {
    for (std::size_t k = 0; k < n; ++k)
      keys_[k] = std::isnan(values[k]) ? std::numeric_limits<double>::infinity() : values[k];
    keys = keys_.data();
  }
  detail::projection_sort(active_kernel_set()).rank(keys, values, n, sorted, order);
}

bool SlicedWasserstein::insertion_sort(std::uint32_t* ranked, std::size_t budget) {
  const std::size_t n = base_.size();
  std::size_t moves = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t k = ranked[i];
    const double value = values_[k];
    std::size_t j = i;
    for (; j > 0 && (projections_[j - 1] > value || (projections_[j - 1] == value && ranked[j - 1] > k)); --j) {
      if (++moves > budget) return false;
      projections_[j] = projections_[j - 1];
      ranked[j] = ranked[j - 1];
    }
    projections_[j] = value;
    ranked[j] = k;
  }
  return true;
}

void SlicedWasserstein::sort_projections(std::size_t p) {
  const Vector3& axis = axes_[p];
  const std::size_t n = base_.size();
  bool has_nan = false;
  for (std::size_t k = 0; k < n; ++k) {
    values_[k] = axis.dot(transformed_[k]);
    has_nan |= std::isnan(values_[k]);
  }
  // An insertion sort never sees a NaN, so that its comparisons stay a total order.
  const std::size_t budget = detail::projection_sort(active_kernel_set()).insertion_budget;
  if (ordered_[p] && !has_nan && insertion_sort(order(p), budget)) return;
  rank_sort(values_.data(), projections_.data(), order(p));
  ordered_[p] = true;
}

double SlicedWasserstein::distance(const Matrix3& m) {
  transform_base(m);
  const std::size_t n = base_.size();
  double total = 0.0;
  for (std::size_t p = 0; p < axes_.size(); ++p) {
    sort_projections(p);
    const double* targets = sorted_targets_.data() + p * n;
    for (std::size_t i = 0; i < n; ++i) total += std::abs(projections_[i] - targets[i]);
  }
  return total / static_cast<double>(n * axes_.size());
}

double SlicedWasserstein::gradient(const Matrix3& m, Matrix3& gradient) {
  transform_base(m);
  const std::size_t n = base_.size();
  // d(axis . w_k) / dM = ((axis - w_k (w_k . axis)) / |M s_k|) s_k^T, w_k = normalize(M s_k); summed over the
  // axes with signs first: sum_p sign_pk (axis_p - w_k proj_pk) = signed_axes_k - w_k signed_projections_k.
  std::fill(signed_axes_.begin(), signed_axes_.end(), Vector3::Zero());
  std::fill(signed_projections_.begin(), signed_projections_.end(), 0.0);
  double total = 0.0;
  for (std::size_t p = 0; p < axes_.size(); ++p) {
    const Vector3& axis = axes_[p];
    sort_projections(p);
    const std::uint32_t* ranked = order(p);
    const double* targets = sorted_targets_.data() + p * n;
    for (std::size_t i = 0; i < n; ++i) {
      const double difference = projections_[i] - targets[i];
      total += std::abs(difference);
      if (difference == 0.0) continue;
      const std::size_t k = ranked[i];
      const double sign = std::copysign(1.0, difference);
      signed_axes_[k] += sign * axis;
      signed_projections_[k] += sign * projections_[i];
    }
  }
  gradient.setZero();
  for (std::size_t k = 0; k < n; ++k) {
    const Vector3 direction = (signed_axes_[k] - transformed_[k] * signed_projections_[k]) / lengths_[k];
    gradient += direction * base_[k].transpose();
  }
  const double scale = 1.0 / static_cast<double>(n * axes_.size());
  gradient *= scale;
  return total * scale;
}

}  // namespace pbrfit::ltc
