#include "pbrfit/ltc/clamped_cosine.hpp"

#include "pbrfit/brdf/sampled_lobe.hpp"
#include "pbrfit/ltc/point_sets.hpp"

namespace pbrfit::ltc {

Vector3 sample_clamped_cosine(double u1, double u2) { return brdf::sample_cosine_hemisphere(u1, u2); }

std::vector<Vector3> cosine_samples(std::size_t count) {
  std::vector<Vector3> samples;
  samples.reserve(count);
  for (const auto& [u1, u2] : golden_lattice(count)) samples.push_back(sample_clamped_cosine(u1, u2));
  return samples;
}

}  // namespace pbrfit::ltc
