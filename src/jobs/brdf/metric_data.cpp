#include "pbrfit/jobs/brdf/metric_data.hpp"

#include <cmath>
#include <stdexcept>

#include "pbrfit/jobs/brdf/brdf_inputs.hpp"

namespace pbrfit::jobs::brdf {
namespace {

constexpr double horizon = 1e-4;

ChannelData channel_data(const render::PrunedLightTable& table, const std::vector<pbrfit::brdf::DirectionPair>& pairs,
                         const pbrfit::brdf::MerlTable& material, std::size_t channel) {
  std::vector<std::size_t> rows;
  for (std::size_t k = 0; k < table.size(); ++k) {
    const auto& p = pairs[k];
    if (p.wi.z() > horizon && p.wo.z() > horizon && material.measured(table.cells()[k]) && table.weight(channel, k) > 0.0)
      rows.push_back(k);
  }
  ChannelData out;
  out.data.inputs.resize(Eigen::Index(rows.size()), Eigen::Index(brdf_input_count));
  out.data.target.resize(Eigen::Index(rows.size()));
  out.data.weights.resize(Eigen::Index(rows.size()));
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const std::size_t k = rows[r];
    const auto in = pbrfit::brdf::direction_inputs(pairs[k].wi, pairs[k].wo);
    for (std::size_t c = 0; c < in.size(); ++c) out.data.inputs(Eigen::Index(r), Eigen::Index(c)) = in[c];
    out.data.target[Eigen::Index(r)] = material.value(channel, table.cells()[k]);
    const double w = table.squared_weights()[channel * table.size() + k];
    out.data.weights[Eigen::Index(r)] = w;
    out.weight_sum += w;
  }
  return out;
}

}  // namespace

MetricData::MetricData(const render::PrunedLightTable& table, const std::vector<pbrfit::brdf::MerlTable>& materials,
                       const std::vector<std::string>& names)
    : names_(names) {
  const auto pairs = render::representative_pairs(table);
  for (std::size_t m = 0; m < materials.size(); ++m) {
    for (std::size_t c = 0; c < 3; ++c) {
      data_.push_back(channel_data(table, pairs, materials[m], c));
      if (data_.back().data.rows() == 0)
        throw std::invalid_argument("material " + names_[m] + " has no measured value where the scene's light falls");
    }
  }
}

}  // namespace pbrfit::jobs::brdf
