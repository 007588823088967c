#include "pbrfit/ebrdf/base_lobe.hpp"

#include <algorithm>
#include <cmath>

#include "pbrfit/ltc/clamped_cosine.hpp"
#include "pbrfit/brdf/ggx_lobe.hpp"

namespace pbrfit::ebrdf {
namespace {


// A visible-normal sample of the lobe, accepted with probability rho / pdf = G2 / G1 <= 1.
Vector3 specular_candidate(const brdf::GgxLobe& target, RandomStream& random, bool& accepted) {
  const double u1 = random.uniform();
  const Vector3 l = target.sample(u1, random.uniform());
  const auto evaluation = target.evaluate(l);
  accepted = evaluation.pdf > 0.0 && random.uniform() * evaluation.pdf < evaluation.value;
  return l;
}

}  // namespace

Frame texel_frame(const Vector3& n, const Vector3& v) {
  Vector3 tangent = v - v.dot(n) * n;
  if (tangent.norm() < 1e-9) return Frame::from_z(n);
  tangent.normalize();
  return {tangent, n.cross(tangent), n};
}

std::vector<Vector3> sample_base_lobe(const BaseLobe& lobe, const Vector3& normal, const Vector3& view,
                                      std::size_t count, RandomStream& random) {
  const Frame frame = texel_frame(normal, view);
  std::vector<Vector3> samples;
  samples.reserve(count);
  if (lobe.component == Component::diffuse) {
    for (std::size_t k = 0; k < count; ++k) {
      const double u1 = random.uniform();
      samples.push_back(frame.from_local(ltc::sample_clamped_cosine(u1, random.uniform())));
    }
    return samples;
  }
  const double cos_q = std::clamp(view.dot(normal), min_view_cosine, 1.0);
  const brdf::GgxLobe target(lobe.alpha, cos_q);
  for (std::size_t attempt = 0; attempt < 64 * count && samples.size() < count; ++attempt) {
    bool accepted = false;
    const Vector3 l = specular_candidate(target, random, accepted);
    if (accepted) samples.push_back(frame.from_local(l).normalized());
  }
  const Vector3& v = target.view();
  if (samples.empty()) samples.push_back(frame.from_local(Vector3(-v.x(), -v.y(), v.z())));
  for (std::size_t k = 0; samples.size() < count; ++k) samples.push_back(samples[k]);
  return samples;
}

}  // namespace pbrfit::ebrdf
