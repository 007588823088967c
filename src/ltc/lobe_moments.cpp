#include "pbrfit/ltc/lobe_moments.hpp"

#include <cmath>

#include "pbrfit/integrate/compensated_sum.hpp"
#include "pbrfit/ltc/point_sets.hpp"

namespace pbrfit::ltc {

LobeMoments measure_moments(const brdf::Lobe& lobe, std::size_t points) {
  integrate::CompensatedSum albedo;
  integrate::CompensatedSum fresnel;
  Vector3 direction = Vector3::Zero();
  for (const auto& [u1, u2] : golden_lattice(points)) {
    const Vector3 l = lobe.sample(u1, u2);
    const brdf::Lobe::Evaluation evaluation = lobe.evaluate(l);
    if (!(evaluation.pdf > 0.0) || evaluation.value == 0.0) continue;
    const double weight = evaluation.value / evaluation.pdf;
    const double schlick = std::pow(1.0 - std::max(0.0, lobe.view().dot((lobe.view() + l).normalized())), 5.0);
    albedo.add(weight);
    fresnel.add(weight * schlick);
    direction += weight * l;
  }
  const double count = static_cast<double>(points);
  LobeMoments moments;
  moments.albedo = albedo.value() / count;
  moments.fresnel = fresnel.value() / count;
  direction.y() = 0.0;
  if (direction.squaredNorm() > 0.0) moments.average_direction = direction.normalized();
  return moments;
}

}  // namespace pbrfit::ltc
