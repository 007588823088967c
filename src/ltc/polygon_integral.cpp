#include "pbrfit/ltc/polygon_integral.hpp"

#include <numbers>
#include <stdexcept>

#include "polygon_clipping.hpp"

namespace pbrfit::ltc {
namespace {

void require_polygon(std::span<const Vector3> vertices) {
  if (vertices.size() < 3) throw std::invalid_argument("ltc: a polygon needs at least 3 vertices");
}

}  // namespace

double clamped_cosine_polygon_integral(std::span<const Vector3> vertices) {
  require_polygon(vertices);
  return detail::clipped_clamped_cosine_integral(vertices.size(), [&](std::size_t i) { return vertices[i]; });
}

Vector3 vector_form_factor(std::span<const Vector3> vertices) {
  require_polygon(vertices);
  Vector3 sum = Vector3::Zero();
  Vector3 previous = vertices.back().normalized();
  for (const Vector3& vertex : vertices) {
    const Vector3 current = vertex.normalized();
    sum += detail::edge_form_factor(previous, current);
    previous = current;
  }
  return sum * (0.5 * std::numbers::inv_pi);
}

}  // namespace pbrfit::ltc
