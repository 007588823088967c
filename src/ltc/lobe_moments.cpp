#include "pbrfit/ltc/lobe_moments.hpp"

#include <algorithm>
#include <cmath>

#include "pbrfit/integrate/compensated_sum.hpp"

namespace pbrfit::ltc {

LobeMoments measure_moments(const brdf::Lobe& lobe, std::size_t points) {
  return measure_moments(lobe, sample_lobe(lobe, points));
}

LobeMoments measure_moments(const brdf::Lobe& lobe, const LobeSamples& samples) {
  integrate::CompensatedSum albedo;
  integrate::CompensatedSum fresnel;
  Vector3 direction = Vector3::Zero();
  for (std::size_t i = 0; i < samples.directions.size(); ++i) {
    const Vector3& l = samples.directions[i];
    if (!(samples.pdfs[i] > 0.0) || samples.values[i] == 0.0) continue;
    const double weight = samples.values[i] / samples.pdfs[i];
    const double schlick = std::pow(1.0 - std::max(0.0, lobe.view().dot((lobe.view() + l).normalized())), 5.0);
    albedo.add(weight);
    fresnel.add(weight * schlick);
    direction += weight * l;
  }
  const double count = static_cast<double>(samples.directions.size());
  LobeMoments moments;
  moments.albedo = albedo.value() / count;
  moments.fresnel = fresnel.value() / count;
  direction.y() = 0.0;
  if (direction.squaredNorm() > 0.0) moments.average_direction = direction.normalized();
  return moments;
}

}  // namespace pbrfit::ltc
