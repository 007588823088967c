#include "pbrfit/integrate/qmc_nodes.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "pbrfit/integrate/halton.hpp"

namespace pbrfit::integrate {
namespace {

constexpr std::array<unsigned, 16> primes = {2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47, 53};
constexpr double pi = std::numbers::pi;

struct Direction {
  double x, y, z;
};

Direction uniform_direction(double u1, double u2, bool hemisphere) {
  const double z = hemisphere ? u1 : 1.0 - 2.0 * u1;
  const double r = std::sqrt(std::max(0.0, 1.0 - z * z)), phi = 2.0 * pi * u2;
  return {r * std::cos(phi), r * std::sin(phi), z};
}

Direction cosine_direction(double u1, double u2) {
  const double r = std::sqrt(u1), phi = 2.0 * pi * u2;
  return {r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0, 1.0 - u1))};
}

double balance_weight(const Direction& d, std::size_t count, bool hemisphere) {
  const double uniform = hemisphere ? 1.0 / (2.0 * pi) : 1.0 / (4.0 * pi);
  const double cosine = std::max(d.z, 0.0) / pi;
  return 1.0 / (double(count) * (uniform + cosine));
}

}  // namespace

WeightedNodes box_qmc_nodes(std::span<const double> lower, std::span<const double> upper, std::size_t count) {
  const std::size_t d = lower.size();
  if (d == 0 || d > primes.size() || upper.size() != d) throw std::invalid_argument("qmc: a box needs 1 to 16 dimensions");
  double volume = 1.0;
  for (std::size_t k = 0; k < d; ++k) {
    if (!(lower[k] < upper[k])) throw std::invalid_argument("qmc: a box needs lower < upper in every dimension");
    volume *= upper[k] - lower[k];
  }
  WeightedNodes nodes{d, std::vector<double>(count * d), std::vector<double>(count, volume / double(count))};
  for (std::size_t i = 0; i < count; ++i)
    for (std::size_t k = 0; k < d; ++k)
      nodes.points[i * d + k] = lower[k] + (upper[k] - lower[k]) * radical_inverse(primes[k], i + 1);
  return nodes;
}

WeightedNodes direction_qmc_nodes(std::size_t count, bool hemisphere) {
  WeightedNodes nodes{3, {}, {}};
  const auto add = [&](const Direction& d) {
    nodes.points.insert(nodes.points.end(), {d.x, d.y, d.z});
    nodes.weights.push_back(balance_weight(d, count, hemisphere));
  };
  for (const auto& u : halton_points(count)) add(uniform_direction(u[0], u[1], hemisphere));
  for (const auto& u : halton_points(count)) add(cosine_direction(u[0], u[1]));
  return nodes;
}

}  // namespace pbrfit::integrate
