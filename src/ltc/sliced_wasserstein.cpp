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
  transformed_.resize(3 * n);
  lengths_.resize(n);
  values_.resize(n);
  keys_.resize(n);
  rerank_keys_.resize(detail::rerank_scratch(n));
  rerank_order_.resize(n);
  projections_.resize(n);
  signed_sums_.resize(4 * n);
  signs_.resize(n);
  orders_.resize(axes_.size() * n);
  ordered_.assign(axes_.size(), false);
  sorted_targets_.resize(axes_.size() * n);
  for (std::size_t p = 0; p < axes_.size(); ++p) {  // order(p) is scratch here: the first call ranks afresh
    for (std::size_t k = 0; k < n; ++k) values_[k] = axes_[p].dot(targets[k]);
    rank_sort(values_.data(), sorted_targets_.data() + p * n, order(p));
  }
}

void SlicedWasserstein::transform_base(const Matrix3& m) {
  const std::size_t n = base_.size();
  for (std::size_t k = 0; k < n; ++k) {
    const Vector3 image = m * base_[k];
    lengths_[k] = image.norm();
    const Vector3 direction = image / lengths_[k];
    for (int c = 0; c < 3; ++c) transformed_[std::size_t(c) * n + k] = direction[c];
  }
}

Vector3 SlicedWasserstein::transformed(std::size_t k) const {
  const std::size_t n = base_.size();
  return {transformed_[k], transformed_[n + k], transformed_[2 * n + k]};
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

void SlicedWasserstein::sort_projections(std::size_t p) {
  const std::size_t n = base_.size();
  const detail::ProjectionSort sort = detail::projection_sort(active_kernel_set());
  const double* w = transformed_.data();
  const bool has_nan = sort.project(axes_[p].data(), w, w + n, w + 2 * n, n, values_.data());
  // A re-rank from the last order never sees a NaN, so that its comparisons stay a total order.
  if (ordered_[p] && !has_nan &&
      sort.rerank(values_.data(), n, order(p), projections_.data(), rerank_keys_.data(), rerank_order_.data()))
    return;
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
  // axes with signs first: sum_p sign_pk (axis_p - w_k proj_pk) = signed axis_k - w_k signed projection_k.
  // Each axis' signs are put in sample order, then added to the per-sample sums a register at a time; each
  // sample's sums still run over the axes in order, as sign * axis one at a time, so the values are those of
  // adding them sample by sample (a sign of 0 adds +-0, which leaves a sum that is never -0 unchanged).
  std::fill(signed_sums_.begin(), signed_sums_.end(), 0.0);
  const detail::ProjectionSort sort = detail::projection_sort(active_kernel_set());
  double* signs = signs_.data();
  double total = 0.0;
  for (std::size_t p = 0; p < axes_.size(); ++p) {
    sort_projections(p);
    const std::uint32_t* ranked = order(p);
    const double* targets = sorted_targets_.data() + p * n;
    for (std::size_t i = 0; i < n; ++i) {
      const double difference = projections_[i] - targets[i];
      total += std::abs(difference);
      signs[ranked[i]] = difference == 0.0 ? 0.0 : std::copysign(1.0, difference);
    }
    // values_ holds the projections by sample, as projections_ by rank.
    sort.add_signed(signs, values_.data(), axes_[p].data(), n, signed_sums_.data());
  }
  const double* signed_x = signed_sums_.data();
  const double* signed_y = signed_x + n;
  const double* signed_z = signed_y + n;
  const double* signed_projections = signed_z + n;
  // The outer products summed in registers, each element in the order of sample index.
  double sum[3][3] = {};
  for (std::size_t k = 0; k < n; ++k) {
    const Vector3 signed_axis(signed_x[k], signed_y[k], signed_z[k]);
    const Vector3 direction = (signed_axis - transformed(k) * signed_projections[k]) / lengths_[k];
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) sum[r][c] += direction[r] * base_[k][c];
  }
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) gradient(r, c) = sum[r][c];
  const double scale = 1.0 / static_cast<double>(n * axes_.size());
  gradient *= scale;
  return total * scale;
}

}  // namespace pbrfit::ltc
