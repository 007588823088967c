#include "pbrfit/render/light_metric.hpp"

#include <stdexcept>

namespace pbrfit::render {
namespace {

// sum of w2 (m - c)^2 over the cells where m is a number; four interleaved partial sums (a fixed order)
// keep the additions independent.
double channel_metric(const double* w2, const double* m, const double* c, std::size_t n) {
  double sums[4] = {0.0, 0.0, 0.0, 0.0};
  for (std::size_t i = 0; i < n; ++i) {
    const double d = m[i] - c[i];
    sums[i % 4] += m[i] == m[i] ? w2[i] * d * d : 0.0;
  }
  return (sums[0] + sums[1]) + (sums[2] + sums[3]);
}

}  // namespace

Rgb light_metric(const PrunedLightTable& table, std::span<const double> measured, std::span<const double> candidate) {
  const std::size_t n = table.size();
  if (measured.size() != 3 * n || candidate.size() != 3 * n)
    throw std::invalid_argument("the metric needs 3 values per kept cell for each BRDF");
  Rgb metric;
  for (std::size_t k = 0; k < 3; ++k)
    metric[k] = channel_metric(table.squared_weights().data() + k * n, measured.data() + k * n,
                               candidate.data() + k * n, n);
  return metric;
}

std::vector<double> kept_values(const PrunedLightTable& table, const brdf::MerlTable& brdf) {
  const std::size_t n = table.size();
  std::vector<double> values(3 * n);
  for (std::size_t k = 0; k < 3; ++k)
    for (std::size_t i = 0; i < n; ++i) values[k * n + i] = brdf.value(k, table.cells()[i]);
  return values;
}

std::vector<double> kept_values(const PrunedLightTable& table, const BrdfFunction& brdf) {
  const std::size_t n = table.size();
  const std::vector<brdf::DirectionPair> pairs = representative_pairs(table);
  std::vector<double> values(3 * n);
  for (std::size_t i = 0; i < n; ++i) {
    const Rgb f = brdf(pairs[i].wi, pairs[i].wo);
    for (std::size_t k = 0; k < 3; ++k) values[k * n + i] = f[k];
  }
  return values;
}

}  // namespace pbrfit::render
