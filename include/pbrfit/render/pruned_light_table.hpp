#pragma once
// The cells of a light weight table (light_weight_table.hpp) that matter, as a compact list: the heaviest
// cells, by the sum over channels of each channel's share of its total, until the kept share of the total
// weight reaches `keep_share` in every channel. What is dropped is reported per channel.
//
// Invariants: 0 < keep_share <= 1 (std::invalid_argument otherwise); cells() are distinct flat MERL
// indices in ascending order, each with weight > 0 in some channel; for every channel the kept weight is
// at least keep_share x total, and dropped_share() = (total - kept) / total (0 for a channel of total 0);
// the heaviest-first order breaks ties by flat index, so the list is a pure function of the table.
// weights are channel-major (3 x size(): all red, then all green, then all blue), as is
// squared_weights(), the T^2 the metric uses.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "pbrfit/brdf/rusinkiewicz.hpp"
#include "pbrfit/render/light_weight_table.hpp"

namespace pbrfit::render {

inline constexpr double default_keep_share = 1.0 - 1e-4;

class PrunedLightTable {
 public:
  explicit PrunedLightTable(const LightWeightTable& table, double keep_share = default_keep_share);

  std::size_t size() const { return cells_.size(); }
  std::span<const std::uint32_t> cells() const { return cells_; }
  double weight(std::size_t channel, std::size_t kept) const { return weights_[channel * size() + kept]; }
  std::span<const double> weights() const { return weights_; }
  std::span<const double> squared_weights() const { return squared_; }
  Rgb dropped_share() const { return dropped_share_; }

 private:
  std::vector<std::uint32_t> cells_;
  std::vector<double> weights_, squared_;
  Rgb dropped_share_ = {0.0, 0.0, 0.0};
};

// The representative direction pair of each kept cell, in kept order: the cell's centre
// (brdf::merl_centre_of) with phi_h = 0, by brdf::from_half_diff. A pair may lie partly below the horizon
// for cells at grazing angles (the centre of a cell some of whose samples are above it).
std::vector<brdf::DirectionPair> representative_pairs(const PrunedLightTable& table);

}  // namespace pbrfit::render
