#pragma once
// A tabulated isotropic BRDF on the MERL grid (merl_grid.hpp): one value per cell and channel (RGB, the
// MERL channel scales already applied), NaN where the measurement is missing (MERL stores those as
// negative numbers).
//
// Invariants: values() has 3 x merl_cells entries, channel-major (all red, all green, all blue), each finite
// and >= 0 or NaN; lookup() of a direction pair reads its cell (nearest, no interpolation); interpolate()
// blends the 8 cells around it linearly in the grid's coordinates (theta_h and theta_d clamped at the grid's
// ends, phi_d periodic over [0, pi)), leaving out unmeasured cells and renormalizing the weights of the
// others (NaN when all 8 are unmeasured): continuous where the data are, for integrators that refine.
#include <array>
#include <cstddef>
#include <vector>

#include "pbrfit/brdf/merl_grid.hpp"

namespace pbrfit::brdf {

class MerlTable {
 public:
  MerlTable() : values_(3 * merl_cells, 0.0) {}
  // Throws std::invalid_argument unless there are 3 x merl_cells values, each finite and >= 0 or NaN.
  explicit MerlTable(std::vector<double> values);

  double value(std::size_t channel, std::size_t cell) const { return values_[channel * merl_cells + cell]; }
  void set(std::size_t channel, std::size_t cell, double v) { values_[channel * merl_cells + cell] = v; }
  bool measured(std::size_t cell) const;  // every channel holds a number
  std::size_t measured_cells() const;
  std::array<double, 3> lookup(const Vector3& wi, const Vector3& wo) const;
  std::array<double, 3> interpolate(const Vector3& wi, const Vector3& wo) const;
  const std::vector<double>& values() const { return values_; }

 private:
  std::vector<double> values_;
};

// The MERL channel scales: stored value x scale = BRDF value (red 1/1500, green 1.15/1500, blue 1.66/1500).
inline constexpr std::array<double, 3> merl_channel_scale = {1.0 / 1500.0, 1.15 / 1500.0, 1.66 / 1500.0};

// From the values a MERL file stores (channel scales not applied, negative where unmeasured) and back.
MerlTable merl_table_from_stored(const std::vector<double>& stored);
std::vector<double> stored_from_merl_table(const MerlTable& table);

}  // namespace pbrfit::brdf
