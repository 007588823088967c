#include "pbrfit/ltc/lobe_moments.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "pbrfit/integrate/compensated_sum.hpp"
#include "pbrfit/ltc/point_sets.hpp"

namespace pbrfit::ltc {

LobeMoments measure_moments(const brdf::Lobe& lobe, std::size_t points) {
  integrate::CompensatedSum albedo;
  integrate::CompensatedSum fresnel;
  Vector3 direction = Vector3::Zero();
  // The samples go through the lobe in groups (Lobe::evaluate_many: vector code where the lobe has it, the
  // same values as one at a time), in the lattice's order.
  const auto lattice = golden_lattice(points);
  constexpr std::size_t group = 256;
  std::array<Vector3, group> samples;
  std::array<brdf::Lobe::Evaluation, group> evaluations;
  for (std::size_t first = 0; first < lattice.size(); first += group) {
    const std::size_t n = std::min(group, lattice.size() - first);
    for (std::size_t i = 0; i < n; ++i) samples[i] = lobe.sample(lattice[first + i][0], lattice[first + i][1]);
    lobe.evaluate_many({samples.data(), n}, {evaluations.data(), n});
    for (std::size_t i = 0; i < n; ++i) {
      const Vector3& l = samples[i];
      const brdf::Lobe::Evaluation& evaluation = evaluations[i];
      if (!(evaluation.pdf > 0.0) || evaluation.value == 0.0) continue;
      const double weight = evaluation.value / evaluation.pdf;
      const double schlick = std::pow(1.0 - std::max(0.0, lobe.view().dot((lobe.view() + l).normalized())), 5.0);
      albedo.add(weight);
      fresnel.add(weight * schlick);
      direction += weight * l;
    }
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
