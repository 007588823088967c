#include "pbrfit/brdf/spherical_harmonics.hpp"

#include <cmath>
#include <numbers>

namespace pbrfit::brdf {
namespace {

constexpr double pi = std::numbers::pi;

}  // namespace

ShCoefficients sh_basis(const Vector3& w) {
  const double c0 = 0.5 / std::sqrt(pi);
  const double c1 = std::sqrt(3.0 / (4.0 * pi));
  const double c2 = std::sqrt(15.0 / (4.0 * pi));
  const double c20 = std::sqrt(5.0 / (16.0 * pi));
  const double x = w.x(), y = w.y(), z = w.z();
  return {c0,         c1 * y,     c1 * z, c1 * x, c2 * x * y, c2 * y * z, c20 * (3.0 * z * z - 1.0),
          c2 * x * z, 0.5 * c2 * (x * x - y * y)};
}

Vector3 optimal_linear_direction(const ShCoefficients& sh) {
  const Vector3 band1(sh[3], sh[1], sh[2]);
  const double length = band1.norm();
  return length > 0.0 ? Vector3(band1 / length) : Vector3::UnitZ();
}

ZonalCoefficients zonal_coefficients(const ShCoefficients& sh, const Vector3& axis) {
  const ShCoefficients at_axis = sh_basis(axis);
  ZonalCoefficients zh{};
  for (int band = 0; band <= 2; ++band) {
    double dot = 0.0;
    for (int m = -band; m <= band; ++m) {
      const int index = band * band + band + m;
      dot += sh[index] * at_axis[index];
    }
    zh[band] = std::sqrt(4.0 * pi / (2.0 * band + 1.0)) * dot;
  }
  return zh;
}

}  // namespace pbrfit::brdf
