#include "pbrfit/ltc/lobe_samples.hpp"

#include "pbrfit/ltc/point_sets.hpp"

namespace pbrfit::ltc {

LobeSamples sample_lobe(const brdf::Lobe& lobe, std::size_t points) {
  LobeSamples samples;
  samples.directions.reserve(points);
  for (const auto& [u1, u2] : golden_lattice(points)) samples.directions.push_back(lobe.sample(u1, u2));
  std::vector<brdf::Lobe::Evaluation> evaluations(points);
  lobe.evaluate_many(samples.directions, evaluations);
  samples.values.reserve(points);
  samples.pdfs.reserve(points);
  for (const brdf::Lobe::Evaluation& e : evaluations) {
    samples.values.push_back(e.value);
    samples.pdfs.push_back(e.pdf);
  }
  return samples;
}

}  // namespace pbrfit::ltc
