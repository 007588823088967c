#include "pbrfit/brdf/multi_lobe_sg.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pbrfit::brdf {

std::vector<SphericalGaussian> multi_lobe_sg_lobes(const MultiLobeSgParameters& parameters, std::size_t lobe_count) {
  if (lobe_count < 2) throw std::invalid_argument("multi-lobe SG: needs at least 2 lobes");
  if (!(parameters.lambda > 0.0)) throw std::invalid_argument("multi-lobe SG: lambda must be > 0");
  const double spread = std::clamp(parameters.spread, 0.0, std::max(0.0, parameters.theta_center));
  const double n = static_cast<double>(lobe_count);
  std::vector<SphericalGaussian> lobes(lobe_count);
  for (std::size_t index = 0; index < lobe_count; ++index) {
    const double i = static_cast<double>(index);
    const double position = 2.0 * i / (n - 1.0) - 1.0;  // -1 .. 1 across the lobes
    const double theta = position * spread + parameters.theta_center;
    const double gaussian_argument = ((i + 1.0) - 0.5 * (n + 1.0)) * position;
    lobes[index].axis = Vector3(-std::sin(theta), 0.0, std::cos(theta));
    lobes[index].sharpness = parameters.lambda;
    lobes[index].amplitude = parameters.amplitude * std::exp(-spread / 3.0 * gaussian_argument * gaussian_argument);
  }
  return lobes;
}

double multi_lobe_sg_value(const std::vector<SphericalGaussian>& lobes, const Vector3& w) {
  double sum = 0.0;
  for (const SphericalGaussian& lobe : lobes) sum += lobe.value(w);
  return sum;
}

double multi_lobe_sg_integral(const std::vector<SphericalGaussian>& lobes) {
  double sum = 0.0;
  for (const SphericalGaussian& lobe : lobes) sum += lobe.integral();
  return sum;
}

MultiLobeSgParameters normalized_to(const MultiLobeSgParameters& parameters, std::size_t lobe_count, double integral) {
  MultiLobeSgParameters unit = parameters;
  unit.amplitude = 1.0;
  const double unit_integral = multi_lobe_sg_integral(multi_lobe_sg_lobes(unit, lobe_count));
  unit.amplitude = integral / unit_integral;
  return unit;
}

}  // namespace pbrfit::brdf
