#include "pbrfit/render/sphere_view.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pbrfit::render {

SphereView::SphereView(std::size_t resolution) : resolution_(resolution) {
  if (resolution == 0) throw std::invalid_argument("a sphere view needs at least one pixel");
}

double SphereView::x_of(std::size_t pixel) const {
  return (double(pixel % resolution_) + 0.5) * 2.0 / double(resolution_) - 1.0;
}

double SphereView::y_of(std::size_t pixel) const {
  return 1.0 - (double(pixel / resolution_) + 0.5) * 2.0 / double(resolution_);
}

bool SphereView::on_sphere(std::size_t pixel) const {
  const double x = x_of(pixel), y = y_of(pixel);
  return x * x + y * y < 1.0;
}

Vector3 SphereView::normal(std::size_t pixel) const {
  const double x = x_of(pixel), y = y_of(pixel);
  return Vector3(x, y, std::sqrt(std::max(0.0, 1.0 - x * x - y * y))).normalized();
}

std::vector<std::uint8_t> SphereView::mask() const {
  std::vector<std::uint8_t> mask(pixels());
  for (std::size_t p = 0; p < pixels(); ++p) mask[p] = on_sphere(p) ? 1 : 0;
  return mask;
}

}  // namespace pbrfit::render
