#include "pbrfit/ltc/clamped_cosine.hpp"

#include <cmath>
#include <numbers>

#include "pbrfit/ltc/point_sets.hpp"

namespace pbrfit::ltc {

Vector3 sample_clamped_cosine(double u1, double u2) {
  const double sin_theta = std::sqrt(u1);
  const double phi = 2.0 * std::numbers::pi * u2;
  return {sin_theta * std::cos(phi), sin_theta * std::sin(phi), std::sqrt(std::max(0.0, 1.0 - u1))};
}

std::vector<Vector3> cosine_samples(std::size_t count) {
  std::vector<Vector3> samples;
  samples.reserve(count);
  for (const auto& [u1, u2] : golden_lattice(count)) samples.push_back(sample_clamped_cosine(u1, u2));
  return samples;
}

}  // namespace pbrfit::ltc
