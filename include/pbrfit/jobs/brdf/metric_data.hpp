#pragma once
// The data a candidate BRDF is fitted to (Brady et al., sections 3.4-3.6): for every material and colour
// channel, a GP dataset over the kept cells of the pruned light weight table (render/pruned_light_table.hpp):
// one row per kept cell where the material is measured and whose representative directions lie above the
// horizon (n.l and n.v > 1e-4), inputs brdf_inputs() of those directions, target the material's value,
// weight T^2 of the channel. The weighted RMSE the interpreter computes then gives the metric:
//   S' = sum T^2 (measured - candidate)^2 = rmse^2 x sum of the weights.
//
// Invariants: built once per process and read by every compute thread; datasets are non-empty (the
// constructor throws std::invalid_argument naming the material otherwise).
#include <string>
#include <vector>

#include "pbrfit/brdf/merl_table.hpp"
#include "pbrfit/gp/dataset.hpp"
#include "pbrfit/render/pruned_light_table.hpp"

namespace pbrfit::jobs::brdf {

struct ChannelData {
  gp::Dataset data;
  double weight_sum = 0.0;
};

class MetricData {
 public:
  MetricData(const render::PrunedLightTable& table, const std::vector<pbrfit::brdf::MerlTable>& materials,
             const std::vector<std::string>& names);

  std::size_t materials() const { return names_.size(); }
  const std::string& name(std::size_t m) const { return names_[m]; }
  const ChannelData& channel(std::size_t material, std::size_t channel) const { return data_[3 * material + channel]; }
  std::size_t datasets() const { return data_.size(); }

 private:
  std::vector<std::string> names_;
  std::vector<ChannelData> data_;  // [material][channel]
};

}  // namespace pbrfit::jobs::brdf
