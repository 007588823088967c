#include "pbrfit/ltc/sgd_fit.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include "pbrfit/ltc/clamped_cosine.hpp"
#include "pbrfit/ltc/sliced_wasserstein.hpp"

namespace pbrfit::ltc {
namespace {

Vector3 uniform_sphere_direction(RandomStream& random) {
  const double z = 1.0 - 2.0 * random.uniform();
  const double radius = std::sqrt(std::max(0.0, 1.0 - z * z));
  const double phi = 2.0 * std::numbers::pi * random.uniform();
  return {radius * std::cos(phi), radius * std::sin(phi), z};
}

}  // namespace

Matrix3 sgd_fit_from_identity(std::span<const Vector3> targets, const SgdOptions& options, RandomStream& random) {
  Matrix3 m = Matrix3::Identity();
  double loss_scale = options.loss_scale;
  Matrix3 gradient;
  for (int epoch = 0; epoch < options.epochs; ++epoch) {
    std::vector<Vector3> base(targets.size());
    for (Vector3& s : base) {
      const double u1 = random.uniform();
      s = sample_clamped_cosine(u1, random.uniform());
    }
    std::vector<Vector3> axes(options.axes);
    for (Vector3& axis : axes) axis = uniform_sphere_direction(random);
    SlicedWasserstein loss(targets, std::move(base), std::move(axes));
    loss.gradient(m, gradient);
    m -= options.learning_rate * loss_scale * gradient;
    loss_scale *= options.loss_scale_decay;
  }
  return m;
}

}  // namespace pbrfit::ltc
