#include "pbrfit/render/light_weight_table.hpp"

namespace pbrfit::render {

LightWeightTable::LightWeightTable() : values_(3 * brdf::merl_cells, 0.0) {}

LightWeightTable::LightWeightTable(const SphereSamples& samples) : LightWeightTable() {
  for (std::size_t s = 0; s < samples.size(); ++s) add(samples.cell(s), samples.weight(s));
}

LightWeightTable::LightWeightTable(const EnvironmentMap& environment, const SphereView& view,
                                   std::size_t samples_per_pixel, PixelRange range)
    : LightWeightTable() {
  visit_light_samples(environment, view, samples_per_pixel, range,
                      [&](std::size_t, const Vector3& wi, const Vector3& wo, const Rgb& weight) {
                        add(merl_cell_of_pair(wi, wo), weight);
                      });
}

LightWeightTable& LightWeightTable::operator+=(const LightWeightTable& other) {
  for (std::size_t i = 0; i < values_.size(); ++i) values_[i] += other.values_[i];
  for (std::size_t k = 0; k < 3; ++k) total_[k] += other.total_[k];
  return *this;
}

void LightWeightTable::add(std::uint32_t cell, const Rgb& weight) {
  for (std::size_t k = 0; k < 3; ++k) {
    values_[k * brdf::merl_cells + cell] += weight[k];
    total_[k] += weight[k];
  }
}

std::size_t LightWeightTable::lit_cells() const {
  std::size_t count = 0;
  for (std::size_t c = 0; c < brdf::merl_cells; ++c)
    if (weight(0, c) > 0.0 || weight(1, c) > 0.0 || weight(2, c) > 0.0) ++count;
  return count;
}

}  // namespace pbrfit::render
