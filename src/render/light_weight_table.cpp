#include "pbrfit/render/light_weight_table.hpp"

namespace pbrfit::render {

LightWeightTable::LightWeightTable(const SphereSamples& samples) : values_(3 * brdf::merl_cells, 0.0) {
  for (std::size_t s = 0; s < samples.size(); ++s) {
    const Rgb w = samples.weight(s);
    for (std::size_t k = 0; k < 3; ++k) values_[k * brdf::merl_cells + samples.cell(s)] += w[k];
  }
  for (std::size_t k = 0; k < 3; ++k)
    for (std::size_t c = 0; c < brdf::merl_cells; ++c) total_[k] += weight(k, c);
}

std::size_t LightWeightTable::lit_cells() const {
  std::size_t count = 0;
  for (std::size_t c = 0; c < brdf::merl_cells; ++c)
    if (weight(0, c) > 0.0 || weight(1, c) > 0.0 || weight(2, c) > 0.0) ++count;
  return count;
}

}  // namespace pbrfit::render
